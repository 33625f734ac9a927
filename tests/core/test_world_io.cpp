#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "text_mutations.h"

using namespace dashbed::core;
using Catch::Matchers::Contains;

namespace {

const std::filesystem::path kWorlds = std::filesystem::path(DASHBED_SOURCE_ROOT) / "tests/core/worlds";

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::filesystem::path> yamlFiles(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  REQUIRE_FALSE(files.empty());  // a loop over nothing checks nothing
  return files;
}

// the message of the WorldError that f throws; other exceptions propagate and fail the test
template <typename F>
std::string worldErrorOf(F&& f) {
  try {
    f();
  } catch (const WorldError& e) {
    return e.what();
  }
  FAIL("no WorldError was thrown");
  return {};
}

// ---- world equality: every field except where things were written ------------------------

void checkSame(const Pose& a, const Pose& b, const std::string& what) {
  INFO(what << "\n" << a.matrix() << "\nvs\n" << b.matrix());
  CHECK(a.matrix() == b.matrix());
}

void checkSameWorld(const World& a, const World& b) {
  CHECK(a.name == b.name);
  CHECK(a.description == b.description);

  REQUIRE(a.robots.size() == b.robots.size());
  for (std::size_t i = 0; i < a.robots.size(); ++i) {
    INFO("robots[" << i << "]");
    CHECK(a.robots[i].name == b.robots[i].name);
    CHECK(a.robots[i].model == b.robots[i].model);
    checkSame(a.robots[i].X_WBase, b.robots[i].X_WBase, "base");
    CHECK(a.robots[i].home == b.robots[i].home);
  }

  REQUIRE(a.fixtures.size() == b.fixtures.size());
  for (std::size_t i = 0; i < a.fixtures.size(); ++i) {
    INFO("fixtures[" << i << "]");
    const FixtureSpec& fa = a.fixtures[i];
    const FixtureSpec& fb = b.fixtures[i];
    CHECK(fa.name == fb.name);
    CHECK(fa.type == fb.type);
    checkSame(fa.X_WF, fb.X_WF, "pose");
    CHECK(fa.size == fb.size);
    CHECK(fa.color == fb.color);
    CHECK(fa.wall_thickness == fb.wall_thickness);
    CHECK(fa.levels == fb.levels);
    REQUIRE(fa.boxes.size() == fb.boxes.size());
    for (std::size_t k = 0; k < fa.boxes.size(); ++k) {
      checkSame(fa.boxes[k].X_WB, fb.boxes[k].X_WB, "box " + std::to_string(k));
      CHECK(fa.boxes[k].size == fb.boxes[k].size);
    }
  }

  REQUIRE(a.surfaces.size() == b.surfaces.size());
  for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
    INFO("surfaces[" << i << "]");
    CHECK(a.surfaces[i].name == b.surfaces[i].name);
    checkSame(a.surfaces[i].X_WS, b.surfaces[i].X_WS, "pose");
    CHECK(a.surfaces[i].size == b.surfaces[i].size);
    CHECK(a.surfaces[i].fixture == b.surfaces[i].fixture);
  }

  REQUIRE(a.regions.size() == b.regions.size());
  for (std::size_t i = 0; i < a.regions.size(); ++i) {
    INFO("regions[" << i << "]");
    CHECK(a.regions[i].name == b.regions[i].name);
    checkSame(a.regions[i].X_WR, b.regions[i].X_WR, "pose");
    CHECK(a.regions[i].size == b.regions[i].size);
    CHECK(a.regions[i].fixture == b.regions[i].fixture);
  }

  REQUIRE(a.objects.size() == b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    INFO("objects[" << i << "]");
    const ObjectSpec& oa = a.objects[i];
    const ObjectSpec& ob = b.objects[i];
    CHECK(oa.name == ob.name);
    CHECK(oa.size == ob.size);
    CHECK(oa.mass == ob.mass);
    CHECK(oa.friction == ob.friction);
    CHECK(oa.color == ob.color);
    CHECK(oa.object_class == ob.object_class);
    checkSame(oa.X_WO, ob.X_WO, "pose");
  }

  REQUIRE(a.goals.size() == b.goals.size());
  for (std::size_t i = 0; i < a.goals.size(); ++i) {
    INFO("goals[" << i << "]");
    CHECK(a.goals[i].object == b.goals[i].object);
    CHECK(a.goals[i].object_class == b.goals[i].object_class);
    CHECK(a.goals[i].region == b.goals[i].region);
  }

  CHECK(a.physics == b.physics);
  CHECK(a.controller == b.controller);
  CHECK(a.checks == b.checks);
  CHECK(a.safety == b.safety);
}

// every solid part of a fixture lies within its outer box, and the parts only touch
void checkFixtureParts(const FixtureSpec& fixture) {
  INFO("fixture " << fixture.name);
  const Box outer{fixture.X_WF * Eigen::Translation3d(0, 0, fixture.size.z() / 2), fixture.size};
  for (const Box& part : fixture.boxes) {
    CHECK((part.size.array() > 0.0).all());
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p_B{(corner & 1 ? 0.5 : -0.5) * part.size.x(),
                                (corner & 2 ? 0.5 : -0.5) * part.size.y(),
                                (corner & 4 ? 0.5 : -0.5) * part.size.z()};
      CHECK(pointInBox(part.X_WB * p_B, outer, 1e-12));
    }
  }
  for (std::size_t i = 0; i < fixture.boxes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      INFO("parts " << j << " and " << i);
      CHECK(boxPenetrationDepth(fixture.boxes[i], fixture.boxes[j]) <= 1e-12);
    }
  }
}

const StableSurface* findSurface(const World& world, const std::string& name) {
  for (const StableSurface& surface : world.surfaces) {
    if (surface.name == name) return &surface;
  }
  return nullptr;
}

