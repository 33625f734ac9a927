#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "core/plan.h"
#include "text_mutations.h"

using namespace dashbed::core;
namespace fs = std::filesystem;

namespace {

const fs::path kPlans = fs::path(DASHBED_SOURCE_ROOT) / "tests" / "core" / "plans";

const std::array<std::string, 6> kJointNames{"shoulder_pan_joint", "shoulder_lift_joint",
                                             "elbow_joint",        "wrist_1_joint",
                                             "wrist_2_joint",      "wrist_3_joint"};
constexpr double kTwoPi = 6.283185307179586;
constexpr double kPi = 3.141592653589793;
// UR5e limits (UR's ROS 2 description, joint_limits.yaml): +-360 deg, elbow +-180 deg, 180 deg/s
const std::array<double, 6> kLower{-kTwoPi, -kTwoPi, -kPi, -kTwoPi, -kTwoPi, -kTwoPi};
const std::array<double, 6> kUpper{kTwoPi, kTwoPi, kPi, kTwoPi, kTwoPi, kTwoPi};
const std::array<double, 6> kMaxVelocity{kPi, kPi, kPi, kPi, kPi, kPi};

// the world the test plans are written for: two robots, four cubes, two bins
World testWorld() {
  World world;
  world.name = "sort_2r_4c_cross_s1";
  for (const char* name : {"r0", "r1"}) {
    RobotSpec robot;
    robot.name = name;
    robot.model = "ur5e_hande";
    world.robots.push_back(robot);
  }
  for (const char* name : {"cube_0", "cube_1", "cube_2", "cube_3"}) {
    ObjectSpec object;
    object.name = name;
    world.objects.push_back(object);
  }
  for (const char* name : {"bin_red", "bin_blue"}) {
    Region region;
    region.name = name;
    region.fixture = name;
    world.regions.push_back(region);
  }
  return world;
}

void validate(const Plan& plan, const std::string& file) {
  validatePlan(plan, testWorld(), kJointNames, kLower, kUpper, kMaxVelocity, file);
}

std::string readText(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::vector<fs::path> plansIn(const std::string& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kPlans / folder)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// bit-exact: round trips must keep every double, including -0.0
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  for (std::size_t i = 0; i < 6; ++i) {
    if (!same(a[i], b[i])) return false;
  }
  return true;
}

void requireSamePlan(const Plan& a, const Plan& b) {
  REQUIRE(a.world == b.world);
  REQUIRE(a.seed == b.seed);
  REQUIRE(a.trajectories.size() == b.trajectories.size());
  for (std::size_t r = 0; r < a.trajectories.size(); ++r) {
    const RobotTrajectory& ta = a.trajectories[r];
    const RobotTrajectory& tb = b.trajectories[r];
    REQUIRE(ta.robot == tb.robot);
    REQUIRE(ta.joint_names == tb.joint_names);
    REQUIRE(ta.points.size() == tb.points.size());
    for (std::size_t p = 0; p < ta.points.size(); ++p) {
      REQUIRE(same(ta.points[p].t, tb.points[p].t));
      REQUIRE(same(ta.points[p].q, tb.points[p].q));
      REQUIRE(ta.points[p].qd.has_value() == tb.points[p].qd.has_value());
      if (ta.points[p].qd) REQUIRE(same(*ta.points[p].qd, *tb.points[p].qd));
    }
  }
  REQUIRE(a.gripper.size() == b.gripper.size());
  for (std::size_t i = 0; i < a.gripper.size(); ++i) {
    REQUIRE(a.gripper[i].robot == b.gripper[i].robot);
    REQUIRE(same(a.gripper[i].t, b.gripper[i].t));
    REQUIRE(a.gripper[i].action == b.gripper[i].action);
    REQUIRE(same(a.gripper[i].force, b.gripper[i].force));
  }
  REQUIRE(a.actions.size() == b.actions.size());
  for (std::size_t i = 0; i < a.actions.size(); ++i) {
    REQUIRE(a.actions[i].type == b.actions[i].type);
    REQUIRE(a.actions[i].robot == b.actions[i].robot);
    REQUIRE(a.actions[i].receiver == b.actions[i].receiver);
    REQUIRE(a.actions[i].object == b.actions[i].object);
    REQUIRE(a.actions[i].region == b.actions[i].region);
    REQUIRE(same(a.actions[i].start, b.actions[i].start));
    REQUIRE(same(a.actions[i].end, b.actions[i].end));
  }
  REQUIRE(a.statistics == b.statistics);
}

// a valid plan with awkward numbers: random doubles of every magnitude, -0.0, subnormals
Plan randomPlan(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> exponent(-300, 2);
  const auto awkward = [&](double scale) {
    const double x = unit(rng);
    switch (rng() % 6) {
      case 0:
        return -0.0;
      case 1:
        return std::numeric_limits<double>::denorm_min() * static_cast<double>(rng() % 1000);
      case 2:
        return std::ldexp(x, exponent(rng));
      case 3:
        return 0.1 + 0.2;
      default:
        return scale * (2.0 * x - 1.0);
    }
  };
  Plan plan;
  plan.world = "w \"quoted\" \\ / \u00e9";
  plan.seed = rng();
  const int robots = 1 + static_cast<int>(rng() % 3);
  double t_end = 0.0;
  for (int r = 0; r < robots; ++r) {
    RobotTrajectory trajectory;
    trajectory.robot = "robot_" + std::to_string(r);
    trajectory.joint_names = kJointNames;
    double t = std::abs(awkward(1.0));
    const int points = 1 + static_cast<int>(rng() % 20);
    for (int p = 0; p < points; ++p) {
      TrajectoryPoint point;
      point.t = t;
      for (double& q : point.q) q = awkward(3.0);
      if (rng() % 2 == 0) {
        point.qd.emplace();
        for (double& qd : *point.qd) qd = awkward(3.0);
      }
      trajectory.points.push_back(point);
      t += 1e-3 + unit(rng);
    }
    t_end = std::max(t_end, trajectory.points.back().t);
    plan.trajectories.push_back(trajectory);
  }
  double t = 0.0;
  for (int i = 0; i < 6; ++i) {
    GripperCommand command;
    command.robot = "robot_" + std::to_string(i % robots);
    command.t = t;
    command.action = i % 2 == 0 ? GripperAction::kClose : GripperAction::kOpen;
    command.force = i % 3 == 0 ? 0.0 : 185.0 * unit(rng);
    plan.gripper.push_back(command);
    t += unit(rng);
  }
  double start = 0.0;
  for (int i = 0; i < 5; ++i) {
    PlanAction action;
    action.type = static_cast<ActionType>(i % 3);
    action.robot = "robot_0";
    if (action.type == ActionType::kHandoff) action.receiver = "robot_1";
    if (action.type == ActionType::kPlace) action.region = "bin";
    action.object = "cube_" + std::to_string(i);
    action.start = start;
    action.end = start + unit(rng);
    plan.actions.push_back(action);
    start += unit(rng);
  }
  plan.statistics = {{"times", {{"search", unit(rng)}, {"total", awkward(10.0)}}},
                     {"seed", plan.seed},
                     {"label", "\u00fc\n\t"},
                     {"list", {1, 2.5, "x", nullptr, true}}};
  return plan;
}

}  // namespace

