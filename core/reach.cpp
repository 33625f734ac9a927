#include "core/reach.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include <Eigen/Geometry>

#include "core/geometry.h"
#include "core/grasps.h"
#include "core/pose.h"
#include "core/ur_ik.h"
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
      msg << "object '" << object.name << "' ("
          << object.size.x() * 1000 << " x " << object.size.y() * 1000
          << " mm across) is too wide for the gripper: it opens to " << kHandeMaxOpening * 1000
          << " mm and keeps " << kGraspClearance * 1000 << " mm of it to spare across a pair of opposite sides";
      throw WorldError(object.where, "objects[" + std::to_string(o) + "].size", msg.str());
    }
    if (reach.start[o].empty()) {
      const Eigen::Vector3d p = object.X_WO.translation();
      std::ostringstream msg;
      msg << "object '" << object.name << "' at [" << p.x() << ", " << p.y() << ", " << p.z()
          << "] is out of every robot's reach (no IK solution for any top or side grasp)";
      throw WorldError(object.where, "objects[" + std::to_string(o) + "].pose", msg.str());
    }
    const Region* region = world.goalRegionOf(object);
    if (region != nullptr && reach.goal[o].empty()) {
      // name the goal that sends the object there
      const Goal* goal = world.goalOf(object);
      const auto goal_index = static_cast<std::size_t>(goal - world.goals.data());
      std::ostringstream msg;
      msg << "region '" << region->name << "' (goal of object '" << object.name
          << "') is out of every robot's reach (no IK solution for placing it there)";
      throw WorldError(goal->where, "goals[" + std::to_string(goal_index) + "].region", msg.str());
    }
  }
}

}  // namespace dashbed::core

namespace dashbed::core {

namespace {

// Handoff zone candidates: moves of the first box along and across the line between the bases
// and up [m], nearest first (ties: lower first, then along, then across, negative first).
std::vector<Eigen::Vector3d> handoffShifts() {
  std::vector<Eigen::Vector3d> shifts;
  for (int i = -3; i <= 3; ++i) {
    for (int j = -4; j <= 4; ++j) {
      for (int k = -5; k <= 2; ++k) shifts.emplace_back(0.1 * i, 0.1 * j, 0.15 * k);
    }
  }
  std::stable_sort(shifts.begin(), shifts.end(), [](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return std::tuple(x.norm(), x.z(), x.x(), x.y()) < std::tuple(y.norm(), y.z(), y.x(), y.y());
  });
  return shifts;
}

// The box of width `width` around the segment from p to q.
Box segmentBox(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double width) {
  Box box;
  box.X_WB = Pose::Identity();
  box.X_WB.translation() = 0.5 * (p + q);
  const Eigen::Vector3d d = q - p;
  box.X_WB.linear() = rotationBetween(Eigen::Vector3d::UnitX(), d);
  box.size = Eigen::Vector3d(d.norm(), width, width);
  return box;
}

// A robot cannot grasp anything farther than this from its base [m]: the UR5e's reach of
// 0.85 m (shoulder to flange, UR5e datasheet) plus its shoulder height and
// the Hand-E's length, rounded up. Only spares IK calls that would fail.
constexpr double kGraspBound = 1.2;

}  // namespace

std::optional<HandoffZone> handoffZone(const World& world, const PlacedRobot& a, const PlacedRobot& b,
                                       const HandoffShape& shape) {
  const Eigen::Vector3d pa = a.spec->X_WBase.translation(), pb = b.spec->X_WBase.translation();
  // the candidates' order depends on the direction of the line: take it one way for both orders
  if (std::tuple(pb.x(), pb.y(), pb.z()) < std::tuple(pa.x(), pa.y(), pa.z())) return handoffZone(world, b, a, shape);
  HandoffZone first;
  first.mid = 0.5 * (pa + pb);
  first.top = std::max(pa.z(), pb.z());
  Eigen::Vector3d along = pb - pa;
  along.z() = 0.0;
  along = along.norm() > 1e-9 ? along.normalized() : Eigen::Vector3d::UnitX();  // bases at one spot
  const Eigen::Vector3d across = Eigen::Vector3d::UnitZ().cross(along);
  const Eigen::Matrix3d R_WZ = Eigen::AngleAxisd(std::atan2(along.y(), along.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const double middle = 0.5 * (shape.min_height + shape.max_height);
  const Eigen::Vector3d cube = Eigen::Vector3d::Constant(0.04);
  constexpr double kFixtureClearance = 0.03;
  constexpr double kArmWidth = 0.12;  // of the corridor from each shoulder to the zone: the upper arm's 0.12 m
  const Eigen::Vector3d up(0.0, 0.0, kUr5eDh.d1);
  const Eigen::Vector3d shoulder_a = a.spec->X_WBase * up, shoulder_b = b.spec->X_WBase * up;
  const auto blocked = [&](const Box& box) {
    return std::any_of(world.fixtures.begin(), world.fixtures.end(), [&](const FixtureSpec& f) {
      return std::any_of(f.boxes.begin(), f.boxes.end(), [&](const Box& part) { return boxesOverlap(box, part); });
    });
  };
  const Eigen::Vector3d half(shape.spread, shape.spread, 0.5 * (shape.max_height - shape.min_height));
  const double bound = kGraspBound + half.norm();
  // a zone whose middle is behind a robot (against its base's x axis, the way the generated
  // worlds face their robots) is taken only when no other fits
  const auto behind = [&](const Eigen::Vector3d& centre) {
    return (centre - pa).dot(a.spec->X_WBase.linear().col(0)) < -1e-9 ||
           (centre - pb).dot(b.spec->X_WBase.linear().col(0)) < -1e-9;
  };
  const auto fits = [&](const HandoffZone& zone, const Eigen::Vector3d& centre) {
    if ((centre - pa).norm() > bound || (centre - pb).norm() > bound) return false;
    Box box;
    box.X_WB = Pose::Identity();
    box.X_WB.linear() = R_WZ;
    box.X_WB.translation() = centre;
    box.size = 2.0 * (half + Eigen::Vector3d::Constant(kFixtureClearance));
    if (blocked(box) || blocked(segmentBox(shoulder_a, centre, kArmWidth)) ||
        blocked(segmentBox(shoulder_b, centre, kArmWidth))) {
      return false;
    }
    for (const double height : {middle, shape.min_height, shape.max_height}) {
      for (const double s : {0.0, -shape.spread, shape.spread}) {
        for (const double t : {0.0, -shape.spread, shape.spread}) {
          Pose X_WO = Pose::Identity();
          X_WO.translation() = Eigen::Vector3d(zone.mid.x(), zone.mid.y(), zone.top + height) + s * along + t * across;
          X_WO.linear() = R_WZ;
          if (reachesBox(a, X_WO, cube) && reachesBox(b, X_WO, cube)) return true;
        }
      }
    }
    return false;
  };
  static const std::vector<Eigen::Vector3d> shifts = handoffShifts();
  for (const bool behind_pass : {false, true}) {
    for (const Eigen::Vector3d& shift : shifts) {
      HandoffZone zone = first;
      zone.mid += shift.x() * along + shift.y() * across;
      zone.top += shift.z();
      const Eigen::Vector3d centre(zone.mid.x(), zone.mid.y(), zone.top + middle);
      if (behind(centre) == behind_pass && fits(zone, centre)) return zone;
    }
  }
  return std::nullopt;
}

}  // namespace dashbed::core