// a valid world with every kind of element, its numbers drawn from a seeded generator
World makeRandomWorld(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double low, double high) { return low + (high - low) * unit(rng); };
  const double pi = std::numbers::pi;

  World world;
  world.name = "gen_world-" + std::to_string(seed) + ".v1";
  world.description = "Tab\there, \"quotes\", back\\slash, a colon: and # hash,\nnew line, \x01, ünïcødé";

  for (int r = 0; r < 3; ++r) {
    RobotSpec robot;
    robot.name = "r" + std::to_string(r);
    robot.model = "ur5e_hande";
    const Eigen::Vector3d xyz{between(-3, 3), between(-3, 3), between(0, 1)};
    // upright, hung from the ceiling, and on a wall
    const Eigen::Vector3d rpy = r == 0 ? Eigen::Vector3d(0, 0, between(-pi, pi))
                              : r == 1 ? Eigen::Vector3d(pi, 0, between(-pi, pi))
                                       : Eigen::Vector3d(pi / 2, 0, between(-pi, pi));
    robot.X_WBase = makePose(xyz, rpy);
    for (double& q : robot.home) q = between(-pi, pi);
    world.robots.push_back(robot);
  }

  // fixtures stand beyond x = 6, the objects on a hand-written surface around the origin
  const FixtureType types[] = {FixtureType::kBox, FixtureType::kBin, FixtureType::kShelf,
                               FixtureType::kBin};
  for (int f = 0; f < 4; ++f) {
    FixtureSpec fixture;
    fixture.name = "fixture_" + std::to_string(f);
    fixture.type = types[f];
    fixture.size = {between(0.2, 1.0), between(0.2, 1.0), between(0.3, 1.5)};
    fixture.X_WF = makePoseXyzYaw({6.0 + 2.0 * f, between(-1, 1), between(0, 0.5)}, between(-pi, pi));
    fixture.color = {unit(rng), unit(rng), unit(rng)};
    if (fixture.type != FixtureType::kBox) {
      fixture.wall_thickness = between(0.001, 0.05);
    }
    if (fixture.type == FixtureType::kShelf) {
      double level = fixture.wall_thickness;
      while (true) {
        level += between(fixture.wall_thickness, 0.4);
        if (level > fixture.size.z() - fixture.wall_thickness) break;
        fixture.levels.push_back(level);
      }
      if (fixture.levels.empty()) fixture.levels.push_back(fixture.wall_thickness);
    }
    world.fixtures.push_back(fixture);
  }

  StableSurface floor;
  floor.name = "floor_zone";
  floor.X_WS = makePoseXyzYaw({0, 0, between(0, 0.1)}, 0.0);
  floor.size = {10.0, 10.0};
  world.surfaces.push_back(floor);
  StableSurface pad;
  pad.name = "pad";
  pad.X_WS = makePoseXyzYaw({between(-1, 1), between(-1, 1), between(0, 2)}, between(-pi, pi));
  pad.size = {between(0.01, 1), between(0.01, 1)};
  world.surfaces.push_back(pad);

  Region slot;
  slot.name = "slot";
  slot.X_WR = makePoseXyzYaw({between(-1, 1), between(-1, 1), between(0, 2)}, between(-pi, pi));
  slot.size = {between(0.01, 1), between(0.01, 1), between(0.01, 1)};
  world.regions.push_back(slot);

  const char* const classes[] = {"red", "blue", ""};
  for (int o = 0; o < 6; ++o) {
    ObjectSpec object;
    object.name = "cube_" + std::to_string(o);
    object.size = {between(0.01, 0.1), between(0.01, 0.1), between(0.01, 0.1)};
    object.mass = between(0.01, 2.0);
    object.friction = between(0.1, 1.5);
    object.color = {unit(rng), unit(rng), unit(rng)};
    object.object_class = classes[o % 3];
    object.X_WO = makePoseXyzYaw({-4.0 + 0.5 * o, between(-4, 4),
                                  floor.X_WS.translation().z() + object.size.z() / 2},
                                 between(-pi, pi));
    world.objects.push_back(object);
  }

  world.goals.push_back(Goal{"cube_2", "", "fixture_1", {}});
  world.goals.push_back(Goal{"", "red", "slot", {}});
  world.goals.push_back(Goal{"", "blue", "fixture_3", {}});

  world.physics.time_step = between(1e-5, 0.01);
  world.physics.gravity = {between(-1, 1), between(-1, 1), between(-12, -1)};
  world.physics.solver_iterations = 1 + static_cast<int>(unit(rng) * 500);
  world.physics.pad_friction = between(0.1, 2);
  world.physics.fixture_friction = between(0.1, 2);
  world.physics.settle_time = between(0, 2);
  for (double& k : world.controller.kp) k = between(0, 1e4);
  for (double& k : world.controller.kd) k = between(0, 1e3);
  world.controller.grip_force = between(20, 185);
  world.controller.finger_speed = between(0.02, 0.15);
  world.checks.slip_tolerance = between(0, 0.01);
  world.checks.slip_angle_tolerance = between(0, 0.2);
  world.checks.lift_clearance = between(0, 0.01);
  world.checks.placement_tolerance = between(0, 0.01);
  world.checks.upright_tolerance = between(0, 0.2);
  world.checks.rest_speed = between(0, 0.05);
  world.checks.settle_time = between(0, 1);
  world.checks.tracking_error_limit = between(0, 0.1);
  world.safety.max_joint_acceleration = between(1, 10);
  world.safety.payload = between(1, 5);
  world.safety.tcp_speed = between(0.25, 2);

  deriveFixtureGeometry(world);
  return world;
}

// ---- the bad worlds and what their messages must say ------------------------------------

struct BadWorld {
  const char* file;
  const char* message;  // "file:line:column: field: ..." (a prefix of the message tail)
};

