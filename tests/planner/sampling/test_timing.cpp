// Time parameterisation: rest-to-rest synchronised trapezoids within the limits, on the line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/trajectory_interpolator.h"
#include "planner/sampling/timing.h"

using namespace dashbed;
using namespace dashbed::planner;

namespace {

TimingLimits limits() {
  TimingLimits l;
  l.max_velocity = {2.0, 2.0, 3.0, 3.0, 3.0, 3.0};
  l.max_acceleration = {4.0, 4.0, 4.0, 8.0, 8.0, 8.0};
  return l;
}

}  // namespace

TEST_CASE("rest-to-rest moves stay on the straight line and within the limits", "[planner][timing]") {
  const core::ArmConfig a{0.0, -1.0, 1.0, 0.5, -0.5, 0.0};
  const core::ArmConfig b = GENERATE(core::ArmConfig{2.0, -1.0, 1.5, 0.5, -0.5, 0.1},   // cruises
                                     core::ArmConfig{0.1, -0.95, 1.0, 0.5, -0.5, 0.0});  // never reaches cruise
  const TimingLimits l = limits();
  const Millis duration = restToRestDuration(a, b, l);
  REQUIRE(duration > 0);
  core::ArmConfig previous = a;
  double previous_t = 0.0;
  for (int k = 1; k <= 400; ++k) {
    const double t = toSeconds(duration) * k / 400.0;
    const auto [q, qd] = restToRestAt(a, b, duration, t, l);
    // on the segment a-b: the same fraction on every moving joint
    const double s = (q[0] - a[0]) / (b[0] - a[0]);
    CHECK(s >= -1e-12);
    CHECK(s <= 1.0 + 1e-12);
    for (int j = 0; j < 6; ++j) {
      CHECK(q[j] == Approx(a[j] + s * (b[j] - a[j])).margin(1e-12));
      CHECK(std::abs(qd[j]) <= l.max_velocity[j] * (1.0 + 1e-9));
      // the average speed between samples is within the limit too
      const double v_avg = (q[j] - previous[j]) / (t - previous_t);
      CHECK(std::abs(v_avg) <= l.max_velocity[j] * (1.0 + 1e-9));
    }
    previous = q;
    previous_t = t;
  }
  CHECK(restToRestAt(a, b, duration, toSeconds(duration), l).first == b);
  CHECK(restToRestAt(a, b, duration, 0.0, l).first == a);
}

