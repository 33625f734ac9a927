#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/trajectory_interpolator.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "planner/sampling/transition_sampler.h"

using namespace dashbed;
using core::Pose;
using Eigen::Vector3d;
using Eigen::VectorXd;
using planner::CollisionChecker;
using planner::CollisionScene;
using planner::Grasp;
using planner::HeldObject;
using planner::Millis;
using planner::ObjectSites;
using planner::TaskSpaceHypergraph;
using planner::TransitionKind;
using planner::TransitionMotion;
using planner::TransitionSample;
using planner::TransitionSampler;
using planner::TransitionSettings;

namespace {

/// A world with everything the sampler reads, built once per world file.
struct Setup {
  explicit Setup(const std::string& world) : Setup(core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/" + world)) {}
  explicit Setup(core::LoadedWorld world)
      : loaded(std::move(world)),
        task_space(TaskSpaceHypergraph::fromWorld(*loaded.world, *loaded.robots, loaded.reach)),
        scene(*loaded.world, *loaded.robots),
        sites(planner::objectSites(loaded)) {}

  std::vector<int> hyperarcs(TransitionKind kind) const {
    std::vector<int> ids;
    for (std::size_t h = 0; h < task_space.numHyperarcs(); ++h) {
      if (task_space.hyperarcs()[h].kind == kind) ids.push_back(static_cast<int>(h));
    }
    return ids;
  }

  core::LoadedWorld loaded;
  TaskSpaceHypergraph task_space;
  CollisionScene scene;
  ObjectSites sites;
};

const Setup& world(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Setup>> setups;
  std::unique_ptr<Setup>& setup = setups[name];
  if (!setup) setup = std::make_unique<Setup>(name);
  return *setup;
}

VectorXd full(const core::ArmConfig& q, double finger) {
  VectorXd x(8);
  for (int j = 0; j < 6; ++j) x[j] = q[j];
  x[6] = finger;
  x[7] = finger;
  return x;
}

Pose lifted(Pose X, double dz) {
  X.translation().z() += dz;
  return X;
}

/// Position and rotation distances of two poses [m], [rad].
std::pair<double, double> poseError(const Pose& a, const Pose& b) {
  const double angle = Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
  return {(a.translation() - b.translation()).norm(), angle};
}

void requireSamePose(const Pose& a, const Pose& b) {
  const auto [distance, angle] = poseError(a, b);
  REQUIRE(distance < 1e-6);
  REQUIRE(angle < 1e-6);
}

/// The curve the simulator follows through a motion's keys: the plan gives no velocities, so
/// the interpolator rests at the ends and passes the other keys shape-preserving.
core::TrajectoryInterpolator simulatedCurve(const TransitionMotion& motion) {
  std::vector<core::TrajectoryPoint> points;
  for (const TransitionMotion::Key& key : motion.keys) points.push_back({planner::toSeconds(key.t), key.q, std::nullopt});
  return core::TrajectoryInterpolator(points);
}

/// Whether `free(q)` holds all along piece i of the motion on that curve, with the fingers at
/// `finger`: checked at three times the straight piece's motion steps, a monotone cubic's speed
/// peaking at no more than three times its mean.
template <class Free>
bool freeAlongCurve(const Setup& s, const TransitionMotion& motion, const core::TrajectoryInterpolator& curve,
                    std::size_t i, double finger, const Free& free) {
  const TransitionMotion::Key& a = motion.keys[i];
  const TransitionMotion::Key& b = motion.keys[i + 1];
  const int n = 3 * s.scene.motionSteps(motion.robot, full(a.q, finger), full(b.q, finger), motion.held[i]);
  const double t0 = planner::toSeconds(a.t), t1 = planner::toSeconds(b.t);
  for (int k = 0; k <= n; ++k) {
    if (!free(full(curve.at(k == n ? t1 : t0 + (t1 - t0) * k / n).q, finger))) return false;
  }
  return true;
}

/// Piece i on the curve free against the static scene, the robot itself and `objects`.
bool curvePieceFree(const Setup& s, CollisionChecker& checker, const TransitionMotion& motion,
                    const core::TrajectoryInterpolator& curve, std::size_t i, double finger,
                    std::span<const planner::RestingObject> objects) {
  return freeAlongCurve(s, motion, curve, i, finger, [&](const VectorXd& q) {
    return checker.robotFree(motion.robot, q, objects, motion.held[i]);
  });
}

/// The index of the key at time t (a gripper command's key).
std::size_t keyAt(const TransitionMotion& motion, Millis t) {
  const auto it =
      std::find_if(motion.keys.begin(), motion.keys.end(), [t](const TransitionMotion::Key& k) { return k.t == t; });
  REQUIRE(it != motion.keys.end());
  return static_cast<std::size_t>(it - motion.keys.begin());
}

std::optional<Millis> gripTime(const TransitionMotion& motion, core::GripperAction action) {
  for (const auto& [t, a] : motion.grips) {
    if (a == action) return t;
  }
  return std::nullopt;
}

/// The held object's grasp as HeldObject stores it.
bool holds(const std::optional<HeldObject>& held, int object, const Grasp& grasp) {
  return held && held->object == object && poseError(held->X_TO, grasp.X_OT.inverse()).first < 1e-9 &&
         poseError(held->X_TO, grasp.X_OT.inverse()).second < 1e-9;
}

/// Timing, joint limits, per-piece bookkeeping and independent collision checks of one motion.
void checkMotion(const Setup& s, const TransitionSample& sample, const TransitionMotion& motion,
                 CollisionChecker& checker) {
  const TransitionSettings settings;
  const core::PlacedRobot& robot = (*s.loaded.robots)[static_cast<std::size_t>(motion.robot)];
  const core::RobotModel& model = *robot.model;
  REQUIRE(motion.keys.size() >= 2);
  REQUIRE(motion.keys.front().t == 0);
  REQUIRE(motion.finger.size() == motion.keys.size() - 1);
  REQUIRE(motion.held.size() == motion.keys.size() - 1);
  REQUIRE(motion.keys.back().t <= sample.duration);
  for (const auto& [t, action] : motion.grips) {
    REQUIRE(t >= 0);
    REQUIRE(t <= sample.duration);
  }
  for (const TransitionMotion::Key& key : motion.keys) {
    for (int j = 0; j < 6; ++j) {
      REQUIRE(key.q[j] >= robot.ik->lower()[j]);
      REQUIRE(key.q[j] <= robot.ik->upper()[j]);
    }
  }
  const core::TrajectoryInterpolator curve = simulatedCurve(motion);
  for (std::size_t i = 0; i + 1 < motion.keys.size(); ++i) {
    const TransitionMotion::Key& a = motion.keys[i];
    const TransitionMotion::Key& b = motion.keys[i + 1];
    REQUIRE(b.t > a.t);
    // no joint faster than its share of the limit, with the simulator's peak factor on top
    const double seconds = planner::toSeconds(b.t - a.t);
    for (int j = 0; j < 6; ++j) {
      const double limit = model.joints()[model.movableJoints()[j]].max_velocity;
      REQUIRE(std::abs(b.q[j] - a.q[j]) / seconds * settings.peak_factor <= settings.speed_fraction * limit + 1e-9);
    }
    const double finger = motion.finger[i];
    REQUIRE((finger == 0.025 || (motion.held[i] && motion.held[i]->object == sample.object)));
    REQUIRE(checker.robotFree(motion.robot, full(a.q, finger), {}, motion.held[i]));
    REQUIRE(checker.robotFree(motion.robot, full(b.q, finger), {}, motion.held[i]));
    REQUIRE(curvePieceFree(s, checker, motion, curve, i, finger, {}));
  }
}

/// Where a pick's approach starts, from the TCP at its grasp [m, world].
Vector3d pickApproach(const Setup& s, const TransitionSample& pick) {
  const TransitionMotion& m = pick.motions.front();
  const Pose X_WT = pick.X_WO * pick.grasp_after->X_OT;
  return (*s.loaded.robots)[static_cast<std::size_t>(m.robot)].tcpPoseInWorld(m.keys.front().q).translation() -
         X_WT.translation();
}

/// A pick whose open gripper comes straight down into a side grasp.
bool pickedFromAbove(const Setup& s, const TransitionSample& pick) {
  const TransitionSettings settings;
  const Pose X_WT = pick.X_WO * pick.grasp_after->X_OT;
  return std::abs(X_WT.linear()(2, 2)) < 1e-6 &&
         (pickApproach(s, pick) - settings.cartesian_distance * Vector3d::UnitZ()).norm() < 1e-6;
}

/// Whether object `object` at X_WO is wholly in front of the open side (-x) of a shelf and
/// within its width and height.
bool inFrontOfAShelf(const Setup& s, const Pose& X_WO, int object) {
  const Vector3d& size = s.loaded.world->objects[static_cast<std::size_t>(object)].size;
  return std::any_of(s.loaded.world->fixtures.begin(), s.loaded.world->fixtures.end(), [&](const core::FixtureSpec& f) {
    if (f.type != core::FixtureType::kShelf) return false;
    const Vector3d p_F = f.X_WF.inverse() * X_WO.translation();
    const Vector3d extent = (f.X_WF.linear().transpose() * X_WO.linear()).cwiseAbs() * size;
    return p_F.x() + extent.x() / 2 <= -f.size.x() / 2 && std::abs(p_F.y()) <= f.size.y() / 2 && p_F.z() >= 0 &&
           p_F.z() <= f.size.z();
  });
}

/// Every property of a sample the sampler promises (transition_sampler.h).
void checkSample(const Setup& s, const TransitionSample& sample, int hyperarc) {
  CollisionChecker checker(s.scene);
  const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(hyperarc)];
  REQUIRE(sample.hyperarc == hyperarc);
  REQUIRE(sample.kind == arc.kind);
  REQUIRE(sample.object == arc.object);
  Millis last = 0;
  for (const TransitionMotion& motion : sample.motions) {
    checkMotion(s, sample, motion, checker);
    last = std::max(last, motion.keys.back().t);
  }
  REQUIRE(sample.duration == last);
  REQUIRE(sample.action_start == 0);
  // touches: only other objects' existing sites
  for (int site = 0; site < s.sites.numSites(); ++site) {
    if (!sample.touches.test(site)) continue;
    REQUIRE(site / 2 != sample.object);
    REQUIRE(s.sites.site(site).has_value());
  }
  const TransitionSettings settings;
  const double open = 0.025;
  const Vector3d& size = s.loaded.world->objects[static_cast<std::size_t>(sample.object)].size;
  const auto fingerOf = [&size](const Grasp& grasp) { return 0.5 * size.dot(grasp.X_OT.linear().col(0).cwiseAbs()); };
  const auto tcp = [&s](const TransitionMotion& motion, std::size_t key) {
    return (*s.loaded.robots)[static_cast<std::size_t>(motion.robot)].tcpPoseInWorld(motion.keys[key].q);
  };

