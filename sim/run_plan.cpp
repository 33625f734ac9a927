#include "sim/run_plan.h"

#include <algorithm>
#include <utility>

#include "core/readiness.h"

#include "sim/action_inference.h"
#include "sim/monitor.h"
#include "sim/plan_executor.h"

namespace dashbed::sim {

StepObserver chained(StepObserver first, StepObserver then) {
  if (!first) return then;
  if (!then) return first;
  return [first = std::move(first), then = std::move(then)](const StepState& step) {
    first(step);
    then(step);
  };
}

Report runPlan(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
               const std::string& plan_file, const RunOptions& options) {
  // a plan made elsewhere, without actions: they are inferred from a first run
  const bool infer = plan.actions.empty() && !plan.gripper.empty();
  core::Plan inferred;
  if (infer) {
    inferred = plan;
    inferred.actions = inferActions(world, robots, plan);
  }
  const core::Plan& judged = infer ? inferred : plan;
  Simulation sim(world, robots);
  const double offset = world.physics.settle_time;
  PlanExecutor executor(sim, judged, offset);
  Monitor monitor(sim, judged, offset);
  const double tail = options.tail_time >= 0.0 ? options.tail_time : world.checks.settle_time + 0.5;
  double end = plan.duration() + tail;
  while (executor.planTime() < end) {
    // after a protective stop the run lasts only until what it dropped has settled
    if (executor.protectiveStop()) end = std::min(end, executor.protectiveStop()->t + tail);
    executor.step();
    monitor.observe(executor);
    if (options.on_step) options.on_step(StepState{sim, executor, monitor, executor.planTime()});
  }
  Report report = monitor.finish(executor);
  report.plan_file = plan_file;
  report.actions_inferred = infer;
  report.readiness = core::checkReadiness(plan, world, robots).checks;
  return report;
}

}  // namespace dashbed::sim
