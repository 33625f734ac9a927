#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/readiness.h"
#include "core/trajectory_interpolator.h"
#include "core/world_io.h"
#include "core/world_loader.h"

using namespace dashbed::core;

namespace {

World defaultWorld() { return loadWorldFile(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml"); }

/// A plan for robot r0 of `world` from home: joint `joint` follows `q` (offsets from home) at
/// times `t`, with optional tangents `qd`.
Plan onePlan(const World& world, const RobotSet& robots, int joint, const std::vector<double>& t,
             const std::vector<double>& q, const std::vector<double>& qd = {}) {
  Plan plan;
  plan.world = world.name;
  RobotTrajectory trajectory;
  trajectory.robot = world.robots[0].name;
  const RobotModel& model = *robots[0].model;
  for (int j = 0; j < 6; ++j) trajectory.joint_names[j] = model.joints()[model.movableJoints()[j]].name;
  for (std::size_t k = 0; k < t.size(); ++k) {
    TrajectoryPoint point;
    point.t = t[k];
    point.q = world.robots[0].home;
    point.q[joint] += q[k];
    if (!qd.empty()) {
      ArmConfig v{};
      v[joint] = qd[k];
      point.qd = v;
    }
    trajectory.points.push_back(point);
  }
  plan.trajectories.push_back(trajectory);
  return plan;
}

const ReadinessCheck& named(const ReadinessReport& report, const std::string& name) {
  for (const ReadinessCheck& c : report.checks) {
    if (c.name == name) return c;
  }
  FAIL("no check " << name);
  return report.checks.front();
}

}  // namespace

TEST_CASE("curve peaks are the extremes of densely sampled curves", "[readiness]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<TrajectoryPoint> points;
    double t = 0.0;
    for (int k = 0; k < 6; ++k) {
      TrajectoryPoint p;
      p.t = t;
      for (int j = 0; j < 6; ++j) p.q[j] = unit(rng);
      if (trial % 2 == 0) {
        ArmConfig v{};
        for (int j = 0; j < 6; ++j) v[j] = 2.0 * unit(rng);
        p.qd = v;
      }
      points.push_back(p);
      t += 0.2 + 0.5 * (1.0 + unit(rng));
    }
    const TrajectoryInterpolator dut(points);
    const std::array<JointPeaks, 6> peaks = dut.peaks();
    std::array<JointPeaks, 6> sampled{};
    for (int j = 0; j < 6; ++j) sampled[j].q_min = sampled[j].q_max = points.front().q[j];
    // every 1e-4 s, and each knot approached from both sides (the curve holds still before its
    // start and after its end, so a velocity given there is reached only just inside)
    std::vector<double> times;
    for (int k = 0; k * 1e-4 < dut.endTime(); ++k) times.push_back(k * 1e-4);
    for (const TrajectoryPoint& p : points) {
      times.push_back(std::max(dut.startTime(), p.t - 1e-12));
      times.push_back(std::min(dut.endTime(), p.t + 1e-12));
    }
    for (const double s : times) {
      const JointReference ref = dut.at(s);
      for (int j = 0; j < 6; ++j) {
        sampled[j].q_min = std::min(sampled[j].q_min, ref.q[j]);
        sampled[j].q_max = std::max(sampled[j].q_max, ref.q[j]);
        sampled[j].speed = std::max(sampled[j].speed, std::abs(ref.qd[j]));
        sampled[j].acceleration = std::max(sampled[j].acceleration, std::abs(ref.qdd[j]));
      }
    }
    for (int j = 0; j < 6; ++j) {
      // the exact extremes bound the samples and are within a sample step of them
      CHECK(peaks[j].q_min <= sampled[j].q_min + 1e-12);
      CHECK(peaks[j].q_min == Approx(sampled[j].q_min).margin(1e-6));
      CHECK(peaks[j].q_max >= sampled[j].q_max - 1e-12);
      CHECK(peaks[j].q_max == Approx(sampled[j].q_max).margin(1e-6));
      CHECK(peaks[j].speed >= sampled[j].speed - 1e-9);
      CHECK(peaks[j].speed == Approx(sampled[j].speed).margin(1e-4));
      CHECK(peaks[j].acceleration >= sampled[j].acceleration - 1e-6);
      CHECK(peaks[j].acceleration == Approx(sampled[j].acceleration).epsilon(2e-3).margin(1e-2));
      // and the reference there has the value reported
      const double inside = std::clamp(peaks[j].t_speed, dut.startTime() + 1e-12, dut.endTime() - 1e-12);
      CHECK(std::abs(dut.at(inside).qd[j]) == Approx(peaks[j].speed).margin(1e-6));
    }
  }
}

TEST_CASE("readiness judges the curve, not the points: a peak between points fails", "[readiness]") {
  const World world = defaultWorld();
  const LoadedWorld loaded = validateWorld(world);
  // 2.5 rad in 1 s: every point and the average (2.5 rad/s) within the 3.14 rad/s limit, the
  // curve through them (at rest at both ends) peaks at 1.5 x the average
  const Plan fast = onePlan(*loaded.world, *loaded.robots, 0, {0.0, 1.0}, {0.0, 2.5});
  const ReadinessReport report = checkReadiness(fast, *loaded.world, *loaded.robots);
  CHECK_FALSE(report.ready());
  const ReadinessCheck& speed = named(report, "joint speed");
  CHECK_FALSE(speed.passed);
  CHECK(speed.value == Approx(3.75));
  CHECK(speed.t == Approx(0.5));
  CHECK(speed.subject == "r0 shoulder_pan_joint");
  CHECK_THAT(speed.detail, Catch::Matchers::Contains("3.75 rad/s") && Catch::Matchers::Contains("3.142 rad/s"));
  // 15 rad/s^2 at the ends of that cubic: above the 5 rad/s^2 default
  CHECK_FALSE(named(report, "joint acceleration").passed);
  CHECK(named(report, "joint acceleration").value == Approx(15.0));

  // given tangents may make a curve overshoot between points that are within the limits
  const Plan tangents = onePlan(*loaded.world, *loaded.robots, 1, {0.0, 2.0, 4.0}, {0.0, 1.0, 0.0}, {0.0, 3.0, 0.0});
  const ReadinessReport overshoot = checkReadiness(tangents, *loaded.world, *loaded.robots);
  CHECK(named(overshoot, "joint speed").passed);
  CHECK(named(overshoot, "joint speed").value == Approx(3.0));

  // slow enough: ready
  const Plan slow = onePlan(*loaded.world, *loaded.robots, 0, {0.0, 2.0}, {0.0, 1.0});
  const ReadinessReport fine = checkReadiness(slow, *loaded.world, *loaded.robots);
  CHECK(fine.ready());
  CHECK(named(fine, "joint speed").value == Approx(0.75));
  CHECK(named(fine, "joint acceleration").value == Approx(1.5));
  // the position check names the joint that came nearest its limits, with its extreme
  const ReadinessCheck& position = named(fine, "joint position");
  CHECK_THAT(position.subject, Catch::Matchers::StartsWith("r0 "));
  CHECK(std::abs(position.value) <= std::abs(position.limit));
  CHECK(std::abs(position.limit) > 3.0);
  // holding still at home takes the shoulder-lift torque against gravity, well within 150 Nm
  const ReadinessCheck& effort = named(fine, "joint effort");
  CHECK(effort.passed);
  CHECK(effort.subject == "r0 shoulder_lift_joint");
  CHECK(effort.value > 10.0);
  CHECK(effort.limit == 150.0);
}

TEST_CASE("readiness: a wrist whipped round needs more than its 28 Nm", "[readiness]") {
  const LoadedWorld loaded = validateWorld(defaultWorld());
  // wrist 1 (28 Nm) swung by 0.3 rad in 50 ms from rest to rest: 720 rad/s^2 at the ends
  const Plan whip = onePlan(*loaded.world, *loaded.robots, 3, {0.0, 0.05}, {0.0, 0.3});
  const ReadinessReport report = checkReadiness(whip, *loaded.world, *loaded.robots);
  const ReadinessCheck& effort = named(report, "joint effort");
  CHECK_FALSE(effort.passed);
  CHECK_THAT(effort.detail, Catch::Matchers::Contains("above its limit 28 Nm"));
}

TEST_CASE("readiness refuses gripper forces outside the Hand-E's range instead of clamping", "[readiness]") {
  const LoadedWorld loaded = validateWorld(defaultWorld());
  Plan plan = onePlan(*loaded.world, *loaded.robots, 0, {0.0, 4.0}, {0.0, 0.5});
  plan.gripper.push_back({"r0", 1.0, GripperAction::kClose, 5.0});
  plan.gripper.push_back({"r0", 2.0, GripperAction::kOpen, 0.0});
  plan.gripper.push_back({"r0", 3.0, GripperAction::kClose, 0.0});  // the world's grip force
  ReadinessReport report = checkReadiness(plan, *loaded.world, *loaded.robots);
  CHECK_FALSE(report.ready());
  CHECK(named(report, "gripper force").value == 5.0);
  CHECK(named(report, "gripper force").limit == 20.0);
  CHECK_THAT(report.failures(), Catch::Matchers::Contains("asks for 5 N, outside the Hand-E's 20-185 N"));
  plan.gripper[0].force = 185.0;
  CHECK(checkReadiness(plan, *loaded.world, *loaded.robots).ready());
  plan.gripper[0].force = 186.0;
  CHECK_FALSE(checkReadiness(plan, *loaded.world, *loaded.robots).ready());
}

TEST_CASE("readiness checks the payload at the flange and the grip by friction", "[readiness]") {
  World world = defaultWorld();
  const std::string object = world.objects[0].name;
  Plan base;
  {
    const LoadedWorld loaded = validateWorld(world);
    base = onePlan(*loaded.world, *loaded.robots, 0, {0.0, 4.0}, {0.0, 0.5});
  }
  base.gripper.push_back({"r0", 1.0, GripperAction::kClose, 0.0});
  base.actions.push_back({ActionType::kPick, "r0", "", object, "", 0.5, 3.0});

  SECTION("a light cube: both pass, the gripper's own mass counted") {
    const LoadedWorld loaded = validateWorld(world);
    const ReadinessReport report = checkReadiness(base, *loaded.world, *loaded.robots);
    CHECK(report.ready());
    // coupling 0.119 + Hand-E 0.86387 + fingers 2 x 0.03804 kg (the URDF's masses)
    CHECK(named(report, "payload").value == Approx(0.119 + 0.86387 + 2 * 0.03804 + world.objects[0].mass));
  }
  SECTION("8 kg: above the rated 5 kg, and more than the grip holds") {
    world.objects[0].mass = 8.0;
    const LoadedWorld loaded = validateWorld(world);
    const ReadinessReport report = checkReadiness(base, *loaded.world, *loaded.robots);
    CHECK_FALSE(named(report, "payload").passed);
    CHECK_THAT(named(report, "payload").detail, Catch::Matchers::Contains("above the UR5e's rated 5 kg"));
    // 2 x 60 N x friction / g
    const double holds = 2 * world.controller.grip_force * world.objects[0].friction * world.physics.pad_friction /
                         world.physics.gravity.norm();
    CHECK(named(report, "grip").limit == Approx(holds));
    CHECK(named(report, "grip").passed == (8.0 <= holds));
  }
}
