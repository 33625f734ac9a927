// Plans made elsewhere: scripted plans exported as ROS 2 YAML and CSV, read back without their
// actions, get the same verdicts as with them; bad files are refused naming file, line and field.

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/asset_paths.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tools/export/foreign_plan.h"
#include "tools/export/plan_export.h"
#include "tools/script/scripted_plan.h"

using namespace dashbed;

namespace {

const std::array<std::string, 6> kJoints{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                         "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};

std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("dashbed_test_foreign_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

/// The world with only cube_0's goal, into bin_red.
const core::LoadedWorld& world() {
  static const core::LoadedWorld loaded = [] {
    core::World w = core::loadWorldFile(core::defaultWorldPath());
    w.goals = {core::Goal{"cube_0", "", "bin_red", {}}};
    return core::validateWorld(std::move(w));
  }();
  return loaded;
}

/// The plan written in `format` ("ros2" or "csv") into `dir` and read back.
core::Plan roundTrip(const core::Plan& plan, const std::string& format, const std::filesystem::path& dir) {
  const exporting::ExportTimeline timeline = exporting::exportTimeline(plan, *world().world);
  const auto files = format == "csv" ? exporting::exportCsv(timeline, {}) : exporting::exportRos2(timeline, {});
  for (const exporting::ExportFile& file : files) write(dir / file.name, file.text);
  std::vector<exporting::ForeignTrajectory> robots;
  for (const core::RobotSpec& robot : world().world->robots) {
    if (format == "csv") {
      robots.push_back({robot.name, (dir / (robot.name + ".csv")).string(), ""});
    } else {
      robots.push_back({robot.name, (dir / (robot.name + ".trajectory.yaml")).string(),
                        (dir / (robot.name + ".gripper.yaml")).string()});
    }
  }
  return exporting::readForeignPlan(*world().world, kJoints, robots);
}

void requireSameVerdicts(const sim::Report& planned, const sim::Report& inferred) {
  CHECK_FALSE(planned.actions_inferred);
  CHECK(inferred.actions_inferred);
  REQUIRE(inferred.actions.size() == planned.actions.size());
  for (std::size_t i = 0; i < planned.actions.size(); ++i) {
    INFO(planned.actions[i].id << ": " << planned.actions[i].failure << " / " << inferred.actions[i].failure);
    CHECK(inferred.actions[i].id == planned.actions[i].id);
    CHECK(inferred.actions[i].verdict == planned.actions[i].verdict);
    // the windows come from the motions around the gripper commands
    CHECK(inferred.actions[i].planned_start == Approx(planned.actions[i].planned_start).margin(0.05));
    CHECK(inferred.actions[i].planned_end == Approx(planned.actions[i].planned_end).margin(0.05));
  }
  CHECK(inferred.execution_verdict == planned.execution_verdict);
  CHECK(inferred.passed() == planned.passed());
}

}  // namespace

TEST_CASE("a pick, handoff and place made elsewhere is judged as the plan with its actions", "[foreign][long]") {
  const core::Plan plan =
      tools::planFromScript(world(), "r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  const sim::Report planned = sim::runPlan(*world().world, *world().robots, plan, "plan");
  REQUIRE(planned.passed());
  for (const std::string format : {"ros2", "csv"}) {
    INFO(format);
    const core::Plan foreign = roundTrip(plan, format, scratch("handoff_" + format));
    CHECK(foreign.actions.empty());
    CHECK(foreign.gripper.size() >= plan.gripper.size() - 2);  // at most the redundant first opens left out
    requireSameVerdicts(planned, sim::runPlan(*world().world, *world().robots, foreign, format));
  }
}

TEST_CASE("a place beside its goal made elsewhere fails as the plan with its actions does", "[foreign][long]") {
  const core::Plan plan = tools::planFromScript(world(), "r1 picks cube_0; r1 hands cube_0 to r0; "
                                                         "r0 places cube_0 in bin_red offset 0 0.15 0");
  const sim::Report planned = sim::runPlan(*world().world, *world().robots, plan, "plan");
  REQUIRE_FALSE(planned.passed());
  const core::Plan foreign = roundTrip(plan, "csv", scratch("beside"));
  const sim::Report inferred = sim::runPlan(*world().world, *world().robots, foreign, "csv");
  requireSameVerdicts(planned, inferred);
  CHECK(inferred.actions.back().region == "bin_red");
}

TEST_CASE("a close on nothing infers no action", "[foreign][long]") {
  core::Plan plan = tools::planFromScript(world(), "r1 picks cube_0 offset 0.1 0 0; r1 moves home");
  plan.actions.clear();
  const sim::Report report = sim::runPlan(*world().world, *world().robots, plan, "plan");
  CHECK(report.actions_inferred);
  CHECK(report.actions.empty());
}

TEST_CASE("a bad trajectory file is refused naming file, line and field", "[foreign]") {
  const std::filesystem::path dir = scratch("bad");
  const auto refused = [&](const std::string& name, const std::string& text, const std::string& expected) {
    write(dir / name, text);
    INFO(name);
    CHECK_THROWS_WITH(exporting::readForeignPlan(*world().world, kJoints, {{"r0", (dir / name).string(), ""}}),
                      Catch::Matchers::StartsWith((dir / name).string() + expected));
  };
  const std::string header =
      "t,shoulder_pan_joint,shoulder_lift_joint,elbow_joint,wrist_1_joint,wrist_2_joint,wrist_3_joint\n";
  refused("no_wrist.csv", "t,shoulder_pan_joint\n0,0\n", ":1: (header): missing column 'shoulder_lift_joint'");
  refused("word.csv", header + "0,0,-1.57,1.57,-1.57,-1.57,0\n0.5,0,-1.57,oops,-1.57,-1.57,0\n",
          ":3: elbow_joint: expected a finite number, got 'oops'");
  refused("back.csv", header + "0,0,-1.57,1.57,-1.57,-1.57,0\n0,0,-1.57,1.57,-1.57,-1.57,0\n",
          ":3: t: times must increase strictly");
  refused("short.csv", header + "0,0,-1.57\n", ":2: (row): 3 cells for 7 columns");
  refused("names.yaml", "joint_names: [a, b]\npoints: []\n", ":1: joint_names: unknown joint 'a'");
  refused("time.yaml",
          "joint_names: [shoulder_pan_joint, shoulder_lift_joint, elbow_joint, wrist_1_joint, wrist_2_joint, "
          "wrist_3_joint]\npoints:\n  - positions: [0, -1.57, 1.57, -1.57, -1.57, 0]\n"
          "    time_from_start: {sec: 0, nanosec: x}\n",
          ":4: points[0].time_from_start.nanosec: expected a finite number, got 'x'");
  // found by fuzzing: a name that is a map escaped as yaml-cpp's own "bad conversion"
  refused("map_name.yaml", "trajectory:\n  joint_names: [a, {b: c}]\n  points: []\n",
          ":2: joint_names[1]: expected a name");
  refused("utf16.yaml", std::string("\xFF\xFEj\0", 4), ":1: (text): the file is UTF-16");
  refused("plan.txt", "", ": expected a .csv, .yaml or .yml trajectory file");
  CHECK_THROWS_WITH(exporting::readForeignPlan(*world().world, kJoints, {{"r9", (dir / "back.csv").string(), ""}}),
                    Catch::Matchers::Contains("the world has no robot 'r9'"));
}