TEST_CASE("the time-optimal duration follows the trapezoid and triangle profiles", "[planner][timing]") {
  const core::ArmConfig a{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const core::ArmConfig b{1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const TimingLimits l = limits();
  // joint 1: 1 rad at 2 rad/s, 4 rad/s^2: two ramps of 0.5 s and 0.5 rad each, no cruise
  CHECK(restToRestDuration(a, b, l) == 1000);
  const core::ArmConfig c{0.25, 0.0, 0.0, 0.0, 0.0, 0.0};  // triangle: 2 sqrt(0.25 / 4) = 0.5 s
  CHECK(restToRestDuration(a, c, l) == 500);
  CHECK(restToRestDuration(a, a, l) == 0);
}

TEST_CASE("an interval's peak speed over its mean speed bounds the spacing of even samples", "[planner][timing]") {
  const core::ArmConfig a{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const core::ArmConfig b{2.0, 0.3, 0.0, 0.0, 0.0, 0.0};  // joint 1 leads: 0.5 s ramps, 0.5 s cruise
  const TimingLimits l = limits();
  const Millis duration = restToRestDuration(a, b, l);
  REQUIRE(duration == 1500);
  CHECK(restToRestPeakOverMean(a, b, duration, 0.0, 0.02, l) == Approx(2.0));  // from rest
  CHECK(restToRestPeakOverMean(a, b, duration, 1.48, 1.5, l) == Approx(2.0));  // to rest
  CHECK(restToRestPeakOverMean(a, b, duration, 0.6, 0.62, l) == Approx(1.0));  // cruising
  CHECK(restToRestPeakOverMean(a, a, 0, 0.0, 0.02, l) == 1.0);
  CHECK(restToRestPeakOverMean(a, b, duration, 0.3, 0.3, l) == 1.0);
  // a triangle (0.25 rad in 0.5 s): over the whole move the peak, 1 rad/s at the middle, is
  // twice the mean; around the middle the speed hardly changes
  const core::ArmConfig c{0.25, 0.0, 0.0, 0.0, 0.0, 0.0};
  CHECK(restToRestPeakOverMean(a, c, 500, 0.0, 0.5, l) == Approx(2.0));
  CHECK(restToRestPeakOverMean(a, c, 500, 0.24, 0.26, l) == Approx(1.0 / 0.98));
  // the largest step between n samples over [t0, t1] is at most ratio / n of the way
  for (int i = 0; i < 75; ++i) {
    const double t0 = 0.02 * i, t1 = t0 + 0.013 + 0.004 * (i % 5);
    const double ratio = restToRestPeakOverMean(a, b, duration, t0, t1, l);
    INFO("[" << t0 << ", " << t1 << "] ratio " << ratio);
    CHECK(ratio >= 1.0);
    CHECK(ratio <= 2.0 + 1e-9);
    const double end = std::min(t1, 1.5);
    const double moved = restToRestAt(a, b, duration, end, l).first[0] - restToRestAt(a, b, duration, t0, l).first[0];
    const int n = 64;
    for (int k = 0; k < n; ++k) {
      const double u0 = t0 + (end - t0) * k / n, u1 = t0 + (end - t0) * (k + 1) / n;
      const double step = restToRestAt(a, b, duration, u1, l).first[0] - restToRestAt(a, b, duration, u0, l).first[0];
      CHECK(step <= ratio * moved / n * (1.0 + 1e-9) + 1e-15);
    }
  }
}

TEST_CASE("a polyline is sampled through every waypoint at rest", "[planner][timing]") {
  const std::vector<core::ArmConfig> path{{0, 0, 0, 0, 0, 0}, {0.5, 0, 0, 0, 0, 0}, {0.5, 0.5, 0.2, 0, 0, 0}};
  const TimingLimits l = limits();
  const std::vector<TimedSample> samples = timePolyline(path, l, 50);
  REQUIRE(samples.front().t == 0);
  CHECK(samples.back().t == polylineDuration(path, l));
  CHECK(samples.back().q == path.back());
  int waypoints_seen = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (i > 0) CHECK(samples[i].t > samples[i - 1].t);
    for (const core::ArmConfig& w : path) {
      if (samples[i].q == w) {
        ++waypoints_seen;
        for (const double v : samples[i].qd) CHECK(v == 0.0);
      }
    }
  }
  CHECK(waypoints_seen == 3);
  CHECK_THROWS_AS(timePolyline({}, l), std::invalid_argument);
}

TEST_CASE("the cubic curve through a polyline's samples keeps the profile's acceleration and speed limits",
          "[planner][timing]") {
  // random polylines: the simulator's Hermite curve through the written samples (positions and
  // velocities) at its exact peaks, against the limits the profiles were planned with
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> joint(-2.0, 2.0);
  const TimingLimits l = limits();
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<core::ArmConfig> path(4);
    for (core::ArmConfig& q : path) {
      for (double& v : q) v = joint(rng) * (trial % 2 == 0 ? 1.0 : 0.05);  // long moves and short ones
    }
    std::vector<core::TrajectoryPoint> points;
    for (const TimedSample& s : timePolyline(path, l, 50)) points.push_back({toSeconds(s.t), s.q, s.qd});
    const auto peaks = core::TrajectoryInterpolator(points).peaks();
    for (int j = 0; j < 6; ++j) {
      CHECK(peaks[j].acceleration <= l.max_acceleration[j] * (1.0 + 1e-6));
      CHECK(peaks[j].speed <= l.max_velocity[j] * (1.0 + 1e-6));
    }
  }
}

TEST_CASE("a speed scale slows a move just enough for a point's speed cap", "[planner][timing]") {
  const core::ArmConfig a{0, 0, 0, 0, 0, 0};
  const core::ArmConfig b{3.0, 0, 0, 0, 0, 0};
  const TimingLimits l = limits();  // joint 1 at 2 rad/s: path speed 2/3 per second
  // a point 0.9 m from joint 1's axis moves 2.7 m per unit of path: 1.8 m/s unscaled
  CHECK(speedScaleWithin(a, b, l, 2.7, 2.0) == 1.0);
  const double scale = speedScaleWithin(a, b, l, 2.7, 0.9);
  CHECK(scale == Approx(0.5));
  const TimingLimits slower = withSpeedScale(l, scale);
  CHECK(slower.max_velocity[0] == Approx(1.0));
  CHECK(slower.max_acceleration[0] == l.max_acceleration[0]);
  // the scaled move's peak joint speed, and so the point's, is within the cap
  const Millis duration = restToRestDuration(a, b, slower);
  double peak = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    peak = std::max(peak, std::abs(restToRestAt(a, b, duration, toSeconds(duration) * k / 1000.0, slower).second[0]));
  }
  CHECK(peak * 0.9 <= 0.9 * (1.0 + 1e-9));
  CHECK(polylineDuration({a, b}, l, {scale}) == duration);
  CHECK(polylineDuration({a, b}, l) < duration);
  CHECK(speedScaleWithin(a, a, l, 0.0, 0.1) == 1.0);  // nothing moves
}
