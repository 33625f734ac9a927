#pragma once
// Triangle meshes for the procedural robot visuals: a few building blocks (surfaces of
// revolution, extruded outlines, boxes) and a deterministic Wavefront OBJ writer.

#include <Eigen/Geometry>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace dashbed::meshgen {

/// An indexed triangle mesh with one normal per vertex. Positions in metres, in the frame of
/// the link the mesh belongs to.
struct Mesh {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> normals;        ///< unit length, same size as positions
  std::vector<std::array<int, 3>> triangles;   ///< counter-clockwise seen from outside

  int addVertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n);

  /// Adds triangle (a, b, c), dropping it if degenerate and flipping its winding so its face
  /// normal agrees with the vertex normals.
  void addTriangle(int a, int b, int c);

  void append(const Mesh& other);
};

/// One point of a lathe profile: radius r from the axis, height z along it, and the outward
/// surface normal (nr, nz) in the (r, z) half-plane.
struct ProfilePoint {
  double r;
  double z;
  double nr;
  double nz;
};

/// A smooth run of profile points; consecutive patches meet at a crease.
using ProfilePatch = std::vector<ProfilePoint>;

/// Straight profile segment from (r0, z0) to (r1, z1), normal to the left of travel when the
/// profile runs from the bottom of the axis, out and up, and back to the top.
ProfilePatch segment(double r0, double z0, double r1, double z1);

/// Convex rounded profile corner: circle of radius `radius` about (rc, zc), from angle a0 to
/// a1 (radians, measured from +r towards +z), in `steps` pieces.
ProfilePatch arc(double rc, double zc, double radius, double a0, double a1, int steps);

/// The closed curve a profile is swept around, in the x-y plane of the sweep frame: ring
/// point i of a profile point (r, z) is centres[i] + r * directions[i] at height z. A circle
/// has all centres at the origin; a rounded rectangle has one centre per corner.
struct SweepCore {
  std::vector<Eigen::Vector2d> centres;
  std::vector<Eigen::Vector2d> directions;  ///< unit outward directions
};

/// Core of a surface of revolution with `segments` facets around.
SweepCore circleCore(int segments);

/// Core of a rounded rectangle: corner centres at (+-hx, +-hy), `corner_steps` facets per
/// rounded corner. A profile radius r gives a rounded rectangle of half sizes hx + r, hy + r.
SweepCore roundedRectCore(double hx, double hy, int corner_steps);

/// Sweeps `profile` around `core` in the frame X_MA (given in the mesh frame). Profile points
/// with r = 0 are closed with a flat fan over the core.
void addSweep(Mesh& mesh, const Eigen::Isometry3d& X_MA, const SweepCore& core,
              const std::vector<ProfilePatch>& profile);

/// Surface of revolution about the z axis of X_MA, with `segments` facets around.
void addLathe(Mesh& mesh, const Eigen::Isometry3d& X_MA, const std::vector<ProfilePatch>& profile,
              int segments);

/// One point of a planar outline with its outward 2-D normal.
struct OutlinePoint {
  Eigen::Vector2d p;
  Eigen::Vector2d n;
};

/// Prism: the closed convex outline (in the x-y plane of X_MA) extruded along that frame's z
/// from z0 to z1, with flat end caps. Outline normals give smooth or sharp side edges.
void addPrism(Mesh& mesh, const Eigen::Isometry3d& X_MA, const std::vector<OutlinePoint>& outline,
              double z0, double z1);

/// Outline of a polygon with sharp corners (every edge flat-shaded), counter-clockwise.
std::vector<OutlinePoint> polygonOutline(const std::vector<Eigen::Vector2d>& corners);

/// Axis-aligned box in the mesh frame.
void addBox(Mesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/// Writes `mesh` as OBJ (v, vn, f v//vn; triangles only) with fixed precision, so the same
/// mesh always gives the same bytes. Throws std::runtime_error if the file cannot be written.
void writeObj(const Mesh& mesh, const std::filesystem::path& file, const std::string& object_name);

/// Isometry from a translation and a rotation that maps the local z axis onto `axis`.
Eigen::Isometry3d axisFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis);

}  // namespace dashbed::meshgen
