#include "sim/action_inference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "sim/plan_executor.h"
#include "sim/simulation.h"

namespace dashbed::sim {
namespace {

/// A reference joint speed below this counts as resting [rad/s]: the eases of rest-to-rest
/// motions stay below it for milliseconds, longer than a step.
constexpr double kRestSpeed = 0.01;
/// How long after a close the pads may take to reach the object [s].
constexpr double kCloseWindow = 1.0;

/// What the first run saw, step by step.
struct Observation {
  std::vector<double> t;                  // plan time of each step
  std::vector<std::vector<char>> moving;  // [robot][step]: the reference moves
  std::vector<std::vector<int>> gripped;  // [robot][step]: object both pads touch, or -1
  std::vector<Eigen::Vector3d> final_position;  // per object, at the end

  /// First step at or after plan time `time`.
  std::size_t stepAt(double time) const {
    return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), time - 1e-9) - t.begin());
  }
  /// Start of robot r's last motion before step k.
  double motionBefore(std::size_t r, std::size_t k) const {
    const std::vector<char>& arm = moving[r];
    k = std::min(k, arm.size() - 1);
    while (k > 0 && !arm[k]) --k;
    while (k > 0 && arm[k - 1]) --k;
    return t[k];
  }
  /// End of robot r's first motion after step k.
  double motionAfter(std::size_t r, std::size_t k) const {
    const std::vector<char>& arm = moving[r];
    while (k < arm.size() && !arm[k]) ++k;
    while (k < arm.size() && arm[k]) ++k;
    return t[std::min(k, arm.size() - 1)];
  }
  /// The object robot r's pads both touch within the close window from step k, before `until`.
  int closedOn(std::size_t r, std::size_t k, double until) const {
    for (; k < t.size() && t[k] < until; ++k) {
      if (gripped[r][k] >= 0) return gripped[r][k];
    }
    return -1;
  }
};

Observation observe(const core::World& world, const core::RobotSet& robots, const core::Plan& plan) {
  // the same run without protective stops: an object the arm was not told of may weigh on it
  core::World unguarded = world;
  const double inf = std::numeric_limits<double>::infinity();
  unguarded.checks.tracking_error_limit = inf;
  unguarded.safety.tcp_force = inf;
  unguarded.safety.external_torque = inf;
  core::Plan bare = plan;
  bare.actions.clear();
  Simulation sim(unguarded, robots);
  PlanExecutor executor(sim, bare, world.physics.settle_time);
  const std::size_t n = world.robots.size();
  std::vector<int> left(n), right(n);
  for (std::size_t r = 0; r < n; ++r) {
    left[r] = robots[r].model->requireLink("hande_left_finger");
    right[r] = robots[r].model->requireLink("hande_right_finger");
  }
  Observation seen;
  seen.moving.resize(n);
  seen.gripped.resize(n);
  const double end = plan.duration() + world.checks.settle_time + 0.5;
  while (executor.planTime() < end) {
    executor.step();
    seen.t.push_back(executor.planTime());
    std::vector<std::vector<int>> by_left(n), by_right(n);
    for (const Contact& c : sim.contacts()) {
      for (const auto& [robot, object] : {std::pair(c.a, c.b), std::pair(c.b, c.a)}) {
        if (robot.kind != BodyRef::Kind::kRobot || object.kind != BodyRef::Kind::kObject) continue;
        const auto r = static_cast<std::size_t>(robot.index);
        if (robot.link == left[r]) by_left[r].push_back(object.index);
        if (robot.link == right[r]) by_right[r].push_back(object.index);
      }
    }
    for (std::size_t r = 0; r < n; ++r) {
      const core::JointReference ref = executor.reference(static_cast<int>(r));
      double speed = 0.0;
      for (int j = 0; j < 6; ++j) speed = std::max(speed, std::abs(ref.qd[j]));
      seen.moving[r].push_back(speed > kRestSpeed);
      int both = -1;
      for (const int o : by_left[r]) {
        if (std::find(by_right[r].begin(), by_right[r].end(), o) != by_right[r].end() && (both < 0 || o < both)) both = o;
      }
      seen.gripped[r].push_back(both);
    }
  }
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    seen.final_position.push_back(sim.objectPose(static_cast<int>(o)).translation());
  }
  return seen;
}


}  // namespace

