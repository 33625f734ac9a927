#include "core/asset_paths.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace dashbed::core {

std::filesystem::path dataRoot() {
  if (const char* home = std::getenv("DASHBED_HOME"); home != nullptr && *home != '\0') {
    return home;
  }
  return DASHBED_SOURCE_ROOT;
}

std::filesystem::path robotUrdfPath(std::string_view model) {
  const auto path = dataRoot() / "assets" / (std::string(model) + ".urdf");
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error("robot model '" + std::string(model) + "': no file " + path.string());
  }
  return path;
}

std::filesystem::path defaultWorldPath() { return dataRoot() / "worlds" / "default.yaml"; }

}  // namespace dashbed::core
