#pragma once
// The check of one robot's motion at its samples (CollisionChecker::motionFree, motionCheck,
// motionObjectHits), internal to the collision checker. The motion is checked item by item: each
// moving body against the static scene, each checked pair of its own bodies, the held object
// against the static scene and the robot's bodies, each resting object. Where a check finds an
// item apart, it also bounds how far apart (the margin of the prefilter that separates it:
// bounding spheres, a sphere against a box, a separating axis), and the samples at which the
// item cannot have closed that gap are not checked again. How fast an item's parts can close
// in follows from the joints between them: their change per sample, each weighted by how far
// the moving part's points lie from it (CollisionScene::motionTravel's bound, for that part
// alone and relative to the other); a resting object closes in as fast as any robot point
// moves. A sample at which every item is known free is not evaluated at all (no forward
// kinematics). The answers are those of checking every item at every sample.

#include <optional>
#include <span>
#include <vector>

#include "planner/collision/internal/collision_checker_state.h"

namespace dashbed::planner::detail {

/// What a motion sweep checks and how it ends.
struct SweepRequest {
  bool check_robot = true;       ///< the static scene and self-collision (a hit ends the sweep)
  bool stop_at_object = false;   ///< the first resting object hit ends the sweep as well
};

/// Checks `robot` holding `held` along `motion` at its n + 1 samples (bisection order) against
/// what `request` names and the resting `objects`; `step_travel` bounds any robot point's travel
/// between two samples [m]. std::nullopt when the robot hits the static scene or itself; else,
/// per object, whether it was hit (with stop_at_object, the sweep ends at the first such hit).
std::optional<std::vector<char>> sweepMotion(CheckerState& state, const RobotData& robot, const MotionRef& motion,
                                             const std::optional<HeldObject>& held, int n, double step_travel,
                                             std::span<const RestingObject> objects, const SweepRequest& request);

}  // namespace dashbed::planner::detail
