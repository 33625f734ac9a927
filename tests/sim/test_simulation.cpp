#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "controllers/joint_pd.h"
#include "core/robot_set.h"
#include "sim/plan_executor.h"
#include "sim/simulation.h"
#include "sim_test_worlds.h"

using namespace dashbed;

namespace {

double maxPoseError(const core::Pose& a, const core::Pose& b) {
  return std::max((a.translation() - b.translation()).norm(), (a.linear() - b.linear()).cwiseAbs().maxCoeff());
}

}  // namespace

TEST_CASE("Bullet's multibody reproduces the model's forward kinematics", "[sim]") {
  const core::World world = test::tableWorld(true);
  const core::RobotSet robots(world);
  sim::Simulation dut(world, robots);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), stroke(0.0, 0.025);
  for (int trial = 0; trial < 50; ++trial) {
    for (int r = 0; r < 2; ++r) {
      Eigen::VectorXd q(8);
      for (int i = 0; i < 6; ++i) q[i] = angle(rng);
      q[6] = stroke(rng);
      q[7] = stroke(rng);
      dut.setJointPositions(r, q);
      REQUIRE((dut.jointPositions(r) - q).norm() < 1e-12);
      for (int link = 0; link < static_cast<int>(robots[r].model->links().size()); ++link) {
        INFO("robot " << r << " link " << robots[r].model->links()[link].name);
        REQUIRE(maxPoseError(dut.linkPoseFromPhysics(r, link), dut.linkPose(r, link)) < 1e-9);
      }
    }
  }
}

TEST_CASE("the arm controller keeps within the effort limits and gives a diverged state no torque", "[sim]") {
  const core::World world = test::tableWorld(true);
  const core::RobotSet robots(world);
  const core::RobotModel& model = *robots[0].model;
  const controllers::JointPdController pd(model, world.controller, Eigen::Vector3d(0.0, 0.0, -9.81));
  Eigen::VectorXd q = Eigen::VectorXd::Zero(8), qd = Eigen::VectorXd::Zero(8);
  core::JointReference ref;
  ref.q[1] = 1.0;  // 1 rad off at the shoulder: far more than 150 Nm unclamped
  const controllers::ArmTorques far = pd.compute(q, qd, ref);
  CHECK(far.saturated);
  CHECK(far.max_effort_ratio > 1.0);
  for (int i = 0; i < 6; ++i) {
    CHECK(std::abs(far.tau[i]) <= model.joints()[model.movableJoints()[i]].max_effort);
  }
  q[2] = std::numeric_limits<double>::quiet_NaN();
  const controllers::ArmTorques diverged = pd.compute(q, qd, ref);
  CHECK(diverged.saturated);
  for (int i = 0; i < 6; ++i) CHECK(std::isfinite(diverged.tau[i]));
}

TEST_CASE("a robot holds its home pose under gravity for 5 s", "[sim]") {
  const core::World world = test::tableWorld(false);
  const core::RobotSet robots(world);
  sim::Simulation sim(world, robots);
  const core::Plan hold;  // no trajectory: hold home
  sim::PlanExecutor dut(sim, hold);
  const int tcp = robots[0].model->requireLink("tcp");
  const core::Pose start = sim.linkPose(0, tcp);
  double drift = 0.0;
  while (sim.time() < 5.0) {
    dut.step();
    drift = std::max(drift, (sim.linkPose(0, tcp).translation() - start.translation()).norm());
  }
  INFO("max TCP drift " << drift * 1e3 << " mm");
  CHECK(drift < 1e-3);
  CHECK(dut.tracking(0).saturated_steps == 0);
}

TEST_CASE("a cube at rest sleeps after 2 s, exactly still where it settled", "[sim]") {
  core::World world = test::tableWorld(false);
  test::addCube(world, "cube", 0.6, 0.5);
  const core::RobotSet robots(world);
  sim::Simulation sim(world, robots);
  const core::Plan hold;  // no trajectory: hold home
  sim::PlanExecutor dut(sim, hold);
  while (sim.time() < 1.0) dut.step();
  const core::Pose settled = sim.objectPose(0);
  while (sim.time() < 3.5) dut.step();
  CHECK(sim.objectLinearVelocity(0) == Eigen::Vector3d::Zero());
  CHECK((sim.objectPose(0).translation() - settled.translation()).norm() < 1e-6);
  CHECK(std::abs(sim.objectPose(0).translation().z() - 0.77) < 1e-3);
}

