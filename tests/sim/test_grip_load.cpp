// The grip's friction load: patch geometry against independent integrals, loads against
// statics worked by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "sim/grip_load.h"

using namespace dashbed;
using namespace dashbed::sim;

namespace {

/// A 22 x 25 mm pad face at `centre` pressing along -x (its normal into the object), turned
/// by `roll` about that normal.
PadFace padAt(const Eigen::Vector3d& centre, double roll = 0.0) {
  PadFace face;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(roll, -Eigen::Vector3d::UnitX()).toRotationMatrix();
  face.X_WF.linear().col(0) = turn * Eigen::Vector3d::UnitZ();
  face.X_WF.linear().col(1) = turn * Eigen::Vector3d::UnitY();
  face.X_WF.linear().col(2) = -Eigen::Vector3d::UnitX();
  face.X_WF.translation() = centre;
  face.half = Eigen::Vector2d(0.0125, 0.011);
  return face;
}

/// The mean distance from the centre of a w x h rectangle, by Monte Carlo.
double meanRadius(double w, double h) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> x(-w / 2, w / 2), y(-h / 2, h / 2);
  double sum = 0.0;
  constexpr int kSamples = 400000;
  for (int i = 0; i < kSamples; ++i) sum += std::hypot(x(rng), y(rng));
  return sum / kSamples;
}

}  // namespace

TEST_CASE("a pad's patch on a box face: area, centre and mean radius of the overlap", "[sim][grip]") {
  // a 40 mm cube at the origin; the pad on its +x face (x = 0.02)
  const core::Pose X_WO = core::Pose::Identity();
  const Eigen::Vector3d cube(0.04, 0.04, 0.04);
  const Patch full = padPatch(padAt({0.02, 0.0, 0.0}), X_WO, cube);
  CHECK(full.area == Approx(0.022 * 0.025).epsilon(1e-9));
  CHECK((full.centre_W - Eigen::Vector3d(0.02, 0.0, 0.0)).norm() < 1e-12);
  CHECK(full.mean_radius == Approx(meanRadius(0.025, 0.022)).epsilon(0.01));
  // slid 15 mm along z: 25 mm of pad, 20 - (15 - 12.5) = 17.5 mm on the face
  const Patch edge = padPatch(padAt({0.02, 0.0, 0.015}), X_WO, cube);
  CHECK(edge.area == Approx(0.022 * 0.0175).epsilon(1e-9));
  CHECK(edge.centre_W.z() == Approx(0.02 - 0.0175 / 2).epsilon(1e-9));
  CHECK(edge.mean_radius == Approx(meanRadius(0.0175, 0.022)).epsilon(0.01));
  // off the face: nothing
  CHECK(padPatch(padAt({0.02, 0.0, 0.05}), X_WO, cube).area == 0.0);
  // turned about its normal on a large face: all of it, still centred
  const Patch turned = padPatch(padAt({0.05, 0.0, 0.0}, 0.7), X_WO, Eigen::Vector3d(0.1, 0.2, 0.2));
  CHECK(turned.area == Approx(0.022 * 0.025).epsilon(1e-9));
  CHECK((turned.centre_W - Eigen::Vector3d(0.05, 0.0, 0.0)).norm() < 1e-12);
  // the object turned so that another of its faces meets the pad: the face turned towards it
  core::Pose X_turned = core::Pose::Identity();
  X_turned.linear() = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Patch other = padPatch(padAt({0.02, 0.0, 0.0}), X_turned, Eigen::Vector3d(0.06, 0.04, 0.04));
  CHECK(other.area == Approx(0.022 * 0.025).epsilon(1e-9));
}

TEST_CASE("a grip's load: gravity across the closing axis, torsion of an off-centre mass", "[sim][grip]") {
  const Eigen::Vector3d gravity(0.0, 0.0, -9.81);
  const double mu = 0.8, squeeze = 60.0, rho = 0.009;
  PadContact left{squeeze, 5.5e-4, rho, Eigen::Vector3d(-0.02, 0.0, 0.0)};
  PadContact right{squeeze, 5.5e-4, rho, Eigen::Vector3d(0.02, 0.0, 0.0)};
  HeldMotion held;
  held.mass = 1.6;
  // centred and still: friction carries the weight, nothing twists
  const GripLoad centred = gripLoad(left, right, Eigen::Vector3d::UnitX(), mu, held, gravity);
  CHECK(centred.tangential_force == Approx(1.6 * 9.81));
  CHECK(centred.torsion == Approx(0.0).margin(1e-12));
  CHECK(centred.use == Approx(1.6 * 9.81 / (mu * 2 * squeeze)));
  // 4 cm off-centre along y: the weight twists the grip about x by m g d
  held.com_W = Eigen::Vector3d(0.0, 0.04, 0.0);
  const GripLoad off = gripLoad(left, right, Eigen::Vector3d::UnitX(), mu, held, gravity);
  CHECK(off.torsion == Approx(1.6 * 9.81 * 0.04));
  CHECK(off.use == Approx(std::hypot(1.6 * 9.81 / (mu * 2 * squeeze), 1.6 * 9.81 * 0.04 / (mu * 2 * squeeze * rho))));
  // accelerating upwards at g doubles the force the pads' friction must give
  held.com_W.setZero();
  held.acceleration_W = Eigen::Vector3d(0.0, 0.0, 9.81);
  CHECK(gripLoad(left, right, Eigen::Vector3d::UnitX(), mu, held, gravity).tangential_force == Approx(2 * 1.6 * 9.81));
  // along the closing axis the normal forces carry the load: no friction needed
  held.acceleration_W = Eigen::Vector3d::Zero();
  const GripLoad along = gripLoad(left, right, Eigen::Vector3d::UnitZ(), mu, held, gravity);
  CHECK(along.tangential_force == Approx(0.0).margin(1e-12));
  // pads that press with nothing cannot hold a load
  left.normal_force = right.normal_force = 0.0;
  CHECK(std::isinf(gripLoad(left, right, Eigen::Vector3d::UnitX(), mu, held, gravity).use));
}