  if (arc.kind == TransitionKind::kPick) {
    REQUIRE(sample.motions.size() == 1);
    const TransitionMotion& m = sample.motions.front();
    REQUIRE(m.robot == arc.robot);
    REQUIRE(sample.grasp_after.has_value());
    REQUIRE_FALSE(sample.grasp_before.has_value());
    REQUIRE(sample.grasp_after->finger == Approx(fingerOf(*sample.grasp_after)).margin(1e-12));
    requireSamePose(sample.X_WO, s.sites.start[static_cast<std::size_t>(sample.object)]);
    REQUIRE(m.grips.size() == 1);
    REQUIRE(m.grips.front().second == core::GripperAction::kClose);
    const std::size_t grasp_key = keyAt(m, m.grips.front().first);
    const Pose X_WT = sample.X_WO * sample.grasp_after->X_OT;
    requireSamePose(tcp(m, grasp_key), X_WT);
    // in along the grasp's approach axis, or into a side grasp from straight above
    const Vector3d back = -settings.cartesian_distance * X_WT.linear().col(2);
    REQUIRE(((pickApproach(s, sample) - back).norm() < 1e-6 || pickedFromAbove(s, sample)));
    // open fingers up to the grasp, closed on the object after it; the dwell, then the lift
    for (std::size_t i = 0; i < m.finger.size(); ++i) {
      if (i < grasp_key) {
        REQUIRE(m.finger[i] == open);
      } else {
        REQUIRE(m.finger[i] == sample.grasp_after->finger);
        REQUIRE(holds(m.held[i], sample.object, *sample.grasp_after));
      }
    }
    REQUIRE(m.keys[grasp_key + 1].q == m.keys[grasp_key].q);
    REQUIRE(m.keys[grasp_key + 1].t - m.keys[grasp_key].t == planner::ceilMillis(settings.gripper_dwell));
    REQUIRE(tcp(m, m.keys.size() - 1).translation().z() ==
            Approx(tcp(m, grasp_key).translation().z() + settings.cartesian_distance).margin(1e-6));
    REQUIRE(sample.action_end == sample.duration);
  } else if (arc.kind == TransitionKind::kPlace) {
    REQUIRE(sample.motions.size() == 1);
    const TransitionMotion& m = sample.motions.front();
    REQUIRE(m.robot == arc.robot);
    REQUIRE(sample.grasp_before.has_value());
    REQUIRE_FALSE(sample.grasp_after.has_value());
    // at the goal site, resting on a face
    const Pose& goal = *s.sites.goal[static_cast<std::size_t>(sample.object)];
    REQUIRE((sample.X_WO.translation() - goal.translation()).norm() < 1e-6);
    REQUIRE(sample.X_WO.linear().row(2).cwiseAbs().maxCoeff() == Approx(1.0).margin(1e-9));
    REQUIRE(m.grips.size() == 1);
    REQUIRE(m.grips.front().second == core::GripperAction::kOpen);
    const std::size_t release_key = keyAt(m, m.grips.front().first);
    // released just above the placement: drop_height after a vertical descent, slide_height
    // after a horizontal approach
    const Pose X_WT = sample.X_WO * sample.grasp_before->X_OT;
    const bool vertical = X_WT.linear()(2, 2) < -1.0 + 1e-6;
    REQUIRE((vertical || std::abs(X_WT.linear()(2, 2)) < 1e-6));
    requireSamePose(tcp(m, release_key), lifted(sample.X_WO, vertical ? settings.drop_height : settings.slide_height) *
                                             sample.grasp_before->X_OT);
    // in straight along the approach axis: cartesian_distance down, or slide_distance in; or
    // a shorter slide into a shelf, from where the object is just out of it
    const Vector3d back = tcp(m, 0).translation() - tcp(m, release_key).translation();
    const double distance = back.norm();
    REQUIRE((back + distance * X_WT.linear().col(2)).norm() < 1e-6);
    if (vertical || distance > settings.slide_distance - 1e-6) {
      REQUIRE(distance == Approx(vertical ? settings.cartesian_distance : settings.slide_distance).margin(1e-6));
    } else {
      REQUIRE(distance >= settings.cartesian_distance - 1e-6);
      Pose start = lifted(sample.X_WO, settings.slide_height);  // the object where the slide starts
      start.translation() += back;
      REQUIRE(inFrontOfAShelf(s, start, sample.object));
    }
    for (std::size_t i = 0; i < m.finger.size(); ++i) {
      if (i < release_key) {
        REQUIRE(m.finger[i] == sample.grasp_before->finger);
        REQUIRE(holds(m.held[i], sample.object, *sample.grasp_before));
      } else {
        REQUIRE(m.finger[i] == open);
        REQUIRE_FALSE(m.held[i].has_value());
      }
    }
    // the retreat ends where the approach started; the robot cleared the resting object
    REQUIRE(m.keys.back().q == m.keys.front().q);
    const planner::RestingObject placed{sample.object, sample.X_WO};
    const core::TrajectoryInterpolator curve = simulatedCurve(m);
    for (std::size_t i = release_key; i + 1 < m.keys.size(); ++i) {
      REQUIRE(curvePieceFree(s, checker, m, curve, i, open, std::span(&placed, 1)));
    }
    REQUIRE(sample.action_end == sample.duration);
  } else {
    REQUIRE(sample.motions.size() == 2);
    const TransitionMotion& g = sample.motions[0];
    const TransitionMotion& r = sample.motions[1];
    REQUIRE(g.robot == arc.robot);
    REQUIRE(r.robot == arc.receiver);
    REQUIRE(sample.grasp_before.has_value());
    REQUIRE(sample.grasp_after.has_value());
    REQUIRE(sample.grasp_after->finger == Approx(fingerOf(*sample.grasp_after)).margin(1e-12));
    // different face pairs (the closing axes perpendicular), or the same pair with the two
    // grippers apart along the object (side by side, end to end): TCPs a fingertip (29.2 mm) apart
    const bool perpendicular =
        std::abs(sample.grasp_before->X_OT.linear().col(0).dot(sample.grasp_after->X_OT.linear().col(0))) < 1e-9;
    const double apart = (sample.grasp_before->X_OT.translation() - sample.grasp_after->X_OT.translation()).norm();
    REQUIRE((perpendicular || apart >= 0.0292));
    requireSamePose(tcp(g, 0), sample.X_WO * sample.grasp_before->X_OT);
    // receiver closes, both hold for a dwell, the giver opens, dwells, retreats, then the
    // receiver retreats
    const Millis dwell = planner::ceilMillis(settings.gripper_dwell);
    const std::optional<Millis> closed = gripTime(r, core::GripperAction::kClose);
    const std::optional<Millis> opened = gripTime(g, core::GripperAction::kOpen);
    REQUIRE(closed.has_value());
    REQUIRE(opened.has_value());
    REQUIRE(*opened == *closed + dwell);
    const std::size_t grasp_key = keyAt(r, *closed);
    requireSamePose(tcp(r, grasp_key), sample.X_WO * sample.grasp_after->X_OT);
    const std::size_t retreat_key = keyAt(g, *opened + dwell);  // giver starts its retreat
    REQUIRE(sample.action_end == g.keys.back().t);
    const std::size_t receiver_retreat = keyAt(r, g.keys.back().t);
    REQUIRE(r.keys[receiver_retreat].q == r.keys[grasp_key].q);
    for (std::size_t k = 0; k <= retreat_key; ++k) REQUIRE(g.keys[k].q == g.keys[0].q);
    // fingers: the giver closed on the object until it opens, the receiver open until it closes
    for (std::size_t i = 0; i < g.finger.size(); ++i) {
      const bool holding = g.keys[i].t < *opened;
      REQUIRE(g.finger[i] == (holding ? sample.grasp_before->finger : open));
      REQUIRE(g.held[i].has_value() == holding);
    }
    for (std::size_t i = 0; i < r.finger.size(); ++i) {
      REQUIRE(r.finger[i] == (i < grasp_key ? open : sample.grasp_after->finger));
      if (i >= grasp_key) REQUIRE(holds(r.held[i], sample.object, *sample.grasp_after));
    }
    // the grippers never touch: the receiver's approach against the giver holding still, the
    // giver's retreat against the receiver holding the object, all along the simulator's curves
    const std::optional<HeldObject> held_g = g.held.front();
    REQUIRE(holds(held_g, sample.object, *sample.grasp_before));
    const std::optional<HeldObject> held_r = r.held[grasp_key];
    REQUIRE(holds(held_r, sample.object, *sample.grasp_after));
    const VectorXd q_giver = full(g.keys[0].q, sample.grasp_before->finger);
    const core::TrajectoryInterpolator r_curve = simulatedCurve(r);
    for (std::size_t i = 0; i < grasp_key; ++i) {
      REQUIRE(freeAlongCurve(s, r, r_curve, i, r.finger[i], [&](const VectorXd& q) {
        return checker.robotsFree(r.robot, q, r.held[i], g.robot, q_giver, held_g);
      }));
    }
    const VectorXd q_receiver = full(r.keys[grasp_key].q, sample.grasp_after->finger);
    const core::TrajectoryInterpolator g_curve = simulatedCurve(g);
    for (std::size_t i = retreat_key; i + 1 < g.keys.size(); ++i) {
      REQUIRE(freeAlongCurve(s, g, g_curve, i, open, [&](const VectorXd& q) {
        return checker.robotsFree(g.robot, q, std::nullopt, r.robot, q_receiver, held_r);
      }));
    }
  }
}

/// Exact equality of two sample lists (determinism).
void requireIdentical(const std::vector<TransitionSample>& a, const std::vector<TransitionSample>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a[i].duration == b[i].duration);
    REQUIRE(a[i].X_WO.matrix() == b[i].X_WO.matrix());
    REQUIRE(a[i].touches == b[i].touches);
    REQUIRE(a[i].motions.size() == b[i].motions.size());
    for (std::size_t m = 0; m < a[i].motions.size(); ++m) {
      const TransitionMotion& ma = a[i].motions[m];
      const TransitionMotion& mb = b[i].motions[m];
      REQUIRE(ma.keys.size() == mb.keys.size());
      for (std::size_t k = 0; k < ma.keys.size(); ++k) {
        REQUIRE(ma.keys[k].t == mb.keys[k].t);
        REQUIRE(ma.keys[k].q == mb.keys[k].q);
      }
      REQUIRE(ma.finger == mb.finger);
      REQUIRE(ma.grips == mb.grips);
    }
    REQUIRE(a[i].grasp_after.has_value() == b[i].grasp_after.has_value());
    if (a[i].grasp_after) REQUIRE(planner::sameGrasp(*a[i].grasp_after, *b[i].grasp_after));
  }
}

