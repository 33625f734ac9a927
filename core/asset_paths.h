#pragma once
// Where dashbed finds its data folders (assets/, worlds/).

#include <filesystem>
#include <string_view>

namespace dashbed::core {

/// The project root holding assets/ and worlds/: $DASHBED_HOME if set, else the source tree
/// the binary was built from.
std::filesystem::path dataRoot();

/// assets/<model>.urdf under dataRoot(). Throws std::runtime_error if it does not exist.
std::filesystem::path robotUrdfPath(std::string_view model);

/// worlds/default.yaml under dataRoot().
std::filesystem::path defaultWorldPath();

}  // namespace dashbed::core
