#include "core/reach.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/grasps.h"
#include "core/world_io.h"

namespace dashbed::core {

Pose placementPose(const Region& region, const ObjectSpec& object) {
  Pose X_WO = region.X_WR;
  X_WO.translation() += region.X_WR.linear() * Eigen::Vector3d(0.0, 0.0, object.size.z() / 2);
  return X_WO;
}

bool reachesBox(const PlacedRobot& robot, const Pose& X_WO, const Eigen::Vector3d& size) {
  const Pose X_BaseW = robot.spec->X_WBase.inverse();
  for (const BoxGrasp& grasp : boxGrasps(size)) {
    if (!robot.ik->solve(X_BaseW * X_WO * grasp.X_OT).empty()) return true;
  }
  return false;
}

bool reachesPlacementIn(const PlacedRobot& robot, const Region& region, const ObjectSpec& object) {
  if (reachesBox(robot, placementPose(region, object), object.size)) return true;
  constexpr int kGrid = 5;
  const double margin = 0.5 * std::max(object.size.x(), object.size.y());
  const double half_x = std::max(0.0, 0.5 * region.size.x() - margin), half_y = std::max(0.0, 0.5 * region.size.y() - margin);
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const Eigen::Vector3d p_R((2.0 * i / (kGrid - 1) - 1.0) * half_x, (2.0 * j / (kGrid - 1) - 1.0) * half_y,
                                object.size.z() / 2);
      Pose X_WO = region.X_WR;
      X_WO.translation() = region.X_WR * p_R;
      if (reachesBox(robot, X_WO, object.size)) return true;
    }
  }
  return false;
}

ReachMap computeReach(const World& world, const RobotSet& robots) {
  ReachMap reach;
  reach.start.resize(world.objects.size());
  reach.goal.resize(world.objects.size());
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const ObjectSpec& object = world.objects[o];
    const Region* region = world.goalRegionOf(object);
    for (std::size_t r = 0; r < robots.size(); ++r) {
      if (reachesBox(robots[r], object.X_WO, object.size)) reach.start[o].push_back(static_cast<int>(r));
      if (region != nullptr && reachesPlacementIn(robots[r], *region, object)) {
        reach.goal[o].push_back(static_cast<int>(r));
      }
    }
  }
  return reach;
}

void requireReachable(const World& world, const ReachMap& reach) {
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const ObjectSpec& object = world.objects[o];
    if (boxGrasps(object.size).empty()) {
      std::ostringstream msg;
      msg << formatLocation(object.where) << ": objects[" << o << "].size: object '" << object.name << "' ("
          << object.size.x() * 1000 << " x " << object.size.y() * 1000
          << " mm across) is too wide for the gripper: it opens to " << kHandeMaxOpening * 1000
          << " mm and keeps " << kGraspClearance * 1000 << " mm of it to spare across a pair of opposite sides";
      throw WorldError(msg.str());
    }
    if (reach.start[o].empty()) {
      const Eigen::Vector3d p = object.X_WO.translation();
      std::ostringstream msg;
      msg << formatLocation(object.where) << ": objects[" << o << "].pose: object '" << object.name
          << "' at [" << p.x() << ", " << p.y() << ", " << p.z()
          << "] is out of every robot's reach (no IK solution for any top or side grasp)";
      throw WorldError(msg.str());
    }
    const Region* region = world.goalRegionOf(object);
    if (region != nullptr && reach.goal[o].empty()) {
      // name the goal that sends the object there
      const Goal* goal = nullptr;
      std::size_t goal_index = 0;
      for (std::size_t g = 0; g < world.goals.size() && goal == nullptr; ++g) {
        const Goal& candidate = world.goals[g];
        if (candidate.region == region->name &&
            (candidate.object == object.name ||
             (!candidate.object_class.empty() && candidate.object_class == object.object_class))) {
          goal = &candidate;
          goal_index = g;
        }
      }
      std::ostringstream msg;
      msg << formatLocation(goal != nullptr ? goal->where : region->where) << ": goals[" << goal_index
          << "].region: region '" << region->name << "' (goal of object '" << object.name
          << "') is out of every robot's reach (no IK solution for placing it there)";
      throw WorldError(msg.str());
    }
  }
}

}  // namespace dashbed::core

namespace dashbed::core {

bool workspacesOverlap(const PlacedRobot& a, const PlacedRobot& b) {
  const Eigen::Vector3d pa = a.spec->X_WBase.translation(), pb = b.spec->X_WBase.translation();
  const Eigen::Vector3d mid = 0.5 * (pa + pb);
  Eigen::Vector3d along = pb - pa;
  along.z() = 0.0;
  if (along.norm() < 1e-9) return true;  // same base position
  along.normalize();
  const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(along);
  const double top = std::max(pa.z(), pb.z());
  const Eigen::Vector3d cube = Eigen::Vector3d::Constant(0.04);
  for (const double height : {0.3, 0.15, 0.45}) {
    for (const double s : {0.0, -0.1, 0.1}) {
      for (const double t : {0.0, -0.1, 0.1}) {
        Pose X_WO = Pose::Identity();
        X_WO.translation() = Eigen::Vector3d(mid.x(), mid.y(), top + height) + s * along + t * across;
        X_WO.linear() = Eigen::AngleAxisd(std::atan2(along.y(), along.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        if (reachesBox(a, X_WO, cube) && reachesBox(b, X_WO, cube)) return true;
      }
    }
  }
  return false;
}

}  // namespace dashbed::core