/// The grasps each robot can end up holding each object in: from its picks, then from
/// handoffs (`count` samples per giver grasp, at most `givers` giver grasps per hyperarc), round
/// after round until no robot gains an object. Checks every sample on the way.
using Holdings = std::map<std::pair<int, int>, std::vector<Grasp>>;  // (robot, object) -> grasps

Holdings sampleHoldings(const Setup& s, TransitionSampler& sampler, std::mt19937_64& rng, std::size_t givers,
                        std::map<int, int>& samples_per_hyperarc) {
  Holdings holdings;
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    for (const TransitionSample& sample : sampler.pick(h)) {
      checkSample(s, sample, h);
      holdings[{arc.robot, arc.object}].push_back(*sample.grasp_after);
      ++samples_per_hyperarc[h];
    }
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const int h : s.hyperarcs(TransitionKind::kHandoff)) {
      const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
      if (samples_per_hyperarc[h] > 0) continue;
      const std::vector<Grasp> from = holdings[{arc.robot, arc.object}];
      for (std::size_t i = 0; i < std::min(givers, from.size()); ++i) {
        for (const TransitionSample& sample : sampler.handoff(h, from[i], rng, 1)) {
          checkSample(s, sample, h);
          std::vector<Grasp>& to = holdings[{arc.receiver, arc.object}];
          grew = grew || to.empty();
          to.push_back(*sample.grasp_after);
          ++samples_per_hyperarc[h];
        }
      }
    }
  }
  return holdings;
}

}  // namespace

