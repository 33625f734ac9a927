#include "planner/sampling/timing.h"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <cmath>
#include <stdexcept>

namespace dashbed::planner {

Millis ceilMillis(double seconds) { return static_cast<Millis>(std::ceil(seconds * 1000.0 - 1e-6)); }

namespace {

/// The straight move a -> b as a path parameter s in [0, 1]: its speed and acceleration limits
/// (the tightest joint's) and the duration T of the time-optimal trapezoid at those limits.
struct PathProfile {
  double s_speed = 0.0;  // [1/s]
  double s_accel = 0.0;  // [1/s^2]
  double duration = 0.0; // [s]
};

PathProfile profile(const core::ArmConfig& a, const core::ArmConfig& b, const TimingLimits& limits) {
  PathProfile p;
  p.s_speed = p.s_accel = std::numeric_limits<double>::infinity();
  for (int j = 0; j < 6; ++j) {
    const double delta = std::abs(b[j] - a[j]);
    if (delta == 0.0) continue;
    if (!(limits.max_velocity[j] > 0.0) || !(limits.max_acceleration[j] > 0.0)) {
      throw std::invalid_argument("timing limits must be positive (joint " + std::to_string(j + 1) + ")");
    }
    p.s_speed = std::min(p.s_speed, limits.max_velocity[j] / delta);
    p.s_accel = std::min(p.s_accel, limits.max_acceleration[j] / delta);
  }
  if (std::isinf(p.s_speed)) return {0.0, 0.0, 0.0};  // a == b
  // the time-optimal ramp and cruise (none: a triangle, when the cruise speed is not reached
  // within half the path), each lengthened to whole milliseconds, so the acceleration switches
  // on sample times (timePolyline) and the duration is whole; slower, so within the limits
  const bool triangle = p.s_speed * p.s_speed / p.s_accel >= 1.0;
  const double ramp = triangle ? std::sqrt(1.0 / p.s_accel) : p.s_speed / p.s_accel;
  const double cruise = triangle ? 0.0 : 1.0 / p.s_speed - ramp;
  const double ramp_whole = toSeconds(std::max<Millis>(1, ceilMillis(ramp)));
  const double cruise_whole = toSeconds(ceilMillis(cruise));
  p.s_speed = 1.0 / (ramp_whole + cruise_whole);
  p.s_accel = p.s_speed / ramp_whole;
  p.duration = 2.0 * ramp_whole + cruise_whole;
  return p;
}

/// s(tau) and ds/dtau of the trapezoid at time tau in [0, p.duration].
std::pair<double, double> trapezoid(const PathProfile& p, double tau) {
  const double ramp = p.s_speed / p.s_accel;
  if (tau <= 0.0) return {0.0, 0.0};
  if (tau >= p.duration) return {1.0, 0.0};
  if (tau < ramp) return {0.5 * p.s_accel * tau * tau, p.s_accel * tau};
  const double left = p.duration - tau;
  if (left < ramp) return {1.0 - 0.5 * p.s_accel * left * left, p.s_accel * left};
  return {0.5 * p.s_accel * ramp * ramp + p.s_speed * (tau - ramp), p.s_speed};
}

}  // namespace

Millis restToRestDuration(const core::ArmConfig& a, const core::ArmConfig& b, const TimingLimits& limits) {
  return ceilMillis(profile(a, b, limits).duration);
}

std::pair<core::ArmConfig, core::ArmConfig> restToRestAt(const core::ArmConfig& a, const core::ArmConfig& b,
                                                         Millis duration, double t, const TimingLimits& limits) {
  const PathProfile p = profile(a, b, limits);
  if (t <= 0.0) return {a, {}};
  if (t >= toSeconds(duration) || p.duration == 0.0) return {b, {}};
  // the time-optimal profile stretched uniformly to `duration`: slower, so within the limits
  const double stretch = p.duration / toSeconds(duration);
  const auto [s, s_dot] = trapezoid(p, t * stretch);
  core::ArmConfig q{}, qd{};
  for (int j = 0; j < 6; ++j) {
    q[j] = a[j] + s * (b[j] - a[j]);
    qd[j] = s_dot * stretch * (b[j] - a[j]);
  }
  return {q, qd};
}

double restToRestPeakOverMean(const core::ArmConfig& a, const core::ArmConfig& b, Millis duration, double t0,
                              double t1, const TimingLimits& limits) {
  const PathProfile p = profile(a, b, limits);
  const double total = toSeconds(duration);
  t0 = std::clamp(t0, 0.0, total);
  t1 = std::clamp(t1, 0.0, total);
  if (p.duration == 0.0 || t1 <= t0) return 1.0;
  const double stretch = p.duration / total;
  const double moved = trapezoid(p, t1 * stretch).first - trapezoid(p, t0 * stretch).first;
  // the speed rises to the middle of the move and falls after it: the peak over [t0, t1] is
  // at its point nearest the middle
  const double peak = trapezoid(p, std::clamp(0.5 * total, t0, t1) * stretch).second * stretch;
  return moved > 0.0 ? std::max(1.0, peak * (t1 - t0) / moved) : 1.0;
}

TimedSample restToRestSample(const core::ArmConfig& a, const core::ArmConfig& b, Millis duration, Millis t,
                             const TimingLimits& limits) {
  const auto [q, qd] = restToRestAt(a, b, duration, toSeconds(t), limits);
  return {t, q, qd};
}

TimingLimits withSpeedScale(TimingLimits limits, double scale) {
  for (double& v : limits.max_velocity) v *= scale;
  return limits;
}

double speedScaleWithin(const core::ArmConfig& a, const core::ArmConfig& b, const TimingLimits& limits,
                        double path_rate, double max_speed) {
  // the profile's path speed never exceeds the velocity limits' cap on it
  double s_speed = std::numeric_limits<double>::infinity();
  for (int j = 0; j < 6; ++j) {
    const double delta = std::abs(b[j] - a[j]);
    if (delta > 0.0) s_speed = std::min(s_speed, limits.max_velocity[j] / delta);
  }
  if (std::isinf(s_speed) || path_rate * s_speed <= max_speed) return 1.0;
  return max_speed / (path_rate * s_speed);
}

namespace {
double scaleOf(const std::vector<double>& speed_scales, std::size_t piece) {
  return piece < speed_scales.size() ? speed_scales[piece] : 1.0;
}
}  // namespace

Millis polylineDuration(const std::vector<core::ArmConfig>& waypoints, const TimingLimits& limits,
                        const std::vector<double>& speed_scales) {
  Millis total = 0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    total += restToRestDuration(waypoints[i - 1], waypoints[i], withSpeedScale(limits, scaleOf(speed_scales, i - 1)));
  }
  return total;
}

