#pragma once
// Tiny worlds built in code for the simulator tests (no file parsing involved).

#include <numbers>
#include <stdexcept>
#include <string>

#include "core/asset_paths.h"
#include "core/world.h"
#include "core/world_io.h"
#include "core/world_loader.h"

namespace dashbed::test {

/// A 2.0 x 1.4 x 0.75 m table with robots r0 at (-0.7, 0) facing +x and, if `two_robots`,
/// r1 at (0.7, 0) facing -x, bases on the table top, home = the UR "ready" pose
/// (gripper pointing down in front of the robot).
inline core::World tableWorld(bool two_robots) {
  core::World world;
  world.name = two_robots ? "test_table_2r" : "test_table_1r";
  core::FixtureSpec table;
  table.name = "table";
  table.size = {2.0, 1.4, 0.75};
  core::Box top;
  top.X_WB.translation() = Eigen::Vector3d(0, 0, 0.375);
  top.size = table.size;
  table.boxes.push_back(top);
  world.fixtures.push_back(table);
  const core::ArmConfig ready{0.0, -std::numbers::pi / 2, std::numbers::pi / 2, -std::numbers::pi / 2,
                              -std::numbers::pi / 2, 0.0};
  core::RobotSpec r0;
  r0.name = "r0";
  r0.model = "ur5e_hande";
  r0.X_WBase = core::makePoseXyzYaw({-0.7, 0.0, 0.75}, 0.0);
  r0.home = ready;
  world.robots.push_back(r0);
  if (two_robots) {
    core::RobotSpec r1 = r0;
    r1.name = "r1";
    r1.X_WBase = core::makePoseXyzYaw({0.7, 0.0, 0.75}, std::numbers::pi);
    world.robots.push_back(r1);
  }
  return world;
}

/// Adds a 40 mm, 0.1 kg cube resting on the table at (x, y) with the given yaw.
inline void addCube(core::World& world, const std::string& name, double x, double y, double yaw = 0.0) {
  core::ObjectSpec cube;
  cube.name = name;
  cube.size = Eigen::Vector3d::Constant(0.04);
  cube.mass = 0.1;
  cube.friction = 0.8;
  cube.object_class = "red";
  cube.X_WO = core::makePoseXyzYaw({x, y, 0.75 + 0.02}, yaw);
  world.objects.push_back(cube);
}

/// The default world (worlds/default.yaml) without its goals, for scripts that move one cube:
/// with them, the run's goal check (every cube in its bin at the end) fails whatever the
/// script's actions do.
inline const core::LoadedWorld& defaultWorldWithoutGoals() {
  static const core::LoadedWorld loaded = [] {
    core::World world = core::loadWorldFile(core::defaultWorldPath());
    world.goals.clear();
    return core::validateWorld(std::move(world));
  }();
  return loaded;
}

/// " Q1 .. Q6": a configuration of robot r of `world` with its TCP at p_W pointing straight
/// down, as an action script's "moves to" takes it (the IK solution nearest home).
inline std::string downAt(const core::LoadedWorld& world, int r, const Eigen::Vector3d& p_W) {
  const auto& robot = (*world.robots)[r];
  core::Pose X_WT = core::Pose::Identity();
  X_WT.linear() = Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  X_WT.translation() = p_W;
  const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
  if (solutions.empty()) throw std::runtime_error("downAt: no IK solution");
  std::string q;
  for (const double v : solutions.front()) q.append(" ").append(std::to_string(v));
  return q;
}

}  // namespace dashbed::test
