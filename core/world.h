#pragma once
// The world: robots, fixtures, stable surfaces, goal regions, objects, goals and settings.
//
// A World is an immutable description loaded from a world file (worlds/*.yaml, format in the
// README) or made by a scenario generator. Frames: W is the world frame (z up, SI units).
// Every element remembers where it was written (SourceLocation) so that checks made after
// loading (reachability, planner infeasibility) can still name the file and line.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/input_text.h"
#include "core/pose.h"

namespace dashbed::core {


/// Linear RGB colour, components in [0, 1].
struct Color {
  double r = 0.5;
  double g = 0.5;
  double b = 0.5;
  bool operator==(const Color&) const = default;
};

/// An oriented box: X_WB is the pose of the box's centre, size the full edge lengths [m].
struct Box {
  Pose X_WB = Pose::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

/// A robot placed in the world.
struct RobotSpec {
  std::string name;
  std::string model;                  ///< robot model name; resolves to assets/<model>.urdf
  Pose X_WBase = Pose::Identity();    ///< pose of the model's root link (base_link) in W
  std::array<double, 6> home{};       ///< home configuration of the six arm joints [rad]
  SourceLocation where;
};

enum class FixtureType {
  kBox,    ///< a solid box (tables, pedestals, walls)
  kBin,    ///< an open box: floor and four walls; its inside is a goal region named like it
  kShelf,  ///< two side panels, a back panel and horizontal boards; each board is a surface
};

/// A static fixture. `X_WF` is the pose of the centre of the fixture's bottom face
/// (for kBox the box stands on that face too); only yaw about +z is allowed.
struct FixtureSpec {
  std::string name;
  FixtureType type = FixtureType::kBox;
  Pose X_WF = Pose::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  ///< outer size [m]
  Color color;
  double wall_thickness = 0.01;  ///< bins and shelves: wall / panel / board thickness [m]
  std::vector<double> levels;    ///< shelves: heights of the boards' top faces above the base [m]
  std::vector<Box> boxes;        ///< derived: the fixture's solid parts in W (collision geometry)
  SourceLocation where;
};

/// A horizontal rectangle objects may rest on. X_WS: centre of the rectangle, z up.
struct StableSurface {
  std::string name;
  Pose X_WS = Pose::Identity();
  Eigen::Vector2d size = Eigen::Vector2d::Zero();  ///< extent along the surface's x and y [m]
  std::string fixture;  ///< the fixture it belongs to ("" when written by hand)
  SourceLocation where;
};

/// A goal region: an upright box volume. X_WR: centre of the region's floor (on a surface),
/// z up; an object is inside when its centre is within the box of `size` standing on the floor.
struct Region {
  std::string name;
  Pose X_WR = Pose::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::string fixture;  ///< the fixture that made it (bins), or ""
  SourceLocation where;
};

/// How far the point p_W is outside the region's box grown by `tolerance` on every side [m];
/// 0 when inside.
double distanceOutside(const Region& region, const Eigen::Vector3d& p_W, double tolerance = 0.0);

/// A moveable box-shaped object resting at its start pose.
struct ObjectSpec {
  std::string name;
  Eigen::Vector3d size = Eigen::Vector3d::Constant(0.04);  ///< edge lengths [m]
  double mass = 0.1;                                      ///< [kg]
  double friction = 0.8;                                  ///< Coulomb coefficient (combined by product)
  Color color;
  std::string object_class;  ///< e.g. "red"; goals may name a class instead of an object
  Pose X_WO = Pose::Identity();  ///< start pose of the object's centre; yaw only
  SourceLocation where;
};

/// A goal: one object (or every object of a class) must end inside a region.
struct Goal {
  std::string object;        ///< set for object goals
  std::string object_class;  ///< set for class goals
  std::string region;
  SourceLocation where;
};

/// Simulation settings (world file section `physics`).
struct PhysicsSettings {
  double time_step = 0.001;                          ///< fixed step [s] (1 kHz)
  Eigen::Vector3d gravity{0.0, 0.0, -9.81};          ///< [m/s^2]
  int solver_iterations = 100;                       ///< sequential-impulse iterations per step
  double pad_friction = 1.0;                         ///< finger pad Coulomb coefficient (rubber)
  double fixture_friction = 0.6;                     ///< table, bins, shelves
  double settle_time = 0.5;                          ///< time objects settle before the plan starts [s]
  bool operator==(const PhysicsSettings&) const = default;
};

/// Controller settings (world file section `controller`).
///
/// The arm runs a joint-space PD in computed-torque form, tau = M(q) (qdd_ref + kp e + kd de)
/// + c(q, qd) + g(q), clamped to the effort limits, so the gains are per-joint accelerations:
/// kp = w^2 and kd = 2 zeta w for a closed-loop natural frequency w. The defaults (w = 40 rad/s,
/// critically damped) keep w * time_step << 1 at 1 kHz and the tracking error at the UR5e's
/// top joint speed far below a millimetre at the TCP (tests/sim/test_simulation.cpp).
struct ControllerSettings {
  std::array<double, 6> kp{1600.0, 1600.0, 1600.0, 1600.0, 1600.0, 1600.0};  ///< [1/s^2]
  std::array<double, 6> kd{80.0, 80.0, 80.0, 80.0, 80.0, 80.0};              ///< [1/s]
  double grip_force = 60.0;     ///< Hand-E closing force [N], 20..185
  double finger_speed = 0.1;    ///< Hand-E finger speed [m/s], 0.02..0.15
  bool operator==(const ControllerSettings&) const = default;
};

/// Thresholds of the physical checks (world file section `checks`).
struct CheckSettings {
  double slip_tolerance = 0.005;        ///< object displacement in the gripper frame [m]
  double slip_angle_tolerance = 0.1;    ///< object rotation in the gripper frame [rad]
  double lift_clearance = 0.005;        ///< min gap to the support after lifting [m]
  double placement_tolerance = 0.0;     ///< extra margin around a goal region [m]
  double upright_tolerance = 0.1;       ///< tilt of a placed object [rad]
  double rest_speed = 0.01;             ///< an object is at rest below this speed [m/s]
  double settle_time = 0.5;             ///< wait after release before judging a placement [s]
  double tracking_error_limit = 0.05;   ///< joint tracking error [rad]
  /// Smallest grip margin while holding: what the pads' friction can resist over the load on it
  /// (sim/grip_load.h). 2: the grip still holds with half the friction coefficient (rubber on
  /// a dusty, oily or worn surface); docs/simulation.md, "Grip margin".
  double grip_margin = 2.0;
  /// Smallest overlap of each pad's face with the held object's face [m^2]: a quarter of the
  /// Hand-E pad face (22 x 25 mm); less is a grasp on the object's edge.
  double pad_contact_area = 1.25e-4;
  bool operator==(const CheckSettings&) const = default;
};

/// The hardware limits a plan is held to before it is simulated (world file section `safety`;
/// core/readiness.h). The joint position, speed and effort limits are the robot model's own.
struct SafetySettings {
  /// Joint acceleration limit [rad/s^2]. The UR5e has none of its own, only torque limits; 5 is
  /// what UR's ROS 2 driver configures for MoveIt's time parameterisation
  /// (Universal_Robots_ROS2_Driver, ur_moveit_config/config/joint_limits.yaml).
  double max_joint_acceleration = 5.0;
  /// Rated payload at the flange, gripper included [kg] (UR5e hardware manual: 5 kg).
  double payload = 5.0;
  /// TCP speed limit of the robot's safety configuration [m/s] (see docs/limits.md).
  double tcp_speed = 1.5;
  /// TCP force limit of the robot's safety configuration [N]: an estimated force beyond it at
  /// the TCP is a protective stop (controllers/collision_detection.h; see docs/limits.md).
  double tcp_force = 150.0;
  /// External torque limit of each arm joint, as a fraction of its rated torque: an estimated
  /// external torque beyond it is a protective stop (docs/simulation.md, "Protective stop").
  double external_torque = 0.5;
  bool operator==(const SafetySettings&) const = default;
};

/// The current world-file format version.
inline constexpr int kWorldFormatVersion = 1;

/// Home configuration of a robot whose world-file entry has no `home` [rad].
inline constexpr std::array<double, 6> kDefaultRobotHome{0.0, -1.5708, 1.5708,
                                                         -1.5708, -1.5708, 0.0};

/// Most robots a world may have: the simulator gives every robot a bit of a 32-bit collision
/// filter and the planner a bit of a 64-bit mask; far beyond any cell DaSH's representation
/// can be built for.
inline constexpr std::size_t kMaxRobots = 16;

/// Most fixtures, and most surfaces and regions written, a world may have: every object's start
/// pose is checked against each of them, so reading stays linear in the number of objects.
inline constexpr std::size_t kMaxFixtures = 1000;

struct World {
  std::string name;
  std::string description;
  std::vector<RobotSpec> robots;
  std::vector<FixtureSpec> fixtures;
  std::vector<StableSurface> surfaces;  ///< written ones and those derived from fixtures
  std::vector<Region> regions;          ///< written ones and those derived from bins
  std::vector<ObjectSpec> objects;
  std::vector<Goal> goals;
  PhysicsSettings physics;
  ControllerSettings controller;
  CheckSettings checks;
  SafetySettings safety;
  std::string source_file;  ///< file it was loaded from ("" when generated)

  const RobotSpec* findRobot(std::string_view name) const;
  const ObjectSpec* findObject(std::string_view name) const;
  const Region* findRegion(std::string_view name) const;
  const FixtureSpec* findFixture(std::string_view name) const;

  /// The goal that sends an object somewhere (its object goal first, then its class's), or
  /// nullptr.
  const Goal* goalOf(const ObjectSpec& object) const;
  /// The region of goalOf(object), or nullptr.
  const Region* goalRegionOf(const ObjectSpec& object) const;
};

/// Rebuilds everything derived from the fixtures: each fixture's `boxes`, the surfaces
/// `<fixture>/top` (box), `<fixture>/floor` (bin), `<fixture>/board<k>` (shelf), and the
/// region `<fixture>` of each bin. Previously derived entries (those with a non-empty
/// `fixture` field) are replaced; hand-written ones are kept in front. Fixture frame F:
/// origin at the centre of the bottom face; shelves open towards -x_F, back panel at +x_F.
/// parseWorldYaml calls this; scenario generators building a World in memory may too.
void deriveFixtureGeometry(World& world);

}  // namespace dashbed::core
