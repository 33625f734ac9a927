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

std::array<JointPeaks, 6> TrajectoryInterpolator::peaks() const {
  std::array<JointPeaks, 6> peaks;
  for (int j = 0; j < 6; ++j) {
    JointPeaks& p = peaks[j];
    p.q_min = p.q_max = q_.front()[j];
    p.t_q_min = p.t_q_max = t_.front();
    const auto position = [&](double q, double t) {
      if (q < p.q_min) p.q_min = q, p.t_q_min = t;
      if (q > p.q_max) p.q_max = q, p.t_q_max = t;
    };
    const auto speed = [&](double v, double t) {
      if (std::abs(v) > p.speed) p.speed = std::abs(v), p.t_speed = t;
    };
    const auto acceleration = [&](double a, double t) {
      if (std::abs(a) > p.acceleration) p.acceleration = std::abs(a), p.t_acceleration = t;
    };
    for (std::size_t i = 0; i + 1 < t_.size(); ++i) {
      // the piece as a s^3 + b s^2 + c s + d on s = (t - t0) / h in [0, 1]
      const double h = t_[i + 1] - t_[i];
      const double p0 = q_[i][j], p1 = q_[i + 1][j], m0 = qd_[i][j] * h, m1 = qd_[i + 1][j] * h;
      const double a = 2 * (p0 - p1) + m0 + m1, b = 3 * (p1 - p0) - 2 * m0 - m1, c = m0;
      const auto at = [&](double s) { return ((a * s + b) * s + c) * s + p0; };
      const auto time = [&](double s) { return t_[i] + s * h; };
      position(p1, t_[i + 1]);
      speed(qd_[i][j], t_[i]);
      speed(qd_[i + 1][j], t_[i + 1]);
      acceleration(2 * b / (h * h), t_[i]);
      acceleration((6 * a + 2 * b) / (h * h), t_[i + 1]);
      // velocity 3a s^2 + 2b s + c: its extremum where the acceleration 6a s + 2b is zero
      if (a != 0.0) {
        const double s = -b / (3 * a);
        if (s > 0.0 && s < 1.0) speed(((3 * a * s) + 2 * b) * s / h + c / h, time(s));
      }
      // position extrema where the velocity is zero
      const double disc = 4 * b * b - 12 * a * c;
      if (a == 0.0) {
        if (b != 0.0) {
          const double s = -c / (2 * b);
          if (s > 0.0 && s < 1.0) position(at(s), time(s));
        }
      } else if (disc >= 0.0) {
        for (const double sign : {-1.0, 1.0}) {
          const double s = (-2 * b + sign * std::sqrt(disc)) / (6 * a);
          if (s > 0.0 && s < 1.0) position(at(s), time(s));
        }
      }
    }
  }
  return peaks;
}

}  // namespace dashbed::core