std::vector<core::PlanAction> inferActions(const core::World& world, const core::RobotSet& robots,
                                           const core::Plan& plan) {
  const Observation seen = observe(world, robots, plan);
  std::vector<core::GripperCommand> commands = plan.gripper;
  std::stable_sort(commands.begin(), commands.end(),
                   [](const core::GripperCommand& a, const core::GripperCommand& b) { return a.t < b.t; });
  const std::size_t n = world.robots.size();
  std::vector<int> held(n, -1);                         // per robot: the object it holds
  std::vector<std::optional<std::size_t>> receiving(n);  // per giver: its open handoff in `actions`
  std::vector<core::PlanAction> actions;
  std::vector<std::size_t> places;  // indices in `actions`
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const core::GripperCommand& command = commands[i];
    const core::RobotSpec* spec = world.findRobot(command.robot);
    if (spec == nullptr) continue;
    const auto r = static_cast<std::size_t>(spec - world.robots.data());
    const std::size_t k = seen.stepAt(command.t);
    if (k >= seen.t.size()) continue;
    if (command.action == core::GripperAction::kClose) {
      double until = command.t + kCloseWindow;
      for (std::size_t j = i + 1; j < commands.size(); ++j) {
        if (commands[j].robot == command.robot) {
          until = std::min(until, commands[j].t);
          break;
        }
      }
      const int o = seen.closedOn(r, k, until);
      if (o < 0) continue;
      const std::string& object = world.objects[static_cast<std::size_t>(o)].name;
      const auto giver = std::find(held.begin(), held.end(), o);
      core::PlanAction action;
      action.object = object;
      action.start = seen.motionBefore(r, k);
      if (giver != held.end() && static_cast<std::size_t>(giver - held.begin()) != r) {
        const auto g = static_cast<std::size_t>(giver - held.begin());
        action.type = core::ActionType::kHandoff;
        action.robot = world.robots[g].name;
        action.receiver = command.robot;
        action.end = action.start;  // until the giver opens
        receiving[g] = actions.size();
      } else {
        action.type = core::ActionType::kPick;
        action.robot = command.robot;
        action.end = seen.motionAfter(r, k);
      }
      actions.push_back(action);
      held[r] = o;
    } else if (held[r] >= 0) {
      if (receiving[r]) {
        actions[*receiving[r]].end = seen.motionAfter(r, k);
        receiving[r].reset();
      } else {
        core::PlanAction action;
        action.type = core::ActionType::kPlace;
        action.robot = command.robot;
        action.object = world.objects[static_cast<std::size_t>(held[r])].name;
        action.start = seen.motionBefore(r, k);
        action.end = seen.motionAfter(r, k);
        places.push_back(actions.size());
        actions.push_back(action);
      }
      held[r] = -1;
    }
  }
  // regions: the goal's unless the object is picked up again later; else where it rests
  for (const std::size_t p : places) {
    core::PlanAction& place = actions[p];
    const bool picked_again = std::any_of(actions.begin(), actions.end(), [&](const core::PlanAction& a) {
      return a.type == core::ActionType::kPick && a.object == place.object && a.start > place.start;
    });
    if (picked_again) continue;
    const core::ObjectSpec& object = *world.findObject(place.object);
    const auto o = static_cast<std::size_t>(&object - world.objects.data());
    if (const core::Region* goal = world.goalRegionOf(object)) {
      place.region = goal->name;
      continue;
    }
    for (const core::Region& region : world.regions) {
      if (core::distanceOutside(region, seen.final_position[o], world.checks.placement_tolerance) <= 0.0) {
        place.region = region.name;
        break;
      }
    }
  }
  // an open handoff (the giver never let go) ends with the run
  for (core::PlanAction& action : actions) {
    if (action.type == core::ActionType::kHandoff && action.end <= action.start) action.end = seen.t.back();
  }
  std::stable_sort(actions.begin(), actions.end(),
                   [](const core::PlanAction& a, const core::PlanAction& b) { return a.start < b.start; });
  return actions;
}

}  // namespace dashbed::sim
