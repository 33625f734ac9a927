#pragma once
// The project's UR5e + Hand-E model (assets/ur5e_hande.urdf), loaded once for the core tests.

#include <string>

#include "core/robot_model.h"

namespace dashbed::test {

inline const core::RobotModel& ur5eHande() {
  static const core::RobotModel model =
      core::RobotModel::fromUrdfFile(std::string(DASHBED_SOURCE_ROOT) + "/assets/ur5e_hande.urdf");
  return model;
}

}  // namespace dashbed::test
