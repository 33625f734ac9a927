// writeWorldYaml: a world as a version-1 world file, byte-for-byte deterministic.

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/world_io.h"
#include "core/world_yaml_detail.h"

namespace dashbed::core {
namespace {

using world_yaml::formatNumber;

template <typename Range>
std::string formatList(const Range& values) {
  std::string text = "[";
  bool first = true;
  for (const double v : values) {
    if (!first) text += ", ";
    text += formatNumber(v);
    first = false;
  }
  return text + "]";
}

std::string formatVector3(const Eigen::Vector3d& v) { return formatList(std::array{v.x(), v.y(), v.z()}); }
std::string formatVector2(const Eigen::Vector2d& v) { return formatList(std::array{v.x(), v.y()}); }

// a YAML double-quoted string; bytes >= 0x80 pass through (UTF-8)
std::string doubleQuoted(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte < 0x20 || byte == 0x7f) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// identifiers plain, anything else quoted
std::string formatName(std::string_view text) {
  const bool plain = world_yaml::isIdentifier(text) && text != "null" && text != "Null" &&
                     text != "NULL" && (std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_');
  return plain ? std::string(text) : doubleQuoted(text);
}

std::string formatColor(const Color& color) {
  for (const NamedColor& named : kNamedColors) {
    if (named.color == color) return std::string(named.name);
  }
  return formatList(std::array{color.r, color.g, color.b});
}

// Angles are written so that they read back to bit-identical rotations whenever possible:
// near the angles recovered from R (atan2 is off by a few ulps, more near pitch = +-pi/2)
// look for ones from which rotationFromRpy rebuilds R exactly, and of those write the one
// with the shortest text (a hand-written 0.2 stays 0.2). When there are none, R is replaced
// by the rotation of the recovered angles and the search repeats; the angles written then
// rebuild a rotation whose search finds those very angles again, so writing what was read
// gives the same bytes: write(parse(write(w))) == write(w). Both hold for every yaw; for
// roll-pitch-yaw they can fail within a few degrees of pitch = +-pi/2, where the angles
// recovered from R are off by hundreds of ulps.
constexpr int kUlpSearch = 4;
constexpr int kMaxRounds = 8;
double stepUlps(double x, int steps) {
  const double toward = (steps > 0 ? 1.0 : -1.0) * std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(steps); ++i) x = std::nextafter(x, toward);
  return x;
}

// candidates for one angle: `start`, then +-1 .. +-kUlpSearch ulps, then round angles a
// file is likely to hold (0, +-pi/2, +-pi) when within 1e-9 rad
std::vector<double> angleCandidates(double start) {
  std::vector<double> candidates{start};
  for (int k = 1; k <= kUlpSearch; ++k) {
    candidates.push_back(stepUlps(start, k));
    candidates.push_back(stepUlps(start, -k));
  }
  constexpr double kPi = 3.141592653589793;
  for (const double round : {0.0, kPi / 2, -kPi / 2, kPi, -kPi}) {
    if (std::abs(start - round) <= 1e-9) candidates.push_back(round);
  }
  return candidates;
}

Eigen::Vector3d recoveredRpy(const Eigen::Matrix3d& R, bool yaw_only) {
  return yaw_only ? Eigen::Vector3d(0.0, 0.0, std::atan2(R(1, 0), R(0, 0))) : rpyFromRotation(R);
}

std::optional<Eigen::Vector3d> exactRpy(const Eigen::Matrix3d& R, bool yaw_only) {
  const Eigen::Vector3d start = recoveredRpy(R, yaw_only);
  const std::vector<double> rolls = yaw_only ? std::vector<double>{0.0} : angleCandidates(start.x());
  const std::vector<double> pitches = yaw_only ? std::vector<double>{0.0} : angleCandidates(start.y());
  const std::vector<double> yaws = angleCandidates(start.z());
  std::optional<Eigen::Vector3d> best;
  std::size_t best_length = 0;
  for (const double roll : rolls) {
    for (const double pitch : pitches) {
      for (const double yaw : yaws) {
        const Eigen::Vector3d rpy(roll, pitch, yaw);
        if (rotationFromRpy(rpy) != R) continue;
        const std::size_t length =
            formatNumber(roll).size() + formatNumber(pitch).size() + formatNumber(yaw).size();
        if (!best || length < best_length) {
          best = rpy;
          best_length = length;
        }
      }
    }
  }
  return best;
}

Eigen::Vector3d writableRpy(const Eigen::Matrix3d& R, bool yaw_only) {
  Eigen::Matrix3d target = R;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (const auto rpy = exactRpy(target, yaw_only)) return *rpy;
    target = rotationFromRpy(recoveredRpy(target, yaw_only));
  }
  return recoveredRpy(target, yaw_only);
}

bool isYawOnly(const Eigen::Matrix3d& R) {
  constexpr double kTolerance = 1e-9;
  return std::abs(R(2, 2) - 1.0) <= kTolerance && std::abs(R(0, 2)) <= kTolerance &&
         std::abs(R(1, 2)) <= kTolerance && std::abs(R(2, 0)) <= kTolerance &&
         std::abs(R(2, 1)) <= kTolerance;
}

double yawOf(const Pose& X, const std::string& field) {
  if (!isYawOnly(X.linear())) {
    throw WorldError(SourceLocation{}, field,
                     "only rotations about +z can be written (fixtures, objects, surfaces and "
                     "regions turn about z only)");
  }
  return writableRpy(X.linear(), true).z();
}

std::string formatYawPose(const Pose& X, const std::string& field) {
  return "{xyz: " + formatVector3(X.translation()) +
         ", yaw: " + formatNumber(yawOf(X, field)) + "}";
}

}  // namespace