TEST_CASE("Transition samples of the default world: every pick, handoff and place hyperarc", "[planner][transition]") {
  const Setup& s = world("default.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  std::mt19937_64 rng(2024);
  std::map<int, int> samples;
  const Holdings holdings = sampleHoldings(s, sampler, rng, 2, samples);
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    INFO(s.task_space.hyperarcName(h));
    REQUIRE(samples[h] > 0);
  }
  for (const int h : s.hyperarcs(TransitionKind::kHandoff)) {
    INFO(s.task_space.hyperarcName(h));
    REQUIRE(samples[h] > 0);
  }
  for (const int h : s.hyperarcs(TransitionKind::kPlace)) {
    INFO(s.task_space.hyperarcName(h));
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    const auto held = holdings.find({arc.robot, arc.object});
    REQUIRE(held != holdings.end());
    int placed = 0;
    for (const Grasp& grasp : held->second) {
      for (const TransitionSample& sample : sampler.place(h, grasp)) {
        checkSample(s, sample, h);
        REQUIRE(planner::sameGrasp(*sample.grasp_before, grasp));
        ++placed;
      }
    }
    REQUIRE(placed > 0);
  }
}

TEST_CASE("Transition sampling is deterministic", "[planner][transition]") {
  const Setup& s = world("default.yaml");
  TransitionSampler a(s.loaded, s.task_space, s.scene, s.sites);
  TransitionSampler b(s.loaded, s.task_space, s.scene, s.sites);
  const int pick = s.hyperarcs(TransitionKind::kPick).front();
  const std::vector<TransitionSample> picks = a.pick(pick);
  REQUIRE_FALSE(picks.empty());
  requireIdentical(picks, b.pick(pick));
  requireIdentical(picks, a.pick(pick));  // the checker's state does not leak between calls
  const planner::TransitionHyperarc& picked = s.task_space.hyperarcs()[static_cast<std::size_t>(pick)];
  for (const int h : s.hyperarcs(TransitionKind::kPlace)) {
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    if (arc.robot == picked.robot)
      requireIdentical(a.place(h, *picks.front().grasp_after), b.place(h, *picks.front().grasp_after));
  }
  for (const int h : s.hyperarcs(TransitionKind::kHandoff)) {
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    if (arc.robot != picked.robot || arc.object != picked.object) continue;
    std::mt19937_64 rng_a(7), rng_b(7);
    const std::vector<TransitionSample> handoffs = a.handoff(h, *picks.front().grasp_after, rng_a, 3);
    REQUIRE_FALSE(handoffs.empty());
    requireIdentical(handoffs, b.handoff(h, *picks.front().grasp_after, rng_b, 3));
    REQUIRE(rng_a() == rng_b());
  }
}

