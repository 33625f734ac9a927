#include "tools/sequential_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <sstream>
#include <stdexcept>

#include "core/reach.h"
#include "tools/scripted_plan.h"

namespace dashbed::tools {
namespace {

// Room a gripper needs around a placed object: 17.4 mm fingertip thickness plus clearance on
// each side of the closing axis (URDF finger geometry).
constexpr double kFingerRoom = 0.025;  // [m]

/// Object-centre positions for placing objects of `size` side by side in a region, row by row.
std::vector<Eigen::Vector3d> regionSlots(const core::Region& region, const Eigen::Vector3d& size) {
  const double pitch_x = size.x() + 2 * kFingerRoom, pitch_y = size.y() + 2 * kFingerRoom;
  const int nx = std::max(1, static_cast<int>(std::floor((region.size.x() - size.x()) / pitch_x)) + 1);
  const int ny = std::max(1, static_cast<int>(std::floor((region.size.y() - size.y()) / pitch_y)) + 1);
  std::vector<Eigen::Vector3d> slots;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Eigen::Vector3d p_R((ix - (nx - 1) / 2.0) * pitch_x, (iy - (ny - 1) / 2.0) * pitch_y, size.z() / 2);
      slots.push_back(region.X_WR * p_R);
    }
  }
  return slots;
}

/// Robots ordered by the horizontal distance of their base from p_W, nearest first: the
/// nearest robot reaches a pose most comfortably (the reach map only says "some IK exists").
std::vector<int> nearestFirst(std::vector<int> robots, const core::World& world, const Eigen::Vector3d& p_W) {
  const auto distance = [&](int r) {
    return (world.robots[r].X_WBase.translation() - p_W).head<2>().norm();
  };
  std::stable_sort(robots.begin(), robots.end(), [&](int a, int b) { return distance(a) < distance(b); });
  return robots;
}

/// Shortest chain of robots from one reaching the start to one reaching the goal, hopping
/// between robots whose workspaces overlap; empty if none. Breadth-first from the robots in
/// `from` in their order, so among equally short chains the one starting earlier wins.
std::vector<int> robotChain(const std::vector<int>& from, const std::vector<int>& to,
                            const std::vector<std::vector<bool>>& overlap) {
  const int n = static_cast<int>(overlap.size());
  std::vector<int> previous(n, -2);
  std::queue<int> frontier;
  for (int r : from) {
    previous[r] = -1;
    frontier.push(r);
  }
  while (!frontier.empty()) {
    const int r = frontier.front();
    frontier.pop();
    if (std::find(to.begin(), to.end(), r) != to.end()) {
      std::vector<int> chain;
      for (int at = r; at >= 0; at = previous[at]) chain.insert(chain.begin(), at);
      return chain;
    }
    for (int next = 0; next < n; ++next) {
      if (overlap[r][next] && previous[next] == -2) {
        previous[next] = r;
        frontier.push(next);
      }
    }
  }
  return {};
}

}  // namespace

std::vector<std::string> sequentialScripts(const core::LoadedWorld& loaded) {
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;
  const std::size_t n = robots.size();
  std::vector<std::vector<bool>> overlap(n, std::vector<bool>(n, false));
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      overlap[a][b] = overlap[b][a] = core::workspacesOverlap(robots[a], robots[b]);
    }
  }
  std::map<std::string, std::size_t> used_slots;
  std::vector<std::string> scripts;
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const core::ObjectSpec& object = world.objects[o];
    const core::Region* region = world.goalRegionOf(object);
    if (region == nullptr) continue;
    const std::vector<Eigen::Vector3d> slots = regionSlots(*region, object.size);
    std::size_t& used = used_slots[region->name];
    if (used >= slots.size()) {
      throw std::runtime_error("region " + region->name + " has room for " + std::to_string(slots.size()) +
                               " objects side by side; more are sent there");
    }
    const Eigen::Vector3d slot = slots[used++];
    const std::vector<int> chain = robotChain(nearestFirst(loaded.reach.start[o], world, object.X_WO.translation()),
                                              nearestFirst(loaded.reach.goal[o], world, slot), overlap);
    if (chain.empty()) {
      throw std::runtime_error("no chain of robots can carry " + object.name + " from its start to " + region->name);
    }
    const auto name = [&](int r) { return world.robots[r].name; };
    std::ostringstream script;
    script.precision(17);
    script << name(chain.front()) << " picks " << object.name << "\n";
    for (std::size_t k = 1; k < chain.size(); ++k) {
      script << name(chain[k - 1]) << " hands " << object.name << " to " << name(chain[k]) << "\n";
    }
    script << name(chain.back()) << " places " << object.name << " at " << slot.x() << " " << slot.y() << " "
           << slot.z() << "\n";
    scripts.push_back(script.str());
  }
  return scripts;
}

core::Plan sequentialPlan(const core::LoadedWorld& world) {
  core::Plan plan;
  plan.world = world.world->name;
  for (const core::RobotSpec& robot : world.world->robots) {
    core::RobotTrajectory trajectory;
    trajectory.robot = robot.name;
    plan.trajectories.push_back(trajectory);
  }
  double offset = 0.0;
  const std::vector<std::string> scripts = sequentialScripts(world);
  for (std::size_t k = 0; k < scripts.size(); ++k) {
    const core::Plan part = planFromScript(world, scripts[k], "sequential object " + std::to_string(k + 1));
    for (const core::RobotTrajectory& piece : part.trajectories) {
      for (core::RobotTrajectory& trajectory : plan.trajectories) {
        if (trajectory.robot != piece.robot) continue;
        trajectory.joint_names = piece.joint_names;
        for (core::TrajectoryPoint point : piece.points) {
          point.t += offset;
          // each part starts where the previous one ended (home): skip a repeated instant
          if (!trajectory.points.empty() && point.t <= trajectory.points.back().t + 1e-9) continue;
          trajectory.points.push_back(point);
        }
      }
    }
    for (core::GripperCommand command : part.gripper) {
      command.t += offset;
      plan.gripper.push_back(command);
    }
    for (core::PlanAction action : part.actions) {
      action.start += offset;
      action.end += offset;
      plan.actions.push_back(action);
    }
    offset += part.duration();
  }
  // robots that never move keep out of the plan
  std::erase_if(plan.trajectories, [](const core::RobotTrajectory& t) { return t.points.empty(); });
  std::stable_sort(plan.gripper.begin(), plan.gripper.end(),
                   [](const core::GripperCommand& a, const core::GripperCommand& b) { return a.t < b.t; });
  return plan;
}

}  // namespace dashbed::tools