std::vector<TimedSample> timePolyline(const std::vector<core::ArmConfig>& waypoints, const TimingLimits& all_limits,
                                      Millis sample_step, const std::vector<double>& speed_scales) {
  if (waypoints.empty()) throw std::invalid_argument("timePolyline: no waypoints");
  if (sample_step <= 0) throw std::invalid_argument("timePolyline: the sample step must be positive");
  std::vector<TimedSample> samples{{0, waypoints.front(), {}}};
  Millis start = 0;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const core::ArmConfig& a = waypoints[i - 1];
    const core::ArmConfig& b = waypoints[i];
    const TimingLimits limits = withSpeedScale(all_limits, scaleOf(speed_scales, i - 1));
    const Millis duration = restToRestDuration(a, b, limits);
    if (duration == 0) continue;
    // a sample where the acceleration switches (end of speeding up, start of slowing down;
    // whole milliseconds by profile()): a cubic piece across a switch would overshoot the
    // acceleration limit by up to half
    const PathProfile p = profile(a, b, limits);
    const Millis ramp = std::llround(p.s_speed / p.s_accel * 1000.0);
    std::vector<Millis> times{ramp, duration - ramp};
    // and evenly spaced samples, no closer than sample_step, kept half a step clear of those
    const Millis pieces = std::max<Millis>(1, duration / sample_step);
    for (Millis k = 1; k <= pieces; ++k) {
      const Millis t = duration * k / pieces;
      const bool clear = std::ranges::all_of(times.begin(), times.begin() + 2, [&](Millis s) { return 2 * std::abs(t - s) >= sample_step; });
      if (clear || k == pieces) times.push_back(t);
    }
    std::ranges::sort(times);
    const auto [last, end] = std::ranges::unique(times);
    times.erase(last, end);
    for (const Millis t : times) {
      if (t <= 0 || t > duration) continue;
      TimedSample sample = restToRestSample(a, b, duration, t, limits);
      sample.t = start + t;
      samples.push_back(sample);
    }
    start += duration;
  }
  return samples;
}

}  // namespace dashbed::planner
