#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "core/trajectory_interpolator.h"

using dashbed::core::JointReference;
using dashbed::core::TrajectoryInterpolator;
using dashbed::core::Vector6;
using dashbed::core::TrajectoryPoint;

namespace {

/// Keys without velocities: joints 0-2 rise, turn back and rise again at uneven intervals,
/// joint 3 stands still, joints 4-5 only rise.
std::vector<TrajectoryPoint> keys() {
  const std::vector<double> t{0.0, 0.4, 0.9, 1.0, 1.7, 2.3};
  const std::vector<double> a{0.0, 0.3, 0.5, 0.2, 0.2, 0.6};
  std::vector<TrajectoryPoint> points;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const auto x = static_cast<double>(k);
    points.push_back({t[k], Vector6{a[k], -a[k], 2 * a[k], 0.7, 0.1 * x, std::sqrt(0.3 * x)}, std::nullopt});
  }
  return points;
}

}  // namespace

TEST_CASE("Keys without velocities: through every key, at rest at the ends, monotone in between",
          "[controllers]") {
  const std::vector<TrajectoryPoint> points = keys();
  const TrajectoryInterpolator curve(points);
  CHECK(curve.startTime() == 0.0);
  CHECK(curve.endTime() == 2.3);
  for (const TrajectoryPoint& p : points) {
    const JointReference ref = curve.at(p.t);
    for (int j = 0; j < 6; ++j) CHECK(ref.q[j] == Approx(p.q[j]).margin(1e-15));
  }
  for (int j = 0; j < 6; ++j) {
    CHECK(curve.at(0.0).qd[j] == 0.0);
    CHECK(curve.at(2.3).qd[j] == 0.0);
    CHECK(curve.at(-1.0).q[j] == points.front().q[j]);
    CHECK(curve.at(5.0).q[j] == points.back().q[j]);
  }
  // between two keys each joint stays within them and moves one way only (shape-preserving),
  // and its velocity is the derivative of its position
  constexpr int kSteps = 200;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double t0 = points[k].t, t1 = points[k + 1].t, h = (t1 - t0) / kSteps;
    for (int j = 0; j < 6; ++j) {
      const double lo = std::min(points[k].q[j], points[k + 1].q[j]);
      const double hi = std::max(points[k].q[j], points[k + 1].q[j]);
      const double direction = points[k + 1].q[j] - points[k].q[j];
      double previous = points[k].q[j];
      for (int i = 1; i < kSteps; ++i) {
        const double t = t0 + i * h;
        const JointReference ref = curve.at(t);
        CHECK(ref.q[j] >= lo - 1e-12);
        CHECK(ref.q[j] <= hi + 1e-12);
        CHECK((ref.q[j] - previous) * direction >= -1e-15);
        previous = ref.q[j];
        const double slope = (curve.at(t + 1e-6).q[j] - curve.at(t - 1e-6).q[j]) / 2e-6;
        CHECK(ref.qd[j] == Approx(slope).margin(1e-6));
      }
    }
  }
  // a joint that turns back stops at the key (joint 0 at 0.9 s)
  CHECK(curve.at(0.9).qd[0] == 0.0);
}

TEST_CASE("position(t) gives at(t).q to the bit", "[controllers]") {
  const TrajectoryInterpolator curve(keys());
  for (int i = -10; i <= 250; ++i) {
    const double t = i * 0.01;
    const Vector6 q = curve.position(t);
    const JointReference ref = curve.at(t);
    for (int j = 0; j < 6; ++j) CHECK(q[j] == ref.q[j]);
  }
}

TEST_CASE("Given velocities are followed, a single point is held", "[controllers]") {
  std::vector<TrajectoryPoint> points = keys();
  points[2].qd = Vector6{0.1, -0.2, 0.3, 0.0, 0.05, 0.4};
  const TrajectoryInterpolator curve(points);
  for (int j = 0; j < 6; ++j) CHECK(curve.at(points[2].t).qd[j] == Approx((*points[2].qd)[j]).margin(1e-12));
  const TrajectoryInterpolator still({points[1]});
  for (const double t : {-1.0, 0.4, 3.0}) {
    for (int j = 0; j < 6; ++j) {
      CHECK(still.position(t)[j] == points[1].q[j]);
      CHECK(still.at(t).qd[j] == 0.0);
    }
  }
}
