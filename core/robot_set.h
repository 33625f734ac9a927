#pragma once
// RobotSet: the robot models and arm IK of every robot of a world, placed at their bases.

#include <memory>
#include <string>
#include <vector>

#include "core/robot_model.h"
#include "core/ur_ik.h"
#include "core/world.h"

namespace dashbed::core {

/// One robot of a world: its spec, its (shared, immutable) model and its arm IK.
struct PlacedRobot {
  const RobotSpec* spec = nullptr;
  const RobotModel* model = nullptr;
  std::unique_ptr<UrArmIk> ik;

  /// TCP pose in the world for an arm configuration.
  Pose tcpPoseInWorld(const ArmConfig& q) const { return spec->X_WBase * ik->tcpPose(q); }
  /// Arm solutions reaching a world TCP pose, nearest to `seed` first.
  std::vector<ArmConfig> solveInWorld(const Pose& X_WT, const ArmConfig& seed) const {
    return ik->solveNearest(spec->X_WBase.inverse() * X_WT, seed);
  }
};

/// The robots of one world. Models are read once per model name from assets/<model>.urdf.
/// Holds pointers into `world`, which must outlive it.
class RobotSet {
 public:
  /// Throws WorldError naming the robot's line when a model cannot be loaded or is not a UR arm.
  explicit RobotSet(const World& world);

  const std::vector<PlacedRobot>& robots() const { return robots_; }
  const PlacedRobot& operator[](std::size_t i) const { return robots_[i]; }
  std::size_t size() const { return robots_.size(); }

 private:
  std::vector<std::unique_ptr<RobotModel>> models_;
  std::vector<std::string> model_names_;
  std::vector<PlacedRobot> robots_;
};

}  // namespace dashbed::core
