#include "sim/render/link_mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <stdexcept>

namespace dashbed::render {
namespace {

// Appends the triangles of every mesh of an assimp node tree, in the file's frame.
void collectNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  aiMatrix3x3 normal_transform(transform);
  normal_transform.Inverse().Transpose();
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
      const aiVector3D p = transform * mesh.mVertices[i];
      aiVector3D n = mesh.HasNormals() ? normal_transform * mesh.mNormals[i] : aiVector3D(0, 0, 1);
      n.NormalizeSafe();
      out.vertices.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}, {1.0f, 1.0f, 1.0f, 1.0f}});
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      for (unsigned k = 0; k < 3; ++k) out.indices.push_back(base + face.mIndices[k]);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collectNode(scene, *node.mChildren[c], transform, out);
}

}  // namespace

TriangleMesh readMeshFile(const std::filesystem::path& file) {
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode) {
    throw std::runtime_error(file.string() + ": cannot read mesh: " + importer.GetErrorString());
  }
  TriangleMesh mesh;
  collectNode(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  if (mesh.indices.empty()) throw std::runtime_error(file.string() + ": mesh has no triangles");
  return mesh;
}

void appendPlaced(TriangleMesh& link_mesh, const TriangleMesh& part, const Eigen::Affine3d& X_LV, const Eigen::Vector4f& rgba) {
  const Eigen::Matrix3d normal_matrix = X_LV.linear().inverse().transpose();
  const auto base = static_cast<std::uint32_t>(link_mesh.vertices.size());
  for (const MeshVertex& v : part.vertices) {
    const Eigen::Vector3d p = X_LV * Eigen::Vector3d(v.position[0], v.position[1], v.position[2]);
    const Eigen::Vector3d n = (normal_matrix * Eigen::Vector3d(v.normal[0], v.normal[1], v.normal[2])).normalized();
    link_mesh.vertices.push_back({{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
                                  {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())},
                                  {rgba[0], rgba[1], rgba[2], rgba[3]}});
  }
  for (std::uint32_t i : part.indices) link_mesh.indices.push_back(base + i);
}

TriangleMesh linkVisualMesh(const core::LinkModel& link, std::map<std::filesystem::path, TriangleMesh>& files) {
  TriangleMesh mesh;
  for (const core::VisualMesh& visual : link.visuals) {
    auto file = files.find(visual.file);
    if (file == files.end()) file = files.emplace(visual.file, readMeshFile(visual.file)).first;
    Eigen::Affine3d X_LV(visual.X_LV.matrix());
    X_LV.scale(visual.scale);
    Eigen::Vector4f rgba = visual.rgba.cast<float>();
    rgba[3] = 1.0f;  // robots are drawn opaque
    appendPlaced(mesh, file->second, X_LV, rgba);
  }
  return mesh;
}

}  // namespace dashbed::render
