// Timing runs of keys that start and end at rest: within the limits on the curve through them,
// at their pace once under way.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/key_timing.h"
#include "core/trajectory_interpolator.h"

using namespace dashbed::core;

namespace {

KeyTimingLimits limits(double velocity, double acceleration) {
  KeyTimingLimits l;
  l.max_velocity.fill(velocity);
  l.max_acceleration.fill(acceleration);
  return l;
}

/// Keys along a curved joint-space path, like the IK keys of a straight TCP line: `n` pieces,
/// joint j at amplitude a_j sin(phase_j + k w).
std::vector<Vector6> curvedRun(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> amplitude(0.05, 0.6), phase(0.0, 3.0);
  Vector6 a{}, p{};
  for (int j = 0; j < 6; ++j) a[j] = amplitude(rng), p[j] = phase(rng);
  std::vector<Vector6> keys;
  for (int k = 0; k <= n; ++k) {
    Vector6 q{};
    for (int j = 0; j < 6; ++j) q[j] = a[j] * std::sin(p[j] + 0.05 * k);
    keys.push_back(q);
  }
  return keys;
}

TrajectoryInterpolator curveOf(const std::vector<Vector6>& keys, const std::vector<std::int64_t>& millis) {
  std::vector<TrajectoryPoint> points;
  for (std::size_t k = 0; k < keys.size(); ++k) points.push_back({static_cast<double>(millis[k]) / 1000.0, keys[k], {}});
  return TrajectoryInterpolator(points);
}

}  // namespace

TEST_CASE("a run of keys stays within the joint limits at the curve's exact peaks", "[core][key_timing]") {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 2 + trial;
    const std::vector<Vector6> keys = curvedRun(rng, n);
    const std::vector<double> pace(static_cast<std::size_t>(n), 0.05 + 0.01 * (trial % 5));
    const KeyTimingLimits l = limits(1.5, trial % 2 == 0 ? 4.0 : 1.0);
    const std::vector<std::int64_t> millis = restToRestKeyTimes(keys, pace, l);
    REQUIRE(millis.size() == keys.size());
    CHECK(millis.front() == 0);
    for (std::size_t k = 1; k < millis.size(); ++k) CHECK(millis[k] > millis[k - 1]);
    for (const JointPeaks& p : curveOf(keys, millis).peaks()) {
      CHECK(p.acceleration <= 4.0);
      CHECK(p.speed <= 1.5 * (1.0 + 1e-9));
      if (trial % 2 == 1) CHECK(p.acceleration <= 1.0 * (1.0 + 1e-9));
    }
  }
}

TEST_CASE("a long run under loose limits goes at its pace once under way", "[core][key_timing]") {
  // 40 pieces of 0.1 rad on joint 1 at 0.1 s each: 1 rad/s; easing at 4 rad/s^2 takes 0.25 s
  std::vector<Vector6> keys;
  for (int k = 0; k <= 40; ++k) keys.push_back(Vector6{0.1 * k, 0, 0, 0, 0, 0});
  const std::vector<double> pace(40, 0.1);
  const std::vector<std::int64_t> millis = restToRestKeyTimes(keys, pace, limits(3.0, 4.0));
  // the middle pieces take their pace to the millisecond; the whole run, the pace plus at least
  // one ease of the time law. The curve through keys without velocities starts harder than the
  // law it samples, so its exact peaks ask for a longer ease, but not for a slower run.
  for (std::size_t k = 15; k < 25; ++k) CHECK(std::abs((millis[k + 1] - millis[k]) - 100) <= 1);
  CHECK(millis.back() >= 4000 + 250);
  CHECK(millis.back() <= 4000 + 4 * 250);
}

TEST_CASE("a run that does not move takes its pace; bad runs are refused", "[core][key_timing]") {
  const std::vector<Vector6> still(3, Vector6{0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
  CHECK(restToRestKeyTimes(still, {0.2, 0.3}, limits(1.0, 1.0)) == std::vector<std::int64_t>{0, 200, 500});
  CHECK_THROWS_AS(restToRestKeyTimes({still.front()}, {}, limits(1.0, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(restToRestKeyTimes(still, {0.2}, limits(1.0, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(restToRestKeyTimes(still, {0.2, 0.0}, limits(1.0, 1.0)), std::invalid_argument);
  CHECK_THROWS_AS(restToRestKeyTimes(still, {0.2, 0.3}, limits(0.0, 1.0)), std::invalid_argument);
  std::vector<Vector6> bad = still;
  bad[1][2] = std::nan("");
  CHECK_THROWS_AS(restToRestKeyTimes(bad, {0.2, 0.3}, limits(1.0, 1.0)), std::invalid_argument);
}
