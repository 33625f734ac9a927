#include "sim/grip_load.h"

#include <cmath>
#include <limits>
#include <vector>

namespace dashbed::sim {
namespace {

/// Grid points per side over a patch for its mean radius (error well under 1 %).
constexpr int kRadiusGrid = 24;

/// The part of polygon `in` (2D, in order) with sign * coordinate `axis` <= limit.
std::vector<Eigen::Vector2d> clip(const std::vector<Eigen::Vector2d>& in, int axis, double sign, double limit) {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Eigen::Vector2d& a = in[i];
    const Eigen::Vector2d& b = in[(i + 1) % in.size()];
    const double da = sign * a[axis] - limit, db = sign * b[axis] - limit;
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

}  // namespace

PadFace padFace(const core::Pose& X_WL, const core::CollisionShape& pad) {
  const core::Pose X_WS = X_WL * pad.X_LS;
  const Eigen::Matrix3d& R = X_WS.linear();
  PadFace face;
  face.X_WF.linear().col(0) = R.col(2);
  face.X_WF.linear().col(1) = R.col(1);
  face.X_WF.linear().col(2) = -R.col(0);
  face.X_WF.translation() = X_WS * Eigen::Vector3d(-0.5 * pad.size.x(), 0.0, 0.0);
  face.half = Eigen::Vector2d(0.5 * pad.size.z(), 0.5 * pad.size.y());
  return face;
}

Patch padPatch(const PadFace& face, const core::Pose& X_WO, const Eigen::Vector3d& size) {
  // the object's face turned most towards the pad: its outward normal against the pad's
  const Eigen::Vector3d n = face.X_WF.linear().col(2);
  int k = 0;
  double sign = 1.0, best = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    for (const double s : {-1.0, 1.0}) {
      const double along = s * X_WO.linear().col(axis).dot(n);
      if (along < best) best = along, k = axis, sign = s;
    }
  }
  const Eigen::Vector3d u = X_WO.linear().col((k + 1) % 3), v = X_WO.linear().col((k + 2) % 3);
  const Eigen::Vector2d extent(0.5 * size[(k + 1) % 3], 0.5 * size[(k + 2) % 3]);
  const Eigen::Vector3d origin = X_WO * Eigen::Vector3d(Eigen::Vector3d::Unit(k) * (0.5 * sign * size[k]));
  // the pad's corners in the face's plane, clipped to the face
  std::vector<Eigen::Vector2d> polygon;
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1), Eigen::Vector2d(1, 1),
                                        Eigen::Vector2d(-1, 1)}) {
    const Eigen::Vector3d p = face.X_WF * Eigen::Vector3d(corner.x() * face.half.x(), corner.y() * face.half.y(), 0.0);
    polygon.emplace_back((p - origin).dot(u), (p - origin).dot(v));
  }
  for (int axis = 0; axis < 2 && !polygon.empty(); ++axis) {
    polygon = clip(polygon, axis, 1.0, extent[axis]);
    if (!polygon.empty()) polygon = clip(polygon, axis, -1.0, extent[axis]);
  }
  Patch patch;
  if (polygon.size() < 3) return patch;
  double twice = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice += cross;
    centroid += (a + b) * cross;
  }
  if (std::abs(twice) <= 0.0) return patch;
  centroid /= 3.0 * twice;
  patch.area = 0.5 * std::abs(twice);
  patch.centre_W = origin + centroid.x() * u + centroid.y() * v;
  // the mean distance from the centroid over the patch, on a grid over its bounding box
  Eigen::Vector2d lo = polygon.front(), hi = polygon.front();
  for (const Eigen::Vector2d& p : polygon) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const auto inside = [&](const Eigen::Vector2d& p) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Eigen::Vector2d e = polygon[(i + 1) % polygon.size()] - polygon[i], d = p - polygon[i];
      if ((e.x() * d.y() - e.y() * d.x()) * twice < 0.0) return false;
    }
    return true;
  };
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < kRadiusGrid; ++i) {
    for (int j = 0; j < kRadiusGrid; ++j) {
      const Eigen::Vector2d p = lo + (hi - lo).cwiseProduct(Eigen::Vector2d((i + 0.5) / kRadiusGrid, (j + 0.5) / kRadiusGrid));
      if (!inside(p)) continue;
      sum += (p - centroid).norm();
      ++count;
    }
  }
  patch.mean_radius = count > 0 ? sum / count : 0.0;
  return patch;
}

GripLoad gripLoad(const PadContact& left, const PadContact& right, const Eigen::Vector3d& closing_W, double mu,
                  const HeldMotion& motion, const Eigen::Vector3d& gravity_W) {
  const Eigen::Vector3d n = closing_W.normalized();
  // the wrench the pads give the object, about the midpoint of their centres of pressure
  const Eigen::Vector3d force = motion.mass * (motion.acceleration_W - gravity_W);
  const Eigen::Vector3d w = motion.angular_velocity_W;
  const Eigen::Vector3d centre = 0.5 * (left.centre_W + right.centre_W);
  const Eigen::Vector3d torque = motion.inertia_W * motion.angular_acceleration_W + w.cross(motion.inertia_W * w) +
                                 (motion.com_W - centre).cross(force);
  GripLoad load;
  load.tangential_force = (force - force.dot(n) * n).norm();
  load.torsion = std::abs(torque.dot(n));
  const double force_max = mu * (left.normal_force + right.normal_force);
  const double torsion_max = mu * (left.normal_force * left.mean_radius + right.normal_force * right.mean_radius);
  const auto share = [](double load_part, double limit) {
    if (load_part == 0.0) return 0.0;
    return limit > 0.0 ? load_part / limit : std::numeric_limits<double>::infinity();
  };
  load.use = std::hypot(share(load.tangential_force, force_max), share(load.torsion, torsion_max));
  return load;
}

}  // namespace dashbed::sim
