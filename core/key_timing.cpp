#include "core/key_timing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/trajectory_interpolator.h"

namespace dashbed::core {
namespace {

/// The trapezoidal time law: progress tau (seconds of pace) advances at rate 0 -> 1 -> 0, the
/// rate changing by `ease` per second at either end.
struct TimeLaw {
  double total_tau = 0.0;
  double ease = 0.0;  ///< [1/s]; infinity: no easing

  /// Seconds each ease lasts.
  double easeTime() const {
    if (std::isinf(ease)) return 0.0;
    return std::min(1.0 / ease, std::sqrt(total_tau / ease));
  }
  /// Seconds from the start to progress tau.
  double timeAt(double tau) const {
    if (std::isinf(ease)) return tau;
    const double ramp = easeTime();
    const double ramp_tau = 0.5 * ease * ramp * ramp;  // progress made during one ease
    const double total = 2.0 * ramp + (total_tau - 2.0 * ramp_tau);
    if (tau <= ramp_tau) return std::sqrt(2.0 * tau / ease);
    if (tau >= total_tau - ramp_tau) return total - std::sqrt(2.0 * std::max(0.0, total_tau - tau) / ease);
    return ramp + (tau - ramp_tau);
  }
};

}  // namespace

std::vector<std::int64_t> restToRestKeyTimes(const std::vector<std::array<double, 6>>& keys,
                                             const std::vector<double>& pace, const KeyTimingLimits& limits) {
  if (keys.size() < 2) throw std::invalid_argument("restToRestKeyTimes: a run needs at least two keys");
  if (pace.size() + 1 != keys.size()) throw std::invalid_argument("restToRestKeyTimes: one pace per piece");
  for (int j = 0; j < 6; ++j) {
    if (!(limits.max_velocity[j] > 0.0) || !(limits.max_acceleration[j] > 0.0)) {
      throw std::invalid_argument("restToRestKeyTimes: limits must be positive");
    }
  }
  for (const auto& q : keys) {
    for (const double v : q) {
      if (!std::isfinite(v)) throw std::invalid_argument("restToRestKeyTimes: a key is not finite");
    }
  }

  TimeLaw law;
  std::vector<double> tau(keys.size(), 0.0);
  // easing at rate `ease` accelerates joint j by ease x its speed at pace; start where the
  // fastest of them meets its limit
  double ease_demand = 0.0;  // [s]: max over pieces and joints of speed at pace / limit
  for (std::size_t i = 0; i < pace.size(); ++i) {
    if (!(pace[i] > 0.0) || !std::isfinite(pace[i])) throw std::invalid_argument("restToRestKeyTimes: pace must be positive");
    tau[i + 1] = tau[i] + pace[i];
    for (int j = 0; j < 6; ++j) {
      ease_demand = std::max(ease_demand, std::abs(keys[i + 1][j] - keys[i][j]) / pace[i] / limits.max_acceleration[j]);
    }
  }
  law.total_tau = tau.back();
  law.ease = ease_demand > 0.0 ? 1.0 / ease_demand : std::numeric_limits<double>::infinity();

  std::vector<TrajectoryPoint> points(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) points[k].q = keys[k];
  std::vector<std::int64_t> millis(keys.size(), 0);
  double stretch = 1.0;  // the whole run's time scale
  for (;;) {
    for (std::size_t k = 1; k < keys.size(); ++k) {
      const double t = stretch * law.timeAt(tau[k]);
      millis[k] = std::max(millis[k - 1] + 1, static_cast<std::int64_t>(std::ceil(t * 1000.0 - 1e-6)));
      points[k].t = static_cast<double>(millis[k]) / 1000.0;
    }
    if (ease_demand == 0.0) return millis;  // nothing moves
    double acceleration_ratio = 0.0, speed_ratio = 0.0, t_acceleration = 0.0;
    const std::array<JointPeaks, 6> peaks = TrajectoryInterpolator(points).peaks();
    for (int j = 0; j < 6; ++j) {
      speed_ratio = std::max(speed_ratio, peaks[j].speed / limits.max_velocity[j]);
      const double ratio = peaks[j].acceleration / limits.max_acceleration[j];
      if (ratio > acceleration_ratio) acceleration_ratio = ratio, t_acceleration = peaks[j].t_acceleration;
    }
    if (acceleration_ratio <= 1.0 && speed_ratio <= 1.0) return millis;
    // the ease's acceleration scales with its rate, the whole run's with 1 / stretch^2, its
    // speeds with 1 / stretch
    const double ramp = stretch * law.easeTime(), end = points.back().t;
    const bool in_ease = t_acceleration <= ramp || t_acceleration >= end - ramp;
    if (acceleration_ratio > 1.0 && in_ease) {
      law.ease /= acceleration_ratio;
    } else if (acceleration_ratio > 1.0) {
      stretch *= std::sqrt(acceleration_ratio);
    }
    if (speed_ratio > 1.0) stretch *= speed_ratio;
  }
}

}  // namespace dashbed::core
