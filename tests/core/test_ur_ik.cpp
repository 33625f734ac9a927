#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "core/kinematics.h"
#include "core/robot_model.h"
#include "core/ur_ik.h"

#include "tests/core/ur5e_hande_model.h"

using namespace dashbed::core;
using dashbed::test::ur5eHande;

namespace {

double poseError(const Pose& a, const Pose& b) {
  return std::max((a.translation() - b.translation()).cwiseAbs().maxCoeff(),
                  (a.linear() - b.linear()).cwiseAbs().maxCoeff());
}

bool sameModTwoPi(const ArmConfig& a, const ArmConfig& b, double tol) {
  for (int i = 0; i < 6; ++i) {
    if (std::abs(wrapToPi(a[i] - b[i])) > tol) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("IK -> FK round trip on 10000 seeded random configurations", "[ik]") {
  const UrArmIk dut(ur5eHande());
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> wide(-2 * std::numbers::pi, 2 * std::numbers::pi);
  std::uniform_real_distribution<double> elbow(-std::numbers::pi, std::numbers::pi);
  int total_solutions = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    ArmConfig q{wide(rng), wide(rng), elbow(rng), wide(rng), wide(rng), wide(rng)};
    const Pose X_RT = dut.tcpPose(q);
    const std::vector<ArmConfig> solutions = dut.solve(X_RT);
    REQUIRE(!solutions.empty());
    REQUIRE(solutions.size() <= 8);
    total_solutions += static_cast<int>(solutions.size());
    bool found = false;
    for (const ArmConfig& s : solutions) {
      REQUIRE(poseError(dut.tcpPose(s), X_RT) < 1e-9);
      found = found || sameModTwoPi(s, q, 1e-6);
    }
    INFO("trial " << trial);
    REQUIRE(found);
  }
  // generic poses of a UR arm have 8 solutions; nearly all random samples are generic
  CHECK(total_solutions > 7 * 10000);
}

TEST_CASE("tcpPose agrees with the URDF forward kinematics of the tcp link", "[ik]") {
  const UrArmIk dut(ur5eHande());
  const int tcp = ur5eHande().requireLink("tcp");
  const ArmConfig q{0.4, -1.3, 1.1, -1.4, -1.6, 0.7};
  Eigen::VectorXd full = Eigen::VectorXd::Zero(8);
  for (int i = 0; i < 6; ++i) full[i] = q[i];
  CHECK(poseError(dut.tcpPose(q), linkPoses(ur5eHande(), full)[tcp]) < 1e-12);
}

TEST_CASE("nearest-to-seed picks the closest 2pi representative within limits", "[ik]") {
  const UrArmIk dut(ur5eHande());
  const ArmConfig q{5.5, -1.2, 1.5, -1.9 + 2 * std::numbers::pi, -1.57, 4.0};
  const Pose X_RT = dut.tcpPose(q);
  const auto best = dut.nearest(X_RT, q);
  REQUIRE(best.has_value());
  for (int i = 0; i < 6; ++i) CHECK((*best)[i] == Approx(q[i]).margin(1e-9));
  // every solution is within the limits and sorted by distance to the seed
  const auto all = dut.solveNearest(X_RT, q);
  double previous = 0.0;
  for (const ArmConfig& s : all) {
    double d = 0.0;
    for (int i = 0; i < 6; ++i) {
      CHECK(s[i] >= dut.lower()[i]);
      CHECK(s[i] <= dut.upper()[i]);
      d += (s[i] - q[i]) * (s[i] - q[i]);
    }
    CHECK(d >= previous);
    previous = d;
  }
}

TEST_CASE("unreachable poses have no solution", "[ik]") {
  const UrArmIk dut(ur5eHande());
  Pose far = Pose::Identity();
  far.translation() = Eigen::Vector3d(1.5, 0.0, 0.3);
  CHECK(dut.solve(far).empty());
  CHECK(!dut.nearest(far, ArmConfig{}).has_value());
  // inside the shoulder cylinder: the wrist centre can't get closer than d4 to the base axis
  Pose inside = Pose::Identity();
  inside.translation() = Eigen::Vector3d(0.0, 0.0, 0.9);
  inside.linear() = Eigen::Matrix3d::Identity();
  CHECK(dut.solve(inside).empty());
}