TEST_CASE("tracking a trajectory at the UR5e's maximum joint speed", "[sim]") {
  // every arm joint at once follows q0 + A (1 - cos(w t)) with A w = pi rad/s, the UR5e's
  // joint speed limit (UR's ROS 2 description, joint_limits.yaml), and peak acceleration
  // A w^2 = 2 pi^2 rad/s^2
  const core::World world = test::tableWorld(false);
  const core::RobotSet robots(world);
  sim::Simulation sim(world, robots);
  constexpr double kAmplitude = 0.5, kOmega = 2 * std::numbers::pi;
  core::Plan plan;
  core::RobotTrajectory trajectory{.robot = "r0", .joint_names = {}, .points = {}};
  const core::ArmConfig q0 = world.robots[0].home;
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.01 * k;
    core::TrajectoryPoint point;
    point.t = t;
    point.qd.emplace();
    for (int j = 0; j < 6; ++j) {
      // joints alternate direction so the arm stays above the table
      const double sign = (j % 2 == 0) ? 1.0 : -1.0;
      point.q[j] = q0[j] + sign * kAmplitude * (1 - std::cos(kOmega * t));
      (*point.qd)[j] = sign * kAmplitude * kOmega * std::sin(kOmega * t);
    }
    trajectory.points.push_back(point);
  }
  plan.trajectories.push_back(trajectory);
  sim::PlanExecutor dut(sim, plan);
  double peak_speed = 0.0;
  while (sim.time() < 2.5) {
    dut.step();
    peak_speed = std::max(peak_speed, sim.jointVelocities(0).head<6>().cwiseAbs().maxCoeff());
  }
  const sim::TrackingStats& stats = dut.tracking(0);
  INFO("max tracking error " << stats.max_tracking_error << " rad, peak speed " << peak_speed << " rad/s, "
                             << "max effort ratio " << stats.max_effort_ratio);
  CHECK(peak_speed > 0.99 * std::numbers::pi);
  // bound: 1 mrad, i.e. under 1 mm at the TCP for the UR5e's 0.85 m + 0.14 m gripper reach
  CHECK(stats.max_tracking_error < 1e-3);
  CHECK(stats.saturated_steps == 0);
}

TEST_CASE("Hand-E fingers pushed apart come back to equal positions", "[sim]") {
  // the rack keeps the fingers equal; in the simulation a difference appears when the coupling
  // hits its impulse limit (an object pulled out of a closed hand) and must not stay
  const core::World world = test::tableWorld(false);
  const core::RobotSet robots(world);
  sim::Simulation sim(world, robots);
  Eigen::VectorXd q = sim.jointPositions(0);
  q[6] = 0.0318;  // a difference as large as a handoff can leave (a generated 6-robot world)
  q[7] = 0.0182;
  sim.setJointPositions(0, q);
  core::Plan plan;
  plan.gripper.push_back({"r0", 0.0, core::GripperAction::kOpen, 0.0});
  sim::PlanExecutor dut(sim, plan);
  while (sim.time() < 0.5) dut.step();
  q = sim.jointPositions(0);
  INFO("fingers " << q[6] << " " << q[7]);
  // Bullet stops correcting within a fraction of a millimetre (0.36 mm / the coupling's erp)
  CHECK(std::abs(q[6] - q[7]) < 1e-3);
  CHECK(q[6] == Approx(0.025).margin(1e-3));  // and back at the open end
}

TEST_CASE("the Hand-E fingers move together and stop at the ends of their stroke", "[sim]") {
  const core::World world = test::tableWorld(false);
  const core::RobotSet robots(world);
  sim::Simulation sim(world, robots);
  core::Plan plan;
  plan.gripper.push_back({"r0", 0.0, core::GripperAction::kClose, 0.0});
  plan.gripper.push_back({"r0", 1.0, core::GripperAction::kOpen, 0.0});
  sim::PlanExecutor dut(sim, plan);
  double max_asymmetry = 0.0, min_position = 1.0;
  double closed_at = -1.0;
  while (sim.time() < 2.0) {
    dut.step();
    const Eigen::VectorXd q = sim.jointPositions(0);
    max_asymmetry = std::max(max_asymmetry, std::abs(q[6] - q[7]));
    min_position = std::min(min_position, std::min(q[6], q[7]));
    if (closed_at < 0 && q[6] < 1e-3) closed_at = sim.time();
  }
  const Eigen::VectorXd q = sim.jointPositions(0);
  INFO("max asymmetry " << max_asymmetry << " m, closed after " << closed_at << " s, final " << q[6] << " " << q[7]);
  CHECK(max_asymmetry < 1e-4);
  CHECK(min_position > -1e-3);  // stops at the closed end
  // 25 mm at the default 0.1 m/s takes 0.25 s plus the slow-down near the stop
  CHECK(closed_at > 0.2);
  CHECK(closed_at < 0.4);
  CHECK(q[6] == Approx(0.025).margin(1e-3));  // open again
}
