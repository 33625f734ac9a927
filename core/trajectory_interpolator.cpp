#include "core/trajectory_interpolator.h"

#include <algorithm>
#include <cmath>

namespace dashbed::core {

TrajectoryInterpolator::TrajectoryInterpolator(const std::vector<core::TrajectoryPoint>& points) {
  const std::size_t n = points.size();
  t_.reserve(n);
  q_.reserve(n);
  for (const auto& p : points) {
    t_.push_back(p.t);
    q_.push_back(p.q);
  }
  qd_.assign(n, Vector6{});
  for (std::size_t i = 0; i < n; ++i) {
    if (points[i].qd) {
      qd_[i] = *points[i].qd;
      continue;
    }
    if (i == 0 || i + 1 == n) continue;  // rest at the ends
    for (int j = 0; j < 6; ++j) {
      const double s0 = (q_[i][j] - q_[i - 1][j]) / (t_[i] - t_[i - 1]);
      const double s1 = (q_[i + 1][j] - q_[i][j]) / (t_[i + 1] - t_[i]);
      // Fritsch-Carlson: zero at extrema and flats, else a weighted harmonic mean of the slopes,
      // which keeps each cubic segment monotone
      if (s0 * s1 <= 0.0) continue;
      const double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
      const double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
      qd_[i][j] = (w0 + w1) / (w0 / s0 + w1 / s1);
    }
  }
}

bool TrajectoryInterpolator::basisAt(double t, Basis& basis) const {
  if (t <= t_.front() || t_.size() == 1 || t >= t_.back()) return false;
  basis.i = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
  basis.h = t_[basis.i + 1] - t_[basis.i];
  const double s = basis.s = (t - t_[basis.i]) / basis.h;
  // cubic Hermite basis on s in [0, 1]
  basis.w_p0 = 2 * s * s * s - 3 * s * s + 1;
  basis.w_m0 = s * s * s - 2 * s * s + s;
  basis.w_p1 = -2 * s * s * s + 3 * s * s;
  basis.w_m1 = s * s * s - s * s;
  return true;
}

double TrajectoryInterpolator::positionOn(const Basis& b, int j) const {
  return b.w_p0 * q_[b.i][j] + b.w_m0 * (qd_[b.i][j] * b.h) + b.w_p1 * q_[b.i + 1][j] +
         b.w_m1 * (qd_[b.i + 1][j] * b.h);
}

Vector6 TrajectoryInterpolator::position(double t) const {
  Basis b;
  if (!basisAt(t, b)) return t <= t_.front() ? q_.front() : q_.back();
  Vector6 q;
  for (int j = 0; j < 6; ++j) q[j] = positionOn(b, j);
  return q;
}

JointReference TrajectoryInterpolator::at(double t) const {
  JointReference ref;
  Basis b;
  if (!basisAt(t, b)) {
    ref.q = t <= t_.front() ? q_.front() : q_.back();
    return ref;
  }
  const double s = b.s, h = b.h;
  const double d00 = 6 * s * s - 6 * s, d10 = 3 * s * s - 4 * s + 1;
  const double d01 = -6 * s * s + 6 * s, d11 = 3 * s * s - 2 * s;
  const double a00 = 12 * s - 6, a10 = 6 * s - 4, a01 = -12 * s + 6, a11 = 6 * s - 2;
  for (int j = 0; j < 6; ++j) {
    const double p0 = q_[b.i][j], p1 = q_[b.i + 1][j];
    const double m0 = qd_[b.i][j] * h, m1 = qd_[b.i + 1][j] * h;
    ref.q[j] = positionOn(b, j);
    ref.qd[j] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / h;
    ref.qdd[j] = (a00 * p0 + a10 * m0 + a01 * p1 + a11 * m1) / (h * h);
  }
  return ref;
}

}  // namespace dashbed::core