TEST_CASE("Shelf slots are filled by pushing side-grasped items in horizontally", "[planner][transition][long]") {
  const Setup& s = world("shelf_2r_4o.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  // every grasp some robot picks each object with
  std::map<int, std::vector<Grasp>> picked;  // object -> grasps
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    for (const TransitionSample& sample : sampler.pick(h)) {
      checkSample(s, sample, h);
      // the items are too tall to be picked from above: the housing would hit their top
      const Vector3d approach_W = (sample.X_WO * sample.grasp_after->X_OT).linear().col(2);
      REQUIRE(std::abs(approach_W.z()) < 1e-6);
      picked[sample.object].push_back(*sample.grasp_after);
    }
  }
  // the object going to the front slot in front of a back slot: reaching into the back slot
  // passes through it, so placing there touches that object's goal site
  const auto frontPartner = [&s](int object) {
    const std::string& region =
        s.loaded.world->regions[static_cast<std::size_t>(s.sites.goal_region[static_cast<std::size_t>(object)])].name;
    if (!region.ends_with("_back")) return -1;
    const std::string front = region.substr(0, region.size() - 4) + "front";
    for (int o = 0; o < s.sites.numObjects(); ++o) {
      if (s.loaded.world->regions[static_cast<std::size_t>(s.sites.goal_region[static_cast<std::size_t>(o)])].name ==
          front)
        return o;
    }
    return -1;
  };
  int back_places = 0;
  for (const int h : s.hyperarcs(TransitionKind::kPlace)) {
    INFO(s.task_space.hyperarcName(h));
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    const int partner = frontPartner(arc.object);
    int placed = 0;
    for (const Grasp& grasp : picked[arc.object]) {
      for (const TransitionSample& sample : sampler.place(h, grasp)) {
        checkSample(s, sample, h);
        const Pose X_WT = sample.X_WO * sample.grasp_before->X_OT;
        REQUIRE(std::abs(X_WT.linear()(2, 2)) < 1e-6);  // horizontal
        if (partner >= 0) REQUIRE(sample.touches.test(ObjectSites::goalSite(partner)));
        back_places += partner >= 0;
        ++placed;
      }
    }
    REQUIRE(placed > 0);
  }
  REQUIRE(back_places > 0);
}

