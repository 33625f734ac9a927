#include <catch2/catch.hpp>

#include <random>

#include "core/dynamics.h"
#include "core/kinematics.h"
#include "core/robot_model.h"

#include "tests/core/ur5e_hande_model.h"

using namespace dashbed::core;
using dashbed::test::ur5eHande;

namespace {

Eigen::VectorXd randomQ(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0), stroke(0.0, 0.025);
  Eigen::VectorXd q(8);
  for (int i = 0; i < 6; ++i) q[i] = angle(rng);
  q[6] = stroke(rng);
  q[7] = stroke(rng);
  return q;
}

}  // namespace

TEST_CASE("gravity torques equal the sum of J_com^T m g over the links", "[dynamics]") {
  const RobotModel& dut = ur5eHande();
  const Eigen::Vector3d g(0, 0, -9.81);
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::VectorXd q = randomQ(rng);
    Eigen::VectorXd expected = Eigen::VectorXd::Zero(8);
    for (int l = 0; l < static_cast<int>(dut.links().size()); ++l) {
      const LinkModel& link = dut.links()[l];
      if (link.mass <= 0.0) continue;
      const auto J = jacobian(dut, q, l, link.X_LCom.translation());
      // holding still needs tau = -J^T (m g)
      expected -= J.topRows<3>().transpose() * (link.mass * g);
    }
    REQUIRE((gravityTorques(dut, q, g) - expected).norm() < 1e-9);
  }
}

TEST_CASE("a payload adds its weight and its kinetic energy to the link carrying it", "[dynamics]") {
  const RobotModel& dut = ur5eHande();
  const Eigen::Vector3d g(0, 0, -9.81);
  Payload payload;
  payload.link = dut.requireLink("tcp");
  payload.mass = 0.7;
  payload.X_LCom.translation() = Eigen::Vector3d(0.01, -0.02, 0.03);
  payload.X_LCom.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  payload.inertia = Eigen::Vector3d(2e-3, 3e-3, 4e-3).asDiagonal();
  std::mt19937_64 rng(5);
  std::normal_distribution<double> rate(0.0, 1.0);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(8);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd q = randomQ(rng);
    const Eigen::MatrixXd J = jacobian(dut, q, payload.link, payload.X_LCom.translation());
    // holding it still: -J^T (m g) more
    const Eigen::VectorXd weight = inverseDynamics(dut, q, zero, zero, g, &payload) - gravityTorques(dut, q, g);
    REQUIRE((weight + J.topRows<3>().transpose() * (payload.mass * g)).norm() < 1e-9);
    // moving: 0.5 qd^T M qd with the payload = the robot's kinetic energy + the payload's
    Eigen::MatrixXd M(8, 8);
    for (int k = 0; k < 8; ++k) {
      M.col(k) = inverseDynamics(dut, q, zero, Eigen::VectorXd::Unit(8, k), Eigen::Vector3d::Zero(), &payload);
    }
    Eigen::VectorXd qd(8);
    for (int i = 0; i < 8; ++i) qd[i] = rate(rng);
    const Eigen::Vector3d v = J.topRows<3>() * qd, w = J.bottomRows<3>() * qd;
    const Eigen::Matrix3d R_RC = linkPoses(dut, q)[static_cast<std::size_t>(payload.link)].linear() *
                                 payload.X_LCom.linear();
    const double payload_energy =
        0.5 * payload.mass * v.squaredNorm() + 0.5 * w.dot(R_RC * payload.inertia * R_RC.transpose() * w);
    REQUIRE(0.5 * qd.dot(M * qd) == Approx(kineticEnergy(dut, q, qd) + payload_energy).epsilon(1e-10));
  }
}

TEST_CASE("mass matrix is symmetric positive definite and matches the kinetic energy", "[dynamics]") {
  const RobotModel& dut = ur5eHande();
  std::mt19937_64 rng(4);
  std::normal_distribution<double> rate(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::VectorXd q = randomQ(rng);
    const Eigen::MatrixXd M = massMatrix(dut, q);
    REQUIRE(Eigen::LLT<Eigen::MatrixXd>(M).info() == Eigen::Success);
    Eigen::VectorXd qd(8);
    for (int i = 0; i < 8; ++i) qd[i] = rate(rng);
    REQUIRE(0.5 * qd.dot(M * qd) == Approx(kineticEnergy(dut, q, qd)).epsilon(1e-10));
  }
}

TEST_CASE("free motion computed from RNEA conserves energy (Coriolis terms)", "[dynamics]") {
  const RobotModel& dut = ur5eHande();
  std::mt19937_64 rng(6);
  std::normal_distribution<double> rate(0.0, 1.0);
  const Eigen::Vector3d no_gravity = Eigen::Vector3d::Zero();
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd q = randomQ(rng);
    Eigen::VectorXd qd(8);
    for (int i = 0; i < 8; ++i) qd[i] = rate(rng);
    // zero effort: M qdd = -(C qd)
    const Eigen::VectorXd bias = inverseDynamics(dut, q, qd, Eigen::VectorXd::Zero(8), no_gravity);
    const Eigen::VectorXd qdd = massMatrix(dut, q).ldlt().solve(-bias);
    constexpr double h = 1e-6;
    const double dT = (kineticEnergy(dut, q + h * qd, qd + h * qdd) - kineticEnergy(dut, q - h * qd, qd - h * qdd)) / (2 * h);
    REQUIRE(std::abs(dT) < 1e-6 * (1.0 + kineticEnergy(dut, q, qd)));
  }
}

TEST_CASE("the arm's moving mass matches UR's published link masses", "[dynamics]") {
  const RobotModel& dut = ur5eHande();
  double arm = 0.0;
  for (const char* name : {"shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"}) {
    arm += dut.links()[dut.requireLink(name)].mass;
  }
  CHECK(arm == Approx(17.7).margin(1e-9));  // sum of the link masses on UR's DH-parameters page
}
