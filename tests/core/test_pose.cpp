#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "core/pose.h"

using namespace dashbed::core;

TEST_CASE("rpy round trip away from the pitch singularity", "[pose]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-3.1, 3.1), pitch(-1.5, 1.5);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d rpy(angle(rng), pitch(rng), angle(rng));
    const Eigen::Vector3d back = rpyFromRotation(rotationFromRpy(rpy));
    REQUIRE((back - rpy).norm() < 1e-12);
  }
}

TEST_CASE("rpy is fixed-axis roll, then pitch, then yaw", "[pose]") {
  // a pure yaw of +90 deg turns x into y
  const Eigen::Matrix3d R = rotationFromRpy({0.0, 0.0, std::numbers::pi / 2});
  REQUIRE((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm() < 1e-15);
  // roll first: roll 90 then yaw 90 maps z -> -y (roll) -> x (yaw)
  const Eigen::Matrix3d R2 = rotationFromRpy({std::numbers::pi / 2, 0.0, std::numbers::pi / 2});
  REQUIRE((R2 * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm() < 1e-15);
}

TEST_CASE("wrapToPi maps angles into the interval from -pi (open) to pi (closed)", "[pose]") {
  REQUIRE(wrapToPi(std::numbers::pi) == Approx(std::numbers::pi));
  REQUIRE(wrapToPi(-std::numbers::pi) == Approx(std::numbers::pi));
  REQUIRE(wrapToPi(3 * std::numbers::pi / 2) == Approx(-std::numbers::pi / 2));
  REQUIRE(wrapToPi(-7.0) == Approx(-7.0 + 2 * std::numbers::pi));
}