TEST_CASE("A side-grasped item among others is picked from above, alone from the side", "[planner][transition]") {
  // coming in sideways into some of its grasps of green_1, r1's wrist passes over green_3,
  // standing 0.36 m away
  const std::string file = "../tests/planner/worlds/shelf_items_side_by_side.yaml";
  const Setup& crowded = world(file);
  core::World alone_world = core::loadWorldFile(std::string(DASHBED_SOURCE_ROOT) + "/worlds/" + file);
  std::erase_if(alone_world.objects, [](const core::ObjectSpec& o) { return o.name != "green_1"; });
  std::erase_if(alone_world.goals, [](const core::Goal& g) { return g.object != "green_1"; });
  const Setup alone(core::validateWorld(std::move(alone_world)));

  // the grasps each robot picks an object in, from above or sideways
  struct Picks {
    std::vector<std::pair<int, Grasp>> above, sideways;
  };
  const auto picksOf = [](const Setup& s, const std::string& object) {
    TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
    Picks picks;
    for (const int h : s.hyperarcs(TransitionKind::kPick)) {
      for (const TransitionSample& sample : sampler.pick(h)) {
        checkSample(s, sample, h);
        const bool above = pickedFromAbove(s, sample);
        if (s.loaded.world->objects[static_cast<std::size_t>(sample.object)].name != object) continue;
        (above ? picks.above : picks.sideways).emplace_back(sample.motions.front().robot, *sample.grasp_after);
      }
    }
    return picks;
  };
  const Picks crowded_picks = picksOf(crowded, "green_1");
  const Picks alone_picks = picksOf(alone, "green_1");
  // a grasp is taken one way, never both; some taken from above among the others are taken
  // sideways alone, with nothing to pass over
  int switched = 0;
  for (const auto& [robot, grasp] : crowded_picks.above) {
    const auto same = [&](const auto& other) { return other.first == robot && planner::sameGrasp(other.second, grasp); };
    switched += std::any_of(alone_picks.sideways.begin(), alone_picks.sideways.end(), same);
    REQUIRE(std::none_of(crowded_picks.sideways.begin(), crowded_picks.sideways.end(), same));
  }
  REQUIRE(switched > 0);
  REQUIRE(alone_picks.above.size() < crowded_picks.above.size());
}