const BadWorld kBadWorlds[] = {
    // YAML itself
    {"syntax_error.yaml", "syntax_error.yaml:12:9: syntax error: end of sequence flow not found"},
    {"syntax_bad_indent.yaml", "syntax_bad_indent.yaml:7:4: syntax error: end of sequence not found"},
    {"empty.yaml", "empty.yaml:1:1: (top level): the file is empty"},
    {"comment_only.yaml", "comment_only.yaml:1:1: (top level): the file is empty"},
    {"two_documents.yaml", "two_documents.yaml:25:1: (top level): a world file holds one YAML document"},
    {"top_level_list.yaml", "top_level_list.yaml:2:1: (top level): expected a map of world sections"},
    {"top_level_scalar.yaml", "top_level_scalar.yaml:2:1: (top level): expected a map of world sections starting with 'dashbed_world: 1', got 'dashbed world 1'"},
    // version
    {"missing_version.yaml", "missing_version.yaml:2:1: dashbed_world: missing (a world file starts with 'dashbed_world: 1')"},
    {"wrong_version.yaml", "wrong_version.yaml:2:16: dashbed_world: unsupported format version 2; this dashbed reads version 1"},
    {"version_not_integer.yaml", "version_not_integer.yaml:2:16: dashbed_world: expected an integer, got '1.5'"},
    // unknown and duplicate keys
    {"unknown_key_top.yaml", "unknown_key_top.yaml:23:1: goal: unknown key; allowed: dashbed_world, name, description, robots, fixtures, surfaces, regions, objects, goals, physics, controller, checks"},
    {"unknown_key_object.yaml", "unknown_key_object.yaml:21:5: objects[0].colour: unknown key; allowed: name, size, mass, friction, color, class, pose"},
    {"unknown_key_pose.yaml", "unknown_key_pose.yaml:22:45: objects[0].pose.roll: unknown key; allowed: xyz, yaw"},
    {"safety_not_positive.yaml", "safety_not_positive.yaml:27:14: safety.tcp_speed: must be > 0, got 0"},
    {"unknown_key_checks.yaml", "unknown_key_checks.yaml:26:3: checks.slip: unknown key; allowed: slip_tolerance,"},
    {"duplicate_key.yaml", "duplicate_key.yaml:22:5: objects[0].mass: duplicate key (first at line 21)"},
    // types and counts
    {"mass_string.yaml", "mass_string.yaml:21:11: objects[0].mass: expected a number, got 'heavy'"},
    {"mass_empty.yaml", "mass_empty.yaml:21:5: objects[0].mass: expected a number, got nothing"},
    {"quoted_number.yaml", "quoted_number.yaml:21:11: objects[0].mass: expected a number, got the quoted string '0.1'"},
    {"tagged_number.yaml", "tagged_number.yaml:21:11: objects[0].mass: expected a number, got '0.1' tagged !!str"},
    {"version_tagged_float.yaml", "version_tagged_float.yaml:2:16: dashbed_world: expected an integer, got '1' tagged !!float"},
    {"robots_map.yaml", "robots_map.yaml:5:3: robots: expected a list, got a map"},
    {"pose_scalar.yaml", "pose_scalar.yaml:22:11: objects[0].pose: expected a map, got '0.5'"},
    {"xyz_two_numbers.yaml", "xyz_two_numbers.yaml:22:17: objects[0].pose.xyz: expected a list of 3 numbers, got 2 items"},
    {"gains_five.yaml", "gains_five.yaml:26:7: controller.kp: expected a list of 6 numbers, got 5 items"},
    {"home_five.yaml", "home_five.yaml:8:11: robots[0].home: expected a list of 6 numbers, got 5 items"},
    {"solver_iterations_fraction.yaml", "solver_iterations_fraction.yaml:25:30: physics.solver_iterations: expected an integer, got '2.5'"},
    {"bad_name.yaml", "bad_name.yaml:19:11: objects[0].name: expected a name of letters, digits, '_', '-' and '.', got 'cube 0'"},
    // missing fields
    {"missing_name.yaml", "missing_name.yaml:2:1: name: missing (required)"},
    {"missing_model.yaml", "missing_model.yaml:5:5: robots[0].model: missing (required)"},
    {"missing_object_pose.yaml", "missing_object_pose.yaml:19:5: objects[0].pose: missing (required)"},
    {"empty_robots.yaml", "empty_robots.yaml:4:9: robots: the world needs at least one robot"},
    {"too_many_robots.yaml", "too_many_robots.yaml:5:3: robots: at most 16 robots, not 17"},
    // numbers out of range
    {"nan_coordinate.yaml", "nan_coordinate.yaml:7:25: robots[0].base.xyz[1]: expected a finite number, got '.nan'"},
    {"inf_mass.yaml", "inf_mass.yaml:21:11: objects[0].mass: expected a finite number, got '.inf'"},
    {"huge_number.yaml", "huge_number.yaml:22:40: objects[0].pose.yaw: expected a finite number, got '1e400'"},
    {"zero_size.yaml", "zero_size.yaml:11:22: fixtures[0].size[2]: must be > 0, got 0"},
    {"negative_object_size.yaml", "negative_object_size.yaml:22:18: objects[0].size[1]: must be > 0, got -0.04"},
    {"negative_mass.yaml", "negative_mass.yaml:21:11: objects[0].mass: must be > 0, got -0.1"},
    {"zero_friction.yaml", "zero_friction.yaml:21:15: objects[0].friction: must be > 0, got 0"},
    {"time_step_range.yaml", "time_step_range.yaml:26:14: physics.time_step: must be in [1e-05, 0.01] s, got 0.02"},
    {"settle_time_range.yaml", "settle_time_range.yaml:26:16: physics.settle_time: must be in [0, 60] s, got 1e+300"},
    {"gravity_range.yaml", "gravity_range.yaml:26:12: physics.gravity: must be at most 100 m/s^2 in magnitude, got 2000"},
    {"mass_range.yaml", "mass_range.yaml:21:11: objects[0].mass: must be at most 1000 kg, got 5000"},
    {"region_too_large.yaml", "region_too_large.yaml:15:12: fixtures[1].size[0]: must be at most 100 m, got 500"},
    {"solver_iterations_zero.yaml", "solver_iterations_zero.yaml:25:30: physics.solver_iterations: must be in [1, 1000000], got 0"},
    {"grip_force_range.yaml", "grip_force_range.yaml:26:15: controller.grip_force: must be in [20, 185] N (the Robotiq Hand-E range), got 200"},
    {"finger_speed_range.yaml", "finger_speed_range.yaml:26:17: controller.finger_speed: must be in [0.02, 0.15] m/s (the Robotiq Hand-E range), got 0.01"},
    {"negative_gain.yaml", "negative_gain.yaml:26:27: controller.kd[4]: must be >= 0, got -30"},
    {"negative_tolerance.yaml", "negative_tolerance.yaml:27:22: checks.upright_tolerance: must be >= 0, got -0.1"},
    {"bad_colour_name.yaml", "bad_colour_name.yaml:21:12: objects[0].color: unknown colour 'pink'; use [r, g, b] in [0, 1] or one of red, green,"},
    {"colour_out_of_range.yaml", "colour_out_of_range.yaml:21:18: objects[0].color[1]: must be in [0, 1], got 1.5"},
    // names
    {"duplicate_name.yaml", "duplicate_name.yaml:19:11: objects[0].name: duplicate name 'table' (also fixtures[0].name at line 9)"},
    {"duplicate_robot.yaml", "duplicate_robot.yaml:8:11: robots[1].name: duplicate name 'r0' (also robots[0].name at line 5)"},
    // fixtures and poses
    {"unknown_fixture_type.yaml", "unknown_fixture_type.yaml:14:11: fixtures[1].type: unknown fixture type 'crate'; expected box, bin or shelf"},
    {"levels_on_box.yaml", "levels_on_box.yaml:13:5: fixtures[0].levels: only shelves have levels (this is a box)"},
    {"wall_on_box.yaml", "wall_on_box.yaml:13:5: fixtures[0].wall: only bins and shelves have walls (this is a box)"},
    {"shelf_missing_levels.yaml", "shelf_missing_levels.yaml:18:5: fixtures[2].levels: missing (required for shelves)"},
    {"levels_not_increasing.yaml", "levels_not_increasing.yaml:23:19: fixtures[2].levels[1]: levels must be increasing, each at least wall = 0.02 m above the previous; got 0.4 after 0.8"},
    {"level_above_top.yaml", "level_above_top.yaml:23:19: fixtures[2].levels[1]: must be at most size[2] - wall = 1.18 m (below the top board), got 1.19"},
    {"wall_too_thick.yaml", "wall_too_thick.yaml:17:11: fixtures[1].wall: must be > 0 and less than half the smaller horizontal size (0.1 m), got 0.12"},
    {"rpy_and_yaw.yaml", "rpy_and_yaw.yaml:7:51: robots[0].base: give either rpy or yaw, not both"},
    {"rpy_on_fixture.yaml", "rpy_on_fixture.yaml:16:37: fixtures[1].pose.rpy: fixtures may only turn about z; use yaw instead of rpy"},
    // goals
    {"goal_unknown_object.yaml", "goal_unknown_object.yaml:24:14: goals[0].object: unknown object 'cube_9'"},
    {"goal_unknown_class.yaml", "goal_unknown_class.yaml:24:13: goals[0].class: no object has class 'blue'"},
    {"goal_unknown_region.yaml", "goal_unknown_region.yaml:24:30: goals[0].region: unknown region 'bin_blue'"},
    {"goal_too_tall_for_bin.yaml", "goal_too_tall_for_bin.yaml:24:30: goals[0].region: object 'post_0' is 200.0 mm tall: standing in region 'bin_red' (90.0 mm high) its centre would be above it, and an object is in a region when its centre is"},
    {"goal_region_is_box.yaml", "goal_region_is_box.yaml:24:30: goals[0].region: unknown region 'table' ('table' is a box fixture; only bins are regions)"},
    {"goal_object_and_class.yaml", "goal_object_and_class.yaml:24:5: goals[0]: give either object or class, not both"},
    {"goal_neither.yaml", "goal_neither.yaml:24:5: goals[0]: needs an object or a class"},
    {"two_goals_one_object.yaml", "two_goals_one_object.yaml:25:14: goals[1].object: object 'cube_0' already has a goal (goals[0] at line 24)"},
    {"two_goals_one_class.yaml", "two_goals_one_class.yaml:25:13: goals[1].class: class 'red' already has a goal (goals[0] at line 24)"},
    // start poses
    {"object_in_table.yaml", "object_in_table.yaml:22:11: objects[0].pose: 'cube_0' penetrates fixture 'table' by 5.0 mm (at most 1.0 mm allowed)"},
    {"object_in_bin_wall.yaml", "object_in_bin_wall.yaml:22:11: objects[0].pose: 'cube_0' penetrates fixture 'bin_red' by"},
    {"objects_overlap.yaml", "objects_overlap.yaml:24:11: objects[1].pose: 'cube_1' overlaps object 'cube_0' (line 22) by"},
    {"object_floating.yaml", "object_floating.yaml:22:11: objects[0].pose: 'cube_0' does not rest on any stable surface (bottom face at z = 0.8000 m must be within 2.0 mm of a surface under its centre); the nearest surface under it, 'table/top' at z = 0.7500 m, is 50.0 mm below its bottom face"},
    // robots
    {"robot_in_table.yaml", "robot_in_table.yaml:7:11: robots[0].base: robot 'r0' is mounted inside fixture 'table' (its base must rest on a fixture's top, not inside it)"},
    {"object_off_table.yaml", "object_off_table.yaml:22:11: objects[0].pose: 'cube_0' does not rest on any stable surface (bottom face at z = 0.7500 m must be within 2.0 mm of a surface under its centre); no stable surface lies under its centre"},
    // text and structure: reported where they are, bytes escaped
    {"alias_wrong_place.yaml", "alias_wrong_place.yaml:21:12: objects[0].color: unknown colour 'r0'; use [r, g, b] in [0, 1] or one of red, green, blue, yellow, orange, purple, cyan, magenta, white, black, grey, brown (the value of alias *robot, anchored at line 5)"},
    {"stray_comma.yaml", "stray_comma.yaml:2:1: (top level): a ',' outside a [list] or {map}"},
    {"nested_too_deep.yaml", "nested_too_deep.yaml:7:72: (structure): nested deeper than 64 levels of lists and maps"},
    {"nul_byte.yaml", "nul_byte.yaml:19:15: (text): a NUL byte (\\x00): not UTF-8 text"},
    {"utf16.yaml", "utf16.yaml:1:1: (text): the file is UTF-16 (it starts with the byte-order mark FF FE); dashbed reads UTF-8 text"},
    {"not_utf8.yaml", "not_utf8.yaml:4:18: (text): byte \\xE9 is not part of a UTF-8 character"},
    {"control_character.yaml", "control_character.yaml:19:15: (text): control character \\x1B (only tab, line feed and carriage return may appear)"},
};

}  // namespace