TEST_CASE("good plans parse, validate and round trip", "[plan]") {
  const std::vector<fs::path> files = plansIn("good");
  REQUIRE(files.size() >= 5);
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    const Plan dut = loadPlanFile(file);
    REQUIRE_NOTHROW(validate(dut, file.string()));
    const std::string written = writePlanJson(dut);
    REQUIRE(writePlanJson(dut) == written);  // deterministic
    const Plan back = parsePlanJson(written, "written.json");
    requireSamePlan(dut, back);
    REQUIRE(writePlanJson(back) == written);  // canonical after one write
  }
}

TEST_CASE("canonical plan files are written back byte for byte", "[plan]") {
  for (const char* name : {"example.json", "empty_plan.json"}) {
    INFO(name);
    const std::string text = readText(kPlans / "good" / name);
    REQUIRE(writePlanJson(parsePlanJson(text, name)) == text);
  }
}

TEST_CASE("a place without a region sets the object aside and is written without one", "[plan]") {
  const Plan dut = loadPlanFile(kPlans / "good" / "set_aside_and_pick_up.json");
  REQUIRE(dut.actions.size() == 4);
  REQUIRE(dut.actions[1].type == ActionType::kPlace);
  REQUIRE(dut.actions[1].region.empty());
  REQUIRE(dut.actions[3].region == "bin_blue");
  const nlohmann::json written = nlohmann::json::parse(writePlanJson(dut));
  REQUIRE_FALSE(written["actions"][1].contains("region"));
  REQUIRE(written["actions"][3]["region"] == "bin_blue");
}

