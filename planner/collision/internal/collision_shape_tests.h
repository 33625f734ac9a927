#pragma once
// Intersection tests of two convex shapes placed in W (box, cylinder, sphere), internal to the
// collision checker: prefilters (bounding spheres, separating axes) that only reject pairs at
// least kPrefilterTolerance apart, in front of FCL's primitive narrow phase, which decides every
// close call.

#include <algorithm>
#include <cmath>
#include <limits>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/detail/gjk_solver_libccd.h>

#include "planner/collision/internal/collision_scene_data.h"

namespace dashbed::planner::detail {

using Solver = fcl::detail::GJKSolver_libccd<double>;

// Prefilters hand every pair closer than this to FCL; they only reject pairs at least this far
// apart, so FCL's own tolerance (1e-6 m) decides all close calls.
inline constexpr double kPrefilterTolerance = 1e-5;

/// A shape placed in W, as the pair tests see it.
struct Placed {
  ShapeType type = ShapeType::kBox;
  const fcl::CollisionGeometryd* geometry = nullptr;
  const Frame* X_W = nullptr;
  const Vector3d* half = nullptr;
  double radius = 0.0;
};

inline bool spheresApart(const Vector3d& a, double ra, const Vector3d& b, double rb) {
  const double r = ra + rb + kPrefilterTolerance;
  return (a - b).squaredNorm() > r * r;
}

/// Sphere (c, r) against an axis-aligned box.
inline bool sphereAabbApart(const Vector3d& c, double r, const fcl::AABBd& box) {
  const Vector3d below = (box.min_ - c).cwiseMax(0.0);
  const Vector3d above = (c - box.max_).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return (below + above).squaredNorm() > rr * rr;
}

inline bool sphereAabbApart(const Vector3d& c, double r, const Vector3d& lo, const Vector3d& hi) {
  const Vector3d below = (lo - c).cwiseMax(0.0);
  const Vector3d above = (c - hi).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return (below + above).squaredNorm() > rr * rr;
}

/// Sphere (c, r) against the oriented box (X_WB, half extents).
inline bool sphereObbApart(const Vector3d& c, double r, const Frame& X_WB, const Vector3d& half) {
  const Vector3d p = X_WB.R.transpose() * (c - X_WB.p);
  const Vector3d outside = (p.cwiseAbs() - half).cwiseMax(0.0);
  const double rr = r + kPrefilterTolerance;
  return outside.squaredNorm() > rr * rr;
}

/// The sphere (c, r)'s margin from the oriented box (X_WB, half extents) beyond
/// kPrefilterTolerance: when positive, a lower bound on their distance [m].
inline double sphereObbMargin(const Vector3d& c, double r, const Frame& X_WB, const Vector3d& half) {
  const Vector3d p = X_WB.R.transpose() * (c - X_WB.p);
  return (p.cwiseAbs() - half).cwiseMax(0.0).norm() - r - kPrefilterTolerance;
}

/// Separating-axis test of two oriented boxes (Gottschalk, Lin, Manocha: "OBBTree", SIGGRAPH
/// 1996): visits the margin by which each of the 15 axes separates them beyond
/// kPrefilterTolerance, until visit(margin) returns true; true when stopped. A positive margin
/// bounds the boxes' distance from below (the edge-pair axes A_i x B_j have length <= 1).
template <class Visit>
inline bool obbMargins(const Frame& X_WA, const Vector3d& a, const Frame& X_WB, const Vector3d& b, Visit&& visit) {
  const Eigen::Matrix3d R = X_WA.R.transpose() * X_WB.R;
  const Vector3d t = X_WA.R.transpose() * (X_WB.p - X_WA.p);
  // the epsilon keeps near-parallel edge pairs (cross product ~ 0) from separating falsely
  const Eigen::Matrix3d absR = R.cwiseAbs().array() + 1e-9;
  const double tol = kPrefilterTolerance;
  for (int i = 0; i < 3; ++i) {
    if (visit(std::abs(t[i]) - (a[i] + absR.row(i).dot(b)) - tol)) return true;
  }
  for (int j = 0; j < 3; ++j) {
    if (visit(std::abs(t.dot(R.col(j))) - (absR.col(j).dot(a) + b[j]) - tol)) return true;
  }
  // A_i x B_j; the tolerance is not scaled by |A_i x B_j| <= 1, which keeps the test conservative
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3;
      const int j2 = (j + 2) % 3;
      const double ra = a[i1] * absR(i2, j) + a[i2] * absR(i1, j);
      const double rb = b[j1] * absR(i, j2) + b[j2] * absR(i, j1);
      if (visit(std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) - (ra + rb) - tol)) return true;
    }
  }
  return false;
}