// ---- good worlds --------------------------------------------------------------------------

TEST_CASE("the minimal world loads with its derived geometry", "[world_io]") {
  const World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  CHECK(world.name == "minimal");
  CHECK(world.source_file == (kWorlds / "good/minimal.yaml").string());
  REQUIRE(world.robots.size() == 1);
  const RobotSpec& r0 = world.robots[0];
  CHECK(r0.model == "ur5e_hande");
  CHECK(r0.home == kDefaultRobotHome);
  CHECK(r0.X_WBase.translation() == Eigen::Vector3d(-0.65, 0, 0.75));
  CHECK(r0.where.line == 6);
  CHECK(r0.where.column == 5);
  CHECK(r0.where.file == world.source_file);

  const FixtureSpec* table = world.findFixture("table");
  REQUIRE(table != nullptr);
  REQUIRE(table->boxes.size() == 1);
  CHECK(table->boxes[0].X_WB.translation().isApprox(Eigen::Vector3d(0, 0, 0.375)));
  CHECK(table->color == Color{0.6, 0.45, 0.3});
  const FixtureSpec* bin = world.findFixture("bin_red");
  REQUIRE(bin != nullptr);
  CHECK(bin->boxes.size() == 5);

  const StableSurface* top = findSurface(world, "table/top");
  REQUIRE(top != nullptr);
  CHECK(top->fixture == "table");
  CHECK(top->X_WS.translation().z() == 0.75);
  CHECK(top->size == Eigen::Vector2d(2.0, 1.2));
  const StableSurface* floor = findSurface(world, "bin_red/floor");
  REQUIRE(floor != nullptr);
  CHECK(floor->X_WS.translation().isApprox(Eigen::Vector3d(0.3, -0.35, 0.76)));
  CHECK(floor->size.isApprox(Eigen::Vector2d(0.28, 0.18)));

  const Region* region = world.findRegion("bin_red");
  REQUIRE(region != nullptr);
  CHECK(region->fixture == "bin_red");
  CHECK(region->X_WR.translation().isApprox(Eigen::Vector3d(0.3, -0.35, 0.76)));
  CHECK(region->size.isApprox(Eigen::Vector3d(0.28, 0.18, 0.09)));

  const ObjectSpec* cube = world.findObject("cube_0");
  REQUIRE(cube != nullptr);
  CHECK(cube->size == Eigen::Vector3d::Constant(0.04));
  CHECK(cube->mass == 0.1);
  CHECK(cube->friction == 0.8);
  CHECK(cube->object_class == "red");
  CHECK(cube->X_WO.isApprox(makePoseXyzYaw({0.3, 0.2, 0.77}, 0.2)));
  CHECK(world.goalRegionOf(*cube) == region);

  // settings not written keep their defaults
  CHECK(world.physics == PhysicsSettings{});
  CHECK(world.controller == ControllerSettings{});
  CHECK(world.checks == CheckSettings{});
  CHECK(world.findRobot("nobody") == nullptr);
}