std::string writeWorldYaml(const World& world) {
  std::string out;
  const auto line = [&out](const std::string& text) {
    out += text;
    out += '\n';
  };

  line("dashbed_world: " + std::to_string(kWorldFormatVersion));
  line("name: " + formatName(world.name));
  if (!world.description.empty()) line("description: " + doubleQuoted(world.description));

  line("robots:");
  for (const RobotSpec& robot : world.robots) {
    line("  - name: " + formatName(robot.name));
    line("    model: " + formatName(robot.model));
    line("    base: {xyz: " + formatVector3(robot.X_WBase.translation()) +
         ", rpy: " + formatVector3(writableRpy(robot.X_WBase.linear(), false)) + "}");
    line("    home: " + formatList(robot.home));
  }

  line(world.fixtures.empty() ? "fixtures: []" : "fixtures:");
  for (std::size_t i = 0; i < world.fixtures.size(); ++i) {
    const FixtureSpec& fixture = world.fixtures[i];
    const std::string field = "fixtures[" + std::to_string(i) + "].pose";
    line("  - name: " + formatName(fixture.name));
    line("    type: " + std::string(world_yaml::fixtureTypeName(fixture.type)));
    line("    size: " + formatVector3(fixture.size));
    line("    pose: " + formatYawPose(fixture.X_WF, field));
    line("    color: " + formatColor(fixture.color));
    if (fixture.type != FixtureType::kBox) line("    wall: " + formatNumber(fixture.wall_thickness));
    if (fixture.type == FixtureType::kShelf) line("    levels: " + formatList(fixture.levels));
  }

  // derived surfaces and regions (non-empty `fixture`) come back from the fixtures
  std::string surfaces;
  for (std::size_t i = 0; i < world.surfaces.size(); ++i) {
    const StableSurface& surface = world.surfaces[i];
    if (!surface.fixture.empty()) continue;
    surfaces += "  - {name: " + formatName(surface.name) +
                ", center: " + formatVector3(surface.X_WS.translation()) +
                ", size: " + formatVector2(surface.size) + ", yaw: " +
                formatNumber(yawOf(surface.X_WS, "surfaces[" + std::to_string(i) + "]")) + "}\n";
  }
  out += surfaces.empty() ? "surfaces: []\n" : "surfaces:\n" + surfaces;

  std::string regions;
  for (std::size_t i = 0; i < world.regions.size(); ++i) {
    const Region& region = world.regions[i];
    if (!region.fixture.empty()) continue;
    regions += "  - {name: " + formatName(region.name) +
               ", center: " + formatVector3(region.X_WR.translation()) +
               ", size: " + formatVector3(region.size) + ", yaw: " +
               formatNumber(yawOf(region.X_WR, "regions[" + std::to_string(i) + "]")) + "}\n";
  }
  out += regions.empty() ? "regions: []\n" : "regions:\n" + regions;

  line(world.objects.empty() ? "objects: []" : "objects:");
  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectSpec& object = world.objects[i];
    line("  - name: " + formatName(object.name));
    line("    size: " + formatVector3(object.size));
    line("    mass: " + formatNumber(object.mass));
    line("    friction: " + formatNumber(object.friction));
    line("    color: " + formatColor(object.color));
    if (!object.object_class.empty()) line("    class: " + formatName(object.object_class));
    line("    pose: " + formatYawPose(object.X_WO, "objects[" + std::to_string(i) + "].pose"));
  }

  line(world.goals.empty() ? "goals: []" : "goals:");
  for (const Goal& goal : world.goals) {
    const std::string who = goal.object.empty() ? "class: " + formatName(goal.object_class)
                                                : "object: " + formatName(goal.object);
    line("  - {" + who + ", region: " + formatName(goal.region) + "}");
  }

  const PhysicsSettings& physics = world.physics;
  line("physics:");
  line("  time_step: " + formatNumber(physics.time_step));
  line("  gravity: " + formatVector3(physics.gravity));
  line("  solver_iterations: " + std::to_string(physics.solver_iterations));
  line("  pad_friction: " + formatNumber(physics.pad_friction));
  line("  fixture_friction: " + formatNumber(physics.fixture_friction));
  line("  settle_time: " + formatNumber(physics.settle_time));

  const ControllerSettings& controller = world.controller;
  line("controller:");
  line("  kp: " + formatList(controller.kp));
  line("  kd: " + formatList(controller.kd));
  line("  grip_force: " + formatNumber(controller.grip_force));
  line("  finger_speed: " + formatNumber(controller.finger_speed));

  const CheckSettings& checks = world.checks;
  line("checks:");
  line("  slip_tolerance: " + formatNumber(checks.slip_tolerance));
  line("  slip_angle_tolerance: " + formatNumber(checks.slip_angle_tolerance));
  line("  lift_clearance: " + formatNumber(checks.lift_clearance));
  line("  placement_tolerance: " + formatNumber(checks.placement_tolerance));
  line("  upright_tolerance: " + formatNumber(checks.upright_tolerance));
  line("  rest_speed: " + formatNumber(checks.rest_speed));
  line("  settle_time: " + formatNumber(checks.settle_time));
  line("  tracking_error_limit: " + formatNumber(checks.tracking_error_limit));
  line("  grip_margin: " + formatNumber(checks.grip_margin));
  line("  pad_contact_area: " + formatNumber(checks.pad_contact_area));

  const SafetySettings& safety = world.safety;
  line("safety:");
  line("  max_joint_acceleration: " + formatNumber(safety.max_joint_acceleration));
  line("  payload: " + formatNumber(safety.payload));
  line("  tcp_speed: " + formatNumber(safety.tcp_speed));
  line("  tcp_force: " + formatNumber(safety.tcp_force));
  line("  external_torque: " + formatNumber(safety.external_torque));
  return out;
}

}  // namespace dashbed::core
