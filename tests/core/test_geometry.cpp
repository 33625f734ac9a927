#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "core/geometry.h"

using namespace dashbed::core;

namespace {

Box makeBox(const Eigen::Vector3d& center, const Eigen::Vector3d& rpy, const Eigen::Vector3d& size) {
  return Box{makePose(center, rpy), size};
}

// the point of the box nearest to p_W (clamping in the box frame)
Eigen::Vector3d projectOntoBox(const Box& box, const Eigen::Vector3d& p_W) {
  const Eigen::Vector3d half = 0.5 * box.size;
  const Eigen::Vector3d p_B = box.X_WB.inverse(Eigen::Isometry) * p_W;
  return box.X_WB * p_B.cwiseMax(-half).cwiseMin(half);
}

// distance between two boxes by alternating projections (von Neumann): converges to a pair
// of nearest points, so to 0 for intersecting boxes. Independent of the separating axis test.
double distanceByProjections(const Box& a, const Box& b) {
  Eigen::Vector3d p = a.X_WB.translation();
  Eigen::Vector3d q = projectOntoBox(b, p);
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d p_next = projectOntoBox(a, q);
    const Eigen::Vector3d q_next = projectOntoBox(b, p_next);
    const bool settled = (p_next - p).norm() + (q_next - q).norm() < 1e-14;
    p = p_next;
    q = q_next;
    if (settled) break;
  }
  return (p - q).norm();
}

}  // namespace

TEST_CASE("axis-aligned boxes: depth is the smallest interval overlap", "[geometry]") {
  const Box a = makeBox({0, 0, 0}, {0, 0, 0}, {1.0, 2.0, 3.0});
  SECTION("apart along x") {
    const Box b = makeBox({1.5, 0, 0}, {0, 0, 0}, {1.0, 1.0, 1.0});
    CHECK(boxPenetrationDepth(a, b) == Approx(-0.5));
    CHECK_FALSE(boxesOverlap(a, b));
  }
  SECTION("touching faces count as no overlap") {
    const Box b = makeBox({1.0, 0, 0}, {0, 0, 0}, {1.0, 1.0, 1.0});
    CHECK(boxPenetrationDepth(a, b) == Approx(0.0).margin(1e-15));
    CHECK_FALSE(boxesOverlap(a, b, 0.0));
  }
  SECTION("shallow overlap below the tolerance") {
    const Box b = makeBox({0.9995, 0, 0}, {0, 0, 0}, {1.0, 1.0, 1.0});
    CHECK(boxPenetrationDepth(a, b) == Approx(0.0005));
    CHECK_FALSE(boxesOverlap(a, b, 0.001));
    CHECK(boxesOverlap(a, b, 0.0));
  }
  SECTION("deep overlap picks the shallowest direction") {
    const Box b = makeBox({0.2, 0.1, 1.3}, {0, 0, 0}, {0.5, 0.5, 0.5});
    // z: 1.5 + 0.25 - 1.3 = 0.45; x: 0.5 + 0.25 - 0.2 = 0.55; y: 1 + 0.25 - 0.1 = 1.15
    CHECK(boxPenetrationDepth(a, b) == Approx(0.45));
  }
  SECTION("symmetric in its arguments") {
    const Box b = makeBox({0.3, -0.8, 1.1}, {0.2, -0.4, 1.0}, {0.5, 0.7, 0.3});
    CHECK(boxPenetrationDepth(a, b) == Approx(boxPenetrationDepth(b, a)));
  }
}

TEST_CASE("rotated boxes: face and edge axes", "[geometry]") {
  const Box a = makeBox({0, 0, 0}, {0, 0, 0}, {1.0, 1.0, 1.0});
  SECTION("a cube turned 45 deg about z reaches sqrt(2)/2 along x") {
    const double d = 1.1;
    const Box b = makeBox({d, 0, 0}, {0, 0, std::numbers::pi / 4}, {1.0, 1.0, 1.0});
    CHECK(boxPenetrationDepth(a, b) == Approx(0.5 + std::sqrt(0.5) - d));
  }
  SECTION("edge against edge: only a cross-product axis separates") {
    // b turned so that one of its edges passes over a's top edge along x without touching:
    // projected on the six face normals the boxes overlap; an edge-edge axis separates them
    const Box b = makeBox({0.0, 1.03, 1.03}, {std::numbers::pi / 4, 0, std::numbers::pi / 4},
                          {1.0, 1.0, 1.0});
    double face_only = std::numeric_limits<double>::infinity();
    for (const Box* box : {&a, &b}) {
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d axis = box->X_WB.linear().col(k);
        double radius = 0.0;
        for (int j = 0; j < 3; ++j) {
          radius += 0.5 * std::abs(axis.dot(a.X_WB.linear().col(j)));
          radius += 0.5 * std::abs(axis.dot(b.X_WB.linear().col(j)));
        }
        face_only = std::min(face_only, radius - std::abs(axis.dot(b.X_WB.translation())));
      }
    }
    REQUIRE(face_only > 0.05);
    const double depth = boxPenetrationDepth(a, b);
    const double distance = distanceByProjections(a, b);
    CHECK(depth < -0.02);
    CHECK(distance > 0.02);
    CHECK(-depth <= distance + 1e-9);
  }
}