TEST_CASE("the shelf world: boards are surfaces, class goals and overrides", "[world_io]") {
  const World world = loadWorldFile(kWorlds / "good/shelf.yaml");
  const FixtureSpec* shelf = world.findFixture("shelf");
  REQUIRE(shelf != nullptr);
  CHECK(shelf->type == FixtureType::kShelf);
  CHECK(shelf->levels == std::vector<double>{0.4, 0.8});
  // two sides, the back, two boards, the top board
  CHECK(shelf->boxes.size() == 6);
  for (int k = 0; k < 2; ++k) {
    const StableSurface* board = findSurface(world, "shelf/board" + std::to_string(k));
    REQUIRE(board != nullptr);
    CHECK(board->X_WS.translation().isApprox(Eigen::Vector3d(1.29, 0, shelf->levels[k])));
    CHECK(board->size.isApprox(Eigen::Vector2d(0.33, 0.76)));
  }
  // the open side faces -x: nothing of the shelf reaches in front of the boards there
  const Eigen::Vector3d front_W{1.3 - 0.175 + 0.001, 0.0, 0.6};
  for (const Box& part : shelf->boxes) CHECK_FALSE(pointInBox(front_W, part));

  CHECK(world.robots[0].X_WBase.linear().isApprox(rotationFromRpy({0, 0, 0.3})));
  CHECK(world.robots[1].home == kDefaultRobotHome);
  CHECK(world.physics.time_step == 0.0005);
  CHECK(world.physics.solver_iterations == 150);
  CHECK(world.controller.kp[5] == 900);
  CHECK(world.controller.grip_force == 80);
  CHECK(world.checks.tracking_error_limit == 0.04);
  CHECK(world.safety.max_joint_acceleration == 4.5);
  CHECK(world.safety.payload == 4.0);
  CHECK(world.safety.tcp_speed == 1.2);
  CHECK(world.findFixture("bin_red")->color == Color{0.9, 0.1, 0.1});

  const Region* upper = world.findRegion("upper_slot");
  const Region* bin = world.findRegion("bin_red");
  REQUIRE(upper != nullptr);
  REQUIRE(bin != nullptr);
  CHECK(world.goalRegionOf(*world.findObject("cube_0")) == upper);
  CHECK(world.goalRegionOf(*world.findObject("cube_1")) == upper);
  CHECK(world.goalRegionOf(*world.findObject("cube_2")) == bin);
  CHECK(world.goalRegionOf(*world.findObject("cube_3")) == upper);  // object goal wins
}

TEST_CASE("derived fixture parts stay inside the fixture and do not overlap", "[world_io]") {
  for (const auto& file : yamlFiles(kWorlds / "good")) {
    const World world = loadWorldFile(file);
    for (const FixtureSpec& fixture : world.fixtures) checkFixtureParts(fixture);
  }
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const World world = makeRandomWorld(seed);
    for (const FixtureSpec& fixture : world.fixtures) checkFixtureParts(fixture);
  }
}

TEST_CASE("deriveFixtureGeometry replaces what it derived before", "[world_io]") {
  World world = loadWorldFile(kWorlds / "good/shelf.yaml");
  const std::size_t surfaces = world.surfaces.size();
  const std::size_t regions = world.regions.size();
  deriveFixtureGeometry(world);
  deriveFixtureGeometry(world);
  CHECK(world.surfaces.size() == surfaces);
  CHECK(world.regions.size() == regions);
  CHECK(world.surfaces.front().name == "staging_pad");  // hand-written first
}

// ---- writer -------------------------------------------------------------------------------

