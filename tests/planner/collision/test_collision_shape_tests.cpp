// The separating margins of the collision checker's shape prefilters (collision_shape_tests.h),
// against FCL's distance: the motion sweep skips samples on them, so they must never exceed the
// true gap between two shapes.
#include <catch2/catch.hpp>

#include <memory>
#include <random>

#include <fcl/narrowphase/distance.h>

#include "planner/collision/internal/collision_shape_tests.h"

using namespace dashbed::planner::detail;

namespace {

/// A shape of random type and size at a random pose within a 0.6 m cube, as the checker places
/// it, with its FCL geometry.
struct RandomShape {
  ShapeType type = ShapeType::kBox;
  Vector3d half = Vector3d::Zero();
  double radius = 0.0;
  Frame X_W;
  std::shared_ptr<fcl::CollisionGeometryd> geometry;

  explicit RandomShape(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> size(0.01, 0.2), place(-0.3, 0.3), unit(-1.0, 1.0);
    switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
      case 0:
        type = ShapeType::kBox;
        half = Vector3d(size(rng), size(rng), size(rng));
        radius = half.norm();
        geometry = std::make_shared<fcl::Boxd>(2.0 * half);
        break;
      case 1:
        type = ShapeType::kCylinder;
        half.x() = half.y() = size(rng);
        half.z() = size(rng);
        radius = std::hypot(half.x(), half.z());
        geometry = std::make_shared<fcl::Cylinderd>(half.x(), 2.0 * half.z());
        break;
      default:
        type = ShapeType::kSphere;
        half = Vector3d::Constant(size(rng));
        radius = half.x();
        geometry = std::make_shared<fcl::Sphered>(half.x());
    }
    const Eigen::Vector4d q(unit(rng), unit(rng), unit(rng), unit(rng));
    X_W.R = Eigen::Quaterniond(q).normalized().toRotationMatrix();
    X_W.p = Vector3d(place(rng), place(rng), place(rng));
  }

  Placed placed() const { return {type, geometry.get(), &X_W, &half, radius}; }
};

}  // namespace

TEST_CASE("The shape prefilters' separating margin never exceeds the shapes' distance", "[planner][collision]") {
  std::mt19937_64 rng(5);
  int separated = 0, touching = 0, violations = 0, inconsistent = 0;
  double largest = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    const RandomShape a(rng), b(rng);
    const double margin = separation(a.placed(), b.placed());
    const fcl::CollisionObjectd object_a(a.geometry, a.X_W.R, a.X_W.p);
    const fcl::CollisionObjectd object_b(b.geometry, b.X_W.R, b.X_W.p);
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(&object_a, &object_b, request, result);
    const double distance = result.min_distance;  // <= 0 when they intersect
    if (margin > 0.0) {
      ++separated;
      largest = std::max(largest, margin);
      // FCL's GJK distance is good to about a micrometre
      if (distance < margin - 1e-6) ++violations;
    }
    if (distance <= 0.0) ++touching;
    // the prefilter tests answer "apart" exactly where the margin is positive
    const bool apart = a.type == ShapeType::kBox && b.type == ShapeType::kBox
                           ? obbsApart(a.X_W, a.half, b.X_W, b.half)
                           : roundApart(a.placed(), b.placed());
    if (apart && !(margin > 0.0)) ++inconsistent;
  }
  CHECK(violations == 0);
  CHECK(inconsistent == 0);
  // both cases are covered, and the margins are worth skipping samples for
  CHECK(separated > 300);
  CHECK(touching > 300);
  CHECK(largest > 0.1);
}