/// True only when some axis separates the boxes by more than kPrefilterTolerance.
inline bool obbsApart(const Frame& X_WA, const Vector3d& a, const Frame& X_WB, const Vector3d& b) {
  return obbMargins(X_WA, a, X_WB, b, [](double margin) { return margin > 0.0; });
}

/// Half the width of a placed shape's projection on the unit axis u (its support function).
inline double halfWidth(const Placed& shape, const Vector3d& u) {
  const Eigen::Matrix3d& R = shape.X_W->R;
  const Vector3d& h = *shape.half;
  switch (shape.type) {
    case ShapeType::kBox:
      return h.x() * std::abs(u.dot(R.col(0))) + h.y() * std::abs(u.dot(R.col(1))) +
             h.z() * std::abs(u.dot(R.col(2)));
    case ShapeType::kCylinder: {
      const double along = u.dot(R.col(2));
      return h.z() * std::abs(along) + h.x() * std::sqrt(std::max(0.0, 1.0 - along * along));
    }
    case ShapeType::kSphere:
      return h.x();
  }
  return 0.0;
}

/// The margin by which the axis (any length) separates the shapes beyond kPrefilterTolerance
/// (-infinity for a null axis): when positive, a lower bound on their distance; d is the vector
/// between their centres.
inline double separationAlong(const Placed& a, const Placed& b, const Vector3d& d, const Vector3d& axis) {
  const double norm2 = axis.squaredNorm();
  if (norm2 < 1e-12) return -std::numeric_limits<double>::infinity();
  const Vector3d u = axis / std::sqrt(norm2);
  return std::abs(d.dot(u)) - (halfWidth(a, u) + halfWidth(b, u)) - kPrefilterTolerance;
}

/// Separating-axis test with the shapes' exact projections, for pairs with a cylinder: visits
/// the candidate axes (any length) until visit(axis) returns true; true when stopped. The
/// candidates: each box's face normals (against large fixtures they separate); the centre line
/// d; each cylinder's axis and the centre line's part across it; a cylinder's axis crossed with
/// the other shape's axes. A box's bounding box is loose for a cylinder (its corners stick out
/// by 41% of the radius), which would hand many touching-by-construction neighbours to the
/// expensive GJK.
template <class Visit>
inline bool roundAxes(const Placed& a, const Placed& b, const Vector3d& d, Visit&& visit) {
  for (const Placed* shape : {&a, &b}) {
    if (shape->type != ShapeType::kBox) continue;
    const Eigen::Matrix3d& R = shape->X_W->R;
    for (int i = 0; i < 3; ++i) {
      if (visit(R.col(i))) return true;
    }
  }
  if (visit(d)) return true;
  for (const Placed* shape : {&a, &b}) {
    if (shape->type != ShapeType::kCylinder) continue;
    const Vector3d axis = shape->X_W->R.col(2);
    if (visit(axis) || visit(d - d.dot(axis) * axis)) return true;
  }
  for (const auto& [cylinder, other] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    if (cylinder->type != ShapeType::kCylinder || other->type == ShapeType::kSphere) continue;
    const Vector3d axis = cylinder->X_W->R.col(2);
    const Eigen::Matrix3d& R = other->X_W->R;
    if (other->type == ShapeType::kCylinder) {
      return visit(axis.cross(R.col(2)));  // both axes done; the pair is symmetric
    }
    for (int i = 0; i < 3; ++i) {
      if (visit(axis.cross(R.col(i)))) return true;
    }
  }
  return false;
}

