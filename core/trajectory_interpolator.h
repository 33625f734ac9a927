#pragma once
// Piecewise-cubic interpolation of a plan's timed joint points (continuous position and
// velocity). Where the plan gives no velocities they are chosen shape-preserving
// (Fritsch-Carlson): zero at the ends and at local extrema, so the motion never overshoots
// a waypoint and straight joint-space segments stay inside their bounding box.

#include <array>
#include <vector>

#include "core/plan.h"

namespace dashbed::core {

using Vector6 = std::array<double, 6>;

/// Reference position, velocity and acceleration at one instant.
struct JointReference {
  Vector6 q{};
  Vector6 qd{};
  Vector6 qdd{};
};

/// The extremes of one joint along a whole curve, each with the time it is reached [s].
struct JointPeaks {
  double q_min = 0.0, t_q_min = 0.0;  ///< lowest position [rad]
  double q_max = 0.0, t_q_max = 0.0;  ///< highest position [rad]
  double speed = 0.0, t_speed = 0.0;  ///< largest |velocity| [rad/s]
  double acceleration = 0.0, t_acceleration = 0.0;  ///< largest |acceleration| [rad/s^2]
};

class TrajectoryInterpolator {
 public:
  /// Precondition: points.size() >= 1 with strictly increasing t (the plan loader checks this).
  explicit TrajectoryInterpolator(const std::vector<core::TrajectoryPoint>& points);

  /// The reference at time t [s]; holds the first point before it and the last after it.
  JointReference at(double t) const;
  /// at(t).q alone (the same numbers), without the derivatives.
  Vector6 position(double t) const;

  /// Per joint, the exact extremes of position, velocity and acceleration along the curve
  /// (on each cubic piece: position at its ends and where the velocity is zero, velocity at its
  /// ends and where the acceleration is zero, acceleration at its ends).
  std::array<JointPeaks, 6> peaks() const;

  double startTime() const { return t_.front(); }
  double endTime() const { return t_.back(); }

 private:
  std::vector<double> t_;
  std::vector<Vector6> q_;
  std::vector<Vector6> qd_;

  /// Where a time lies: on the cubic piece i (t_[i] <= t < t_[i + 1]) at s = (t - t_[i]) / h,
  /// with the Hermite basis weights of the piece's end positions (w_p0, w_p1) and end tangents
  /// (w_m0, w_m1) there.
  struct Basis {
    std::size_t i = 0;
    double s = 0.0, h = 0.0;
    double w_p0 = 0.0, w_m0 = 0.0, w_p1 = 0.0, w_m1 = 0.0;
  };
  /// False when t is not strictly inside the points (the position is then the first or last
  /// point's).
  bool basisAt(double t, Basis& basis) const;
  /// The position on piece b.i at b.s, joint j.
  double positionOn(const Basis& b, int j) const;
};

}  // namespace dashbed::core
