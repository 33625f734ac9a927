#pragma once
// Where dashbed finds its data folders (assets/, worlds/), and how written files name others.

#include <filesystem>
#include <string>
#include <string_view>

namespace dashbed::core {

/// The folder holding assets/ and worlds/, the first of: $DASHBED_HOME if set; the running
/// binary's ../share/dashbed (an installed dashbed); the source tree the library was built
/// from; the install prefix's share/dashbed (a program of one's own linked to an installed
/// dashbed). A candidate counts when it holds assets/.
std::filesystem::path dataRoot();

/// assets/<model>.urdf under dataRoot(). Throws std::runtime_error if it does not exist.
std::filesystem::path robotUrdfPath(std::string_view model);

/// worlds/default.yaml under dataRoot().
std::filesystem::path defaultWorldPath();

/// Writes `text` to `file` (replacing it, bytes as given). Throws std::runtime_error
/// "cannot write FILE" when it cannot.
void writeFile(const std::filesystem::path& file, std::string_view text);

/// `file` as seen from `folder` ("../plans/p.json", "/" separators): how a written file names
/// another, so that its bytes do not depend on where both were put. `file` as given when
/// either is empty.
std::string pathFrom(const std::filesystem::path& file, const std::filesystem::path& folder);

}  // namespace dashbed::core
