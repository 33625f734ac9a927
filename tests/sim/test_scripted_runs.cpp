// End-to-end checks of the simulator and its monitor with scripted plans on the default world
// (2 robots facing each other, 4 cubes, cross starts): good plans pass, each kind of bad plan
// fails with the right reason, and reports are reproducible.

#include <catch2/catch.hpp>

#include <numbers>
#include <string>

#include "core/world_loader.h"
#include "sim/report.h"
#include "sim/run_plan.h"
#include "tools/scripted_plan.h"

using namespace dashbed;

namespace {

const core::LoadedWorld& defaultWorld() {
  static const core::LoadedWorld world = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  return world;
}

sim::Report simulate(const std::string& script) {
  const core::LoadedWorld& world = defaultWorld();
  const core::Plan plan = tools::planFromScript(world, script);
  sim::validatePlanForWorld(plan, *world.world, *world.robots, "script");
  return sim::runPlan(*world.world, *world.robots, plan, "script");
}

const sim::ActionReport& action(const sim::Report& report, const std::string& id) {
  for (const auto& a : report.actions) {
    if (a.id == id) return a;
  }
  FAIL("no action " << id);
  return report.actions.front();
}

bool hasEvent(const sim::Report& report, const std::string& kind) {
  for (const auto& e : report.events) {
    if (e.kind == kind) return true;
  }
  return false;
}

/// A joint configuration of robot r putting the TCP at p_W pointing straight down.
std::string downAt(int r, const Eigen::Vector3d& p_W) {
  const auto& robot = (*defaultWorld().robots)[r];
  core::Pose X_WT = core::Pose::Identity();
  X_WT.linear() = Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  X_WT.translation() = p_W;
  const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
  REQUIRE(!solutions.empty());
  std::string q;
  for (double v : solutions.front()) q += " " + std::to_string(v);
  return q;
}

}  // namespace

TEST_CASE("scripted pick, lift and place of one cube passes", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 places cube_0 in bin_green");
  INFO(sim::writeReportJson(report));
  CHECK(action(report, "pick cube_0 by r1").verdict == sim::Verdict::kPassed);
  CHECK(action(report, "place cube_0 in bin_green by r1").verdict == sim::Verdict::kPassed);
  CHECK(report.passed());
}

TEST_CASE("scripted handoff between two robots passes", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  INFO(sim::writeReportJson(report));
  const auto& handoff = action(report, "handoff cube_0 from r1 to r0");
  CHECK(handoff.verdict == sim::Verdict::kPassed);
  CHECK(report.passed());
}

TEST_CASE("closing 3 cm beside the cube is a failed grasp", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0 offset 0 0.03 0; r1 moves home");
  const auto& pick = action(report, "pick cube_0 by r1");
  INFO(pick.failure);
  CHECK(pick.verdict == sim::Verdict::kFailed);
  CHECK_THAT(pick.failure, Catch::Matchers::Contains("grasp:"));
  CHECK(!report.passed());
}

TEST_CASE("opening the gripper mid-carry is reported as a drop", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 opens; r1 moves home");
  REQUIRE(hasEvent(report, "drop"));
  const auto& pick = action(report, "pick cube_0 by r1");
  CHECK_THAT(pick.failure, Catch::Matchers::Contains("drop"));
  CHECK(!report.passed());
}

TEST_CASE("a trajectory into the table is an unplanned contact", "[sim][scripted]") {
  const sim::Report report = simulate("r0 moves to" + downAt(0, {-0.3, 0.0, 0.70}) + "; r0 moves home");
  CHECK(hasEvent(report, "robot-fixture contact"));
  CHECK(report.execution_verdict == sim::Verdict::kFailed);
  CHECK_THAT(report.execution_failure, Catch::Matchers::Contains("touches table"));
}

TEST_CASE("a place outside the goal region fails the placement", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 places cube_0 in bin_green offset 0.15 0 0");
  const auto& place = action(report, "place cube_0 in bin_green by r1");
  INFO(place.failure);
  CHECK(place.verdict == sim::Verdict::kFailed);
  CHECK_THAT(place.failure, Catch::Matchers::Contains("outside bin_green"));
}

TEST_CASE("an arm sweeping through a resting cube knocks it", "[sim][scripted]") {
  // cube_1 rests at about (-0.405, -0.121); r0 sweeps its open gripper across it 15 mm up
  const sim::Report report = simulate("r0 moves to" + downAt(0, {-0.405, -0.221, 0.785}) + "; r0 moves to" +
                                      downAt(0, {-0.405, -0.021, 0.785}) + "; r0 moves home");
  REQUIRE(hasEvent(report, "knocked object"));
  CHECK_THAT(report.execution_failure, Catch::Matchers::Contains("cube_1"));
}

TEST_CASE("two runs of the same plan give byte-identical reports", "[sim][scripted]") {
  const std::string script = "r1 picks cube_2; r1 hands cube_2 to r0; r0 places cube_2 in bin_blue";
  const std::string first = sim::writeReportJson(simulate(script));
  const std::string second = sim::writeReportJson(simulate(script));
  CHECK(first == second);
}
