#pragma once
// Cameras: a pinhole camera looking from `eye` at `target`, presets that frame any world, and
// the projection of world points to pixels that the renderer and the overlays share.

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/world.h"

namespace dashbed::render {

/// A perspective camera. Frames: W the world (z up); image pixels with the origin at the
/// top-left corner, x to the right, y down; pixel (i, j) covers [i, i+1) x [j, j+1).
struct Camera {
  Eigen::Vector3d eye{2.0, -2.0, 2.0};        ///< camera centre in W [m]
  Eigen::Vector3d target{0.0, 0.0, 0.5};      ///< point looked at, in W [m]; shown at the image centre
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< W direction shown upwards; not parallel to target - eye
  double fov_deg = 45.0;                      ///< vertical field of view [deg], in (0, 180)
  int width = 640;                            ///< image size [px]
  int height = 480;
};

/// Throws std::invalid_argument naming the problem: non-positive size, fov outside (0, 180),
/// eye == target, up parallel to the viewing direction, non-finite numbers.
void validateCamera(const Camera& camera);

/// The 4x4 OpenGL view matrix (world -> camera frame C: x right, y up, looking along -z).
Eigen::Matrix4d viewMatrix(const Camera& camera);

/// The 4x4 OpenGL perspective matrix for the camera's fov and aspect with clip planes
/// `near_m` and `far_m` [m].
Eigen::Matrix4d projectionMatrix(const Camera& camera, double near_m, double far_m);

/// Pixel coordinates of the world point p_W (origin top-left, y down; a point that lands in
/// pixel (i, j) has coordinates in [i, i+1) x [j, j+1)). Meaningful for points in front of
/// the camera only (see depthInCamera).
Eigen::Vector2d project(const Camera& camera, const Eigen::Vector3d& p_W);

/// Distance of p_W in front of the camera along its viewing direction [m]; <= 0 behind it.
double depthInCamera(const Camera& camera, const Eigen::Vector3d& p_W);

/// Axis-aligned box around everything of the world worth framing: fixtures, objects, goal
/// regions and each robot's working volume near its base (a box around the base reaching
/// 0.45 m sideways and 0.85 m up). Includes the origin when the world is empty.
Eigen::AlignedBox3d worldBounds(const core::World& world);

/// The preset names valid for `world`: "oblique", "front", "top", "side:<robot>" per robot.
std::vector<std::string> cameraPresetNames(const core::World& world);

/// A preset camera framing `world` (every corner of worldBounds inside the image):
///  - "oblique": a 3/4 view from the front right (azimuth -60 deg), 35 deg above the horizon;
///    in a world with a shelf, from the shelf's open side (its -x, 30 deg to its -y) instead, so
///    that the slots are in view rather than the back panel;
///  - "front":   from -y towards +y, 22 deg above the horizon;
///  - "top":     straight down, +x to the right and +y up in the image;
///  - "side:<robot>": from behind and beside the robot (its base frame's -x, -y) over its
///    shoulder towards the workspace in front of it (+x of its base).
/// Throws std::invalid_argument naming the preset and the valid names for an unknown preset
/// or robot, or for a non-positive size.
Camera cameraPreset(const core::World& world, std::string_view preset, int width = 640, int height = 480);

/// A camera looking along `view_dir_W` (from the eye towards the scene) with the given up
/// direction and fov, placed so that every corner of `box` projects inside the image with a
/// margin of `margin` (a fraction of the half-size of the image, e.g. 0.06).
Camera frameBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& view_dir_W, const Eigen::Vector3d& up_W,
                double fov_deg, int width, int height, double margin = 0.06);

}  // namespace dashbed::render