TEST_CASE("written good worlds read back equal, and writing is stable", "[world_io]") {
  for (const auto& file : yamlFiles(kWorlds / "good")) {
    INFO(file);
    const World loaded = loadWorldFile(file);
    const std::string text = writeWorldYaml(loaded);
    const World reread = parseWorldYaml(text, "written.yaml");
    checkSameWorld(loaded, reread);
    CHECK(writeWorldYaml(loaded) == text);
    CHECK(writeWorldYaml(reread) == text);
  }
}

TEST_CASE("a generated world with every kind of element round-trips exactly", "[world_io]") {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("seed " << seed);
    const World generated = makeRandomWorld(seed);
    const std::string text = writeWorldYaml(generated);
    INFO(text);
    const World reread = parseWorldYaml(text, "generated.yaml");
    checkSameWorld(generated, reread);
    CHECK(writeWorldYaml(reread) == text);
  }
}

TEST_CASE("the writer leaves out derived elements and writes fixed text", "[world_io]") {
  const World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  const std::string text = writeWorldYaml(world);
  CHECK_THAT(text, !Contains("table/top"));
  CHECK_THAT(text, !Contains("bin_red/floor"));
  CHECK_THAT(text, Contains("regions: []\n"));
  CHECK_THAT(text, Contains("    pose: {xyz: [0.3, 0.2, 0.77], yaw: 0.2}\n"));
  CHECK_THAT(text, Contains("    base: {xyz: [-0.65, 0, 0.75], rpy: [0, 0, 0]}\n"));
  CHECK_THAT(text, Contains("    color: red\n"));
  CHECK_THAT(text, Contains("  time_step: 0.001\n"));
  CHECK(text.rfind("dashbed_world: 1\nname: minimal\n", 0) == 0);
}

TEST_CASE("robot bases with any roll and pitch: written text is stable", "[world_io]") {
  World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> angle(-3.14, 3.14), pitch(-1.3, 1.3);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d rpy{angle(rng), pitch(rng), angle(rng)};
    world.robots[0].X_WBase = makePose({0.1, 0.2, 1.3}, rpy);  // above the table (a ceiling mount)
    const std::string text = writeWorldYaml(world);
    const World reread = parseWorldYaml(text, "written.yaml");
    INFO("rpy " << rpy.transpose());
    REQUIRE(reread.robots[0].X_WBase.linear().isApprox(world.robots[0].X_WBase.linear(), 1e-14));
    REQUIRE(writeWorldYaml(reread) == text);
  }
}

TEST_CASE("yaw outside the interval from -pi to pi is written wrapped and reads back stable", "[world_io]") {
  World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  world.objects[0].X_WO = makePoseXyzYaw({0.3, 0.2, 0.77}, 7.0);
  const std::string text = writeWorldYaml(world);
  CHECK_THAT(text, Contains("yaw: 0.7168146928204"));
  const World reread = parseWorldYaml(text, "written.yaml");
  CHECK(reread.objects[0].X_WO.isApprox(world.objects[0].X_WO, 1e-14));
  CHECK(writeWorldYaml(reread) == text);
}

TEST_CASE("the writer refuses poses the format cannot express", "[world_io]") {
  World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  world.objects[0].X_WO = makePose({0.3, 0.2, 0.77}, {0.3, 0.0, 0.0});
  CHECK_THROWS_MATCHES(writeWorldYaml(world), WorldError,
                       Catch::Matchers::Message("<memory>: objects[0].pose: only rotations about +z "
                                                "can be written (fixtures, objects, surfaces and "
                                                "regions turn about z only)"));
}

// ---- reader errors ------------------------------------------------------------------------

TEST_CASE("each bad world fails with file, line, column, field and reason", "[world_io]") {
  REQUIRE(std::size(kBadWorlds) >= 25);
  for (const BadWorld& bad : kBadWorlds) {
    const std::filesystem::path file = kWorlds / "bad" / bad.file;
    INFO(file);
    REQUIRE(std::filesystem::exists(file));
    const std::string message = worldErrorOf([&] { loadWorldFile(file); });
    CHECK_THAT(message, Contains(bad.message));
    CHECK(message.rfind(file.string() + ":", 0) == 0);  // starts with the path as given
  }
}

TEST_CASE("every file in bad/ has its expected message", "[world_io]") {
  std::set<std::string> listed;
  for (const BadWorld& bad : kBadWorlds) listed.insert(bad.file);
  CHECK(listed.size() == std::size(kBadWorlds));
  for (const auto& file : yamlFiles(kWorlds / "bad")) {
    INFO(file);
    CHECK(listed.count(file.filename().string()) == 1);
  }
}

TEST_CASE("truncated world files throw WorldError or parse, nothing else", "[world_io]") {
  std::vector<std::string> problems;
  int parsed = 0;
  int rejected = 0;
  for (const char* dir : {"bad", "good"}) {
    for (const auto& file : yamlFiles(kWorlds / dir)) {
      const std::string text = readText(file);
      for (std::size_t length = 0; length <= text.size(); length += 7) {
        const std::string where = file.filename().string() + " cut at " + std::to_string(length);
        try {
          parseWorldYaml(std::string_view(text).substr(0, length), where);
          ++parsed;
        } catch (const WorldError& e) {
          ++rejected;
          if (std::string(e.what()).rfind(where + ":", 0) != 0) {
            problems.push_back(where + ": message without location: " + e.what());
          }
        } catch (const std::exception& e) {
          problems.push_back(where + ": " + e.what());
        } catch (...) {
          problems.push_back(where + ": unknown exception");
        }
      }
    }
  }
  INFO("parsed " << parsed << ", rejected " << rejected);
  CHECK(problems.empty());
  for (const std::string& problem : problems) UNSCOPED_INFO(problem);
  CHECK(rejected > 1000);
}