TEST_CASE("the example plan reads as written", "[plan]") {
  const Plan dut = loadPlanFile(kPlans / "good" / "example.json");
  CHECK(dut.world == "sort_2r_4c_cross_s1");
  CHECK(dut.seed == 1);
  REQUIRE(dut.trajectories.size() == 2);
  CHECK(dut.trajectories[1].robot == "r1");
  CHECK(dut.trajectories[0].joint_names == kJointNames);
  REQUIRE(dut.trajectories[0].points.size() == 4);
  CHECK(dut.trajectories[0].points[1].t == 1.5);
  CHECK(dut.trajectories[0].points[1].q[1] == -1.2708);
  REQUIRE(dut.trajectories[0].points[1].qd.has_value());
  CHECK((*dut.trajectories[0].points[1].qd)[0] == 0.25);
  CHECK_FALSE(dut.trajectories[0].points[0].qd.has_value());
  REQUIRE(dut.gripper.size() == 4);
  CHECK(dut.gripper[0].action == GripperAction::kClose);
  CHECK(dut.gripper[0].force == 60.0);
  CHECK(dut.gripper[1].force == 0.0);
  CHECK(dut.gripper[2].action == GripperAction::kOpen);
  REQUIRE(dut.actions.size() == 3);
  CHECK(dut.actions[1].type == ActionType::kHandoff);
  CHECK(dut.actions[1].robot == "r0");
  CHECK(dut.actions[1].receiver == "r1");
  CHECK(dut.actions[2].type == ActionType::kPlace);
  CHECK(dut.actions[2].region == "bin_red");
  CHECK(dut.actions[0].region.empty());
  CHECK(dut.statistics["hypergraph"]["vertices"] == 412);
  CHECK(dut.duration() == 8.5);
}

TEST_CASE("optional fields take their defaults", "[plan]") {
  const Plan dut = loadPlanFile(kPlans / "good" / "minimal.json");
  CHECK(dut.seed == 0);
  CHECK(dut.statistics == nlohmann::json::object());
  CHECK(dut.gripper.empty());
  CHECK(dut.actions.empty());
  CHECK(dut.duration() == 0.0);
  const Plan large_seed = loadPlanFile(kPlans / "good" / "pick_place_one_robot.json");
  CHECK(large_seed.seed == std::numeric_limits<std::uint64_t>::max());
  CHECK(large_seed.gripper[0].force == 185.0);
}

TEST_CASE("random plans round trip bit for bit", "[plan]") {
  std::mt19937_64 rng(20240611);
  for (int i = 0; i < 200; ++i) {
    const Plan dut = randomPlan(rng);
    REQUIRE_NOTHROW(checkPlanStructure(dut, "random"));
    const std::string written = writePlanJson(dut);
    requireSamePlan(dut, parsePlanJson(written, "random.json"));
    REQUIRE(writePlanJson(dut) == written);
  }
}