TEST_CASE("separating axis test agrees with alternating projections", "[geometry]") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> position(-0.8, 0.8), angle(-3.1, 3.1), edge(0.1, 1.0);
  int separated = 0;
  int overlapping = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Box a = makeBox({position(rng), position(rng), position(rng)},
                          {angle(rng), angle(rng), angle(rng)}, {edge(rng), edge(rng), edge(rng)});
    const Box b = makeBox({position(rng), position(rng), position(rng)},
                          {angle(rng), angle(rng), angle(rng)}, {edge(rng), edge(rng), edge(rng)});
    const double depth = boxPenetrationDepth(a, b);
    if (std::abs(depth) < 1e-2) continue;  // projections converge slowly when barely touching
    const double distance = distanceByProjections(a, b);
    INFO("trial " << trial << " depth " << depth << " distance " << distance);
    if (depth < 0.0) {
      ++separated;
      REQUIRE(distance > 1e-6);
      REQUIRE(-depth <= distance + 1e-9);  // the gap along one axis bounds the distance
    } else {
      ++overlapping;
      REQUIRE(distance < 1e-6);
    }
  }
  CHECK(separated > 20);
  CHECK(overlapping > 20);
}

TEST_CASE("moving a box by the penetration depth along the best axis separates it", "[geometry]") {
  // axis-aligned a, b turned about z only: the depth's direction is one of the face normals
  const Box a = makeBox({0, 0, 0}, {0, 0, 0}, {1.0, 1.0, 0.2});
  Box b = makeBox({0.3, 0.2, 0.15}, {0, 0, 0.3}, {0.4, 0.4, 0.2});
  const double depth = boxPenetrationDepth(a, b);
  REQUIRE(depth == Approx(0.05));  // b's bottom at 0.05, a's top at 0.1
  b.X_WB.translation().z() += depth + 1e-9;
  CHECK(boxPenetrationDepth(a, b) <= 0.0);
}

TEST_CASE("pointInBox uses the box frame and the margin", "[geometry]") {
  const Box box = makeBox({1, 0, 0}, {0, 0, std::numbers::pi / 2}, {0.4, 0.2, 0.1});
  // turned 90 deg: the long edge lies along world y
  CHECK(pointInBox({1.0, 0.19, 0.0}, box));
  CHECK_FALSE(pointInBox({1.19, 0.0, 0.0}, box));
  CHECK(pointInBox({1.05, 0.0, 0.05}, box));  // on the top face
  CHECK_FALSE(pointInBox({1.0, 0.0, 0.06}, box));
  CHECK(pointInBox({1.0, 0.0, 0.06}, box, 0.011));
}

TEST_CASE("rotatedBoxExtent bounds the turned box by its corners", "[geometry]") {
  const Eigen::Vector3d size(0.4, 0.2, 0.1);
  // a quarter turn about z swaps the horizontal extents, a quarter turn about x stands it on a side
  CHECK(rotatedBoxExtent(makePose({0, 0, 0}, {0, 0, std::numbers::pi / 2}).linear(), size).isApprox(Eigen::Vector3d(0.2, 0.4, 0.1)));
  CHECK(rotatedBoxExtent(makePose({0, 0, 0}, {std::numbers::pi / 2, 0, 0}).linear(), size).isApprox(Eigen::Vector3d(0.4, 0.1, 0.2)));
  // any turn: the extent is the spread of the eight corners along each axis
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Matrix3d R = makePose({0, 0, 0}, {angle(rng), angle(rng), angle(rng)}).linear();
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d sign((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0);
      const Eigen::Vector3d p = R * sign.cwiseProduct(size / 2);
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    CHECK((rotatedBoxExtent(R, size) - (high - low)).cwiseAbs().maxCoeff() < 1e-12);
  }
}
