#pragma once
// Timing a run of keys that starts and ends at rest, such as the IK keys of a straight TCP line,
// on the curve core::TrajectoryInterpolator draws through keys written without velocities.
//
// Each piece has a pace: how long it takes once the run is under way. The run eases in and out
// of that pace along a trapezoidal time law (constant rate of progress in the middle, constant
// change of it at either end), so the arm starts and stops smoothly instead of jumping to speed
// within one key interval. The exact peaks of the curve through the timed keys are then held to
// the joint limits: where an acceleration peak lies in the ease it eases longer, elsewhere the
// whole run slows down.

#include <array>
#include <cstdint>
#include <vector>

namespace dashbed::core {

/// Per-joint limits a run is timed within.
struct KeyTimingLimits {
  std::array<double, 6> max_velocity{};      ///< [rad/s], > 0
  std::array<double, 6> max_acceleration{};  ///< [rad/s^2], > 0
};

/// Times of keys[0..n] in whole milliseconds from keys[0] (the first 0, strictly increasing),
/// for a run at rest at keys[0] and keys[n]; pace[i] [s] > 0 is the time piece i (keys[i] ->
/// keys[i + 1]) takes once under way. The curve TrajectoryInterpolator draws through the keys at
/// these times (no velocities given) stays within `limits` at its exact peaks. Throws
/// std::invalid_argument for fewer than two keys, a pace per piece missing or not positive, a
/// limit not positive, or a key not finite.
std::vector<std::int64_t> restToRestKeyTimes(const std::vector<std::array<double, 6>>& keys,
                                             const std::vector<double>& pace, const KeyTimingLimits& limits);

}  // namespace dashbed::core
