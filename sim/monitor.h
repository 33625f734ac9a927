#pragma once
// Monitor: the physical checks of a plan's execution (see the README, Physical checks).
//
// It observes the simulation after every step and, at the end, judges every planned action:
//  - pick:    after the close command both finger pads touch the object; at the end of the
//             pick the object no longer touches its support and has been lifted; its pose in
//             the TCP frame stays within the slip tolerance until the robot releases it.
//  - handoff: giver and receiver both hold the object for an overlap before the giver
//             opens; afterwards the receiver holds it within the slip tolerance; the object
//             touches nothing but the two grippers in between.
//  - place:   a settle time after release the object is at rest, inside its goal region,
//             flat on a face within the upright tolerance, and it is still there at the end.
//             A place without a region sets the object aside to be picked up again: a
//             settle time after release it is at rest, flat on a face, on a stable surface.
//  - execution: no robot-robot or robot-scenery contact, no robot touching an object it is
//             not manipulating, no object knocked from rest, joint tracking within its limit,
//             and at the end every object the world's goals send to a region is inside it
//             (so a plan that leaves one out fails, whatever its actions did).
// Drops, slips and knocked objects become events attributed to the action in progress.

#include <memory>
#include <string>
#include <vector>

#include "core/plan.h"
#include "sim/plan_executor.h"
#include "sim/report.h"
#include "sim/simulation.h"

namespace dashbed::sim {

class Monitor {
 public:
  /// `plan_time_offset`: simulation time at which plan time 0 starts (the settle pre-roll).
  Monitor(const Simulation& sim, const core::Plan& plan, double plan_time_offset);
  ~Monitor();

  /// Records what happened in the step just taken (the executor tells the grippers' state).
  void observe(const PlanExecutor& executor);

  /// The events found so far (drops, slips, knocks, unplanned contacts), in time order.
  const std::vector<ExecutionEvent>& events() const;

  /// Judges every action and the execution; call once after the run.
  Report finish(const PlanExecutor& executor);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace dashbed::sim
