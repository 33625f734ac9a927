#pragma once
// Time parameterisation of joint-space paths within the UR5e's velocity limits and
// configurable acceleration limits.
//
// Planner time is kept in whole milliseconds (Millis): sums are exact, schedules are
// reproducible to the byte, and the plan file's numbers stay short.
//
// A path is a polyline in joint space. timePolyline() drives it rest to rest along each
// straight piece with a synchronised trapezoidal profile: every joint starts and stops
// together, so the arm stays exactly on the straight line between waypoints (the line the
// collision checker checked), and each piece's duration is rounded up to a whole millisecond.
// The samples it writes carry the profile's velocities, so the simulator's cubic Hermite
// interpolation between them stays on the same line.

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/ur_ik.h"

namespace dashbed::planner {

using Millis = std::int64_t;

inline double toSeconds(Millis t) { return static_cast<double>(t) / 1000.0; }
/// Smallest whole number of milliseconds >= seconds (within 1 ns).
Millis ceilMillis(double seconds);

/// Joint limits for time parameterisation.
struct TimingLimits {
  std::array<double, 6> max_velocity{};      ///< [rad/s], > 0
  std::array<double, 6> max_acceleration{};  ///< [rad/s^2], > 0
};

/// One timed sample of a trajectory: time from the start of the path, position, velocity.
struct TimedSample {
  Millis t = 0;
  core::ArmConfig q{};
  core::ArmConfig qd{};
};

/// Duration of the rest-to-rest synchronised trapezoidal move a -> b, rounded up to whole
/// milliseconds (0 when a == b).
Millis restToRestDuration(const core::ArmConfig& a, const core::ArmConfig& b, const TimingLimits& limits);

/// Position and velocity at time t in [0, duration] of the rest-to-rest move a -> b stretched
/// to `duration` (>= restToRestDuration). Outside the interval: the end positions, zero velocity.
TimedSample restToRestSample(const core::ArmConfig& a, const core::ArmConfig& b, Millis duration, Millis t,
                             const TimingLimits& limits);

/// The same at a time given in seconds (exact, for collision checks between samples):
/// position and velocity.
std::pair<core::ArmConfig, core::ArmConfig> restToRestAt(const core::ArmConfig& a, const core::ArmConfig& b,
                                                         Millis duration, double t, const TimingLimits& limits);

/// Over [t0, t1] (seconds, within [0, duration]; the clamp to it only absorbs rounding) of the
/// rest-to-rest move a -> b stretched to `duration`: its peak speed over its mean speed, from 1
/// (cruising) to 2 (accelerating from rest throughout); 1 where the arm does not move. Samples
/// evenly spaced in time over [t0, t1] lie at most this many times the mean spacing apart along
/// the line.
double restToRestPeakOverMean(const core::ArmConfig& a, const core::ArmConfig& b, Millis duration, double t0,
                              double t1, const TimingLimits& limits);

/// `limits` with every velocity limit scaled by `scale` in (0, 1].
TimingLimits withSpeedScale(TimingLimits limits, double scale);

/// The scale (<= 1) of the velocity limits at which the rest-to-rest move a -> b keeps a point
/// within `max_speed` [m/s], the point moving at most `path_rate` [m] per unit of path (s from 0
/// at a to 1 at b; e.g. the TCP, max over s of |J(q(s)) (b - a)|).
double speedScaleWithin(const core::ArmConfig& a, const core::ArmConfig& b, const TimingLimits& limits,
                        double path_rate, double max_speed);

/// Total rest-to-rest duration of a polyline (sum over its pieces), piece i's velocity limits
/// scaled by speed_scales[i] (none: 1).
Millis polylineDuration(const std::vector<core::ArmConfig>& waypoints, const TimingLimits& limits,
                        const std::vector<double>& speed_scales = {});

/// Samples of a polyline driven rest to rest along each piece: every waypoint (at rest), the
/// instants the acceleration switches (to the nearest millisecond; so the cubic Hermite curve
/// through the samples keeps the profile's acceleration), and points about every `sample_step`
/// in between, starting at t = 0 with waypoints.front().
/// Piece i's velocity limits are scaled by speed_scales[i] (none: 1).
std::vector<TimedSample> timePolyline(const std::vector<core::ArmConfig>& waypoints, const TimingLimits& limits,
                                      Millis sample_step = 50, const std::vector<double>& speed_scales = {});

}  // namespace dashbed::planner
