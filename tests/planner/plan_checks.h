#pragma once
// Independent checks of a written plan, shared by the DaSH planner tests (Catch2 assertions).

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/trajectory_interpolator.h"
#include "core/grasps.h"
#include "core/plan.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "sim/simulation.h"

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

/// No collision along the plan as the simulator interpolates it, every 2 ms, judged on the
/// simulator's own geometry (Bullet), not the planner's (FCL): robots stand in the plan's
/// configurations, fingers open or closed on what they hold, held objects move with their
/// gripper, and a released object stays where it was let go. Deeper than 0.5 mm is a collision:
/// robot with robot, with a fixture (its base's own mounting aside), with an object not in its
/// hand nor in an action it is doing; a held object with another robot or another held object,
/// and with a fixture outside the picks and places that set it down or lift it off.
inline std::vector<std::string> collisionsAlong(const core::Plan& plan, const core::LoadedWorld& loaded) {
  using Kind = sim::BodyRef::Kind;
  std::vector<std::string> found;
  constexpr double kDepth = -5e-4;  // [m]
  const core::World& world = *loaded.world;
  sim::Simulation scene(world, *loaded.robots);
  const int n = static_cast<int>(plan.trajectories.size());
  std::vector<core::TrajectoryInterpolator> arms;
  std::vector<int> robot_of;  // trajectory -> robot index in the world
  for (const core::RobotTrajectory& t : plan.trajectories) {
    arms.emplace_back(t.points);
    robot_of.push_back(static_cast<int>(world.findRobot(t.robot) - world.robots.data()));
  }
  const auto robotIndex = [&](const std::string& name) { return static_cast<int>(world.findRobot(name) - world.robots.data()); };
  const auto objectIndex = [&](const std::string& name) { return static_cast<int>(world.findObject(name) - world.objects.data()); };
  std::vector<core::Pose> X_WO;  // every object's pose now
  for (const core::ObjectSpec& object : world.objects) X_WO.push_back(object.X_WO);
  std::vector<std::optional<std::pair<int, core::Pose>>> held(world.robots.size());  // robot -> (object, X_TO)
  std::vector<double> finger(world.robots.size(), core::kHandeMaxOpening / 2);
  std::vector<core::ArmConfig> q(world.robots.size());
  for (std::size_t r = 0; r < world.robots.size(); ++r) q[r] = world.robots[r].home;
  // the action of robot r going on at time t that involves object o (a pick, place or handoff)
  const auto actionOf = [&](int r, double t, std::optional<core::ActionType> type = {}) -> const core::PlanAction* {
    for (const core::PlanAction& a : plan.actions) {
      if (t < a.start - 1e-9 || t > a.end + 1e-9 || (type && a.type != *type)) continue;
      if (robotIndex(a.robot) == r || (!a.receiver.empty() && robotIndex(a.receiver) == r)) return &a;
    }
    return nullptr;
  };
  std::size_t next_command = 0;
  for (double t = 0.0; t <= plan.duration(); t += 0.002) {
    for (int k = 0; k < n; ++k) {
      const auto ref = arms[k].at(t);
      for (int j = 0; j < 6; ++j) q[robot_of[k]][j] = ref.q[j];
    }
    const auto X_WT = [&](int r) { return (*loaded.robots)[r].tcpPoseInWorld(q[r]); };
    for (; next_command < plan.gripper.size() && plan.gripper[next_command].t <= t; ++next_command) {
      const core::GripperCommand& c = plan.gripper[next_command];
      const int r = robotIndex(c.robot);
      if (c.action == core::GripperAction::kOpen) {
        held[r].reset();
        finger[r] = core::kHandeMaxOpening / 2;
        continue;
      }
      const core::PlanAction* a = actionOf(r, c.t);
      if (a == nullptr) continue;  // a close on nothing
      const int o = objectIndex(a->object);
      held[r] = std::pair(o, X_WT(r).inverse() * X_WO[o]);
      const Eigen::Vector3d size = world.objects[o].size;
      finger[r] = std::min({size.x(), size.y(), size.z()}) / 2;
    }
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      Eigen::VectorXd joints = scene.jointPositions(static_cast<int>(r));
      for (int j = 0; j < 6; ++j) joints[j] = q[r][j];
      joints[6] = joints[7] = finger[r];
      scene.setJointPositions(static_cast<int>(r), joints);
      if (held[r]) {
        X_WO[held[r]->first] = X_WT(static_cast<int>(r)) * held[r]->second;
      }
    }
    for (std::size_t o = 0; o < X_WO.size(); ++o) scene.setObjectPose(static_cast<int>(o), X_WO[o]);
    scene.detectContacts();
    const auto holderOf = [&](int o) {
      for (std::size_t r = 0; r < held.size(); ++r) {
        if (held[r] && held[r]->first == o) return static_cast<int>(r);
      }
      return -1;
    };
    for (const sim::Contact& c : scene.contacts()) {
      if (c.min_distance > kDepth) continue;
      const sim::BodyRef& a = c.a;  // ordered: floor, fixture, object, robot
      const sim::BodyRef& b = c.b;
      const auto name = [&](const sim::BodyRef& body) {
        switch (body.kind) {
          case Kind::kFloor: return std::string("the floor");
          case Kind::kFixture: return "fixture " + world.fixtures[body.index].name;
          case Kind::kObject: return "object " + world.objects[body.index].name;
          case Kind::kRobot: return "robot " + world.robots[body.index].name + " link " + std::to_string(body.link);
        }
        return std::string();
      };
      bool allowed = true;
      if (a.kind == Kind::kRobot && b.kind == Kind::kRobot) {
        allowed = a.index == b.index;  // a robot's own neighbouring links (not checked here)
      } else if ((a.kind == Kind::kFixture || a.kind == Kind::kFloor) && b.kind == Kind::kRobot) {
        allowed = b.link == 0;  // the base stands on its fixture
      } else if (a.kind == Kind::kObject && b.kind == Kind::kRobot) {
        const core::PlanAction* doing = actionOf(b.index, t);
        allowed = holderOf(a.index) == b.index || (doing != nullptr && objectIndex(doing->object) == a.index);
      } else if (a.kind == Kind::kObject && b.kind == Kind::kObject) {
        allowed = holderOf(a.index) < 0 && holderOf(b.index) < 0;  // resting objects may touch
      } else if ((a.kind == Kind::kFixture || a.kind == Kind::kFloor) && b.kind == Kind::kObject) {
        const int holder = holderOf(b.index);
        const core::PlanAction* doing = holder >= 0 ? actionOf(holder, t) : nullptr;
        allowed = holder < 0 || (doing != nullptr && doing->type != core::ActionType::kHandoff);
      }
      if (!allowed) {
        found.push_back("t = " + std::to_string(t) + " s: " + name(a) + " and " + name(b) + ", " +
                        std::to_string(-c.min_distance * 1000) + " mm deep");
      }
    }
  }
  return found;
}

/// collisionsAlong finds nothing.
inline void requireNoCollision(const core::Plan& plan, const core::LoadedWorld& loaded) {
  const std::vector<std::string> found = collisionsAlong(plan, loaded);
  INFO((found.empty() ? std::string() : found.front()) << " (" << found.size() << " samples)");
  CHECK(found.empty());
}

}  // namespace dashbed::planner::testing
