// End-to-end checks of the simulator and its monitor with scripted plans on the default world
// (2 robots facing each other, 4 cubes, cross starts): good plans pass, each kind of bad plan
// fails with the right reason, and reports are reproducible.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "core/world_loader.h"
#include "sim/plan_executor.h"
#include "sim/report.h"
#include "sim/run_plan.h"
#include "sim/simulation.h"
#include "tests/sim/sim_test_worlds.h"
#include "tools/script/scripted_plan.h"

using namespace dashbed;

namespace {

// the scripts move one or two cubes: the goals of the others are left out
const core::LoadedWorld& defaultWorld() { return test::defaultWorldWithoutGoals(); }

sim::Report simulate(const std::string& script, const core::LoadedWorld& world = defaultWorld()) {
  const core::Plan plan = tools::planFromScript(world, script);
  core::validatePlanForWorld(plan, *world.world, *world.robots, "script");
  return sim::runPlan(*world.world, *world.robots, plan, "script");
}

const sim::ActionReport& action(const sim::Report& report, const std::string& id) {
  for (const auto& a : report.actions) {
    if (a.id == id) return a;
  }
  FAIL("no action " << id);
  return report.actions.front();
}

/// The measurement of `report` named `name` (nullptr when there is none).
const sim::Measurement* measurement(const sim::ActionReport& report, const std::string& name) {
  for (const sim::Measurement& m : report.measurements) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

const sim::ExecutionEvent* event(const sim::Report& report, const std::string& kind) {
  for (const auto& e : report.events) {
    if (e.kind == kind) return &e;
  }
  return nullptr;
}

bool hasEvent(const sim::Report& report, const std::string& kind) { return event(report, kind) != nullptr; }

std::string downAt(int r, const Eigen::Vector3d& p_W) { return test::downAt(defaultWorld(), r, p_W); }

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

TEST_CASE("a run whose actions all pass fails when a cube the goals send to a bin is left out", "[sim][scripted]") {
  const std::string script = "r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red";
  // every cube of the default world has a goal: cube_0 reaches it, the other three do not
  core::World all = core::loadWorldFile(core::defaultWorldPath());
  const core::LoadedWorld with_goals = core::validateWorld(all);
  const sim::Report report = simulate(script, with_goals);
  INFO(report.execution_failure);
  CHECK(report.failedCount() == 0);
  CHECK_FALSE(report.passed());
  CHECK_THAT(report.execution_failure, Catch::Matchers::Contains("goal: cube_1 ends") &&
                                           Catch::Matchers::Contains("outside bin_green"));
  CHECK_THAT(report.execution_failure, !Catch::Matchers::Contains("goal: cube_0"));
  // with cube_0's goal alone, the same run passes
  all.goals = {core::Goal{"cube_0", "", "bin_red", {}}};
  const core::LoadedWorld cube_0_goal = core::validateWorld(all);
  CHECK(simulate(script, cube_0_goal).passed());
}

TEST_CASE("closing 3 cm beside the cube is a failed grasp", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0 offset 0 0.03 0; r1 moves home");
  const auto& pick = action(report, "pick cube_0 by r1");
  INFO(pick.failure);
  CHECK(pick.verdict == sim::Verdict::kFailed);
  CHECK_THAT(pick.failure, Catch::Matchers::Contains("grasp:"));
  CHECK(!report.passed());
}

TEST_CASE("a grasp with little margin fails with its margin, though it held", "[sim][scripted][grip]") {
  // cube_0 made a 1.6 kg bar, 16 cm long: held at its middle it has margin to spare; held 4 cm
  // off-centre its weight twists the grip by 0.6 Nm, most of what the pads' friction resists
  // (60 N, friction 0.8), and the bar hangs on; on real pads it may not
  core::World world = core::loadWorldFile(core::defaultWorldPath());
  world.objects[0].size = Eigen::Vector3d(0.04, 0.16, 0.04);
  world.objects[0].mass = 1.6;
  world.goals = {core::Goal{"cube_0", "", "bin_green", {}}};
  const core::LoadedWorld bar = core::validateWorld(world);
  const sim::Report centred = simulate("r1 picks cube_0; r1 places cube_0 in bin_green", bar);
  CHECK(centred.passed());
  const sim::Measurement* margin = measurement(action(centred, "pick cube_0 by r1"), "grip_margin");
  REQUIRE(margin != nullptr);
  CHECK(margin->value > 4.0);

  const sim::Report off = simulate("r1 picks cube_0 offset 0 0.04 0; r1 places cube_0 in bin_green", bar);
  const auto& pick = action(off, "pick cube_0 by r1");
  INFO(pick.failure);
  CHECK(pick.verdict == sim::Verdict::kFailed);
  CHECK_THAT(pick.failure, Catch::Matchers::StartsWith("grip margin "));
  CHECK(measurement(pick, "slip")->value <= world.checks.slip_tolerance);
  CHECK(measurement(pick, "grip_margin")->value < world.checks.grip_margin);
}

TEST_CASE("a grasp on the edge of a cube fails with its pad contact, though it held", "[sim][scripted][grip]") {
  // 28 mm off the centre of the 40 mm cube the pads overlap it by 3 of their 25 mm
  const sim::Report report = simulate("r1 picks cube_0 offset 0.028 0 0; r1 places cube_0 in bin_green");
  const auto& pick = action(report, "pick cube_0 by r1");
  INFO(pick.failure);
  CHECK(pick.verdict == sim::Verdict::kFailed);
  CHECK_THAT(pick.failure, Catch::Matchers::StartsWith("pad contact "));
  CHECK(measurement(pick, "pad_contact_area")->value == Approx(0.003 * 0.025).epsilon(0.05));
  CHECK(action(report, "place cube_0 in bin_green by r1").verdict == sim::Verdict::kPassed);
}

TEST_CASE("opening the gripper mid-carry is reported as a drop", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 opens; r1 moves home");
  REQUIRE(hasEvent(report, "drop"));
  const auto& pick = action(report, "pick cube_0 by r1");
  CHECK_THAT(pick.failure, Catch::Matchers::Contains("drop"));
  CHECK(!report.passed());
}

TEST_CASE("a held cube pushed into the table slips in the fingers without falling; set down level it passes",
          "[sim][scripted]") {
  // cube_0 made slippery (friction 0.3) and held with the Hand-E's least force, 20 N, 8 mm
  // above its centre: the pads hold 12 N. Set down 1 cm below its resting height, the table
  // pushes it up between the fingers, whose tips stay clear of the table.
  core::World world = *test::defaultWorldWithoutGoals().world;
  world.objects[0].friction = 0.3;
  const core::LoadedWorld slippery = core::validateWorld(std::move(world));
  const auto place_at = [&](const std::string& z) {
    core::Plan plan = tools::planFromScript(slippery, "r1 picks cube_0 offset 0 0 0.008; r1 places cube_0 at 0.41 -0.125 " + z);
    for (core::GripperCommand& c : plan.gripper) {
      if (c.robot == "r1" && c.action == core::GripperAction::kClose) c.force = 20.0;
    }
    return sim::runPlan(*slippery.world, *slippery.robots, plan, "script");
  };
  const sim::Report pushed = place_at("0.76");
  const sim::ActionReport& place = action(pushed, "set aside cube_0 by r1");
  INFO(place.failure);
  CHECK(place.verdict == sim::Verdict::kFailed);
  CHECK_THAT(place.failure, Catch::Matchers::Contains("slip at") && Catch::Matchers::Contains("cube_0 slipped"));
  REQUIRE(hasEvent(pushed, "slip"));
  CHECK(event(pushed, "slip")->action == place.id);
  CHECK_FALSE(hasEvent(pushed, "drop"));
  CHECK_FALSE(hasEvent(pushed, "protective stop"));
  CHECK(action(pushed, "pick cube_0 by r1").verdict == sim::Verdict::kPassed);

  const sim::Report level = place_at("0.77");
  INFO(level.execution_failure);
  CHECK(level.passed());
}

TEST_CASE("a finger landing on the cube is a protective stop, not a twisted wrist", "[sim][scripted][stop]") {
  // 3 cm off the cube's centre one finger comes down on its top face
  const sim::Report report = simulate("r1 picks cube_0 offset 0 0.03 0; r1 moves home");
  const sim::ExecutionEvent* stop = event(report, "protective stop");
  REQUIRE(stop != nullptr);
  INFO(stop->detail);
  CHECK_THAT(stop->detail, Catch::Matchers::StartsWith("r1 "));
  CHECK(stop->action == "pick cube_0 by r1");
  const core::CheckSettings& checks = defaultWorld().world->checks;
  // the cell stops while every joint is within the tracking limit of its path
  for (const sim::RobotExecution& robot : report.robots) CHECK(robot.max_tracking_error <= checks.tracking_error_limit);
  // and the run ends a settle time after the stop, not at the plan's end
  CHECK(report.simulated_time == Approx(stop->t + checks.settle_time + 0.5).margin(2e-3));
  CHECK(!report.passed());
}

TEST_CASE("a trajectory into the table is an unplanned contact and a protective stop on the TCP force", "[sim][scripted][stop]") {
  const sim::Report report = simulate("r0 moves to" + downAt(0, {-0.3, 0.0, 0.70}) + "; r0 moves home");
  CHECK(hasEvent(report, "robot-fixture contact"));
  CHECK(report.execution_verdict == sim::Verdict::kFailed);
  CHECK_THAT(report.execution_failure, Catch::Matchers::Contains("touches table"));
  const sim::ExecutionEvent* stop = event(report, "protective stop");
  REQUIRE(stop != nullptr);
  INFO(stop->detail);
  CHECK_THAT(stop->detail, Catch::Matchers::Contains("external"));
  const sim::RobotExecution& r0 = report.robots[0];
  CHECK((r0.max_tcp_force > defaultWorld().world->safety.tcp_force || r0.max_external_torque_ratio > 1.0));
}

TEST_CASE("a clean run stays far from the protective stop's limits", "[sim][scripted][stop]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  REQUIRE(report.passed());
  for (const sim::RobotExecution& robot : report.robots) {
    INFO(robot.robot);
    CHECK(robot.max_tcp_force < 0.25 * defaultWorld().world->safety.tcp_force);
    CHECK(robot.max_external_torque_ratio < 0.25);
  }
}

TEST_CASE("a place outside the goal region fails the placement", "[sim][scripted]") {
  const sim::Report report = simulate("r1 picks cube_0; r1 places cube_0 in bin_green offset 0.15 0 0");
  const auto& place = action(report, "place cube_0 in bin_green by r1");
  INFO(place.failure);
  CHECK(place.verdict == sim::Verdict::kFailed);
  CHECK_THAT(place.failure, Catch::Matchers::Contains("outside bin_green"));
}

TEST_CASE("a cube set aside on the table and picked up again passes, one set down on another fails", "[sim][scripted]") {
  // cube_0 rests at about (0.409, -0.125); r1 sets it down 0.15 m further along y, at table height
  const sim::Report report =
      simulate("r1 picks cube_0; r1 places cube_0 at 0.41 0.03 0.77; r1 picks cube_0; r1 places cube_0 in bin_green");
  INFO(sim::writeReportJson(report));
  const auto& aside = action(report, "set aside cube_0 by r1");
  CHECK(aside.verdict == sim::Verdict::kPassed);
  CHECK(aside.region.empty());
  CHECK(report.passed());
  // set down on top of cube_2 (about (0.406, 0.232) on the table): at rest, but on no surface
  const sim::Report stacked = simulate("r1 picks cube_0; r1 places cube_0 at 0.4064 0.2323 0.81; r1 moves home");
  const auto& on_cube = action(stacked, "set aside cube_0 by r1");
  INFO(on_cube.failure);
  CHECK_THAT(on_cube.failure, Catch::Matchers::Contains("set aside: cube_0 rests 4") &&
                                  Catch::Matchers::Contains("mm off stable surface"));
  CHECK(on_cube.verdict == sim::Verdict::kFailed);
}

namespace {

/// The run `low` knocks `object` (and fails on it); the same run higher, `high`, is clean.
void checkKnockedThenClear(const sim::Report& low, const sim::Report& high, const std::string& object) {
  REQUIRE(hasEvent(low, "knocked object"));
  CHECK_THAT(event(low, "knocked object")->detail, Catch::Matchers::StartsWith(object + " moved"));
  CHECK_THAT(low.execution_failure, Catch::Matchers::Contains(object));
  CHECK_FALSE(low.passed());
  INFO(high.execution_failure);
  CHECK(high.events.empty());
  CHECK(high.passed());
}

}  // namespace

TEST_CASE("an arm sweeping through a resting cube knocks it; 7 cm higher it passes", "[sim][scripted]") {
  // cube_1 rests at about (-0.405, -0.121); after 3 s, when it sleeps (Simulation), r0 sweeps
  // its open gripper across it 15 mm up: coming near wakes it
  const auto sweep = [](double z) {
    return simulate("r0 waits 3; r0 moves to" + downAt(0, {-0.405, -0.221, z}) + "; r0 moves to" +
                    downAt(0, {-0.405, -0.021, z}) + "; r0 moves home");
  };
  checkKnockedThenClear(sweep(0.785), sweep(0.86), "cube_1");
}

TEST_CASE("a carried cube swept through a resting one knocks it; 5 cm higher it passes", "[sim][scripted]") {
  // r1 carries cube_0 across cube_2 (resting at about (0.406, 0.232), top at 0.79 m) with the
  // held cube's centre at z, and puts it back where it was
  const auto carry = [](double z) {
    return simulate("r1 picks cube_0; r1 moves to" + downAt(1, {0.406, 0.10, z}) + "; r1 moves to" +
                    downAt(1, {0.406, 0.36, z}) + "; r1 places cube_0 at 0.41 -0.125 0.77");
  };
  checkKnockedThenClear(carry(0.80), carry(0.85), "cube_2");
}

TEST_CASE("two runs of the same plan give byte-identical reports", "[sim][scripted]") {
  const std::string script = "r1 picks cube_2; r1 hands cube_2 to r0; r0 places cube_2 in bin_blue";
  const std::string first = sim::writeReportJson(simulate(script));
  const std::string second = sim::writeReportJson(simulate(script));
  CHECK(first == second);
}

TEST_CASE("an object in the gripper is the arm controller's payload from closing on it until opening",
          "[sim][scripted]") {
  const core::LoadedWorld& world = defaultWorld();
  const core::Plan plan =
      tools::planFromScript(world, "r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  // the time of the first command of `robot` to `action` after `after`
  const auto command = [&](const std::string& robot, core::GripperAction action, double after) {
    for (const core::GripperCommand& c : plan.gripper) {
      if (c.robot == robot && c.action == action && c.t > after) return c.t;
    }
    FAIL("no such command of " << robot);
    return 0.0;
  };
  // r1 closes on the cube, opens in the handoff; r0 closes in the handoff, opens in the place
  const double r1_close = command("r1", core::GripperAction::kClose, 0.0);
  const double r1_open = command("r1", core::GripperAction::kOpen, r1_close);
  const double r0_close = command("r0", core::GripperAction::kClose, 0.0);
  const double r0_open = command("r0", core::GripperAction::kOpen, r0_close);
  REQUIRE(r0_close < r1_open);  // both hold the cube in between

  sim::Simulation sim(*world.world, *world.robots);
  sim::PlanExecutor dut(sim, plan);
  // per robot: the plan times at which it first and last had a payload
  std::array<std::optional<double>, 2> first, last;
  bool both = false;  // in the handoff the receiver takes the payload over from the giver
  const double step = world.world->physics.time_step;
  while (dut.planTime() < r0_open + 0.5) {
    dut.step();
    const double t = dut.planTime() - step;  // the step just applied
    for (int r = 0; r < 2; ++r) {
      if (!dut.payload(r)) continue;
      if (!first[r]) {
        first[r] = t;
        CHECK(dut.payload(r)->mass == world.world->objects[0].mass);
        CHECK(dut.payload(r)->X_LCom.translation().norm() < 0.03);  // the cube between the fingers
      }
      last[r] = t;
    }
    both |= dut.payload(0) && dut.payload(1);
  }
  CHECK(!both);
  REQUIRE(first[1]);
  REQUIRE(first[0]);
  CHECK(*first[1] == Approx(r1_close).margin(step));
  CHECK(*last[1] == Approx(r1_open - step).margin(step));
  CHECK(*first[0] == Approx(r1_open).margin(step));
  CHECK(*last[0] == Approx(r0_open - step).margin(step));
}

TEST_CASE("a heavy cube carried through a handoff is tracked as closely as a light one", "[sim][scripted]") {
  // 2 kg: gravity on it alone would bend the light wrist joints out of the tracking bound
  core::World heavy = *defaultWorld().world;
  heavy.objects[0].mass = 2.0;
  const core::LoadedWorld world = core::validateWorld(heavy);
  const sim::Report report = simulate("r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red", world);
  INFO(sim::writeReportJson(report));
  CHECK(report.passed());
  for (const sim::RobotExecution& robot : report.robots) {
    INFO(robot.robot);
    CHECK(robot.max_tracking_error < 0.01);
  }
}

TEST_CASE("the Hand-E squeezes a cube with the force its command asks, within 20-185 N", "[sim][scripted][grip]") {
  // the controller's force limit and the finger servo's bound, measured at the contacts: each
  // finger presses on the cube with the commanded force once the fingers have closed on it
  const core::LoadedWorld& world = defaultWorld();
  core::Plan plan = tools::planFromScript(world, "r1 picks cube_0; r1 waits 1");
  const auto close = std::find_if(plan.gripper.begin(), plan.gripper.end(), [](const core::GripperCommand& c) {
    return c.robot == "r1" && c.action == core::GripperAction::kClose;
  });
  REQUIRE(close != plan.gripper.end());
  // commanded -> expected: within the range as asked, outside it clamped to 20 N and 185 N
  // (plan files cannot ask for those; the controller clamps whatever it is given)
  for (const auto& [force, expected] : {std::pair{5.0, 20.0}, std::pair{40.0, 40.0}, std::pair{120.0, 120.0},
                                        std::pair{185.0, 185.0}, std::pair{400.0, 185.0}}) {
    close->force = force;
    sim::Simulation sim(*world.world, *world.robots);
    sim::PlanExecutor dut(sim, plan);
    while (sim.time() < close->t + 0.3) dut.step();
    std::map<int, double> per_finger;  // finger link -> normal force on cube_0 [N]
    for (const sim::Contact& c : sim.contacts()) {
      const bool ab = c.a.kind == sim::BodyRef::Kind::kRobot && c.a.index == 1 &&
                      c.b.kind == sim::BodyRef::Kind::kObject && c.b.index == 0;
      const bool ba = c.b.kind == sim::BodyRef::Kind::kRobot && c.b.index == 1 &&
                      c.a.kind == sim::BodyRef::Kind::kObject && c.a.index == 0;
      if (ab) per_finger[c.a.link] += c.normal_force;
      if (ba) per_finger[c.b.link] += c.normal_force;
    }
    INFO("commanded " << force << " N");
    REQUIRE(per_finger.size() == 2);
    for (const auto& [link, measured] : per_finger) {
      INFO("finger link " << link << ": " << measured << " N");
      CHECK(measured == Approx(expected).epsilon(0.01));
    }
  }
}

namespace {

// The scripted hand-over of cube_0 from r1 to r0 (and r0's place), with `edit` applied to the
// receiver's close and the giver's open of the handoff; returns the handoff's report.
template <class Edit>
sim::ActionReport editedHandoff(const core::LoadedWorld& world, Edit&& edit) {
  core::Plan plan = tools::planFromScript(world, "r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  const core::PlanAction& handoff = plan.actions[1];
  REQUIRE(handoff.type == core::ActionType::kHandoff);
  core::GripperCommand* receiver_close = nullptr;
  core::GripperCommand* giver_open = nullptr;
  for (core::GripperCommand& c : plan.gripper) {
    if (c.t < handoff.start || c.t > handoff.end) continue;
    if (c.robot == "r0" && c.action == core::GripperAction::kClose) receiver_close = &c;
    if (c.robot == "r1" && c.action == core::GripperAction::kOpen) giver_open = &c;
  }
  REQUIRE(receiver_close != nullptr);
  REQUIRE(giver_open != nullptr);
  edit(plan, handoff, *receiver_close, *giver_open);
  const sim::Report report = sim::runPlan(*world.world, *world.robots, plan, "script");
  return action(report, "handoff cube_0 from r1 to r0");
}

}  // namespace

TEST_CASE("a giver that opens before the receiver holds fails the handoff's overlap", "[sim][scripted][handoff][long]") {
  const sim::ActionReport handoff =
      editedHandoff(defaultWorld(), [](core::Plan&, const core::PlanAction&, core::GripperCommand& close,
                                       core::GripperCommand& open) { open.t = close.t + 0.03; });
  INFO(handoff.failure);
  CHECK(handoff.verdict == sim::Verdict::kFailed);
  CHECK_THAT(handoff.failure, Catch::Matchers::Contains("overlap: both grippers held cube_0 together for"));
}

TEST_CASE("a giver that keeps its grip while it retreats pulls the cube away: the handoff fails",
          "[sim][scripted][handoff][long]") {
  const sim::ActionReport handoff = editedHandoff(
      defaultWorld(), [](core::Plan&, const core::PlanAction& a, core::GripperCommand&, core::GripperCommand& open) {
        open.t = a.end - 0.04;
      });
  INFO(handoff.failure);
  CHECK(handoff.verdict == sim::Verdict::kFailed);
  CHECK_THAT(handoff.failure, Catch::Matchers::Contains("transfer: r1 still touches cube_0 at the end"));
}

TEST_CASE("a receiver gripping a heavy, slippery cube too lightly lets it slip", "[sim][scripted][handoff][long]") {
  // 1.5 kg at friction 0.3: the giver's 185 N holds it, the receiver's 20 N holds 1.2 kg at most
  core::World world = *test::defaultWorldWithoutGoals().world;
  world.objects[0].mass = 1.5;
  world.objects[0].friction = 0.3;
  const core::LoadedWorld heavy = core::validateWorld(std::move(world));
  const sim::ActionReport handoff = editedHandoff(heavy, [](core::Plan& plan, const core::PlanAction&,
                                                            core::GripperCommand& close, core::GripperCommand&) {
    close.force = 20.0;
    for (core::GripperCommand& c : plan.gripper) {
      if (c.robot == "r1" && c.action == core::GripperAction::kClose) c.force = 185.0;
    }
  });
  INFO(handoff.failure);
  CHECK(handoff.verdict == sim::Verdict::kFailed);
  CHECK_THAT(handoff.failure, Catch::Matchers::Contains("receiver slip") &&
                                  Catch::Matchers::Contains("transfer: r0 does not hold cube_0 at the end"));
}