TEST_CASE("the writer's layout: key order, indent, one-line number arrays", "[plan]") {
  const std::string text = writePlanJson(loadPlanFile(kPlans / "good" / "example.json"));
  std::size_t previous = 0;
  for (const char* key : {"\"dashbed_plan\": 1", "\"world\"", "\"seed\"", "\"robots\"",
                          "\"gripper\"", "\"actions\"", "\"statistics\""}) {
    const std::size_t at = text.find(std::string("\n  ") + key);
    INFO(key);
    REQUIRE(at != std::string::npos);
    REQUIRE(at >= previous);
    previous = at;
  }
  CHECK(text.rfind("{\n  \"dashbed_plan\": 1,\n", 0) == 0);
  CHECK(text.find("\"q\": [0.5, -1.2708, 1.3708, -1.5708, -1.5708, 0.0]") != std::string::npos);
  CHECK(text.find("\"giver\": \"r0\",\n      \"receiver\": \"r1\"") != std::string::npos);
  CHECK(text.back() == '\n');
  CHECK(text.find('\t') == std::string::npos);
}

TEST_CASE("duration is the last point, gripper command or action end", "[plan]") {
  Plan dut;
  CHECK(dut.duration() == 0.0);
  RobotTrajectory trajectory;
  trajectory.robot = "r0";
  trajectory.points = {{0.0, {}, std::nullopt}, {2.0, {}, std::nullopt}};
  dut.trajectories.push_back(trajectory);
  CHECK(dut.duration() == 2.0);
  dut.gripper.push_back({"r0", 3.5, GripperAction::kClose, 0.0});
  CHECK(dut.duration() == 3.5);
  PlanAction action;
  action.end = 4.25;
  dut.actions.push_back(action);
  CHECK(dut.duration() == 4.25);
}