TEST_CASE("edited world files load or are refused naming file, line and field, nothing else", "[world_io]") {
  // a thousand seeded edits of good worlds, each loaded as `dashbed run` does (parse, robot
  // models, reach): a WorldError that starts with the file's name or a valid world
  const std::vector<std::string> odd{"",   "abc", "-1",    "0",     "1e309",   "-1e309", ".nan", ".inf",
                                     "[1, 2]", "{a: 1}", "[]", "{}", "null",  "~",     "true",    "'x'",
                                     "99999999999999999999", "1e-12", "0x10",  "'",     "[",       "&a", "*a"};
  const std::filesystem::path repo(DASHBED_SOURCE_ROOT);
  const std::vector<std::filesystem::path> files{
      kWorlds / "good/minimal.yaml", kWorlds / "good/shelf.yaml", repo / "worlds/default.yaml",
      repo / "worlds/handwritten/v05_shapes.yaml", repo / "worlds/handwritten/v04_object_goals.yaml"};
  const dashbed::test::EditedReads reads = dashbed::test::readEdited<WorldError>(
      1000, odd,
      [&](int trial) {
        const std::filesystem::path& file = files[static_cast<std::size_t>(trial) % files.size()];
        return std::pair{readText(file), file.stem().string() + "_edit_" + std::to_string(trial) + ".yaml"};
      },
      [](const std::string& text, const std::string& name) { validateWorld(parseWorldYaml(text, name)); });
  INFO("loaded " << reads.accepted << ", refused " << reads.refused);
  for (const std::string& problem : reads.problems) UNSCOPED_INFO(problem);
  CHECK(reads.problems.empty());
  CHECK(reads.refused > 500);
  CHECK(reads.accepted > 25);
}

TEST_CASE("unreadable world files name the path", "[world_io]") {
  const std::filesystem::path missing = kWorlds / "no_such_world.yaml";
  CHECK_THROWS_MATCHES(loadWorldFile(missing), WorldError,
                       Catch::Matchers::Message(missing.string() + ": cannot read the world file: no such file"));
  CHECK_THAT(worldErrorOf([&] { loadWorldFile(kWorlds); }),
             Contains(kWorlds.string() + ": cannot read the world file: it is a directory"));
}

TEST_CASE("inline YAML: file name in messages and a few more cases", "[world_io]") {
  const std::string head =
      "dashbed_world: 1\n"
      "name: inline\n"
      "robots: [{name: r0, model: ur5e_hande, base: {xyz: [0, 0, 0]}}]\n";
  SECTION("a valid world with nothing but a robot") {
    const World world = parseWorldYaml(head, "inline.yaml");
    CHECK(world.robots.size() == 1);
    CHECK(world.source_file.empty());
    CHECK(world.robots[0].where.file == "inline.yaml");
  }
  SECTION("an object resting on a hand-written surface, turned so its centre is just inside") {
    const World world = parseWorldYaml(
        head + "surfaces: [{name: pad, center: [1, 0, 0.5], size: [0.2, 0.1], yaw: 1.5707963267948966}]\n"
               "objects: [{name: c, pose: {xyz: [1, 0.099, 0.521]}}]\n",
        "inline.yaml");
    CHECK(world.objects.size() == 1);
  }
  SECTION("touching objects are fine, 1 mm is the limit") {
    CHECK_NOTHROW(parseWorldYaml(
        head + "surfaces: [{name: pad, center: [0, 0, 0], size: [1, 1]}]\n"
               "objects: [{name: a, pose: {xyz: [0, 0, 0.02]}}, {name: b, pose: {xyz: [0.0395, 0, 0.02]}}]\n",
        "inline.yaml"));
    CHECK_THROWS_WITH(
        parseWorldYaml(head + "surfaces: [{name: pad, center: [0, 0, 0], size: [1, 1]}]\n"
                              "objects: [{name: a, pose: {xyz: [0, 0, 0.02]}}, {name: b, pose: {xyz: [0.038, 0, 0.02]}}]\n",
                       "inline.yaml"),
        Contains("inline.yaml:5:65: objects[1].pose: 'b' overlaps object 'a' (line 5) by 2.0 mm"));
  }
  SECTION("a region name used by a bin fixture and by hand clashes") {
    CHECK_THROWS_WITH(
        parseWorldYaml(head + "fixtures: [{name: b, type: bin, size: [1, 1, 1], pose: {xyz: [5, 5, 0]}}]\n"
                              "regions: [{name: b, center: [0, 0, 0], size: [1, 1, 1]}]\n",
                       "inline.yaml"),
        Contains("inline.yaml:5:18: regions[0].name: duplicate name 'b' (also fixtures[0].name at line 4)"));
  }
  SECTION("a name with '/' is refused (reserved for derived surfaces)") {
    CHECK_THROWS_WITH(parseWorldYaml(head + "surfaces: [{name: table/top, center: [0, 0, 0], size: [1, 1]}]\n",
                                     "inline.yaml"),
                      Contains("inline.yaml:4:19: surfaces[0].name: expected a name of letters"));
  }
  SECTION("a key that is not a plain name") {
    CHECK_THROWS_WITH(parseWorldYaml(head + "[a, b]: 1\n", "inline.yaml"),
                      Contains("inline.yaml:4:1: (top level): keys must be plain names, got a list"));
  }
  SECTION("an object must rest on a surface at the right height, not just inside it") {
    CHECK_THROWS_WITH(
        parseWorldYaml(head + "surfaces: [{name: pad, center: [0, 0, 0], size: [1, 1]}]\n"
                              "objects: [{name: a, pose: {xyz: [0, 0, 0.0225]}}]\n",
                       "inline.yaml"),
        Contains("inline.yaml:5:27: objects[0].pose: 'a' does not rest on any stable surface"));
    CHECK_NOTHROW(parseWorldYaml(head + "surfaces: [{name: pad, center: [0, 0, 0], size: [1, 1]}]\n"
                                        "objects: [{name: a, pose: {xyz: [0, 0, 0.0215]}}]\n",
                                 "inline.yaml"));
  }
}

TEST_CASE("a home angle outside its joint's limits is a world error naming robots[i].home[j]", "[world_io]") {
  World world = loadWorldFile(kWorlds / "good/minimal.yaml");
  world.robots[0].home[5] = 7.0;  // wrist 3 turns +-2 pi
  CHECK_THROWS_MATCHES(validateWorld(world), WorldError,
                       Catch::Matchers::Message((kWorlds / "good/minimal.yaml").string() +
                                                ":6:5: robots[0].home[5]: wrist_3_joint at 7 rad is outside its "
                                                "limits [-6.28319, 6.28319]"));
}

TEST_CASE("formatLocation", "[world_io]") {
  CHECK(formatLocation({"w.yaml", 3, 7}) == "w.yaml:3:7");
  CHECK(formatLocation({"w.yaml", 0, 0}) == "w.yaml");
  CHECK(formatLocation({}) == "<memory>");
}

