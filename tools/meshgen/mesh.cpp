#include "tools/meshgen/mesh.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/pose.h"

namespace dashbed::meshgen {

int Mesh::addVertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  positions.push_back(p);
  normals.push_back(n.normalized());
  return static_cast<int>(positions.size()) - 1;
}

void Mesh::addTriangle(int a, int b, int c) {
  const Eigen::Vector3d face =
      (positions[b] - positions[a]).cross(positions[c] - positions[a]);
  // zero-area triangles appear where a lathe profile touches its axis or where two outline
  // points share a corner; they carry nothing
  if (face.norm() <= 1e-14) return;
  const Eigen::Vector3d vertex_sum = normals[a] + normals[b] + normals[c];
  if (face.dot(vertex_sum) < 0.0) std::swap(b, c);
  triangles.push_back({a, b, c});
}

void Mesh::append(const Mesh& other) {
  const int offset = static_cast<int>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  for (const auto& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
}

ProfilePatch segment(double r0, double z0, double r1, double z1) {
  const double dr = r1 - r0;
  const double dz = z1 - z0;
  const double len = std::hypot(dr, dz);
  if (len <= 0.0) throw std::invalid_argument("segment: zero length");
  const double nr = dz / len;
  const double nz = -dr / len;
  return {{r0, z0, nr, nz}, {r1, z1, nr, nz}};
}

ProfilePatch arc(double rc, double zc, double radius, double a0, double a1, int steps) {
  ProfilePatch patch;
  for (int i = 0; i <= steps; ++i) {
    const double a = a0 + (a1 - a0) * i / steps;
    patch.push_back({rc + radius * std::cos(a), zc + radius * std::sin(a), std::cos(a), std::sin(a)});
  }
  return patch;
}

SweepCore circleCore(int segments) {
  SweepCore core;
  for (int k = 0; k < segments; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / segments;
    core.centres.emplace_back(0.0, 0.0);
    core.directions.emplace_back(std::cos(phi), std::sin(phi));
  }
  return core;
}

SweepCore roundedRectCore(double hx, double hy, int corner_steps) {
  const std::array<Eigen::Vector2d, 4> corners = {Eigen::Vector2d(hx, hy), Eigen::Vector2d(-hx, hy),
                                                  Eigen::Vector2d(-hx, -hy), Eigen::Vector2d(hx, -hy)};
  SweepCore core;
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i <= corner_steps; ++i) {
      const double a = std::numbers::pi / 2.0 * (c + static_cast<double>(i) / corner_steps);
      core.centres.push_back(corners[c]);
      core.directions.emplace_back(std::cos(a), std::sin(a));
    }
  }
  return core;
}

void addSweep(Mesh& mesh, const Eigen::Isometry3d& X_MA, const SweepCore& core,
              const std::vector<ProfilePatch>& profile) {
  const Eigen::Matrix3d R_MA = X_MA.linear();
  const int n = static_cast<int>(core.centres.size());
  for (const auto& patch : profile) {
    std::vector<int> previous_ring;
    for (const auto& pt : patch) {
      std::vector<int> ring;
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector2d p = core.centres[k] + pt.r * core.directions[k];
        const Eigen::Vector2d d = pt.nr * core.directions[k];
        ring.push_back(mesh.addVertex(X_MA * Eigen::Vector3d(p.x(), p.y(), pt.z),
                                      R_MA * Eigen::Vector3d(d.x(), d.y(), pt.nz)));
      }
      if (!previous_ring.empty()) {
        for (int k = 0; k < n; ++k) {
          const int k1 = (k + 1) % n;
          mesh.addTriangle(previous_ring[k], previous_ring[k1], ring[k1]);
          mesh.addTriangle(previous_ring[k], ring[k1], ring[k]);
        }
      }
      if (pt.r == 0.0) {
        // flat end over the core (degenerate, hence dropped, for a circle)
        const Eigen::Vector3d normal = R_MA * Eigen::Vector3d(0.0, 0.0, pt.nz);
        const int centre = mesh.addVertex(X_MA * Eigen::Vector3d(0.0, 0.0, pt.z), normal);
        std::vector<int> rim;
        for (int k = 0; k < n; ++k) {
          const Eigen::Vector2d p = core.centres[k];
          rim.push_back(mesh.addVertex(X_MA * Eigen::Vector3d(p.x(), p.y(), pt.z), normal));
        }
        for (int k = 0; k < n; ++k) mesh.addTriangle(centre, rim[k], rim[(k + 1) % n]);
      }
      previous_ring = std::move(ring);
    }
  }
}

void addLathe(Mesh& mesh, const Eigen::Isometry3d& X_MA, const std::vector<ProfilePatch>& profile,
              int segments) {
  addSweep(mesh, X_MA, circleCore(segments), profile);
}

