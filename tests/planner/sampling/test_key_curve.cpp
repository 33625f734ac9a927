#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/world_loader.h"
#include "planner/sampling/key_curve.h"

using namespace dashbed;
using planner::TransitionMotion;

namespace {

/// Robot 0 of the default world: an approach of three unevenly timed keys, a dwell (same
/// configuration) and a lift of two keys, one joint turning back.
TransitionMotion motion(const core::World& world) {
  TransitionMotion m;
  m.robot = 0;
  core::ArmConfig q = world.robots[0].home;
  const std::vector<std::pair<planner::Millis, std::array<double, 6>>> steps{
      {0, {0, 0, 0, 0, 0, 0}},           {300, {0.02, 0.01, -0.03, 0, 0.01, 0}},
      {500, {0.05, 0.02, -0.05, 0.01, 0.01, 0}}, {1100, {0.06, 0.04, -0.06, 0.02, 0.0, 0.01}},
      {1400, {0.06, 0.04, -0.06, 0.02, 0.0, 0.01}}, {1700, {0.03, 0.02, -0.04, 0.0, 0.02, 0.01}},
      {2300, {0.0, 0.0, -0.01, 0.0, 0.03, 0.02}}};
  for (const auto& [t, dq] : steps) {
    core::ArmConfig key = q;
    for (int j = 0; j < 6; ++j) key[j] += dq[j];
    m.keys.push_back({t, key});
  }
  for (std::size_t i = 0; i + 1 < m.keys.size(); ++i) {
    m.finger.push_back(i < 3 ? 0.025 : 0.012);
    m.held.push_back(std::nullopt);
  }
  return m;
}

}  // namespace

TEST_CASE("A key curve piece is the interpolator's curve between two keys, sampled at its peak speed",
          "[planner][key_curve]") {
  const core::LoadedWorld loaded = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  const planner::CollisionScene scene(*loaded.world, *loaded.robots);
  const TransitionMotion m = motion(*loaded.world);
  const core::TrajectoryInterpolator curve = planner::keyCurve(m);
  CHECK(curve.startTime() == 0.0);
  CHECK(curve.endTime() == 2.3);
  int sped_up = 0;
  for (std::size_t i = 0; i + 1 < m.keys.size(); ++i) {
    const planner::CurvePiece piece = planner::keyCurvePiece(scene, m, curve, i);
    REQUIRE(piece.from.size() == 8);
    CHECK(piece.from == scene.configuration(0, m.keys[i].q, m.finger[i]));
    CHECK(piece.to == scene.configuration(0, m.keys[i + 1].q, m.finger[i]));
    Eigen::VectorXd q;
    piece.at(0.0, q);
    CHECK(q == piece.from);
    piece.at(1.0, q);
    CHECK(q == piece.to);
    // on the curve, fingers as the piece's; no joint faster in s than peak_over_mean times its
    // mean, and one nearly that fast
    const double t0 = planner::toSeconds(m.keys[i].t), t1 = planner::toSeconds(m.keys[i + 1].t);
    CHECK(piece.peak_over_mean >= 1.0);
    CHECK(piece.peak_over_mean <= 3.0);
    constexpr int kSteps = 400;
    double fastest = 0.0;
    Eigen::VectorXd previous = piece.from;
    for (int k = 1; k <= kSteps; ++k) {
      const double s = static_cast<double>(k) / kSteps;
      piece.at(s, q);
      const core::Vector6 expected = curve.at(t0 + s * (t1 - t0)).q;
      for (int j = 0; j < 6; ++j) CHECK(q[j] == Approx(expected[j]).margin(1e-12));
      CHECK(q[6] == m.finger[i]);
      CHECK(q[7] == m.finger[i]);
      for (int j = 0; j < 6; ++j) {
        const double mean = std::abs(piece.to[j] - piece.from[j]);
        if (mean < 1e-9) continue;
        fastest = std::max(fastest, std::abs(q[j] - previous[j]) * kSteps / mean);
      }
      previous = q;
    }
    if (fastest == 0.0) continue;  // the dwell
    CHECK(fastest <= piece.peak_over_mean * (1 + 1e-6));
    CHECK(fastest >= 0.97 * piece.peak_over_mean);
    sped_up += piece.peak_over_mean > 1.2;
  }
  // from rest and into the dwell the curve is faster than its mean
  CHECK(sped_up >= 2);
}
