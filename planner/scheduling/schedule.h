#pragma once
// A schedule: each robot's part of a transition history as a timeline of segments (a move along
// its roadmap path, its part of a transition, ...) with their start times. Conflict resolution
// (scheduled_cbs.h) makes one free of robot-robot collisions (robot_conflicts.h checks it), the
// plan writer (plan_writer.h) writes it out for the simulator.

#include <optional>
#include <vector>

#include "core/hande.h"
#include "planner/motion/motion_hypergraph.h"

namespace dashbed::planner {

/// One segment of a robot's timeline.
struct ScheduleSegment {
  int robot = -1;
  const Move* move = nullptr;                  ///< a move, or
  const TransitionMotion* motion = nullptr;    ///< a robot's part of a transition
  int step = -1;      ///< the history step it belongs to (-1: folding, the final move, unfolding)
  /// The history step during which it runs in a sequential history: its step, except that a
  /// robot's way to where it waits after a transition (parking, or the final move) belongs to
  /// that transition's step; folding comes before every step (-1), unfolding after them all
  /// (the number of steps).
  int phase = -1;
  Millis duration = 0;
  std::optional<HeldObject> held;  ///< moves: the object carried
  double finger = core::kFingersOpen;           ///< moves: finger position [m]
  /// moves into a transition: may arrive before it starts and wait in front of it (set by
  /// conflict resolution; by default a robot arrives just in time)
  bool early = false;
  /// moves: a robot's way to a parking (the first part of a parked move; set by conflict
  /// resolution, which does not park it again)
  bool to_parking = false;
};

struct Schedule {
  std::vector<ScheduleSegment> segments;  ///< per robot in order, robots one after another
  std::vector<Millis> start;              ///< [segment] start time
  Millis makespan = 0;
};

}  // namespace dashbed::planner
