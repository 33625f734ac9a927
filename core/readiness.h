#pragma once
// Hardware readiness: whether a UR5e with a Robotiq Hand-E could run a plan as written, judged
// on the curve the plan means (core::TrajectoryInterpolator, the one the simulator tracks and an
// export sends), not on its points alone:
//  - joint positions within the robot model's limits, joint speeds within its velocity limits
//    (UR5e: 180 deg/s, UR's datasheet) and joint accelerations within the world's safety limit, at the
//    exact extremes of every cubic piece; the joint efforts that curve needs (inverse dynamics
//    at every simulation step, a held object at the TCP) within the model's effort limits, and
//    the TCP's speed there within the safety configuration's;
//  - gripper commands within the Hand-E's force range (core/hande.h): out of range is refused,
//    never clamped;
//  - payload: every object a robot picks or receives, plus the gripper, within the UR5e's rated
//    payload; and within what the grip holds by friction standing still.
// A plan that passes is not yet known to work: the simulator judges that.

#include <string>
#include <vector>

#include "core/plan.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::core {

/// One check of the readiness report: the measured value against its limit.
struct ReadinessCheck {
  std::string name;     ///< "joint position", "joint speed", "joint acceleration", "joint effort", "tcp speed", "gripper force", "payload", "grip"
  std::string subject;  ///< what it is about: "r0 wrist_3_joint", "gripper command 3 (r1 close at 12.5 s)", "r1 holding cube_2"
  double value = 0.0;   ///< the measured extreme
  double limit = 0.0;
  std::string unit;
  double t = 0.0;       ///< plan time of the extreme [s]
  bool passed = true;
  std::string detail;   ///< why it failed, in words ("" when passed)
};

struct ReadinessReport {
  std::vector<ReadinessCheck> checks;
  bool ready() const;
  /// The failed checks' details, joined by "; ".
  std::string failures() const;
};

/// Judges `plan` (which must have passed core::validatePlan for the world) on `world`'s robots,
/// within the robot model's limits and the world's safety settings.
ReadinessReport checkReadiness(const Plan& plan, const World& world, const RobotSet& robots);

}  // namespace dashbed::core
