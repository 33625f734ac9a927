#include "core/grasps.h"

#include <algorithm>
#include <numbers>

namespace dashbed::core {

std::vector<BoxGrasp> boxGrasps(const Eigen::Vector3d& size, double clearance, double top_reach) {
  const double max_width = kHandeMaxOpening - clearance;
  const double half_height = size.z() / 2;
  std::vector<BoxGrasp> grasps;
  // from above the fingertips must stay clear of the surface, and the top below top_reach
  const double top_raise = std::max({0.0, kFingertipBeyondTcp + clearance - half_height, half_height - top_reach});
  // from above: approach -z of the object, closing along its x (k even) or y (k odd)
  for (int k = 0; k < 4; ++k) {
    const double yaw = k * std::numbers::pi / 2;
    const double width = k % 2 == 0 ? size.x() : size.y();
    if (width > max_width) continue;
    BoxGrasp g;
    g.approach = GraspApproach::kTop;
    g.X_OT.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitY()))
                          .toRotationMatrix();
    g.X_OT.translation() = Eigen::Vector3d(0.0, 0.0, top_raise);
    grasps.push_back(g);
  }
  // from the side the body passes kHandeBodyHalfWidth below the TCP
  constexpr double kMinPadOverlap = 0.010;
  const double side_raise = std::max(0.0, kHandeBodyHalfWidth + clearance - half_height);
  if (side_raise > half_height - kMinPadOverlap) return grasps;
  // from the side: approach along a horizontal face normal, closing on the other horizontal pair
  for (int k = 0; k < 4; ++k) {
    const double heading = k * std::numbers::pi / 2;
    const double width = k % 2 == 0 ? size.y() : size.x();
    if (width > max_width) continue;
    const Eigen::Vector3d z = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) * Eigen::Vector3d::UnitX();
    for (const double flip : {1.0, -1.0}) {
      const Eigen::Vector3d x = flip * Eigen::Vector3d::UnitZ().cross(z);
      BoxGrasp g;
      g.approach = GraspApproach::kSide;
      g.X_OT.linear().col(0) = x;
      g.X_OT.linear().col(1) = z.cross(x);
      g.X_OT.linear().col(2) = z;
      g.X_OT.translation() = Eigen::Vector3d(0.0, 0.0, side_raise);
      grasps.push_back(g);
    }
  }
  return grasps;
}

double frictionHoldMass(double friction, double grip_force, double g) { return 2.0 * friction * grip_force / g; }

}  // namespace dashbed::core
