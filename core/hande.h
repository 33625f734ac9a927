#pragma once
// The Robotiq Hand-E's public figures, in one place for the planner, the controllers and the
// file readers. Sources: Robotiq's ROS 2 description of the Hand-E (github.com/robotiq/ros,
// robotiq_description: 0-25 mm per finger, 0.15 m/s, 185 N) and the Hand-E instruction
// manual's specifications (stroke 50 mm, closing speed 20-150 mm/s, grip force 20-185 N).

namespace dashbed::core {

inline constexpr double kHandeStroke = 0.025;                  ///< per finger, 0 = closed [m]
inline constexpr double kHandeMaxOpening = 2 * kHandeStroke;   ///< between the pads, fully open [m]
inline constexpr double kHandeMinSpeed = 0.020;                ///< finger closing speed [m/s]
inline constexpr double kHandeMaxSpeed = 0.150;                ///< finger closing speed [m/s]
inline constexpr double kHandeMinForce = 20.0;                 ///< grip force [N]
inline constexpr double kHandeMaxForce = 185.0;                ///< grip force [N]

/// Finger position of an open Hand-E, each finger at the end of its stroke [m].
inline constexpr double kFingersOpen = kHandeStroke;

}  // namespace dashbed::core
