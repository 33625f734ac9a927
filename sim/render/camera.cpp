#include "sim/render/camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dashbed::render {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Rotation rows: camera x (right), y (up), z (backwards) expressed in W.
Eigen::Matrix3d cameraRotation(const Camera& camera) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  Eigen::Matrix3d R_CW;
  R_CW.row(0) = right.transpose();
  R_CW.row(1) = up.transpose();
  R_CW.row(2) = -forward.transpose();
  return R_CW;
}

void extendByBox(Eigen::AlignedBox3d& bounds, const core::Pose& X_WB, const Eigen::Vector3d& size) {
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p_B(((corner & 1) ? 0.5 : -0.5) * size.x(), ((corner & 2) ? 0.5 : -0.5) * size.y(),
                              ((corner & 4) ? 0.5 : -0.5) * size.z());
    bounds.extend(X_WB * p_B);
  }
}

}  // namespace

void validateCamera(const Camera& camera) {
  if (camera.width <= 0 || camera.height <= 0) {
    throw std::invalid_argument("camera: size must be positive (got " + std::to_string(camera.width) + "x" +
                                std::to_string(camera.height) + ")");
  }
  if (!camera.eye.allFinite() || !camera.target.allFinite() || !camera.up.allFinite() ||
      !std::isfinite(camera.fov_deg)) {
    throw std::invalid_argument("camera: eye, target, up and fov must be finite");
  }
  if (!(camera.fov_deg > 0.0 && camera.fov_deg < 180.0)) {
    throw std::invalid_argument("camera: fov_deg must be in (0, 180) (got " + std::to_string(camera.fov_deg) + ")");
  }
  const Eigen::Vector3d view = camera.target - camera.eye;
  if (view.norm() < 1e-9) throw std::invalid_argument("camera: eye and target coincide");
  if (camera.up.norm() < 1e-12 || view.normalized().cross(camera.up.normalized()).norm() < 1e-6) {
    throw std::invalid_argument("camera: up is zero or parallel to the viewing direction");
  }
}

Eigen::Matrix4d viewMatrix(const Camera& camera) {
  const Eigen::Matrix3d R_CW = cameraRotation(camera);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = R_CW;
  view.topRightCorner<3, 1>() = -R_CW * camera.eye;
  return view;
}

Eigen::Matrix4d projectionMatrix(const Camera& camera, double near_m, double far_m) {
  const double f = 1.0 / std::tan(0.5 * camera.fov_deg * kDegToRad);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = f / aspect;
  proj(1, 1) = f;
  proj(2, 2) = (far_m + near_m) / (near_m - far_m);
  proj(2, 3) = 2.0 * far_m * near_m / (near_m - far_m);
  proj(3, 2) = -1.0;
  return proj;
}

Eigen::Vector2d project(const Camera& camera, const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d p_C = cameraRotation(camera) * (p_W - camera.eye);
  const double f = 1.0 / std::tan(0.5 * camera.fov_deg * kDegToRad);
  const double aspect = static_cast<double>(camera.width) / camera.height;
  // normalised device coordinates, then the viewport transform with y flipped
  const double ndc_x = (f / aspect) * p_C.x() / -p_C.z();
  const double ndc_y = f * p_C.y() / -p_C.z();
  return {0.5 * (ndc_x + 1.0) * camera.width, 0.5 * (1.0 - ndc_y) * camera.height};
}

double depthInCamera(const Camera& camera, const Eigen::Vector3d& p_W) {
  return (p_W - camera.eye).dot((camera.target - camera.eye).normalized());
}

Eigen::AlignedBox3d worldBounds(const core::World& world) {
  Eigen::AlignedBox3d bounds;
  // with robots, frame the workspace: bins and shelves but not the tables they stand on
  for (const core::FixtureSpec& fixture : world.fixtures) {
    if (!world.robots.empty() && fixture.type == core::FixtureType::kBox) continue;
    for (const core::Box& box : fixture.boxes) extendByBox(bounds, box.X_WB, box.size);
  }
  for (const core::ObjectSpec& object : world.objects) extendByBox(bounds, object.X_WO, object.size);
  for (const core::Region& region : world.regions) {
    core::Pose X_WC = region.X_WR;
    X_WC.translation() += region.X_WR.linear() * Eigen::Vector3d(0.0, 0.0, 0.5 * region.size.z());
    extendByBox(bounds, X_WC, region.size);
  }
  for (const core::RobotSpec& robot : world.robots) {
    core::Pose X_WC = robot.X_WBase;
    X_WC.translation() += robot.X_WBase.linear() * Eigen::Vector3d(0.0, 0.0, 0.425);
    extendByBox(bounds, X_WC, Eigen::Vector3d(0.9, 0.9, 0.85));
  }
  if (bounds.isEmpty()) bounds.extend(Eigen::Vector3d::Zero());
  // frame the workspace, not the legs of the table the robots stand on: cut the box 15 cm
  // below the lowest robot base
  if (!world.robots.empty()) {
    double lowest_base = 1e300;
    for (const core::RobotSpec& robot : world.robots) lowest_base = std::min(lowest_base, robot.X_WBase.translation().z());
    bounds.min().z() = std::min(bounds.max().z(), std::max(bounds.min().z(), lowest_base - 0.15));
  }
  return bounds;
}

