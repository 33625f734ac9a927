#include "core/robot_set.h"

#include <exception>

#include "core/asset_paths.h"
#include "core/world_io.h"

namespace dashbed::core {

RobotSet::RobotSet(const World& world) {
  for (std::size_t i = 0; i < world.robots.size(); ++i) {
    const RobotSpec& spec = world.robots[i];
    const std::string field = "robots[" + std::to_string(i) + "].model";
    std::size_t model_index = 0;
    while (model_index < model_names_.size() && model_names_[model_index] != spec.model) ++model_index;
    try {
      if (model_index == model_names_.size()) {
        models_.push_back(std::make_unique<RobotModel>(RobotModel::fromUrdfFile(robotUrdfPath(spec.model))));
        model_names_.push_back(spec.model);
      }
      PlacedRobot placed;
      placed.spec = &spec;
      placed.model = models_[model_index].get();
      placed.ik = std::make_unique<UrArmIk>(*placed.model);
      robots_.push_back(std::move(placed));
    } catch (const WorldError&) {
      throw;
    } catch (const std::exception& e) {
      throw WorldError(spec.where, field, e.what());
    }
  }
}

}  // namespace dashbed::core
