#include "core/asset_paths.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <string>

namespace dashbed::core {

void writeFile(const std::filesystem::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::filesystem::path dataRoot() {
  if (const char* home = std::getenv("DASHBED_HOME"); home != nullptr && *home != '\0') {
    return home;
  }
  std::error_code error;
  const std::filesystem::path binary = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path candidates[] = {
      error ? std::filesystem::path() : binary.parent_path().parent_path() / "share" / "dashbed",
      DASHBED_SOURCE_ROOT, DASHBED_INSTALL_DATADIR};
  for (const std::filesystem::path& root : candidates) {
    if (!root.empty() && std::filesystem::is_directory(root / "assets", error)) return root;
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

std::string pathFrom(const std::filesystem::path& file, const std::filesystem::path& folder) {
  if (file.empty() || folder.empty()) return file.generic_string();
  const std::filesystem::path relative = std::filesystem::absolute(file).lexically_normal().lexically_relative(
      std::filesystem::absolute(folder).lexically_normal());
  return relative.empty() ? file.generic_string() : relative.generic_string();
}

}  // namespace dashbed::core