std::vector<std::string> cameraPresetNames(const core::World& world) {
  std::vector<std::string> names{"oblique", "front", "top"};
  for (const core::RobotSpec& robot : world.robots) names.push_back("side:" + robot.name);
  return names;
}

Camera frameBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& view_dir_W, const Eigen::Vector3d& up_W,
                double fov_deg, int width, int height, double margin) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("frameBox: size must be positive");
  const Eigen::Vector3d forward = view_dir_W.normalized();
  const Eigen::Vector3d right = forward.cross(up_W).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const double tan_v = std::tan(0.5 * fov_deg * kDegToRad) * (1.0 - margin);
  const double tan_h = tan_v * width / height;

  std::array<Eigen::Vector3d, 8> corners;
  for (int corner = 0; corner < 8; ++corner) {
    corners[corner] = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
  }
  Eigen::Vector3d target = box.center();
  double distance = 0.0;
  // the distance that fits every corner for the current target, then a re-centre of the
  // target on the projected extent; a few rounds converge for any box
  for (int round = 0; round < 4; ++round) {
    distance = 0.0;
    for (const Eigen::Vector3d& c : corners) {
      const Eigen::Vector3d rel = c - target;
      const double x = rel.dot(right), y = rel.dot(up), z = rel.dot(forward);
      distance = std::max({distance, std::abs(x) / tan_h - z, std::abs(y) / tan_v - z});
    }
    double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
    for (const Eigen::Vector3d& c : corners) {
      const Eigen::Vector3d rel = c - target;
      const double depth = distance + rel.dot(forward);
      min_x = std::min(min_x, rel.dot(right) / depth);
      max_x = std::max(max_x, rel.dot(right) / depth);
      min_y = std::min(min_y, rel.dot(up) / depth);
      max_y = std::max(max_y, rel.dot(up) / depth);
    }
    target += distance * (0.5 * (min_x + max_x) * right + 0.5 * (min_y + max_y) * up);
  }
  distance = 0.0;
  for (const Eigen::Vector3d& c : corners) {
    const Eigen::Vector3d rel = c - target;
    const double x = rel.dot(right), y = rel.dot(up), z = rel.dot(forward);
    distance = std::max({distance, std::abs(x) / tan_h - z, std::abs(y) / tan_v - z});
  }
  Camera camera;
  camera.target = target;
  camera.eye = target - distance * forward;
  camera.up = up_W;
  camera.fov_deg = fov_deg;
  camera.width = width;
  camera.height = height;
  return camera;
}

Camera cameraPreset(const core::World& world, std::string_view preset, int width, int height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("camera preset '" + std::string(preset) + "': size must be positive");
  }
  const Eigen::AlignedBox3d bounds = worldBounds(world);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  // direction from an azimuth (about +z from +x) and an elevation above the horizon,
  // pointing from the scene towards the eye
  const auto towardsEye = [](double azimuth_deg, double elevation_deg) {
    const double a = azimuth_deg * kDegToRad, e = elevation_deg * kDegToRad;
    return Eigen::Vector3d(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  };
  if (preset == "oblique") {
    double azimuth = -60.0;
    const auto shelf = std::find_if(world.fixtures.begin(), world.fixtures.end(),
                                    [](const core::FixtureSpec& f) { return f.type == core::FixtureType::kShelf; });
    if (shelf != world.fixtures.end()) {
      const Eigen::Vector3d x_F = shelf->X_WF.linear().col(0);
      azimuth = std::atan2(x_F.y(), x_F.x()) / kDegToRad + 210.0;
    }
    return frameBox(bounds, -towardsEye(azimuth, 35.0), z, 40.0, width, height);
  }
  if (preset == "front") return frameBox(bounds, -towardsEye(-90.0, 22.0), z, 40.0, width, height);
  if (preset == "top") return frameBox(bounds, -z, Eigen::Vector3d::UnitY(), 40.0, width, height);
  if (preset.starts_with("side:")) {
    const std::string_view name = preset.substr(5);
    if (const core::RobotSpec* robot = world.findRobot(name)) {
      // the robot's working volume in front of its base, in the base frame: 0.3 m behind
      // to 0.9 m in front, 0.6 m to either side, from the base plane to 0.8 m above it
      const core::Pose& X_WB = robot->X_WBase;
      Eigen::AlignedBox3d work;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p_B((corner & 1) ? 0.9 : -0.3, (corner & 2) ? 0.6 : -0.6, (corner & 4) ? 0.8 : 0.0);
        work.extend(X_WB * p_B);
      }
      const Eigen::Vector3d eye_dir_B = Eigen::Vector3d(-1.0, -0.55, 0.75).normalized();
      return frameBox(work, -(X_WB.linear() * eye_dir_B), z, 45.0, width, height);
    }
  }
  std::string valid;
  for (const std::string& name : cameraPresetNames(world)) valid += (valid.empty() ? "" : ", ") + name;
  throw std::invalid_argument("unknown camera preset '" + std::string(preset) + "' (valid: " + valid + ")");
}

}  // namespace dashbed::render
