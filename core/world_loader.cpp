#include "core/world_loader.h"

#include <algorithm>

#include "core/world_io.h"

namespace dashbed::core {

LoadedWorld validateWorld(World world) {
  // a world built in memory (every fixture has solid parts once derived); derived entries
  // edited since are kept
  if (std::any_of(world.fixtures.begin(), world.fixtures.end(), [](const FixtureSpec& f) { return f.boxes.empty(); })) {
    deriveFixtureGeometry(world);
  }
  LoadedWorld loaded;
  loaded.world = std::make_unique<const World>(std::move(world));
  loaded.robots = std::make_unique<const RobotSet>(*loaded.world);
  loaded.reach = computeReach(*loaded.world, *loaded.robots);
  requireReachable(*loaded.world, loaded.reach);
  return loaded;
}

LoadedWorld loadWorld(const std::filesystem::path& file) { return validateWorld(loadWorldFile(file)); }

}  // namespace dashbed::core
