#include "controllers/hande_controller.h"

#include <algorithm>

namespace dashbed::controllers {

HandeController::HandeController(const core::ControllerSettings& settings)
    : speed_(std::clamp(settings.finger_speed, kHandeMinSpeed, kHandeMaxSpeed)),
      default_force_(std::clamp(settings.grip_force, kHandeMinForce, kHandeMaxForce)),
      force_(default_force_) {}

void HandeController::command(core::GripperAction action, double force) {
  action_ = action;
  force_ = force > 0.0 ? std::clamp(force, kHandeMinForce, kHandeMaxForce) : default_force_;
}

FingerServo HandeController::servo(double position) const {
  // proportional approach to the stop: at 50 1/s the speed tapers off within 2 mm (at 0.1 m/s)
  constexpr double kApproachGain = 50.0;  // [1/s]
  const double target = action_ == core::GripperAction::kOpen ? kHandeStroke : 0.0;
  return {std::clamp(kApproachGain * (target - position), -speed_, speed_), force_};
}

}  // namespace dashbed::controllers
