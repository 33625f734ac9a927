#include <catch2/catch.hpp>

#include <algorithm>
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

namespace {

// R is a proper rotation turning the direction of `from` onto that of `to`
void requireTurnsOnto(const Eigen::Matrix3d& R, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  REQUIRE((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  REQUIRE(R.determinant() == Approx(1.0).margin(1e-12));
  REQUIRE((R * from.normalized() - to.normalized()).norm() < 1e-12);
}

}  // namespace

TEST_CASE("rotationBetween turns one direction onto another by the shortest rotation", "[pose]") {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Vector3d from(gauss(rng), gauss(rng), gauss(rng));
    const Eigen::Vector3d to = 3.0 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    const Eigen::Matrix3d R = rotationBetween(from, to);
    requireTurnsOnto(R, from, to);
    // shortest: the common normal is the axis, and the angle is the one between the directions
    const Eigen::Vector3d normal = from.cross(to).normalized();
    REQUIRE((R * normal - normal).norm() < 1e-12);
    const double angle = std::acos(std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0));
    REQUIRE(angle == Approx(std::acos(from.normalized().dot(to.normalized()))).margin(1e-9));
  }
}

TEST_CASE("rotationBetween of equal and of opposite directions", "[pose]") {
  const Eigen::Vector3d d(0.3, -0.4, 1.2);
  REQUIRE((rotationBetween(d, 2.0 * d) - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  // opposite, including along x, where the half turn's axis cannot come from a cross with x
  for (const Eigen::Vector3d& from : {d, Eigen::Vector3d(Eigen::Vector3d::UnitX()),
                                      Eigen::Vector3d(Eigen::Vector3d::UnitY()),
                                      Eigen::Vector3d(-Eigen::Vector3d::UnitZ())}) {
    const Eigen::Matrix3d R = rotationBetween(from, -from);
    requireTurnsOnto(R, from, -from);
    REQUIRE(R.trace() == Approx(-1.0).margin(1e-12));  // a half turn
  }
}