TEST_CASE("large worlds: overlaps, goals and names are found among thousands of elements", "[world_io]") {
  const std::string head =
      "dashbed_world: 1\n"
      "name: large\n"
      "robots: [{name: r0, model: ur5e_hande, base: {xyz: [0, 0, 0]}}]\n"
      "surfaces: [{name: floor, center: [0, 0, 0], size: [90, 90]}]\n"
      "regions: [{name: area, center: [40, 40, 0], size: [1, 1, 0.1]}]\n";
  // 3000 cubes 50 mm apart on rows of 60 (line 7 + i), each with its own goal
  const auto objects = [](int count, const std::string& last_pose) {
    std::string text = "objects:\n";
    for (int i = 0; i < count; ++i) {
      const std::string pose = i + 1 == count && !last_pose.empty()
                                   ? last_pose
                                   : std::string("[") + std::to_string(0.05 * (i % 60)) + ", " + std::to_string(0.05 * (i / 60)) + ", 0.02]";
      text += std::string("  - {name: c") + std::to_string(i) + ", pose: {xyz: " + pose + "}}\n";
    }
    return text;
  };
  const auto goals = [](int count) {
    std::string text = "goals:\n";
    for (int i = 0; i < count; ++i) text += "  - {object: c" + std::to_string(i) + ", region: area}\n";
    return text;
  };
  SECTION("all apart: the world reads") {
    const World world = parseWorldYaml(head + objects(3000, "") + goals(3000), "large.yaml");
    CHECK(world.objects.size() == 3000);
    CHECK(world.goals.size() == 3000);
  }
  SECTION("the last cube overlaps two early ones: the earlier is named") {
    // between c61 (0.05, 0.05) and c62 (0.10, 0.05), 10 mm into each
    const std::string text = head + objects(3000, "[0.075, 0.05, 0.02]") + goals(3000);
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "large.yaml"); }),
               Contains("large.yaml:3006:25: objects[2999].pose: 'c2999' overlaps object 'c61' (line 68) by 15.0 mm"));
  }
  SECTION("a cube far from the others in the list but next to one on the table") {
    const std::string text = head + objects(3000, "[2.95, -0.0395, 0.02]") + goals(3000);
    CHECK_NOTHROW(parseWorldYaml(text, "large.yaml"));  // touches c59 at (2.95, 0): 0.5 mm apart
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(head + objects(3000, "[2.95, -0.038, 0.02]") + goals(3000), "large.yaml"); }),
               Contains("objects[2999].pose: 'c2999' overlaps object 'c59' (line 66) by 2.0 mm"));
  }
  SECTION("the last goal repeats the first object's") {
    const std::string text = head + objects(3000, "") + goals(3000) + "  - {object: c0, region: area}\n";
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "large.yaml"); }),
               Contains("large.yaml:6008:14: goals[3000].object: object 'c0' already has a goal (goals[0] at line 3008)"));
  }
  SECTION("the last name repeats an early one") {
    const std::string text = head + objects(3000, "") + "  - {name: c7, pose: {xyz: [5, 5, 0.02]}}\n";
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "large.yaml"); }),
               Contains("large.yaml:3007:12: objects[3000].name: duplicate name 'c7' (also objects[7].name at line 14)"));
  }
  SECTION("more fixtures than the format allows") {
    std::string text = head + "fixtures:\n";
    for (int i = 0; i <= 1000; ++i) {
      text += "  - {name: f" + std::to_string(i) + ", type: box, size: [0.1, 0.1, 0.1], pose: {xyz: [" +
              std::to_string(i) + ", 10, 0]}}\n";
    }
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "large.yaml"); }),
               Contains("large.yaml:7:3: fixtures: at most 1000 entries, not 1001"));
  }
  SECTION("a map with many keys, one given twice") {
    std::string text = head + "physics: {";
    for (int i = 0; i < 2000; ++i) text += std::string("k") + std::to_string(i) + ": 1, ";
    text += "k5: 2}\n";
    CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "large.yaml"); }),
               Contains("physics.k5: duplicate key (first at line 6)"));
  }
}

TEST_CASE("aliases: a bad value is reported where the alias stands, naming the anchor", "[world_io]") {
  const std::string head =
      "dashbed_world: 1\n"
      "name: aliases\n"
      "robots:\n"
      "  - {name: r0, model: ur5e_hande, base: &mount {xyz: [0, 0, .nan]}}\n"
      "  - {name: r1, model: ur5e_hande, base: *mount}\n";
  CHECK_THAT(worldErrorOf([&] { parseWorldYaml(head, "a.yaml"); }),
             Contains("a.yaml:4:61: robots[0].base.xyz[2]: expected a finite number, got '.nan'"));
  const std::string reused =
      "dashbed_world: 1\n"
      "name: aliases\n"
      "robots:\n"
      "  - {name: r0, model: ur5e_hande, base: &mount {xyz: [0, 0, 0]}, home: &home [0, -1.5, 1.5, -1.5, -1.5, 0]}\n"
      "  - {name: r1, model: ur5e_hande, base: {xyz: [1, 0, 0]}, home: *home}\n"
      "surfaces: [{name: pad, center: [0, 0, 0], size: *home}]\n";
  CHECK_THAT(worldErrorOf([&] { parseWorldYaml(reused, "a.yaml"); }),
             Contains("a.yaml:6:49: surfaces[0].size: expected a list of 2 numbers, got 6 items (the value of alias "
                      "*home, anchored at line 4)"));
  const World world = parseWorldYaml(reused.substr(0, reused.find("surfaces")), "a.yaml");
  CHECK(world.robots[1].home == world.robots[0].home);
}

TEST_CASE("escapes in quoted YAML strings reach messages escaped", "[world_io]") {
  const std::string text =
      "dashbed_world: 1\n"
      "name: \"a\\0b\\e\"\n"
      "robots: [{name: r0, model: ur5e_hande, base: {xyz: [0, 0, 0]}}]\n";
  CHECK_THAT(worldErrorOf([&] { parseWorldYaml(text, "q.yaml"); }),
             Contains("q.yaml:2:7: name: expected a name of letters, digits, '_', '-' and '.', got 'a\\x00b\\x1B'"));
}
