#pragma once
// The Robotiq Hand-E's behaviour: both fingers move at the set speed (20-150 mm/s) towards
// open or closed, and a closing finger pushes with at most the set grip force (20-185 N).
// The output is a velocity target with a force bound per finger, which the simulator
// applies as a force-limited velocity servo on each finger joint; both fingers get the same
// command, so they stay symmetric about the TCP.

#include "core/hande.h"
#include "core/plan.h"
#include "core/world.h"

namespace dashbed::controllers {

using core::kHandeMaxForce;
using core::kHandeMaxSpeed;
using core::kHandeMinForce;
using core::kHandeMinSpeed;
using core::kHandeStroke;

struct FingerServo {
  double velocity = 0.0;   ///< finger joint velocity target [m/s]; + opens
  double max_force = 0.0;  ///< bound on the servo force [N]
};

class HandeController {
 public:
  explicit HandeController(const core::ControllerSettings& settings);

  /// Starts opening or closing. `force` [N] 0 means the configured grip force; values are
  /// clamped to the Hand-E range.
  void command(core::GripperAction action, double force = 0.0);

  core::GripperAction state() const { return action_; }
  double force() const { return force_; }

  /// The servo command for each finger at finger position `position` [m] (0 closed, 0.025
  /// open): full speed towards the commanded end, slowing within the last millimetres so an
  /// empty gripper comes to rest at its stop; a finger blocked by an object keeps pushing with
  /// the grip force.
  FingerServo servo(double position) const;

 private:
  double speed_;
  double default_force_;
  core::GripperAction action_ = core::GripperAction::kOpen;
  double force_;
};

}  // namespace dashbed::controllers
