#pragma once
// Independent checks of a written plan, shared by the DaSH planner tests (Catch2 assertions).

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/trajectory_interpolator.h"
#include "core/grasps.h"
#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"

namespace dashbed::planner::testing {

/// Every object's actions form a chain: picked at its start by one robot, handed along, placed
/// in its goal region by the robot holding it, or set aside (a place without a region) at most
/// once and picked up again; no robot ever holds two objects.
inline void requireValidActions(const core::Plan& plan, const core::World& world) {
  std::map<std::string, std::string> holder;     // object -> robot holding it
  std::map<std::string, std::string> holding;    // robot -> object
  std::set<std::string> placed, aside, set_aside;  // at the goal, aside now, ever set aside
  std::vector<core::PlanAction> actions = plan.actions;
  std::stable_sort(actions.begin(), actions.end(), [](const auto& a, const auto& b) { return a.end < b.end; });
  for (const core::PlanAction& a : actions) {
    INFO(core::toString(a.type) << " " << a.robot << " " << a.object);
    switch (a.type) {
      case core::ActionType::kPick:
        REQUIRE(holder.count(a.object) == 0);
        REQUIRE(placed.count(a.object) == 0);
        REQUIRE(holding.count(a.robot) == 0);
        REQUIRE(aside.count(a.object) == set_aside.count(a.object));  // from its start, or from aside
        aside.erase(a.object);
        holder[a.object] = a.robot;
        holding[a.robot] = a.object;
        break;
      case core::ActionType::kHandoff:
        REQUIRE(holder.at(a.object) == a.robot);
        REQUIRE(holding.count(a.receiver) == 0);
        holding.erase(a.robot);
        holder[a.object] = a.receiver;
        holding[a.receiver] = a.object;
        break;
      case core::ActionType::kPlace:
        REQUIRE(holder.at(a.object) == a.robot);
        holder.erase(a.object);
        holding.erase(a.robot);
        if (a.region.empty()) {
          REQUIRE(set_aside.insert(a.object).second);
          aside.insert(a.object);
          break;
        }
        REQUIRE(a.region == world.goalRegionOf(*world.findObject(a.object))->name);
        placed.insert(a.object);
        break;
    }
  }
  for (const core::ObjectSpec& object : world.objects) {
    if (world.goalRegionOf(object) != nullptr) CHECK(placed.count(object.name) == 1);
  }
  CHECK(holding.empty());
  CHECK(aside.empty());
}

/// Every move starts from rest as written: a point with a non-zero joint velocity (a move's
/// sample) follows a point whose velocity is written too, never one the interpolator would give
/// a velocity of its own (a transition's key), which would bend the start of the move off the
/// straight line it was checked along.
inline void requireMovesStartAtRest(const core::Plan& plan) {
  for (const core::RobotTrajectory& trajectory : plan.trajectories) {
    for (std::size_t i = 1; i < trajectory.points.size(); ++i) {
      const core::TrajectoryPoint& point = trajectory.points[i];
      const bool moving =
          point.qd && std::any_of(point.qd->begin(), point.qd->end(), [](double v) { return v != 0.0; });
      INFO(trajectory.robot << " at t = " << point.t << " s");
      if (moving) REQUIRE(trajectory.points[i - 1].qd);
    }
  }
}

/// No two robot bodies touch along the plan as the simulator interpolates it, every 2 ms,
/// with a checker of zero margin (the planner's own checks use a margin and its timelines).
/// Fingers follow the gripper commands: open, or closed on an object (the worlds used here have
/// objects of one narrowest width, the only one within the Hand-E's stroke).
inline void requireNoRobotCollision(const core::Plan& plan, const core::LoadedWorld& loaded) {
  const double width = loaded.world->objects.front().size.minCoeff();
  for (const core::ObjectSpec& object : loaded.world->objects) {
    for (const double side : object.size) REQUIRE((side == width || side > core::kHandeMaxOpening));
  }
  CollisionSettings exact;
  exact.margin = 0.0;
  exact.motion_step = 1e-3;
  const CollisionScene scene(*loaded.world, *loaded.robots, exact);
  CollisionChecker checker(scene);
  std::vector<core::TrajectoryInterpolator> arms;
  for (const core::RobotTrajectory& t : plan.trajectories) arms.emplace_back(t.points);
  const int n = static_cast<int>(arms.size());
  for (double t = 0.0; t <= plan.duration(); t += 0.002) {
    std::vector<Eigen::VectorXd> q(n, Eigen::VectorXd::Constant(8, 0.0));
    for (int r = 0; r < n; ++r) {
      const auto ref = arms[r].at(t);
      for (int j = 0; j < 6; ++j) q[r][j] = ref.q[j];
      double finger = 0.025;
      for (const core::GripperCommand& command : plan.gripper) {
        if (command.robot == plan.trajectories[r].robot && command.t <= t) {
          finger = command.action == core::GripperAction::kOpen ? 0.025 : width / 2;
        }
      }
      q[r][6] = q[r][7] = finger;
    }
    for (int a = 0; a < n; ++a) {
      for (int b = a + 1; b < n; ++b) {
        INFO("t = " << t << " s, robots " << a << " and " << b);
        REQUIRE(checker.robotsFree(a, q[a], std::nullopt, b, q[b], std::nullopt));
      }
    }
  }
}

}  // namespace dashbed::planner::testing
