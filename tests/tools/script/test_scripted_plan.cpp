// Scripted plans: grasp poses by FK, speed limits, timing of actions and handoffs, parse
// errors, determinism. The world is built in memory: two UR5e facing each other across a
// table, three bins, three cubes.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/grasps.h"
#include "core/kinematics.h"
#include "core/plan.h"
#include "core/reach.h"
#include "core/trajectory_interpolator.h"
#include "core/world_loader.h"
#include "tools/script/scripted_plan.h"

namespace dashbed::tools {
namespace {

using core::ArmConfig;
using core::GripperAction;
using core::Pose;

constexpr double kTableTop = 0.75;

core::FixtureSpec bin(const std::string& name, double x, double y) {
  core::FixtureSpec fixture;
  fixture.name = name;
  fixture.type = core::FixtureType::kBin;
  fixture.X_WF = core::makePoseXyzYaw({x, y, kTableTop}, 0.0);
  fixture.size = {0.2, 0.2, 0.1};
  return fixture;
}

core::ObjectSpec cube(const std::string& name, double x, double y, double yaw) {
  core::ObjectSpec object;
  object.name = name;
  object.size = Eigen::Vector3d::Constant(0.04);
  object.X_WO = core::makePoseXyzYaw({x, y, kTableTop + 0.02}, yaw);
  return object;
}

/// r0 at (-0.7, 0) facing +x, r1 at (0.7, 0) facing -x, bases on a 2.0 x 1.4 x 0.75 m table.
core::LoadedWorld twoRobotWorld() {
  core::World world;
  world.name = "script_test";
  core::FixtureSpec table;
  table.name = "table";
  table.size = {2.0, 1.4, kTableTop};
  world.fixtures = {table, bin("bin_red", -0.3, -0.4), bin("bin_blue", 0.3, -0.4), bin("bin_mid", 0.0, -0.45)};
  core::RobotSpec r0;
  r0.name = "r0";
  r0.model = "ur5e_hande";
  r0.X_WBase = core::makePoseXyzYaw({-0.7, 0.0, kTableTop}, 0.0);
  r0.home = core::kDefaultRobotHome;
  core::RobotSpec r1 = r0;
  r1.name = "r1";
  r1.X_WBase = core::makePoseXyzYaw({0.7, 0.0, kTableTop}, std::numbers::pi);
  world.robots = {r0, r1};
  core::ObjectSpec post = cube("post", -0.35, 0.05, 0.0);  // tall enough for side grasps
  post.size.z() = 0.12;
  post.X_WO.translation().z() = kTableTop + 0.06;
  core::ObjectSpec thin = cube("thin", -0.45, -0.2, 0.0);  // 25 mm: the giver's fingers too close for the receiver's
  thin.size.head<2>() = Eigen::Vector2d(0.025, 0.025);
  core::ObjectSpec tall = cube("tall", -0.15, 0.15, 0.0);  // 60 mm along the handoff line: too wide for the receiver
  tall.size.z() = 0.06;
  tall.X_WO.translation().z() = kTableTop + 0.03;
  world.objects = {cube("cube_0", -0.3, 0.25, 0.3), cube("cube_1", -0.25, -0.1, 0.0), cube("cube_2", 0.3, 0.25, -0.2), post,
                   thin, tall};
  core::deriveFixtureGeometry(world);
  return core::validateWorld(std::move(world));
}

const core::LoadedWorld& testWorld() {
  static const core::LoadedWorld world = twoRobotWorld();
  return world;
}

int robotIndex(const std::string& name) {
  const auto& robots = testWorld().world->robots;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    if (robots[r].name == name) return static_cast<int>(r);
  }
  FAIL("no robot " << name);
  return -1;
}

/// TCP pose in W by the URDF chain (independent of the IK's DH model), fingers closed.
Pose tcpByUrdf(const std::string& robot, const ArmConfig& q) {
  const core::PlacedRobot& placed = (*testWorld().robots)[static_cast<std::size_t>(robotIndex(robot))];
  Eigen::VectorXd q_all = Eigen::VectorXd::Zero(placed.model->numPositions());
  for (int j = 0; j < 6; ++j) q_all[j] = q[j];
  return placed.spec->X_WBase * core::linkPoses(*placed.model, q_all)[placed.model->requireLink("tcp")];
}

const core::RobotTrajectory& trajectoryOf(const core::Plan& plan, const std::string& robot) {
  for (const auto& trajectory : plan.trajectories) {
    if (trajectory.robot == robot) return trajectory;
  }
  FAIL("no trajectory for " << robot);
  throw std::logic_error("unreachable");
}

/// The configuration of a trajectory point at exactly time t (the plan's times are whole ms).
ArmConfig pointAt(const core::RobotTrajectory& trajectory, double t) {
  for (const auto& point : trajectory.points) {
    if (std::abs(point.t - t) < 1e-12) return point.q;
  }
  FAIL(trajectory.robot << " has no point at t = " << t);
  return {};
}

std::vector<core::GripperCommand> commandsOf(const core::Plan& plan, const std::string& robot, GripperAction action) {
  std::vector<core::GripperCommand> commands;
  for (const auto& c : plan.gripper) {
    if (c.robot == robot && c.action == action) commands.push_back(c);
  }
  return commands;
}

const core::PlanAction& actionOf(const core::Plan& plan, core::ActionType type, std::size_t nth = 0) {
  for (const auto& action : plan.actions) {
    if (action.type == type && nth-- == 0) return action;
  }
  FAIL("no such action");
  throw std::logic_error("unreachable");
}

void requireValid(const core::Plan& plan) {
  const core::PlacedRobot& robot = (*testWorld().robots)[0];
  std::array<std::string, 6> names;
  std::array<double, 6> velocity{};
  for (int j = 0; j < 6; ++j) {
    const core::JointModel& joint = robot.model->joints()[robot.model->movableJoints()[j]];
    names[j] = joint.name;
    velocity[j] = joint.max_velocity;
  }
  REQUIRE_NOTHROW(core::validatePlan(plan, *testWorld().world, names, robot.ik->lower(), robot.ik->upper(), velocity, "script"));
}

/// Every segment's average speed x 1.5 (the peak of a cubic resting at both ends) stays within
/// half the joint limit.
void requireHalfSpeed(const core::Plan& plan) {
  const core::PlacedRobot& robot = (*testWorld().robots)[0];
  for (const auto& trajectory : plan.trajectories) {
    for (std::size_t p = 1; p < trajectory.points.size(); ++p) {
      const auto& a = trajectory.points[p - 1];
      const auto& b = trajectory.points[p];
      REQUIRE(b.t > a.t);
      for (int j = 0; j < 6; ++j) {
        const double limit = robot.model->joints()[robot.model->movableJoints()[j]].max_velocity;
        INFO(trajectory.robot << " point " << p << " joint " << j);
        REQUIRE(std::abs(b.q[j] - a.q[j]) / (b.t - a.t) * 1.5 <= 0.5 * limit + 1e-9);
      }
    }
  }
}

bool samePose(const Pose& a, const Pose& b, double tolerance) {
  return (a.translation() - b.translation()).norm() < tolerance && (a.linear() - b.linear()).norm() < tolerance;
}

/// The grasps of an upright object at X_WO (optionally displaced by offset in its frame).
std::vector<Pose> graspPoses(const Pose& X_WO, core::GraspApproach approach,
                             const Eigen::Vector3d& offset = Eigen::Vector3d::Zero(),
                             const Eigen::Vector3d& size = Eigen::Vector3d::Constant(0.04)) {
  std::vector<Pose> poses;
  for (const core::BoxGrasp& g : core::boxGrasps(size)) {
    if (g.approach == approach) poses.push_back(X_WO * Eigen::Translation3d(offset) * g.X_OT);
  }
  return poses;
}

bool matchesOne(const Pose& X, const std::vector<Pose>& candidates, double tolerance) {
  return std::any_of(candidates.begin(), candidates.end(), [&](const Pose& c) { return samePose(X, c, tolerance); });
}

TEST_CASE("pick and place: grasp and release poses by FK, lift, actions, home at the end", "[script]") {
  const core::World& world = *testWorld().world;
  const core::Plan dut = planFromScript(testWorld(), "r0 picks cube_0; r0 places cube_0 in bin_red");
  requireValid(dut);
  requireHalfSpeed(dut);
  const auto& r0 = trajectoryOf(dut, "r0");

  REQUIRE(dut.actions.size() == 2);
  const core::PlanAction& pick = actionOf(dut, core::ActionType::kPick);
  const core::PlanAction& place = actionOf(dut, core::ActionType::kPlace);
  CHECK(pick.robot == "r0");
  CHECK(place.region == "bin_red");
  CHECK(pick.start < pick.end);
  CHECK(pick.end <= place.start);
  CHECK(place.start < place.end);

  // the gripper opens before the pick, closes at the grasp, opens at the release
  const auto closes = commandsOf(dut, "r0", GripperAction::kClose);
  const auto opens = commandsOf(dut, "r0", GripperAction::kOpen);
  REQUIRE(closes.size() == 1);
  REQUIRE(opens.size() == 2);
  CHECK(opens[0].t < pick.start);
  CHECK(closes[0].force == 0.0);  // the world's grip force
  CHECK(closes[0].t > pick.start);
  CHECK(closes[0].t < pick.end);
  CHECK(opens[1].t > place.start);
  CHECK(opens[1].t < place.end);

  const Pose X_WO = world.findObject("cube_0")->X_WO;
  const Pose X_grasp = tcpByUrdf("r0", pointAt(r0, closes[0].t));
  CHECK(matchesOne(X_grasp, graspPoses(X_WO, core::GraspApproach::kTop), 1e-9));

  // descent straight down from 0.10 m above, at most 1 cm between waypoints
  const Pose X_pre = tcpByUrdf("r0", pointAt(r0, pick.start));
  CHECK((X_pre.translation() - X_grasp.translation() - Eigen::Vector3d(0, 0, 0.10)).norm() < 1e-9);
  for (const auto& point : r0.points) {
    if (point.t <= pick.start || point.t > closes[0].t) continue;
    const Pose X = tcpByUrdf("r0", point.q);
    CHECK((X.translation().head<2>() - X_grasp.translation().head<2>()).norm() < 1e-9);
    CHECK((X.linear() - X_grasp.linear()).norm() < 1e-9);
  }
  // the arm rests for the gripper dwell, then lifts 0.10 m by the end of the pick
  CHECK(std::abs(pointAt(r0, closes[0].t + 0.6)[0] - pointAt(r0, closes[0].t)[0]) == 0.0);
  const Pose X_lift = tcpByUrdf("r0", pointAt(r0, pick.end));
  CHECK((X_lift.translation() - X_grasp.translation() - Eigen::Vector3d(0, 0, 0.10)).norm() < 1e-9);

  // release: the cube's centre at the region's placement pose plus the drop height,
  // top grasp so the TCP is at the centre, approach straight down
  const Pose X_release = tcpByUrdf("r0", pointAt(r0, opens[1].t));
  const Pose X_place = core::placementPose(*world.findRegion("bin_red"), *world.findObject("cube_0"));
  CHECK((X_release.translation() - X_place.translation() - Eigen::Vector3d(0, 0, 0.002)).norm() < 1e-9);
  CHECK((X_release.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm() < 1e-9);

  // both robots end at home; r1 never moves
  CHECK(r0.points.back().q == world.robots[0].home);
  CHECK(trajectoryOf(dut, "r1").points.size() == 1);
  CHECK(trajectoryOf(dut, "r1").points.front().q == world.robots[1].home);
}

TEST_CASE("segment durations follow the speed rule, the acceleration cap and the 0.3 s minimum", "[script]") {
  const core::Plan dut = planFromScript(testWorld(), "r0 moves to 1 -1.5708 1.5708 -1.5708 -1.5708 0");
  const auto& r0 = trajectoryOf(dut, "r0");
  REQUIRE(r0.points.size() == 3);  // home, the target, home again
  // 1 rad on the pan joint from rest to rest: the speed rule asks for 1 x 1.5 / (0.5 pi) =
  // 0.955 s, but the cubic then starts at 6 / 0.955^2 = 6.6 rad/s^2; within the 4 rad/s^2 cap it
  // takes sqrt(6 / 4) s, rounded up to whole ms
  CHECK(r0.points[1].t == Approx(std::ceil(std::sqrt(6.0 / 4.0) * 1000) / 1000).epsilon(1e-12));
  CHECK(r0.points[1].q[0] == 1.0);
  for (int j = 0; j < 6; ++j) CHECK(r0.points[1].qd.value()[j] == 0.0);  // at rest there, written so
  // a tiny move takes the minimum segment time (and its ease, under a millisecond)
  const core::Plan tiny = planFromScript(testWorld(), "r0 moves to 0.001 -1.5708 1.5708 -1.5708 -1.5708 0; r0 stays");
  CHECK(trajectoryOf(tiny, "r0").points[1].t >= 0.3);
  CHECK(trajectoryOf(tiny, "r0").points[1].t <= 0.301);
  requireValid(dut);
  requireHalfSpeed(dut);
}

TEST_CASE("handoff: the planner's handoff, arrival together, the receiver on another face pair", "[script]") {
  const core::World& world = *testWorld().world;
  const core::Plan dut =
      planFromScript(testWorld(), "r0 picks cube_1\nr0 hands cube_1 to r1\nr1 places cube_1 in bin_blue\n");
  requireValid(dut);
  REQUIRE(dut.actions.size() == 3);
  const core::PlanAction& pick = dut.actions[0];
  const core::PlanAction& handoff = dut.actions[1];
  const core::PlanAction& place = dut.actions[2];
  CHECK(pick.type == core::ActionType::kPick);
  CHECK(handoff.type == core::ActionType::kHandoff);
  CHECK(place.type == core::ActionType::kPlace);
  CHECK(handoff.robot == "r0");
  CHECK(handoff.receiver == "r1");
  CHECK(place.robot == "r1");
  for (const auto& action : dut.actions) CHECK(action.start < action.end);
  CHECK(pick.end <= handoff.start);
  CHECK(handoff.end <= place.start);

  // both have arrived, at rest, when the handoff starts
  for (const char* robot : {"r0", "r1"}) {
    const auto& points = trajectoryOf(dut, robot).points;
    const auto at = std::find_if(points.begin(), points.end(),
                                 [&](const core::TrajectoryPoint& p) { return p.t == handoff.start; });
    REQUIRE(at != points.end());
    REQUIRE(at->qd);
    for (const double v : *at->qd) CHECK(v == 0.0);
  }

  // the receiver closes, both hold for a dwell, then the giver opens
  const auto receiver_close = commandsOf(dut, "r1", GripperAction::kClose);
  const auto giver_open = commandsOf(dut, "r0", GripperAction::kOpen);
  REQUIRE(receiver_close.size() == 1);
  REQUIRE(giver_open.size() == 2);  // before the pick, and in the handoff
  CHECK(receiver_close[0].t > handoff.start);
  CHECK(giver_open[1].t > receiver_close[0].t + 0.2);
  CHECK(giver_open[1].t < handoff.end);

  // at the close both grippers are on the cube (their TCPs within its half-diagonal) and close
  // on different face pairs; the cube is in the two robots' handoff zone
  const auto curveAt = [&](const char* robot, double t) {
    return core::TrajectoryInterpolator(trajectoryOf(dut, robot).points).at(t).q;
  };
  const Pose X_giver = tcpByUrdf("r0", curveAt("r0", receiver_close[0].t));
  const Pose X_receiver = tcpByUrdf("r1", curveAt("r1", receiver_close[0].t));
  CHECK((X_giver.translation() - X_receiver.translation()).norm() < 0.04 * std::sqrt(3.0));
  CHECK(std::abs(X_giver.linear().col(0).dot(X_receiver.linear().col(0))) < 1e-6);
  const auto zone = core::handoffZone(world, (*testWorld().robots)[0], (*testWorld().robots)[1]);
  REQUIRE(zone);
  const core::HandoffShape shape;
  const Eigen::Vector3d centre = 0.5 * (X_giver.translation() + X_receiver.translation());
  CHECK((centre - zone->mid).head<2>().norm() < std::sqrt(2.0) * shape.spread + 0.04);
  CHECK(centre.z() > zone->top + shape.min_height - 0.04);
  CHECK(centre.z() < zone->top + shape.max_height + 0.04);

  // the giver goes home after the handoff; both end at home
  CHECK(trajectoryOf(dut, "r0").points.back().q == world.robots[0].home);
  CHECK(trajectoryOf(dut, "r1").points.back().q == world.robots[1].home);
}

TEST_CASE("the script hands over both ways between a robot on the table and one on a riser", "[script]") {
  const core::LoadedWorld riser =
      core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/handwritten/u15_riser_35cm.yaml");
  const core::Plan down =
      planFromScript(riser, "r1 picks cube_0; r1 hands cube_0 to r0; r0 moves home; r0 places cube_0 in bin_red");
  const core::Plan up = planFromScript(riser, "r0 picks cube_2; r0 hands cube_2 to r1; r1 places cube_2 in bin_blue");
  for (const core::Plan* plan : {&down, &up}) {
    REQUIRE(plan->actions.size() == 3);
    CHECK(plan->actions[1].type == core::ActionType::kHandoff);
  }
}

TEST_CASE("handoffs both ways and a place by the original robot", "[script]") {
  const core::Plan dut = planFromScript(
      testWorld(), "r0 picks cube_1; r0 hands cube_1 to r1; r1 hands cube_1 to r0; r0 places cube_1 in bin_red");
  requireValid(dut);
  requireHalfSpeed(dut);
  REQUIRE(dut.actions.size() == 4);
  CHECK(dut.actions[1].robot == "r0");
  CHECK(dut.actions[2].robot == "r1");
  CHECK(dut.actions[1].end <= dut.actions[2].start);
}

TEST_CASE("handoffs whose grippers would touch or cannot close are refused", "[script]") {
  CHECK_THROWS_WITH(planFromScript(testWorld(), "r0 picks thin; r0 hands thin to r1"),
                    Catch::StartsWith("script:1:25: r0 cannot hand thin to r1: r1 has no face pair of thin to close on"));
  CHECK_THROWS_WITH(planFromScript(testWorld(), "r0 picks tall; r0 hands tall to r1"),
                    Catch::StartsWith("script:1:25: r0 cannot hand tall to r1: r1 has no face pair of tall to close on"));
  // the same objects can be picked and placed by one robot
  CHECK_NOTHROW(planFromScript(testWorld(), "r0 picks thin; r0 places thin in bin_red; r0 picks tall"));
}

TEST_CASE("side picks approach horizontally", "[script]") {
  const core::Plan dut = planFromScript(testWorld(), "r0 picks post from the side; r0 places post in bin_red");
  requireValid(dut);
  requireHalfSpeed(dut);
  const auto close = commandsOf(dut, "r0", GripperAction::kClose);
  REQUIRE(close.size() == 1);
  const Pose X = tcpByUrdf("r0", pointAt(trajectoryOf(dut, "r0"), close[0].t));
  const core::ObjectSpec& post = *testWorld().world->findObject("post");
  CHECK(matchesOne(X, graspPoses(post.X_WO, core::GraspApproach::kSide, Eigen::Vector3d::Zero(), post.size), 1e-9));
  CHECK(std::abs(X.linear().col(2).z()) < 1e-9);
  // the approach comes in horizontally from 0.10 m back
  const Pose X_pre = tcpByUrdf("r0", pointAt(trajectoryOf(dut, "r0"), actionOf(dut, core::ActionType::kPick).start));
  CHECK((X_pre.translation() + 0.10 * X.linear().col(2) - X.translation()).norm() < 1e-9);
  // a 40 mm cube is too low for the gripper body to pass above the table
  CHECK_THROWS_WITH(planFromScript(testWorld(), "r0 picks cube_1 from the side"),
                    Catch::Contains("no grasp of cube_1 from the side") && Catch::Contains("too low"));
}

TEST_CASE("timelines: robots run in parallel, waits delay, objects wait for their release", "[script]") {
  const core::Plan both = planFromScript(testWorld(), "r0 picks cube_0; r1 picks cube_2");
  const core::PlanAction& a = actionOf(both, core::ActionType::kPick, 0);
  const core::PlanAction& b = actionOf(both, core::ActionType::kPick, 1);
  CHECK(a.start < b.end);  // they overlap in time
  CHECK(b.start < a.end);
  requireValid(both);
  // r1's timeline does not depend on r0's statements
  const core::Plan alone = planFromScript(testWorld(), "r1 picks cube_2");
  CHECK(trajectoryOf(alone, "r1").points.size() == trajectoryOf(both, "r1").points.size());
  CHECK(trajectoryOf(alone, "r1").points.back().t == trajectoryOf(both, "r1").points.back().t);
  CHECK(actionOf(alone, core::ActionType::kPick).start == b.start);

  const core::Plan plain = planFromScript(testWorld(), "r0 picks cube_0");
  const core::Plan waited = planFromScript(testWorld(), "r0 waits 0.5; r0 picks cube_0");
  CHECK(actionOf(waited, core::ActionType::kPick).start ==
        Approx(actionOf(plain, core::ActionType::kPick).start + 0.5).epsilon(1e-12));

  // r1 picks the cube r0 put in the shared bin only after r0's place is complete
  const core::Plan relay = planFromScript(testWorld(), "r0 picks cube_1; r0 places cube_1 in bin_mid; r1 picks cube_1");
  requireValid(relay);
  const core::PlanAction& place = actionOf(relay, core::ActionType::kPlace);
  const core::PlanAction& second = actionOf(relay, core::ActionType::kPick, 1);
  CHECK(second.robot == "r1");
  CHECK(second.start > place.end);
}

TEST_CASE("bad-plan modifiers: offsets, bare gripper commands, joint moves, stays", "[script]") {
  const core::World& world = *testWorld().world;
  const core::Plan offset = planFromScript(testWorld(), "r0 picks cube_1 offset 0.03 0 0");
  requireValid(offset);
  const auto close = commandsOf(offset, "r0", GripperAction::kClose);
  REQUIRE(close.size() == 1);
  const Pose X = tcpByUrdf("r0", pointAt(trajectoryOf(offset, "r0"), close[0].t));
  CHECK(matchesOne(X, graspPoses(world.findObject("cube_1")->X_WO, core::GraspApproach::kTop, {0.03, 0, 0}), 1e-9));
  CHECK((X.translation() - world.findObject("cube_1")->X_WO.translation()).norm() == Approx(0.03).epsilon(1e-9));

  const core::Plan bare = planFromScript(testWorld(), "r0 closes\nr0 opens\nr0 waits 0.2; r0 closes");
  REQUIRE(bare.gripper.size() == 3);
  CHECK(bare.gripper[0].action == GripperAction::kClose);
  CHECK(bare.gripper[0].t == 0.0);
  CHECK(bare.gripper[1].action == GripperAction::kOpen);
  CHECK(bare.gripper[1].t == 0.6);
  CHECK(bare.gripper[2].t == Approx(1.4).epsilon(1e-12));
  requireValid(bare);

  const ArmConfig q{0.5, -1.2, 1.4, -1.7, -1.5708, 0.3};
  const core::Plan moved = planFromScript(testWorld(), "r0 moves to 0.5 -1.2 1.4 -1.7 -1.5708 0.3; r0 stays");
  CHECK(trajectoryOf(moved, "r0").points.back().q == q);
  const core::Plan back = planFromScript(testWorld(), "r0 moves to 0.5 -1.2 1.4 -1.7 -1.5708 0.3; r0 moves home");
  CHECK(trajectoryOf(back, "r0").points.back().q == world.robots[0].home);
}

TEST_CASE("the same script gives the same bytes", "[script]") {
  const std::string script =
      "# sort two cubes\nr0 picks cube_0; r0 places cube_0 in bin_red\n"
      "r0 picks cube_1; r0 hands cube_1 to r1; r1 places cube_1 in bin_blue\nr1 picks cube_2\nr0 picks post from the side\n";
  const std::string first = core::writePlanJson(planFromScript(testWorld(), script));
  const core::LoadedWorld fresh = twoRobotWorld();
  const std::string second = core::writePlanJson(planFromScript(fresh, script));
  CHECK(first == second);
  // and the written plan reads back to the same plan
  CHECK(core::writePlanJson(core::parsePlanJson(first, "plan.json")) == first);
}

TEST_CASE("script errors name the line, the column and the problem", "[script]") {
  const auto fails = [](const std::string& script, const std::string& message) {
    INFO(script);
    CHECK_THROWS_MATCHES(planFromScript(testWorld(), script, "t.script"), ScriptError, Catch::Message(message));
  };
  fails("r0 picks cube_0\nr0 jumps", "t.script:2:4: unknown verb 'jumps' (expected picks, places, hands, waits, moves, opens, closes or stays)");
  fails("r7 picks cube_0", "t.script:1:1: unknown robot 'r7' (world 'script_test' has r0, r1)");
  fails("r0 picks cube_0\nr0 pla\x01" "ces", "t.script:2:7: control character \\x01 (only tab, line feed and carriage return may appear)");
  fails("r0 picks cube_\xff", "t.script:1:15: byte \\xFF is not part of a UTF-8 character");
  fails("r0 picks cube_9", "t.script:1:10: unknown object 'cube_9' (world 'script_test' has cube_0, cube_1, cube_2, post, thin, tall)");
  fails("r0 picks cube_0; r0 places cube_0 in bin_green",
        "t.script:1:38: unknown region 'bin_green' (world 'script_test' has bin_red, bin_blue, bin_mid)");
  fails("# nothing yet\n\n  r0 places cube_0 in bin_red", "t.script:3:13: r0 does not hold cube_0");
  fails("r0 picks cube_1; r1 places cube_1 in bin_blue", "t.script:1:28: r1 does not hold cube_1 (r0 does)");
  fails("r0 hands cube_1 to r1", "t.script:1:10: r0 does not hold cube_1");
  fails("r0 picks cube_0; r0 picks cube_1",
        "t.script:1:27: r0 already holds cube_0; place it or hand it over before picking cube_1");
  fails("r0 picks cube_1; r1 picks cube_2; r0 hands cube_1 to r1",
        "t.script:1:44: r1 already holds cube_2 and cannot receive cube_1");
  fails("r0 picks cube_1; r1 picks cube_1", "t.script:1:27: cube_1 is held by r0");
  fails("r0 hands cube_1 to r0", "t.script:1:20: r0 cannot hand an object to itself");
  fails("r0 waits", "t.script:1:10: expected a duration [s] after 'waits'");
  fails("r0 waits soon", "t.script:1:10: expected a duration [s] (a number), got 'soon'");
  fails("r0 waits -1", "t.script:1:10: a wait cannot be negative");
  fails("r0 picks cube_0 from below", "t.script:1:22: expected 'side', 'top' or 'above', got 'below'");
  fails("r0 picks cube_0 offset 0.01 0", "t.script:1:31: expected an offset DX DY DZ [m] (3 numbers) after '0'");
  fails("r0 picks cube_0 gently", "t.script:1:17: unexpected 'gently' at the end of the statement");
  fails("r0 moves to 0 0 4 0 0 0", "t.script:1:4: elbow_joint at 4.0000 rad is outside its limits [-3.1416, 3.1416] rad");
  fails("r0 moves away", "t.script:1:10: expected 'home' or 'to Q1 .. Q6', got 'away'");
  fails("r0 places cube_0 into bin_red", "t.script:1:18: expected 'in REGION' or 'at X Y Z', got 'into'");
  // unreachable: names the robot and the pose
  const std::string far = "r0 picks cube_0; r0 places cube_0 at 1.5 0.5 0.77";
  CHECK_THROWS_AS(planFromScript(testWorld(), far, "t.script"), ScriptError);
  CHECK_THROWS_WITH(planFromScript(testWorld(), far, "t.script"),
                    Catch::StartsWith("t.script:1:28: r0 cannot place cube_0 at (1.500, 0.500, 0.770) m: no IK solution") &&
                        Catch::Contains("TCP at (1.500, 0.500,"));
  CHECK_THROWS_AS(planFromScript(testWorld(), "r1 picks cube_0", "t.script"), ScriptError);
  CHECK_THROWS_WITH(planFromScript(testWorld(), "r1 picks cube_0", "t.script"),
                    Catch::StartsWith("t.script:1:10: r1 cannot pick cube_0 from above: no IK solution") &&
                        Catch::Contains("TCP at (-0.300, 0.250,"));
}

TEST_CASE("places at an explicit position are judged in the region that contains them, else as set aside", "[script]") {
  const core::World& world = *testWorld().world;
  const core::Region& bin = *world.findRegion("bin_red");
  const Eigen::Vector3d p = bin.X_WR.translation() + Eigen::Vector3d(0.02, 0.01, 0.02);
  std::ostringstream script;
  script << "r0 picks cube_0; r0 places cube_0 at " << p.x() << " " << p.y() << " " << p.z();
  const core::Plan inside = planFromScript(testWorld(), script.str());
  requireValid(inside);
  CHECK(actionOf(inside, core::ActionType::kPlace).region == "bin_red");
  const auto opens = commandsOf(inside, "r0", GripperAction::kOpen);
  CHECK((tcpByUrdf("r0", pointAt(trajectoryOf(inside, "r0"), opens.back().t)).translation() - p).norm() < 1e-9);

  const core::Plan outside = planFromScript(testWorld(), "r0 picks cube_0; r0 places cube_0 at -0.2 0.2 0.77");
  requireValid(outside);
  REQUIRE(outside.actions.size() == 2);
  CHECK(outside.actions[1].type == core::ActionType::kPlace);
  CHECK(outside.actions[1].region.empty());  // set aside: judged at rest on a stable surface
}

}  // namespace
}  // namespace dashbed::tools
