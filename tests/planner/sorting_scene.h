#pragma once
// The default sorting world (worlds/default.yaml) and its collision scene, each loaded once, for
// the planner's unit tests of the collision checker and the roadmaps.

#include <string>

#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"

namespace dashbed::planner::testing {

inline const core::LoadedWorld& sortingWorld() {
  static const core::LoadedWorld loaded = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  return loaded;
}

inline const CollisionScene& sortingScene() {
  static const CollisionScene scene(*sortingWorld().world, *sortingWorld().robots);
  return scene;
}

}  // namespace dashbed::planner::testing
