#pragma once
// Plans made elsewhere: per robot a joint trajectory and gripper commands in the formats
// `dashbed export` writes (ROS 2 trajectory YAML, gripper timeline YAML, CSV), read into a plan
// without actions for the simulator, which infers them (sim/action_inference.h).

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_text.h"
#include "core/plan.h"
#include "core/world.h"

namespace dashbed::exporting {

/// One robot's files.
struct ForeignTrajectory {
  std::string robot;
  /// .yaml / .yml: a trajectory_msgs/JointTrajectory, or a control_msgs FollowJointTrajectory
  /// goal holding one under `trajectory`; .csv: a header row with `t` and the joint names,
  /// optionally NAME_velocity, gripper_opening [m] and gripper_force [N] columns.
  std::string trajectory_file;
  /// Optional gripper timeline YAML (`gripper:` list of time_from_start, command open|close,
  /// force [N]); a CSV's gripper columns give the commands where none is given.
  std::string gripper_file;
};

/// A file that cannot be read as a trajectory or timeline: "FILE:LINE: field: what".
class ForeignPlanError : public core::InputError {
 public:
  using core::InputError::InputError;
};

/// The plan of `world` the files describe: per robot its points (positions, with velocities
/// where every point has them; joints reordered from the file's names to `joint_names`), and
/// the gripper commands, all robots' sorted by time; no actions. A CSV's gripper command is a
/// row whose opening or force differs from the row before (the first row with a force > 0
/// included): close when the opening is under half the stroke, else open. Throws
/// ForeignPlanError for an unreadable file, a missing or unknown joint, a non-numeric or
/// non-finite value, times not strictly increasing, or a robot the world lacks.
core::Plan readForeignPlan(const core::World& world, const std::array<std::string, 6>& joint_names,
                           const std::vector<ForeignTrajectory>& robots);

}  // namespace dashbed::exporting