TEST_CASE("A bar goes into a bin turned by 45 degrees along its goal slot's axes", "[planner][transition]") {
  const Setup& s = world("../tests/planner/worlds/turned_bin_45.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  const core::Region& bin = s.loaded.world->regions.at(0);
  const Eigen::Matrix3d R_RW = bin.X_WR.linear().transpose();
  const Vector3d size = s.loaded.world->objects.at(0).size;
  // the bar's extents along the bin's axes at its goal slot: the long side along one of them
  const Vector3d slot_extents = (R_RW * s.sites.goal.at(0)->linear()).cwiseAbs() * size;
  REQUIRE(std::abs(slot_extents.maxCoeff() - 0.08) < 1e-9);
  std::vector<Grasp> held;
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    for (const TransitionSample& sample : sampler.pick(h)) held.push_back(*sample.grasp_after);
  }
  REQUIRE_FALSE(held.empty());
  int placed = 0;
  for (const int h : s.hyperarcs(TransitionKind::kPlace)) {
    for (const Grasp& grasp : held) {
      for (const TransitionSample& sample : sampler.place(h, grasp)) {
        checkSample(s, sample, h);
        const Vector3d extents = (R_RW * sample.X_WO.linear()).cwiseAbs() * size;
        REQUIRE((extents - slot_extents).cwiseAbs().maxCoeff() < 1e-9);
        ++placed;
      }
    }
  }
  REQUIRE(placed > 0);
}

TEST_CASE("Handoffs between adjacent robots of the four-robot world", "[planner][transition]") {
  const Setup& s = world("sort_4r_8c_cross.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  std::mt19937_64 rng(5);
  // one object per ordered pair of neighbours (bases 1.06 m apart; opposite ones are 1.5 m)
  std::set<std::pair<int, int>> tried;
  for (const int h : s.hyperarcs(TransitionKind::kHandoff)) {
    const planner::TransitionHyperarc& arc = s.task_space.hyperarcs()[static_cast<std::size_t>(h)];
    const Vector3d between = s.loaded.world->robots[static_cast<std::size_t>(arc.robot)].X_WBase.translation() -
                             s.loaded.world->robots[static_cast<std::size_t>(arc.receiver)].X_WBase.translation();
    if (between.norm() > 1.2 || tried.count({arc.robot, arc.receiver}) > 0) continue;
    int pick = -1;
    for (const int p : s.hyperarcs(TransitionKind::kPick)) {
      const planner::TransitionHyperarc& candidate = s.task_space.hyperarcs()[static_cast<std::size_t>(p)];
      if (candidate.robot == arc.robot && candidate.object == arc.object) pick = p;
    }
    if (pick < 0) continue;
    const std::vector<TransitionSample> picks = sampler.pick(pick);
    REQUIRE_FALSE(picks.empty());
    INFO(s.task_space.hyperarcName(h));
    const std::vector<TransitionSample> handoffs = sampler.handoff(h, *picks.front().grasp_after, rng, 2);
    REQUIRE_FALSE(handoffs.empty());
    for (const TransitionSample& sample : handoffs) checkSample(s, sample, h);
    tried.insert({arc.robot, arc.receiver});
  }
  REQUIRE(tried.size() == 8);
}

TEST_CASE("A receiver closes on the faces of a cube the giver's fingers leave free", "[planner][transition]") {
  const Setup& s = world("default.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  for (const int pick : s.hyperarcs(TransitionKind::kPick)) {
    const int object = s.task_space.hyperarcs()[static_cast<std::size_t>(pick)].object;
    for (const TransitionSample& sample : sampler.pick(pick)) {
      const Grasp& giver = *sample.grasp_after;
      const std::vector<Grasp> received = sampler.handoffGrasps(object, giver);
      REQUIRE_FALSE(received.empty());
      for (const Grasp& grasp : received) {
        // the receiver's closing axis along the giver's approach, so its pads sit on the two
        // faces between the giver's fingers, not on the giver's pads
        CHECK(std::abs(grasp.X_OT.linear().col(0).dot(giver.X_OT.linear().col(2))) > 0.99);
        CHECK(std::abs(grasp.X_OT.linear().col(0).dot(giver.X_OT.linear().col(0))) < 0.01);
      }
    }
  }
}

TEST_CASE("A tall item going into a bin is picked from above at its top and handed over end to end",
          "[planner][transition]") {
  // housing front face 46.4 mm behind the TCP (Robotiq Hand-E ROS 2 description and Isaac Sim
  // assets, github.com/robotiq), 5 mm kept clear
  constexpr double kTopReach = 0.1325 - 0.0861 - 0.005;
  const Setup& s = world("handwritten/x1b_tall_handoff_into_bin.yaml");  // 120 mm item, bin goal
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  const double half_height = s.loaded.world->objects[0].size.z() / 2;
  std::vector<std::pair<int, Grasp>> from_above;  // (picking robot, grasp)
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    for (const TransitionSample& sample : sampler.pick(h)) {
      checkSample(s, sample, h);
      const Grasp& grasp = *sample.grasp_after;
      if ((sample.X_WO * grasp.X_OT).linear().col(2).z() > -1.0 + 1e-6) continue;
      // the TCP above the centre, the item's top just out of the housing
      CHECK(half_height - grasp.X_OT.translation().z() == Approx(kTopReach).margin(1e-9));
      from_above.emplace_back(s.task_space.hyperarcs()[static_cast<std::size_t>(h)].robot, grasp);
    }
  }
  REQUIRE_FALSE(from_above.empty());
  std::mt19937_64 rng(3);
  int end_to_end = 0, end_to_end_handoffs = 0;
  for (const auto& [robot, giver] : from_above) {
    const Vector3d giver_approach = giver.X_OT.linear().col(2);
    for (const Grasp& grasp : sampler.handoffGrasps(0, giver)) {
      // coming the other way with its fingertips (13 mm beyond each TCP) 5 mm past the giver's
      const double apart = (grasp.X_OT.translation() - giver.X_OT.translation()).dot(giver_approach);
      if (grasp.X_OT.linear().col(2).dot(giver_approach) > -0.99) continue;
      CHECK(apart >= 2 * 0.013 + 0.005 - 1e-9);
      ++end_to_end;
    }
    for (const int h : s.hyperarcs(TransitionKind::kHandoff)) {
      if (s.task_space.hyperarcs()[static_cast<std::size_t>(h)].robot != robot) continue;
      for (const TransitionSample& sample : sampler.handoff(h, giver, rng, 4)) {
        checkSample(s, sample, h);
        if (sample.grasp_after->X_OT.linear().col(2).dot(giver_approach) < -0.99) ++end_to_end_handoffs;
      }
    }
  }
  CHECK(end_to_end > 0);
  CHECK(end_to_end_handoffs > 0);
  // the same item going onto a pad keeps its centred grasps: from above its top would be in
  // the housing, so it is picked from the side only
  const Setup& pad = world("handwritten/v05_shapes.yaml");
  TransitionSampler pad_sampler(pad.loaded, pad.task_space, pad.scene, pad.sites);
  int tall_picks = 0;
  for (const int h : pad.hyperarcs(TransitionKind::kPick)) {
    const int object = pad.task_space.hyperarcs()[static_cast<std::size_t>(h)].object;
    if (pad.loaded.world->objects[static_cast<std::size_t>(object)].size.z() < 0.1) continue;
    for (const TransitionSample& sample : pad_sampler.pick(h)) {
      CHECK(std::abs((sample.X_WO * sample.grasp_after->X_OT).linear().col(2).z()) < 1e-6);
      ++tall_picks;
    }
  }
  CHECK(tall_picks > 0);
}

