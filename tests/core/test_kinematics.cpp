#include <catch2/catch.hpp>

#include <array>
#include <random>

#include "core/kinematics.h"
#include "core/robot_model.h"
#include "core/ur_ik.h"

#include "tests/core/ur5e_hande_model.h"

using namespace dashbed::core;
using dashbed::test::ur5eHande;

namespace {

Eigen::VectorXd fullQ(const ArmConfig& arm) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(ur5eHande().numPositions());
  for (int i = 0; i < 6; ++i) q[i] = arm[i];
  return q;
}

struct FkCase {
  const char* name;
  ArmConfig q;
  Eigen::Vector3d p;  // tool0 position in base_link [m]
  std::array<std::array<double, 3>, 3> R;  // tool0 rotation in base_link, row by row
};

// FK reference cases computed from UR's DH table (UR's DH-parameters page, universal-robots.com)
// and cross-checked against UR's ROS 2 description
// (github.com/UniversalRobots/Universal_Robots_ROS2_Description), tool0 in base_link.
const std::array<FkCase, 7> kCases{{
    {"zero", {0, 0, 0, 0, 0, 0}, {0.8172, 0.2329, 0.0628}, {{{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}}},
    {"upright", {0.0, -1.570796326795, 0.0, -1.570796326795, 0.0, 0.0}, {0.0, 0.2329, 1.0794},
     {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}}},
    {"ready", {0.0, -1.570796326795, 1.570796326795, -1.570796326795, -1.570796326795, 0.0},
     {0.4919, 0.1333, 0.4879}, {{{0, -1, 0}, {-1, 0, 0}, {0, 0, -1}}}},
    {"mixed_a", {1.570796326795, -0.785398163397, 1.047197551197, -1.570796326795, -1.570796326795, 0.523598775598},
     {-0.1333, 0.749880919, 0.239501081},
     {{{0.866025404, -0.5, 0.0}, {-0.482962913, -0.836516304, -0.258819045}, {0.129409523, 0.224143868, -0.965925826}}}},
    {"mixed_b", {0.1, -1.2, 1.5, -1.9, -1.57, 0.3}, {0.614781439, 0.195732895, 0.34606728},
     {{{-0.198521879, -0.979668088, 0.028974137}, {-0.980051479, 0.198709219, 0.003707436},
       {-0.009389484, -0.027660139, -0.999573286}}}},
    {"mixed_c", {-1.0, -2.0, 2.2, -0.2, 1.2, -2.5}, {0.3048177, -0.161214226, 0.371333295},
     {{{-0.471473913, 0.352201525, 0.808496404}, {-0.647721732, 0.483862576, -0.588501117},
       {-0.598472144, -0.801143616, 0.0}}}},
    {"mixed_d", {2.5, -0.7, -1.4, 3.0, 0.8, 1.1}, {-0.19611053, -0.106504374, 0.656901054},
     {{{-0.596641224, -0.211259086, -0.774202072}, {0.039547481, 0.955815776, -0.291294009},
       {0.80153306, -0.204415756, -0.56192433}}}},
}};

}  // namespace

TEST_CASE("URDF forward kinematics reproduces every reference case", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  const int tool0 = dut.requireLink("tool0");
  for (const FkCase& c : kCases) {
    INFO("case " << c.name);
    const Pose X_RTool0 = linkPoses(dut, fullQ(c.q))[tool0];
    // the reference values carry 9 decimals, so they are exact to 5e-10
    CHECK((X_RTool0.translation() - c.p).cwiseAbs().maxCoeff() < 1e-9);
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 3; ++k) CHECK(std::abs(X_RTool0.linear()(r, k) - c.R[r][k]) < 1e-9);
    }
  }
}

TEST_CASE("the URDF frame chain agrees with the DH model everywhere", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  const int base = dut.requireLink("base");
  const int tool0 = dut.requireLink("tool0");
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-6.28, 6.28);
  for (int i = 0; i < 2000; ++i) {
    ArmConfig q;
    for (double& v : q) v = angle(rng);
    const std::vector<Pose> X = linkPoses(dut, fullQ(q));
    const Pose X_BaseTool0 = X[base].inverse() * X[tool0];
    const Pose T_06 = urForwardKinematics(kUr5eDh, q);
    REQUIRE((X_BaseTool0.matrix() - T_06.matrix()).cwiseAbs().maxCoeff() < 1e-12);
  }
}