// Every file in plans/bad has an entry here: the stage that must reject it and the message
// after "FILE: ". Stage "parse" files fail parsePlanJson; "validate" files parse and fail
// validatePlan against testWorld().
TEST_CASE("bad plans are rejected with the field's JSON pointer", "[plan]") {
  struct BadPlan {
    std::string stage;
    std::string message;
  };
  const std::string top_keys = "dashbed_plan, world, seed, robots, gripper, actions, statistics";
  // statistics_too_deep: {"a": [[[...]]]} nested 300 arrays deep on line 99, which starts
  // '  "statistics": {"a": ': the document, statistics, "a" and 253 arrays make 256 levels, so
  // the 254th '[' (column 23 + 253 = 276 is the 253rd) is the one refused
  const std::map<std::string, BadPlan> expected{
      {"invalid_json",
       {"parse",
        "/: invalid JSON: parse error at line 4, column 14: syntax error while parsing "
        "value - unexpected '}'; expected '[', '{', or a literal (byte 71)"}},
      {"q_overflow",
       {"parse", "/: invalid JSON: number overflow parsing '1e400' at line 16, column 17"}},
      {"not_object", {"parse", "/: expected a JSON object, got an array"}},
      {"missing_version",
       {"parse", "/dashbed_plan: missing: not a dashbed plan (expected \"dashbed_plan\": 1)"}},
      {"version_2",
       {"parse", "/dashbed_plan: unsupported plan format version 2 (this build reads version 1)"}},
      {"version_string", {"parse", "/dashbed_plan: expected the integer 1, got a string \"1\""}},
      {"utf16",
       {"parse",
        "/: line 1, column 1: the file is UTF-16 (it starts with the byte-order mark FF FE); dashbed reads UTF-8 text"}},
      {"unknown_top_key", {"parse", "/comment: unknown key (expected " + top_keys + ")"}},
      {"key_needs_escaping", {"parse", "/a~1b~0c: unknown key (expected " + top_keys + ")"}},
      {"duplicate_key", {"parse", "/robots/1/name: duplicate key"}},
      {"missing_robots", {"parse", "/robots: missing"}},
      {"world_number", {"parse", "/world: expected a string, got a number"}},
      {"empty_world", {"parse", "/world: empty name"}},
      {"seed_negative", {"parse", "/seed: expected a non-negative integer, got -1"}},
      {"seed_fraction", {"parse", "/seed: expected a non-negative integer, got 1.5"}},
      {"unknown_point_key", {"parse", "/robots/0/points/1/qdd: unknown key (expected t, q, qd)"}},
      {"joint_names_five", {"parse", "/robots/0/joint_names: expected 6 joint names, got 5"}},
      {"q_five", {"parse", "/robots/0/points/1/q: expected 6 joint positions, got 5"}},
      {"q_string", {"parse", "/robots/0/points/0/q/2: expected a number, got a string"}},
      {"qd_seven", {"parse", "/robots/1/points/2/qd: expected 6 joint velocities, got 7"}},
      {"t_null", {"parse", "/robots/1/points/2/t: expected a number, got null"}},
      {"negative_time", {"parse", "/robots/0/points/0/t: negative time -0.5 s"}},
      {"times_not_increasing",
       {"parse", "/robots/0/points/2/t: times must increase (1.5 after 1.5)"}},
      {"no_points", {"parse", "/robots/1/points: a robot needs at least one point"}},
      {"duplicate_robot", {"parse", "/robots/1/name: duplicate robot 'r0' (also /robots/0)"}},
      {"gripper_command",
       {"parse", "/gripper/0/command: unknown command 'grab' (expected open or close)"}},
      {"force_too_high",
       {"parse",
        "/gripper/0/force: 200 N outside [0, 185] N (0: the world's grip force; "
        "185 N: the Hand-E maximum)"}},
      {"force_negative",
       {"parse",
        "/gripper/1/force: -5 N outside [0, 185] N (0: the world's grip force; "
        "185 N: the Hand-E maximum)"}},
      {"gripper_unsorted",
       {"parse", "/gripper/2/t: gripper commands must be sorted by time (4 after 4.5)"}},
      {"gripper_same_time",
       {"parse", "/gripper/3/t: robot 'r0' already has a gripper command at 5 s (/gripper/2)"}},
      {"action_type",
       {"parse", "/actions/0/type: unknown action type 'push' (expected pick, place or handoff)"}},
      {"handoff_no_receiver",
       {"parse", "/actions/1/receiver: missing (a handoff names its giver and receiver)"}},
      {"handoff_robot_key",
       {"parse",
        "/actions/1/robot: unknown key (expected type, giver, receiver, object, start, "
        "end)"}},
      {"place_empty_region",
       {"parse", "/actions/2/region: a region name must not be empty (leave the field out to set the object aside)"}},
      {"pick_with_region",
       {"parse", "/actions/0/region: unknown key (expected type, robot, object, start, end)"}},
      {"end_before_start", {"parse", "/actions/0/end: ends at 0.5 s, before its start 1 s"}},
      {"handoff_self",
       {"parse",
        "/actions/1/receiver: the receiver is the giver 'r0'; a handoff needs two "
        "robots"}},
      {"actions_unsorted",
       {"parse", "/actions/2/start: actions must be sorted by start time (2 after 3)"}},
      {"statistics_array", {"parse", "/statistics: expected an object, got an array"}},
      {"statistics_too_deep", {"parse", "/: line 99, column 277: nested deeper than 256 levels"}},
      {"time_beyond_a_day", {"parse", "/robots/0/points/3/t: time 1e+07 s beyond a day (86400 s)"}},
      // against the world
      {"wrong_world",
       {"validate",
        "/world: the plan is for world 'sort_2r_4c_cross_s2', not "
        "'sort_2r_4c_cross_s1'"}},
      {"unknown_robot",
       {"validate", "/robots/1/name: unknown robot 'r2' (world 'sort_2r_4c_cross_s1' has r0, r1)"}},
      {"name_with_nul",
       {"validate", "/robots/1/name: unknown robot 'r\\x00\\x1B2' (world 'sort_2r_4c_cross_s1' has r0, r1)"}},
      {"unknown_gripper_robot",
       {"validate",
        "/gripper/1/robot: unknown robot 'r7' (world 'sort_2r_4c_cross_s1' has r0, "
        "r1)"}},
      {"unknown_receiver",
       {"validate",
        "/actions/1/receiver: unknown robot 'r5' (world 'sort_2r_4c_cross_s1' has "
        "r0, r1)"}},
      {"unknown_object",
       {"validate",
        "/actions/0/object: unknown object 'cube_9' (world 'sort_2r_4c_cross_s1' "
        "has cube_0, cube_1, cube_2, cube_3)"}},
      {"unknown_region",
       {"validate",
        "/actions/2/region: unknown region 'bin_purple' (world "
        "'sort_2r_4c_cross_s1' has bin_red, bin_blue)"}},
      {"joint_names_mismatch",
       {"validate",
        "/robots/0/joint_names/2: expected 'elbow_joint', got 'elbow' (the model's "
        "arm joints in order: shoulder_pan_joint, shoulder_lift_joint, elbow_joint, "
        "wrist_1_joint, wrist_2_joint, wrist_3_joint)"}},
      {"joint_names_swapped",
       {"validate",
        "/robots/1/joint_names/0: expected 'shoulder_pan_joint', got "
        "'shoulder_lift_joint' (the model's arm joints in order: shoulder_pan_joint, "
        "shoulder_lift_joint, elbow_joint, wrist_1_joint, wrist_2_joint, "
        "wrist_3_joint)"}},
      {"q_outside_limits",
       {"validate",
        "/robots/0/points/2/q/2: elbow_joint at 3.5 rad outside its limits "
        "[-3.14159, 3.14159] rad"}},
      {"too_fast",
       {"validate",
        "/robots/0/points/1: shoulder_pan_joint moves 5 rad in 1.5 s from point 0: "
        "3.33333 rad/s above its limit 3.14159 rad/s"}},
      {"qd_too_fast",
       {"validate",
        "/robots/1/points/1/qd/4: wrist_2_joint velocity -3.5 rad/s above its limit "
        "3.14159 rad/s"}},
      {"action_after_end",
       {"validate",
        "/actions/2/end: ends at 9 s, after the plan's last trajectory point or "
        "gripper command at 8.5 s"}},
  };

  const std::vector<fs::path> files = plansIn("bad");
  REQUIRE(files.size() == expected.size());
  int parse_count = 0;
  int validate_count = 0;
  for (const fs::path& file : files) {
    const std::string name = file.stem().string();
    INFO(name);
    const auto entry = expected.find(name);
    REQUIRE(entry != expected.end());
    const std::string message = file.string() + ": " + entry->second.message;
    if (entry->second.stage == "parse") {
      ++parse_count;
      REQUIRE_THROWS_MATCHES(loadPlanFile(file), PlanError, Catch::Matchers::Message(message));
    } else {
      ++validate_count;
      Plan plan;
      REQUIRE_NOTHROW(plan = loadPlanFile(file));
      REQUIRE_THROWS_MATCHES(validate(plan, file.string()), PlanError,
                             Catch::Matchers::Message(message));
    }
  }
  CHECK(parse_count >= 20);
  CHECK(validate_count >= 10);
}

