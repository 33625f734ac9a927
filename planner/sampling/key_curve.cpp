#include "planner/sampling/key_curve.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "planner/sampling/timing.h"

namespace dashbed::planner {

core::TrajectoryInterpolator keyCurve(const TransitionMotion& motion) {
  std::vector<core::TrajectoryPoint> points;
  points.reserve(motion.keys.size());
  for (const TransitionMotion::Key& key : motion.keys) points.push_back({toSeconds(key.t), key.q, std::nullopt});
  return core::TrajectoryInterpolator(points);
}

// A joint's speed over [a, b] is a quadratic v(s), s in [0, 1], known from v(0), v(1) and its
// mean m: v = v0 + c1 s + c2 s^2 with c2 = 3 (v0 + v1) - 6 m, c1 = 6 m - 4 v0 - 2 v1. Each
// joint is monotone within a piece, so v keeps its sign and the ratio is at most 3 (v = c s^2).
double curvePeakOverMean(const core::TrajectoryInterpolator& curve, double a, double b) {
  constexpr double kMaxRatio = 3.0;
  if (b <= a) return 1.0;
  const core::JointReference ra = curve.at(a), rb = curve.at(b);
  double ratio = 1.0;
  for (int j = 0; j < 6; ++j) {
    const double v0 = ra.qd[j], v1 = rb.qd[j], m = (rb.q[j] - ra.q[j]) / (b - a);
    const double c2 = 3.0 * (v0 + v1) - 6.0 * m, c1 = 6.0 * m - 4.0 * v0 - 2.0 * v1;
    double peak = std::max(std::abs(v0), std::abs(v1));
    if (c2 != 0.0) {
      const double s = -c1 / (2.0 * c2);
      if (s > 0.0 && s < 1.0) peak = std::max(peak, std::abs(v0 + c1 * s + c2 * s * s));
    }
    if (peak == 0.0) continue;
    ratio = std::max(ratio, std::abs(m) * kMaxRatio <= peak ? kMaxRatio : peak / std::abs(m));
  }
  return ratio;
}

CurvePiece keyCurvePiece(const CollisionScene& scene, const TransitionMotion& motion,
                         const core::TrajectoryInterpolator& curve, std::size_t i) {
  CurvePiece piece;
  piece.from = scene.configuration(motion.robot, motion.keys[i].q, motion.finger[i]);
  piece.to = scene.configuration(motion.robot, motion.keys[i + 1].q, motion.finger[i]);
  const double t0 = toSeconds(motion.keys[i].t), t1 = toSeconds(motion.keys[i + 1].t);
  piece.peak_over_mean = curvePeakOverMean(curve, t0, t1);
  piece.at = [&curve, t0, t1, fingers = piece.from](double s, Eigen::VectorXd& q) {
    q = fingers;
    const core::Vector6 arm = curve.position(s >= 1.0 ? t1 : t0 + s * (t1 - t0));
    for (int j = 0; j < 6; ++j) q[j] = arm[j];
  };
  return piece;
}

}  // namespace dashbed::planner
