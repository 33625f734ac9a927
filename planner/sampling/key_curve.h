#pragma once
// A transition's key curve: the path the simulator follows through a transition's keys. The
// plan writes the keys without velocities, so core::TrajectoryInterpolator comes to rest
// at the first and last key and passes the others shape-preserving (each joint monotone between
// two keys). The transition sampler checks a transition along it against the scene, conflict
// resolution checks the robots along it against each other.

#include <cstddef>

#include "core/trajectory_interpolator.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/transition.h"

namespace dashbed::planner {

/// The curve through the motion's keys, times from the transition's start [s].
core::TrajectoryInterpolator keyCurve(const TransitionMotion& motion);

/// Over [a, b] within one piece of `curve` (no key strictly inside): its peak speed over its mean
/// speed, the largest over the joints (1 where nothing moves, at most 3).
double curvePeakOverMean(const core::TrajectoryInterpolator& curve, double a, double b);

/// Piece i of the motion (keys[i] -> keys[i + 1]) on `curve` = keyCurve(motion), with the
/// fingers at motion.finger[i], for the collision checker. It refers to `curve`, which must
/// outlive it.
CurvePiece keyCurvePiece(const CollisionScene& scene, const TransitionMotion& motion,
                         const core::TrajectoryInterpolator& curve, std::size_t i);

}  // namespace dashbed::planner