TEST_CASE("the model has the UR5e + Hand-E structure", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  REQUIRE(dut.numPositions() == 8);
  const std::array<const char*, 8> names{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                         "wrist_1_joint", "wrist_2_joint", "wrist_3_joint",
                                         "hande_left_finger_joint", "hande_right_finger_joint"};
  for (int i = 0; i < 8; ++i) CHECK(dut.joints()[dut.movableJoints()[i]].name == names[i]);
  // the TCP is 11 mm (coupling) + 132.5 mm (Hand-E) along tool0's z
  const Pose X = dut.fixedTransform(dut.requireLink("tool0"), dut.requireLink("tcp"));
  CHECK((X.translation() - Eigen::Vector3d(0, 0, 0.1435)).norm() < 1e-12);
  CHECK(X.linear().isIdentity(1e-12));
}

TEST_CASE("finger joints open the pads symmetrically along the TCP x axis", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(8);
  q[6] = q[7] = 0.02;
  const std::vector<Pose> X = linkPoses(dut, q);
  const Pose X_TL = X[dut.requireLink("tcp")].inverse() * X[dut.requireLink("hande_left_finger")];
  const Pose X_TR = X[dut.requireLink("tcp")].inverse() * X[dut.requireLink("hande_right_finger")];
  CHECK(X_TL.translation().x() == Approx(0.02));
  CHECK(X_TR.translation().x() == Approx(-0.02));
  CHECK(X_TL.translation().y() == Approx(-X_TR.translation().y()).margin(1e-12));
}

TEST_CASE("geometric Jacobian matches central finite differences", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  const int tcp = dut.requireLink("tcp");
  const int finger = dut.requireLink("hande_left_finger");
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), stroke(0.0, 0.025);
  constexpr double h = 1e-6;
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd q(8);
    for (int i = 0; i < 6; ++i) q[i] = angle(rng);
    q[6] = stroke(rng);
    q[7] = stroke(rng);
    for (const int link : {tcp, finger}) {
      const Eigen::Vector3d p_LP(0.01, -0.02, 0.03);
      const auto J = jacobian(dut, q, link, p_LP);
      for (int k = 0; k < 8; ++k) {
        Eigen::VectorXd qp = q, qm = q;
        qp[k] += h;
        qm[k] -= h;
        const Pose Xp = linkPoses(dut, qp)[link], Xm = linkPoses(dut, qm)[link];
        const Eigen::Vector3d v = (Xp * p_LP - Xm * p_LP) / (2 * h);
        // angular velocity from the rotation difference: skew(w) ~ (Rp - Rm) Rc^T / 2h
        const Eigen::Matrix3d dR = (Xp.linear() - Xm.linear()) / (2 * h) * linkPoses(dut, q)[link].linear().transpose();
        const Eigen::Vector3d w(dR(2, 1), dR(0, 2), dR(1, 0));
        REQUIRE((J.col(k).head<3>() - v).norm() < 1e-7);
        REQUIRE((J.col(k).tail<3>() - w).norm() < 1e-7);
      }
    }
  }
}

TEST_CASE("bad inputs to the kinematics throw", "[kinematics]") {
  const RobotModel& dut = ur5eHande();
  REQUIRE_THROWS_AS(linkPoses(dut, Eigen::VectorXd::Zero(3)), std::invalid_argument);
  REQUIRE_THROWS_AS(jacobian(dut, Eigen::VectorXd::Zero(8), 999), std::invalid_argument);
  REQUIRE_THROWS_AS(dut.requireLink("no_such_link"), std::out_of_range);
  REQUIRE_THROWS_WITH(RobotModel::fromUrdfFile("/nonexistent/robot.urdf"),
                      Catch::Matchers::Contains("/nonexistent/robot.urdf"));
}
