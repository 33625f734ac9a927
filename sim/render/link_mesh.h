#pragma once
// The triangles of a robot link's visual meshes (assimp), placed in the link frame and coloured
// by their URDF material: what the offscreen renderer uploads and the HTML replay embeds.

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include <Eigen/Geometry>

#include "core/robot_model.h"

namespace dashbed::render {

struct MeshVertex {
  float position[3];
  float normal[3];
  float color[4];  ///< the visual's colour (robot links), or white for a mesh file's own triangles
};

struct TriangleMesh {
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;  ///< three per triangle
};

/// The triangles of a mesh file in its own frame, with normals. Throws std::runtime_error
/// naming the file when it cannot be read or holds no triangles.
TriangleMesh readMeshFile(const std::filesystem::path& file);

/// Appends `part` placed by X_LV (with its scale) and painted `rgba` to `mesh`.
void appendPlaced(TriangleMesh& mesh, const TriangleMesh& part, const Eigen::Affine3d& X_LV, const Eigen::Vector4f& rgba);

/// Every visual of `link` scaled, placed in the link frame and painted its colour (opaque); empty
/// without visuals. Mesh files are read once into `files`.
TriangleMesh linkVisualMesh(const core::LinkModel& link, std::map<std::filesystem::path, TriangleMesh>& files);

}  // namespace dashbed::render
