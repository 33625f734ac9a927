#pragma once
// Piecewise-cubic interpolation of a plan's timed joint points (continuous position and
// velocity). Where the plan gives no velocities they are chosen shape-preserving
// (Fritsch-Carlson): zero at the ends and at local extrema, so the motion never overshoots
// a waypoint and straight joint-space segments stay inside their bounding box.

#include <array>
#include <vector>

#include "core/plan.h"

namespace dashbed::controllers {

using Vector6 = std::array<double, 6>;

/// Reference position, velocity and acceleration at one instant.
struct JointReference {
  Vector6 q{};
  Vector6 qd{};
  Vector6 qdd{};
};

class TrajectoryInterpolator {
 public:
  /// Precondition: points.size() >= 1 with strictly increasing t (the plan loader checks this).
  explicit TrajectoryInterpolator(const std::vector<core::TrajectoryPoint>& points);

  /// The reference at time t [s]; holds the first point before it and the last after it.
  JointReference at(double t) const;

  double startTime() const { return t_.front(); }
  double endTime() const { return t_.back(); }

 private:
  std::vector<double> t_;
  std::vector<Vector6> q_;
  std::vector<Vector6> qd_;
};

}  // namespace dashbed::controllers