TEST_CASE("The transition sampler rejects hyperarcs of the wrong kind", "[planner][transition]") {
  const Setup& s = world("default.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  std::mt19937_64 rng(1);
  const int pick = s.hyperarcs(TransitionKind::kPick).front();
  REQUIRE_THROWS_AS(sampler.place(pick, Grasp{}), std::invalid_argument);
  REQUIRE_THROWS_AS(sampler.handoff(pick, Grasp{}, rng, 1), std::invalid_argument);
  REQUIRE_THROWS_AS(sampler.pick(s.hyperarcs(TransitionKind::kPlace).front()), std::invalid_argument);
  REQUIRE_THROWS_AS(sampler.pick(-1), std::invalid_argument);
  REQUIRE_THROWS_AS(sampler.pick(static_cast<int>(s.task_space.numHyperarcs())), std::invalid_argument);
}

TEST_CASE("A robot slides an item into a slot in front of the other robot's base from just out of the shelf",
          "[planner][transition]") {
  // slot_5_front lies straight in front of r1. r0, reaching across, would have its wrist over
  // r1's base at the start of a slide_distance slide: it slides in from nearer
  const Setup& s = world("../tests/planner/worlds/shelf_far_front_slot.yaml");
  TransitionSampler sampler(s.loaded, s.task_space, s.scene, s.sites);
  const TransitionSettings settings;
  std::vector<Grasp> grasps;  // every grasp r1 picks blue_5 in
  for (const int h : s.hyperarcs(TransitionKind::kPick)) {
    for (const TransitionSample& sample : sampler.pick(h)) grasps.push_back(*sample.grasp_after);
  }
  REQUIRE_FALSE(grasps.empty());
  int full = 0, shorter = 0;
  for (const int h : s.hyperarcs(TransitionKind::kPlace)) {
    if (s.task_space.hyperarcs()[static_cast<std::size_t>(h)].robot != 0) continue;
    for (const Grasp& grasp : grasps) {
      for (const TransitionSample& sample : sampler.place(h, grasp)) {
        checkSample(s, sample, h);  // with where the slide starts
        const Pose X_WT = sample.X_WO * grasp.X_OT;
        if (X_WT.linear().col(2).x() < 0.99) continue;  // not in through the shelf's open side
        const Vector3d start = (*s.loaded.robots)[0].tcpPoseInWorld(sample.motions.front().keys.front().q).translation();
        (X_WT.translation().x() - start.x() < settings.slide_distance - 1e-6 ? shorter : full) += 1;
      }
    }
  }
  CHECK(shorter > 0);
  CHECK(full > 0);  // the grasps whose wrist clears r1's base slide in all the way
}
