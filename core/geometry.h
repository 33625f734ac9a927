#pragma once
// Small exact geometric queries on oriented boxes (core::Box): world validation, footprints and
// resting heights.

#include <Eigen/Core>

#include "core/world.h"

namespace dashbed::core {

/// Penetration depth of two oriented boxes [m] by the separating axis theorem
/// (Gottschalk, Lin, Manocha: "OBBTree", SIGGRAPH 1996): the smallest overlap of the two
/// boxes' projections over the 15 candidate axes (3 + 3 face normals, 9 edge-edge cross
/// products). Positive: the boxes interpenetrate by that much (the minimum translation that
/// separates them). Zero: they touch. Negative: they are apart; its magnitude is a lower
/// bound of their distance (the gap along the best separating axis).
double boxPenetrationDepth(const Box& a, const Box& b);

/// True when the boxes interpenetrate by more than `tolerance` [m] (touching is fine).
bool boxesOverlap(const Box& a, const Box& b, double tolerance = 0.0);

/// The extent [m] along the axes of a frame F of a box with edge lengths `size` turned by R_FB
/// relative to F: the size of the smallest F-aligned box around it.
Eigen::Vector3d rotatedBoxExtent(const Eigen::Matrix3d& R_FB, const Eigen::Vector3d& size);

/// True when the point p_W lies inside the box grown by `margin` [m] on every side.
bool pointInBox(const Eigen::Vector3d& p_W, const Box& box, double margin = 0.0);

}  // namespace dashbed::core
