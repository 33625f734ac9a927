#pragma once
// Actions of a plan made elsewhere: trajectories and gripper commands without an action list.
// A first run in simulation tells what each gripper closed on; the motions of the reference
// trajectories tell where each action starts and ends. The monitor then judges the inferred
// actions as it judges planned ones.

#include <vector>

#include "core/plan.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::sim {

/// The actions `plan`'s gripper commands carry out, inferred from a run of the plan in
/// simulation (its own actions are ignored):
///  - a close on an object both pads then touch is a pick, or the receiving end of a handoff
///    when another robot's pads hold the object at that moment;
///  - the holder's open is the place of the object, or the end of its handoff;
///  - a place is into the region the world's goals send the object to, or, when the object is
///    picked up again later or has no goal, a set-aside (no region) unless it came to rest in a
///    region;
///  - a pick or place spans the arm's motion into its gripper command and the motion out of it
///    (from the start of the last motion before the command to the end of the first one after
///    it, the arm resting between motions); a handoff from the receiver's motion into its close
///    to the end of the giver's motion out of its open.
/// A close on nothing, and an open of an empty gripper, are no action. Sorted by start time;
/// deterministic.
std::vector<core::PlanAction> inferActions(const core::World& world, const core::RobotSet& robots,
                                           const core::Plan& plan);

}  // namespace dashbed::sim