TEST_CASE("plans built in memory get the same structural checks", "[plan]") {
  const Plan good = loadPlanFile(kPlans / "good" / "example.json");
  const auto message = [](const std::string& what) {
    return Catch::Matchers::Message("mem: " + what);
  };

  Plan dut = good;
  dut.trajectories[0].points[1].q[3] = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/robots/0/points/1/q/3: not a finite number (nan)"));
  // validatePlan runs the structural checks too
  REQUIRE_THROWS_MATCHES(validate(dut, "mem"), PlanError,
                         message("/robots/0/points/1/q/3: not a finite number (nan)"));

  dut = good;
  dut.trajectories[1].points[2].qd = std::array<double, 6>{};
  (*dut.trajectories[1].points[2].qd)[5] = -std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/robots/1/points/2/qd/5: not a finite number (-inf)"));

  dut = good;
  dut.actions[0].end = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/actions/0/end: not a finite number (inf)"));

  dut = good;
  dut.actions[0].region = "bin_red";
  REQUIRE_THROWS_MATCHES(
      checkPlanStructure(dut, "mem"), PlanError,
      message("/actions/0/region: only place actions have a region, this is a pick"));

  dut = good;
  dut.actions[2].receiver = "r0";
  REQUIRE_THROWS_MATCHES(
      checkPlanStructure(dut, "mem"), PlanError,
      message("/actions/2/receiver: only handoffs have a receiver, this is a place"));

  dut = good;
  dut.actions[1].receiver.clear();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/actions/1/receiver: empty name"));

  dut = good;
  dut.actions[1].robot.clear();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/actions/1/giver: empty name"));

  dut = good;
  dut.gripper[0].force = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_MATCHES(checkPlanStructure(dut, "mem"), PlanError,
                         message("/gripper/0/force: nan N outside [0, 185] N (0: the world's grip "
                                 "force; 185 N: the Hand-E maximum)"));
}