/// True only when some roundAxes axis separates the shapes by more than kPrefilterTolerance.
inline bool roundApart(const Placed& a, const Placed& b) {
  const Vector3d d = b.X_W->p - a.X_W->p;
  return roundAxes(a, b, d, [&](const Vector3d& axis) { return separationAlong(a, b, d, axis) > 0.0; });
}

/// The largest margin by which the prefilters of a shape pair (bounding spheres, then the
/// separating axes of its shape types) separate two shapes beyond kPrefilterTolerance: when
/// positive, a lower bound on their distance [m]; otherwise they may touch.
inline double separation(const Placed& a, const Placed& b) {
  const Vector3d d = b.X_W->p - a.X_W->p;
  double best = d.norm() - a.radius - b.radius - kPrefilterTolerance;
  const auto keep = [&best](double margin) {
    best = std::max(best, margin);
    return false;
  };
  if (a.type == ShapeType::kBox && b.type == ShapeType::kBox) {
    obbMargins(*a.X_W, *a.half, *b.X_W, *b.half, keep);
  } else if (a.type == ShapeType::kSphere && b.type == ShapeType::kBox) {
    keep(sphereObbMargin(a.X_W->p, a.radius, *b.X_W, *b.half));
  } else if (b.type == ShapeType::kSphere && a.type == ShapeType::kBox) {
    keep(sphereObbMargin(b.X_W->p, b.radius, *a.X_W, *a.half));
  } else if (a.type != ShapeType::kSphere || b.type != ShapeType::kSphere) {
    roundAxes(a, b, d, [&](const Vector3d& axis) { return keep(separationAlong(a, b, d, axis)); });
  }
  return best;
}

/// True when the point p lies inside the shape, at least kPrefilterTolerance from its surface:
/// a certain intersection that needs no narrow phase.
inline bool deepInside(const Vector3d& p, const Placed& shape) {
  const Vector3d local = shape.X_W->R.transpose() * (p - shape.X_W->p);
  const Vector3d& h = *shape.half;
  const double tol = kPrefilterTolerance;
  switch (shape.type) {
    case ShapeType::kBox:
      return (local.cwiseAbs() - h).maxCoeff() < -tol;
    case ShapeType::kCylinder:
      return std::abs(local.z()) < h.z() - tol && local.head<2>().norm() < h.x() - tol;
    case ShapeType::kSphere:
      return local.norm() < h.x() - tol;
  }
  return false;
}

template <class ShapeA>
inline bool narrowPhaseAs(const Solver& solver, const ShapeA& a, const Pose& X_WA, const Placed& b) {
  const Pose X_WB = b.X_W->pose();
  switch (b.type) {
    case ShapeType::kBox:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Boxd&>(*b.geometry), X_WB, nullptr);
    case ShapeType::kCylinder:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Cylinderd&>(*b.geometry), X_WB,
                                   nullptr);
    case ShapeType::kSphere:
      return solver.shapeIntersect(a, X_WA, static_cast<const fcl::Sphered&>(*b.geometry), X_WB,
                                   nullptr);
  }
  return true;
}

/// FCL's primitive intersection test, as fcl::collide runs it for two shapes.
inline bool narrowPhase(const Solver& solver, const Placed& a, const Placed& b) {
  const Pose X_WA = a.X_W->pose();
  switch (a.type) {
    case ShapeType::kBox:
      return narrowPhaseAs(solver, static_cast<const fcl::Boxd&>(*a.geometry), X_WA, b);
    case ShapeType::kCylinder:
      return narrowPhaseAs(solver, static_cast<const fcl::Cylinderd&>(*a.geometry), X_WA, b);
    case ShapeType::kSphere:
      return narrowPhaseAs(solver, static_cast<const fcl::Sphered&>(*a.geometry), X_WA, b);
  }
  return true;
}

}  // namespace dashbed::planner::detail
