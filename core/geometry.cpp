#include "core/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace dashbed::core {

double boxPenetrationDepth(const Box& a, const Box& b) {
  const Eigen::Matrix3d& R_WA = a.X_WB.linear();
  const Eigen::Matrix3d& R_WB = b.X_WB.linear();
  const Eigen::Vector3d half_a = 0.5 * a.size;
  const Eigen::Vector3d half_b = 0.5 * b.size;
  const Eigen::Vector3d p_AB_W = b.X_WB.translation() - a.X_WB.translation();

  // projected half-width of both boxes along a unit axis minus the centres' distance
  const auto overlapAlong = [&](const Eigen::Vector3d& axis_W) {
    double radius = 0.0;
    for (int k = 0; k < 3; ++k) {
      radius += half_a[k] * std::abs(axis_W.dot(R_WA.col(k)));
      radius += half_b[k] * std::abs(axis_W.dot(R_WB.col(k)));
    }
    return radius - std::abs(axis_W.dot(p_AB_W));
  };

  double depth = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    depth = std::min(depth, overlapAlong(R_WA.col(k)));
    depth = std::min(depth, overlapAlong(R_WB.col(k)));
  }
  // edge-edge axes; (nearly) parallel edge pairs add nothing the face axes do not cover
  constexpr double kMinAxisNorm = 1e-9;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d axis = R_WA.col(i).cross(R_WB.col(j));
      const double norm = axis.norm();
      if (norm < kMinAxisNorm) continue;
      depth = std::min(depth, overlapAlong(axis / norm));
    }
  }
  return depth;
}

bool boxesOverlap(const Box& a, const Box& b, double tolerance) {
  return boxPenetrationDepth(a, b) > tolerance;
}

Eigen::Vector3d rotatedBoxExtent(const Eigen::Matrix3d& R_FB, const Eigen::Vector3d& size) {
  return (R_FB * size.asDiagonal()).cwiseAbs().rowwise().sum();
}

bool pointInBox(const Eigen::Vector3d& p_W, const Box& box, double margin) {
  const Eigen::Vector3d p_B = box.X_WB.inverse(Eigen::Isometry) * p_W;
  return ((p_B.array().abs()) <= (0.5 * box.size.array() + margin)).all();
}

}  // namespace dashbed::core