void addPrism(Mesh& mesh, const Eigen::Isometry3d& X_MA, const std::vector<OutlinePoint>& outline,
              double z0, double z1) {
  const Eigen::Matrix3d R_MA = X_MA.linear();
  const int n = static_cast<int>(outline.size());
  // sides
  std::vector<int> lower;
  std::vector<int> upper;
  for (const auto& o : outline) {
    const Eigen::Vector3d normal = R_MA * Eigen::Vector3d(o.n.x(), o.n.y(), 0.0);
    lower.push_back(mesh.addVertex(X_MA * Eigen::Vector3d(o.p.x(), o.p.y(), z0), normal));
    upper.push_back(mesh.addVertex(X_MA * Eigen::Vector3d(o.p.x(), o.p.y(), z1), normal));
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.addTriangle(lower[i], lower[j], upper[j]);
    mesh.addTriangle(lower[i], upper[j], upper[i]);
  }
  // end caps: fans about the centroid (the outline is convex)
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const auto& o : outline) centroid += o.p;
  centroid /= n;
  for (const double z : {z0, z1}) {
    const Eigen::Vector3d normal = R_MA * Eigen::Vector3d(0.0, 0.0, z == z0 ? -1.0 : 1.0);
    const int centre = mesh.addVertex(X_MA * Eigen::Vector3d(centroid.x(), centroid.y(), z), normal);
    std::vector<int> rim;
    for (const auto& o : outline) {
      rim.push_back(mesh.addVertex(X_MA * Eigen::Vector3d(o.p.x(), o.p.y(), z), normal));
    }
    for (int i = 0; i < n; ++i) mesh.addTriangle(centre, rim[i], rim[(i + 1) % n]);
  }
}

std::vector<OutlinePoint> polygonOutline(const std::vector<Eigen::Vector2d>& corners) {
  std::vector<OutlinePoint> outline;
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = corners[i];
    const Eigen::Vector2d& b = corners[(i + 1) % n];
    const Eigen::Vector2d d = (b - a).normalized();
    const Eigen::Vector2d normal(d.y(), -d.x());  // right of travel: outward for a CCW polygon
    outline.push_back({a, normal});
    outline.push_back({b, normal});
  }
  return outline;
}

void addBox(Mesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {-1.0, 1.0}) {
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      normal[axis] = sign;
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      std::array<int, 4> quad{};
      for (int corner = 0; corner < 4; ++corner) {
        Eigen::Vector3d p;
        p[axis] = sign < 0 ? lo[axis] : hi[axis];
        p[u] = (corner == 1 || corner == 2) ? hi[u] : lo[u];
        p[v] = (corner >= 2) ? hi[v] : lo[v];
        quad[corner] = mesh.addVertex(p, normal);
      }
      mesh.addTriangle(quad[0], quad[1], quad[2]);
      mesh.addTriangle(quad[0], quad[2], quad[3]);
    }
  }
}

namespace {

// prints with fixed precision and without the "-0.000000" that rounding would otherwise give
double clean(double value) { return std::abs(value) < 5e-7 ? 0.0 : value; }

}  // namespace

void writeObj(const Mesh& mesh, const std::filesystem::path& file, const std::string& object_name) {
  // only vertices used by a triangle are written, renumbered in order of first use
  std::vector<int> new_index(mesh.positions.size(), -1);
  std::vector<int> used;
  for (const auto& t : mesh.triangles) {
    for (const int v : t) {
      if (new_index[v] < 0) {
        new_index[v] = static_cast<int>(used.size());
        used.push_back(v);
      }
    }
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::fopen(file.c_str(), "w"), &std::fclose);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  std::FILE* f = out.get();
  std::fprintf(f, "# dashbed procedural mesh (tools/meshgen); metres, link frame\n");
  std::fprintf(f, "# vertices %zu, triangles %zu\n", used.size(), mesh.triangles.size());
  std::fprintf(f, "o %s\n", object_name.c_str());
  for (const int v : used) {
    const Eigen::Vector3d& p = mesh.positions[v];
    std::fprintf(f, "v %.6f %.6f %.6f\n", clean(p.x()), clean(p.y()), clean(p.z()));
  }
  for (const int v : used) {
    const Eigen::Vector3d& n = mesh.normals[v];
    std::fprintf(f, "vn %.6f %.6f %.6f\n", clean(n.x()), clean(n.y()), clean(n.z()));
  }
  for (const auto& t : mesh.triangles) {
    const int a = new_index[t[0]] + 1;
    const int b = new_index[t[1]] + 1;
    const int c = new_index[t[2]] + 1;
    std::fprintf(f, "f %d//%d %d//%d %d//%d\n", a, a, b, b, c, c);
  }
  if (std::ferror(f)) throw std::runtime_error("error while writing " + file.string());
}

Eigen::Isometry3d axisFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = core::rotationBetween(Eigen::Vector3d::UnitZ(), axis);
  X.translation() = origin;
  return X;
}

}  // namespace dashbed::meshgen