TEST_CASE("limits are checked with their documented slack", "[plan]") {
  const Plan good = loadPlanFile(kPlans / "good" / "example.json");
  Plan dut = good;
  // exactly at a position limit passes
  dut.trajectories[0].points[3].q[2] = kPi;
  dut.trajectories[0].points[3].t = 6.0;
  REQUIRE_NOTHROW(validate(dut, "mem"));

  // r0, point 1 -> 2: 1.5 s; shoulder_pan moves 0.5 * 1.5 * limit * factor
  const auto withSpeed = [&](double factor) {
    Plan plan = good;
    TrajectoryPoint& point = plan.trajectories[0].points[2];
    point.q[0] = plan.trajectories[0].points[1].q[0] + kPi * factor * 1.5;
    plan.trajectories[0].points[3].q[0] = point.q[0];  // keep the next segment slow
    return plan;
  };
  REQUIRE_NOTHROW(validate(withSpeed(1.0), "mem"));
  REQUIRE_NOTHROW(validate(withSpeed(1.009), "mem"));
  REQUIRE_THROWS_WITH(
      validate(withSpeed(1.011), "mem"),
      Catch::Matchers::StartsWith("mem: /robots/0/points/2: shoulder_pan_joint moves"));
}

TEST_CASE("edited plan files parse and validate or are refused naming the file, nothing else", "[plan]") {
  const std::vector<std::string> odd{"",   "nan", "\"x\"", "\"\"", "-1", "0", "1e309", "-1e309", "[]", "{}", "null",
                                     "true", "[1, 2]", "99999999999999999999", "1e-12", "-0", "{", "]", "\"r1\""};
  const dashbed::test::EditedReads reads = dashbed::test::readEdited<PlanError>(
      1000, odd,
      [](int trial) {
        const std::string name = trial % 2 == 0 ? "example.json" : "pick_place_one_robot.json";
        return std::pair{readText(kPlans / "good" / name), "edit_" + std::to_string(trial) + "_" + name};
      },
      [](const std::string& text, const std::string& name) { validate(parsePlanJson(text, name), name); });
  INFO("accepted " << reads.accepted << ", refused " << reads.refused);
  for (const std::string& problem : reads.problems) UNSCOPED_INFO(problem);
  CHECK(reads.problems.empty());
  CHECK(reads.refused > 500);
  CHECK(reads.accepted > 25);
}

TEST_CASE("unreadable files and empty text", "[plan]") {
  const fs::path missing = kPlans / "no_such_plan.json";
  REQUIRE_THROWS_MATCHES(
      loadPlanFile(missing), PlanError,
      Catch::Matchers::Message(missing.string() +
                               ": cannot read the plan file: no such file"));
  REQUIRE_THROWS_WITH(
      parsePlanJson("", "empty.json"),
      Catch::Matchers::StartsWith("empty.json: /: invalid JSON: parse error at line 1, column 1"));
  REQUIRE_THROWS_WITH(parsePlanJson("null", ""),
                      Catch::Matchers::Equals("<memory>: /: expected a JSON object, got null"));
}

TEST_CASE("enum names", "[plan]") {
  CHECK(toString(ActionType::kPick) == "pick");
  CHECK(toString(ActionType::kPlace) == "place");
  CHECK(toString(ActionType::kHandoff) == "handoff");
  CHECK(toString(GripperAction::kOpen) == "open");
  CHECK(toString(GripperAction::kClose) == "close");
}
