#include "planner/sampling/transition_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>

#include "core/geometry.h"
#include "core/hande.h"
#include "core/key_timing.h"
#include "core/grasps.h"
#include "planner/sampling/key_curve.h"

namespace dashbed::planner {

bool sameGrasp(const Grasp& a, const Grasp& b) {
  return (a.X_OT.linear() - b.X_OT.linear()).cwiseAbs().maxCoeff() <= 1e-9 &&
         (a.X_OT.translation() - b.X_OT.translation()).cwiseAbs().maxCoeff() <= 1e-9;
}

namespace {

using core::ArmConfig;
using core::GripperAction;
using core::Pose;
using Eigen::Matrix3d;
using Eigen::Vector3d;

const Vector3d kUp = Vector3d::UnitZ();
/// Width of a Hand-E standard fingertip across the closing axis (Robotiq's Hand-E Isaac Sim
/// assets, github.com/robotiq/isaacsim_assets; the URDF's tip box).
constexpr double kFingertipWidth = 0.0292;
/// How far the Hand-E housing's front face lies behind the TCP: TCP 132.5 mm (Robotiq Hand-E
/// ROS 2 description, github.com/robotiq/ros), face 86.1 mm (Robotiq's Hand-E Isaac Sim assets)
/// from the mounting face (the URDF's housing box).
constexpr double kHousingBehindTcp = 0.1325 - 0.0861;
/// Room kept between two grippers' fingertips along an object, and between a held object and
/// the housing [m] (above twice the collision margin).
constexpr double kHandoffClearance = 0.005;
/// Handoff orientations of the giver's TCP: approach axis towards the receiver, level or
/// pitched 45 degrees down, turned about itself by multiples of 90 degrees.
constexpr std::array<double, 2> kHandoffPitches{0.0, std::numbers::pi / 4};
constexpr int kHandoffRolls = 4;
constexpr int kHandoffOrientations = static_cast<int>(kHandoffPitches.size()) * kHandoffRolls;
/// A handoff hyperarc gets at most this many pose draws per requested sample (transition_sampler.h).
constexpr int kDrawsPerSample = 20;
/// Tolerance of the axis tests on rotations built from 90-degree turns.
constexpr double kAxisTolerance = 1e-6;
/// How far in front of a shelf's open side a held object may start sliding in at the nearest,
/// when it cannot start slide_distance back (placeSample) [m].
constexpr double kSlideClearance = 0.01;
/// How much nearer each further try of such a slide starts (placeSample) [m].
constexpr double kSlideShortening = 0.02;

Pose shifted(Pose X, const Vector3d& delta) {
  X.translation() += delta;
  return X;
}

/// A double uniform in [0, 1) from the top 53 bits of one draw (no std distribution: its
/// output differs between standard libraries).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

/// Index in [0, n) from a uniform u in [0, 1).
int indexOf(double u, int n) { return std::min(n - 1, static_cast<int>(u * n)); }

// ---- object geometry ------------------------------------------------------------------------

/// The object frame O relabelled as U, whose z is object axis k (pointing up when `up`, else
/// down) and whose x, y are the other two axes, right-handed: R_OU and the box size in U.
struct Relabelled {
  Matrix3d R_OU;
  Vector3d size_U;
};

Relabelled relabel(const Vector3d& size, int k, bool up) {
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  Relabelled U{Matrix3d::Zero(), Vector3d::Zero()};
  U.R_OU(k, 2) = up ? 1.0 : -1.0;
  U.R_OU(up ? a : b, 0) = 1.0;  // (a, b, k) and (b, a, -k) are right-handed
  U.R_OU(up ? b : a, 1) = 1.0;
  U.size_U = Vector3d(size[up ? a : b], size[up ? b : a], size[k]);
  return U;
}

/// The relabelling whose z is the object axis nearest the world vertical at R_WO, upwards.
Relabelled uprightFrame(const Matrix3d& R_WO, const Vector3d& size) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(R_WO(2, i)) > std::abs(R_WO(2, k))) k = i;
  }
  return relabel(size, k, R_WO(2, k) > 0.0);
}

/// The grasps core::boxGrasps gives for the object in frame U (only those from above when
/// `top_only`; from above reaching at most `top_reach` above the TCP), in the object frame;
/// the fingers close to half the box's width along the TCP x
/// axis. Where the box is at least two fingertips long along the pads' width axis (TCP y), each
/// also comes shifted along it to either end, the pads still fully on the box: on a long object
/// (the shelf items) two grippers can then hold it side by side in a handoff, which the
/// centred grasps alone never allow (the holder's 75 mm wide housing blocks the other's
/// fingers). Never downwards in U (a side grasp of an upright item): the housing would reach
/// into the surface the box rests on, which boxGrasps keeps it clear of. Fixed order.
std::vector<Grasp> graspsOf(const Relabelled& U, const Vector3d& size, bool top_only,
                            double top_reach = std::numeric_limits<double>::infinity()) {
  Pose X_OU = Pose::Identity();
  X_OU.linear() = U.R_OU;
  const Vector3d up = U.R_OU.col(2);
  std::vector<Grasp> grasps;
  for (const core::BoxGrasp& box_grasp : core::boxGrasps(U.size_U, core::kGraspClearance, top_reach)) {
    if (top_only && box_grasp.approach != core::GraspApproach::kTop) continue;
    Grasp grasp;
    grasp.X_OT = X_OU * box_grasp.X_OT;
    grasp.finger = 0.5 * size.dot(grasp.X_OT.linear().col(0).cwiseAbs());
    grasps.push_back(grasp);
    const Vector3d width_axis = grasp.X_OT.linear().col(1);
    const double length = size.dot(width_axis.cwiseAbs());
    if (length < 2 * kFingertipWidth) continue;
    for (const double end : {1.0, -1.0}) {
      if (end * width_axis.dot(up) < -0.5) continue;
      grasps.push_back(grasp);
      grasps.back().X_OT.translation() += end * (length - kFingertipWidth) / 2 * width_axis;
    }
  }
  return grasps;
}

/// How far before the grasp pose (along the approach) the fingertips, kFingertipBeyondTcp
/// ahead of the TCP, reach the plane of the object's near face: from there on the open fingers
/// surround the object [m].
double surroundDistance(const Vector3d& size, const Grasp& grasp) {
  const Vector3d approach = grasp.X_OT.linear().col(2);
  return 0.5 * size.dot(approach.cwiseAbs()) + grasp.X_OT.translation().dot(approach) + core::kFingertipBeyondTcp;
}

/// How far `object` may reach above the TCP in a grasp from above [m]: an object that goes into
/// a bin (placed only from above) is held high enough for its top to stay kHandoffClearance
/// out of the housing, a tall one above its centre; any other keeps the TCP at its centre (a
/// tall one is then picked from the side, as shelf items are slid in).
double topReach(const core::World& world, const ObjectSites& sites, int object) {
  const int region = sites.goal_region[static_cast<std::size_t>(object)];
  const bool into_bin = region >= 0 && !world.regions[static_cast<std::size_t>(region)].fixture.empty();  // bins' insides
  return into_bin ? kHousingBehindTcp - kHandoffClearance : std::numeric_limits<double>::infinity();
}

/// Grasps a receiver may take of an object held in `giver`: those from above (graspsOf) of the
/// object relabelled with each of its six faces up, i.e. every approach along a face normal,
/// with the receiver coming in across both the giver's approach and closing axes (and so
/// closing along the giver's approach axis), its pads fitting between the giver's fingers with
/// kHandoffClearance to spare (not so on a cube under 40 mm), and its open fingers passing the
/// object with more than the collision checker's margins (`margin` on the receiver's fingers
/// and on the object the giver holds) on either side (not so on a 45 mm cube: 2.5 mm beside it
/// in the Hand-E's 50 mm). This is the handoff that holds in
/// simulation (the scripted-plan tool's: giver level, receiver from above): a receiver coming
/// head-on loses the cube when the giver withdraws, and one coming along the giver's closing
/// axis has its housing next to a giver finger, which touches it when the giver opens.
/// On a long object (the shelf items) the receiver may also come head-on, against the giver's
/// approach, closing on the giver's face pair, where the two pairs of fingertips sit apart
/// along the object's length (the pads' width axis of both): the giver at one end, the receiver
/// in the middle or at the other end. The receiver then ends with a side grasp it can slide
/// into a shelf. And on an item held at one end from above (a tall item going into a bin,
/// topReach), the receiver may come head-on end to end, at the other end: the two pairs of
/// fingertips kHandoffClearance apart along the item, the receiver's grasp from above with
/// the item upside down. Grasps whose object would reach back into the receiver's housing
/// (within kHandoffClearance of it) are left out (an end-on grasp of a tall item with the TCP
/// at its centre, where `top_reach` does not raise it). Fixed order, no repeats.
std::vector<Grasp> receiverGrasps(const Vector3d& size, const Grasp& giver, double margin, double top_reach) {
  const Vector3d giver_closing = giver.X_OT.linear().col(0);
  const Vector3d giver_width = giver.X_OT.linear().col(1);
  const Vector3d giver_approach = giver.X_OT.linear().col(2);
  std::vector<Grasp> grasps;
  for (int k = 0; k < 3; ++k) {
    for (const bool up : {true, false}) {
      for (const Grasp& grasp : graspsOf(relabel(size, k, up), size, true, top_reach)) {
        const Vector3d approach = grasp.X_OT.linear().col(2);
        // how far the object reaches back from the TCP, towards the housing (against the
        // approach): its half extent along the approach plus the TCP's offset along it
        const double behind = 0.5 * size.dot(approach.cwiseAbs()) + grasp.X_OT.translation().dot(approach);
        if (behind > kHousingBehindTcp - kHandoffClearance + kAxisTolerance) continue;  // (topReach exactly)
        const double width = size.dot(grasp.X_OT.linear().col(0).cwiseAbs());  // across the fingers
        if (width + 4 * margin >= core::kHandeMaxOpening) continue;
        // across: the receiver's pads, kFingertipWidth wide along the giver's closing axis, fit
        // between the giver's fingers (a 30 mm cube leaves 0.4 mm beside a 29.2 mm pad)
        const double pad_offset = std::abs((grasp.X_OT.translation() - giver.X_OT.translation()).dot(giver_closing));
        // (closing along the giver's approach axis: on the faces the giver's fingers leave free)
        const bool across = std::abs(approach.dot(giver_closing)) <= 0.5 &&
                            std::abs(approach.dot(giver_approach)) <= 0.5 &&
                            std::abs(grasp.X_OT.linear().col(0).dot(giver_approach)) > 0.5 &&
                            pad_offset + kFingertipWidth / 2 + kHandoffClearance <= giver.finger;
        const bool head_on = approach.dot(giver_approach) < -0.5 &&
                             std::abs(grasp.X_OT.linear().col(1).dot(giver_width)) > 0.5 &&
                             std::abs((grasp.X_OT.translation() - giver.X_OT.translation()).dot(giver_width)) >=
                                 kFingertipWidth + kHandoffClearance;
        // the receiver's fingertips beyond the giver's along the item, coming the other way
        const bool end_to_end = approach.dot(giver_approach) < -0.5 &&
                                (grasp.X_OT.translation() - giver.X_OT.translation()).dot(giver_approach) >=
                                    2 * core::kFingertipBeyondTcp + kHandoffClearance;
        if (!across && !head_on && !end_to_end) continue;
        const auto same = [&grasp](const Grasp& other) { return sameGrasp(grasp, other); };
        if (std::none_of(grasps.begin(), grasps.end(), same)) grasps.push_back(grasp);
      }
    }
  }
  return grasps;
}

// ---- arms: IK along straight lines ------------------------------------------------------------

/// What a transition needs of one robot.
struct Arm {
  int robot = -1;
  const core::PlacedRobot* placed = nullptr;
  ArmConfig home{};
  std::array<double, 6> max_velocity{};  // [rad/s]
  double max_acceleration = 0.0;         // [rad/s^2], the world's safety limit
};

Arm armOf(const core::LoadedWorld& world, int robot) {
  Arm arm;
  arm.robot = robot;
  arm.placed = &(*world.robots)[static_cast<std::size_t>(robot)];
  arm.home = world.world->robots[static_cast<std::size_t>(robot)].home;
  const core::RobotModel& model = *arm.placed->model;
  for (int j = 0; j < 6; ++j) arm.max_velocity[j] = model.joints()[model.movableJoints()[j]].max_velocity;
  arm.max_acceleration = world.world->safety.max_joint_acceleration;
  return arm;
}

/// Clear of the elbow (sin q3 = 0) and wrist (sin q5 = 0) singularities.
bool regular(const ArmConfig& q, double margin) {
  return std::abs(std::sin(q[2])) >= margin && std::abs(std::sin(q[4])) >= margin;
}

/// How many equal steps a straight TCP line by delta_W takes: each cartesian_step or shorter.
int lineSteps(const Vector3d& delta_W, const TransitionSettings& settings) {
  return std::max(1, static_cast<int>(std::ceil(delta_W.norm() / settings.cartesian_step - 1e-9)));
}

/// Keys of a straight TCP line from X_from (at q_from) by delta_W in lineSteps steps, q_from
/// excluded: each the IK solution nearest the previous key, regular, within max_step_jump of
/// it. std::nullopt when the line leaves the workspace or would jump.
std::optional<std::vector<ArmConfig>> straightLine(const Arm& arm, const Pose& X_from, const ArmConfig& q_from,
                                                   const Vector3d& delta_W, const TransitionSettings& settings) {
  const int steps = lineSteps(delta_W, settings);
  std::vector<ArmConfig> keys;
  ArmConfig previous = q_from;
  for (int k = 1; k <= steps; ++k) {
    const Pose X_WT = shifted(X_from, delta_W * (static_cast<double>(k) / steps));
    const std::vector<ArmConfig> solutions = arm.placed->solveInWorld(X_WT, previous);
    if (solutions.empty() || !regular(solutions.front(), settings.singularity_margin)) return std::nullopt;
    const ArmConfig& q = solutions.front();
    for (int j = 0; j < 6; ++j) {
      if (std::abs(q[j] - previous[j]) > settings.max_step_jump) return std::nullopt;
    }
    keys.push_back(q);
    previous = q;
  }
  return keys;
}

/// A straight TCP line: its first key and the keys after it, equally spaced.
struct Line {
  ArmConfig start;
  std::vector<ArmConfig> keys;
};

/// The first result `use(line)` gives for the straight TCP lines from X_from by delta_W that
/// start at a regular IK solution of X_from, nearest the robot's home first. (The nearest
/// solution alone misses transitions whose nearest branch turns the wrist into the table or
/// loses the line.)
template <typename Use>
auto firstLine(const Arm& arm, const Pose& X_from, const Vector3d& delta_W, const TransitionSettings& settings,
               const Use& use) -> decltype(use(Line{})) {
  for (const ArmConfig& q : arm.placed->solveInWorld(X_from, arm.home)) {
    if (!regular(q, settings.singularity_margin)) continue;
    std::optional<std::vector<ArmConfig>> keys = straightLine(arm, X_from, q, delta_W, settings);
    if (!keys) continue;
    if (auto result = use(Line{q, std::move(*keys)})) return result;
  }
  return std::nullopt;
}

// ---- motions ----------------------------------------------------------------------------------

/// What a robot carries during one piece: its finger position, the object it holds, and the
/// transition's own object resting within reach (checked like any resting object).
struct Carry {
  double finger = core::kFingersOpen;
  std::optional<HeldObject> held;
  std::optional<RestingObject> resting;
};

/// Builds one robot's TransitionMotion key by key, timing each piece.
struct MotionBuilder {
  MotionBuilder(const Arm& arm_, const ArmConfig& q0, const TransitionSettings& settings_)
      : arm(&arm_), settings(&settings_) {
    motion.robot = arm_.robot;
    motion.keys.push_back({0, q0});
  }

  Millis now() const { return motion.keys.back().t; }
  const ArmConfig& q() const { return motion.keys.back().q; }

  /// A key at q reached along a straight TCP line of `length` [m], at the average Cartesian
  /// speed but no joint faster than peak_factor x its average allows under speed_fraction of its
  /// limit (the curve through the keys peaks above the average). Consecutive keys form one run
  /// from rest to rest, eased in and out within the acceleration limit (core/key_timing.h).
  void moveTo(const ArmConfig& q_next, double length, const Carry& carry) {
    double seconds = length / settings->cartesian_speed;
    for (int j = 0; j < 6; ++j) {
      seconds = std::max(seconds, std::abs(q_next[j] - q()[j]) * settings->peak_factor /
                                      (settings->speed_fraction * arm->max_velocity[j]));
    }
    push(q_next, 1, carry);
    run_pace_.push_back(seconds);
    retimeRun();
  }

  /// A key at the current configuration `duration` later (none for a zero duration); the arm
  /// is at rest.
  void hold(Millis duration, const Carry& carry) {
    if (duration > 0) push(q(), duration, carry);
    endRun();
  }

  /// A gripper command now; the arm is at rest.
  void grip(GripperAction action) {
    motion.grips.push_back({now(), action});
    endRun();
  }

  /// Key k as the collision checker takes it, with the fingers of piece i.
  Eigen::VectorXd configuration(const CollisionScene& scene, std::size_t k, std::size_t i) const {
    return scene.configuration(motion.robot, motion.keys[k].q, motion.finger[i]);
  }
  /// Piece i on the key curve the simulator follows through the keys so far (keyCurvePiece).
  CurvePiece piece(const CollisionScene& scene, std::size_t i) const {
    if (!curve_) curve_ = keyCurve(motion);
    return keyCurvePiece(scene, motion, *curve_, i);
  }

  const Arm* arm;
  const TransitionSettings* settings;
  TransitionMotion motion;
  std::vector<std::optional<RestingObject>> resting;  // per piece

 private:
  mutable std::optional<core::TrajectoryInterpolator> curve_;
  std::size_t run_start_ = 0;     // the key the current run starts from, at rest
  std::vector<double> run_pace_;  // the run's pieces at pace [s]

  void endRun() {
    run_start_ = motion.keys.size() - 1;
    run_pace_.clear();
  }

  /// Times the keys after run_start_ as one run ending at rest at the last key.
  void retimeRun() {
    curve_.reset();
    std::vector<ArmConfig> keys;
    for (std::size_t k = run_start_; k < motion.keys.size(); ++k) keys.push_back(motion.keys[k].q);
    core::KeyTimingLimits limits;
    limits.max_velocity = arm->max_velocity;
    limits.max_acceleration.fill(std::min(settings->max_acceleration, arm->max_acceleration));
    const std::vector<Millis> times = core::restToRestKeyTimes(keys, run_pace_, limits);
    const Millis t0 = motion.keys[run_start_].t;
    for (std::size_t k = 1; k < times.size(); ++k) motion.keys[run_start_ + k].t = t0 + times[k];
  }

  void push(const ArmConfig& q_next, Millis duration, const Carry& carry) {
    curve_.reset();
    motion.keys.push_back({now() + duration, q_next});
    motion.finger.push_back(carry.finger);
    motion.held.push_back(carry.held);
    resting.push_back(carry.resting);
  }
};

/// Shared by the sample builders: the inputs and the sampler's checker.
struct Context {
  const core::World& world;
  const CollisionScene& scene;
  const ObjectSites& sites;
  const TransitionSettings& settings;
  CollisionChecker& checker;
};

/// How finely a motion is checked: at its keys (one configuration each: cheap, and where
/// nearly every rejection already shows, keys being a centimetre apart), or along its pieces on
/// the key curve the simulator follows (key_curve.h) at the collision scene's motion step (both
/// keys included). Samples are checked at the keys first, then along the pieces.
enum class Check { kKeys, kPieces };

/// Every piece free against the static scene and the robot itself with the piece's fingers and
/// held object, and against the transition's object where it rests.
bool staticFree(Context& c, const MotionBuilder& m, Check check) {
  const TransitionMotion& motion = m.motion;
  for (std::size_t i = 0; i + 1 < motion.keys.size(); ++i) {
    std::vector<RestingObject> resting;
    if (m.resting[i]) resting.push_back(*m.resting[i]);
    const auto keyFree = [&](std::size_t k) {
      return c.checker.robotFree(motion.robot, m.configuration(c.scene, k, i), resting, motion.held[i]);
    };
    const bool free = check == Check::kKeys ? keyFree(i) && keyFree(i + 1)
                                            : c.checker.motionFree(motion.robot, m.piece(c.scene, i), resting, motion.held[i]);
    if (!free) return false;
  }
  return true;
}

/// Robot against robot while `moving` runs pieces [first, last) of its motion and the other
/// robot stays at q with its fingers at `finger`, holding `held`.
bool clearOf(Context& c, const MotionBuilder& moving, std::size_t first, std::size_t last, const Arm& still,
             const ArmConfig& q, double finger, const std::optional<HeldObject>& held, Check check) {
  const TransitionMotion& motion = moving.motion;
  const StandingRobot other{still.robot, c.scene.configuration(still.robot, q, finger), held};
  for (std::size_t i = first; i < last; ++i) {
    const auto keyFree = [&](std::size_t k) {
      return c.checker.robotsFree(motion.robot, moving.configuration(c.scene, k, i), motion.held[i], other.robot, other.q,
                                  other.held);
    };
    const bool free = check == Check::kKeys ? keyFree(i) && keyFree(i + 1)
                                            : c.checker.motionClearOf(motion.robot, moving.piece(c.scene, i),
                                                                      motion.held[i], std::span(&other, 1));
    if (!free) return false;
  }
  return true;
}

/// The sites of other objects (ObjectSites) that some piece of the motions would touch. The
/// motions must have passed staticFree(..., Check::kPieces).
SiteSet touchedSites(Context& c, const std::vector<const MotionBuilder*>& motions, int object) {
  SiteSet touches(c.sites.numSites());
  std::vector<RestingObject> others;
  std::vector<int> other_sites;
  for (int site = 0; site < c.sites.numSites(); ++site) {
    const std::optional<RestingObject> resting = c.sites.site(site);
    if (!resting || resting->object == object) continue;
    others.push_back(*resting);
    other_sites.push_back(site);
  }
  for (const MotionBuilder* m : motions) {
    const TransitionMotion& motion = m->motion;
    for (std::size_t i = 0; i + 1 < motion.keys.size(); ++i) {
      // the piece is free against the static scene and the robot itself (staticFree): each
      // site's check reduces to its object
      const std::vector<char> hits = c.checker.motionObjectHits(motion.robot, m->piece(c.scene, i), others, motion.held[i]);
      for (std::size_t s = 0; s < others.size(); ++s) {
        if (hits[s]) touches.set(other_sites[s]);
      }
    }
  }
  return touches;
}

/// The parts every sample shares.
TransitionSample sampleOf(int hyperarc, TransitionKind kind, int object, const Pose& X_WO,
                          const std::vector<const MotionBuilder*>& motions, SiteSet touches) {
  TransitionSample sample;
  sample.hyperarc = hyperarc;
  sample.kind = kind;
  sample.object = object;
  sample.X_WO = X_WO;
  for (const MotionBuilder* m : motions) {
    sample.motions.push_back(m->motion);
    sample.duration = std::max(sample.duration, m->now());
  }
  sample.touches = std::move(touches);
  sample.action_end = sample.duration;
  return sample;
}

/// Whether an object that has moved `height` above its rest pose still touches its support:
/// within the collision margin, by which the held object's box is grown.
bool onSupport(const Context& c, double height) { return height <= c.scene.settings().margin + 1e-9; }

/// One robot's part in a transition: it grasps or releases `object` at X_WO with `grasp`.
struct Part {
  int hyperarc = -1;
  const Arm* arm = nullptr;
  int object = -1;
  Pose X_WO = Pose::Identity();
  Grasp grasp;
};

/// The sample's own object as the robot holds it (X_TO from the grasp).
HeldObject heldIn(const Part& p, bool check_static) {
  return HeldObject{p.object, p.grasp.X_OT.inverse(), check_static};
}

/// Where the line into a grasp or release pose X_WT starts: cartesian_distance back along the
/// TCP's approach axis.
Pose backedOff(const Pose& X_WT, double distance) { return shifted(X_WT, -distance * X_WT.linear().col(2)); }

// ---- pick ------------------------------------------------------------------------------------

/// Along the approach `in` (the object counts as held, not against the static scene, once the
/// open fingers surround it: the last `surround` of the line), close, dwell, lift straight up.
std::optional<TransitionSample> pickAlong(Context& c, const Part& p, const Line& in, double surround) {
  const TransitionSettings& s = c.settings;
  const double d = s.cartesian_distance;
  const auto lift = straightLine(*p.arm, p.X_WO * p.grasp.X_OT, in.keys.back(), d * kUp, s);
  if (!lift) return std::nullopt;

  MotionBuilder m(*p.arm, in.start, s);
  const auto n_in = static_cast<double>(in.keys.size());
  for (std::size_t k = 0; k < in.keys.size(); ++k) {
    const double remaining = d * (n_in - static_cast<double>(k) - 1.0) / n_in;  // after this piece
    if (remaining < surround) {
      m.moveTo(in.keys[k], d / n_in, {core::kFingersOpen, heldIn(p, false), std::nullopt});
    } else {
      m.moveTo(in.keys[k], d / n_in, {core::kFingersOpen, std::nullopt, RestingObject{p.object, p.X_WO}});
    }
  }
  m.grip(GripperAction::kClose);
  m.hold(ceilMillis(s.gripper_dwell), {p.grasp.finger, heldIn(p, false), std::nullopt});
  const auto n_lift = static_cast<double>(lift->size());
  for (std::size_t k = 0; k < lift->size(); ++k) {
    const double height = d * static_cast<double>(k) / n_lift;  // at the start of this piece
    m.moveTo((*lift)[k], d / n_lift, {p.grasp.finger, heldIn(p, !onSupport(c, height)), std::nullopt});
  }
  if (!staticFree(c, m, Check::kKeys) || !staticFree(c, m, Check::kPieces)) return std::nullopt;

  TransitionSample sample =
      sampleOf(p.hyperarc, TransitionKind::kPick, p.object, p.X_WO, {&m}, touchedSites(c, {&m}, p.object));
  sample.grasp_after = p.grasp;
  return sample;
}

/// Pre-grasp back along the grasp's approach axis, straight approach, close, dwell, lift. A side
/// grasp (horizontal approach) may instead come straight down from above, its open fingers
/// passing on either side of the item: coming in sideways, the gripper and wrist sweep the table
/// beside the item at its height, where the items next to it stand; from above they pass over
/// them. The one from above is taken where it touches fewer sites (a strict subset), or where
/// the sideways approach has no sample.
std::optional<TransitionSample> pickSample(Context& c, const Part& p) {
  const Pose X_WT = p.X_WO * p.grasp.X_OT;
  const Vector3d approach = X_WT.linear().col(2);
  const double d = c.settings.cartesian_distance;
  const double surround = surroundDistance(c.world.objects[static_cast<std::size_t>(p.object)].size, p.grasp);
  std::optional<TransitionSample> sideways = firstLine(*p.arm, backedOff(X_WT, d), d * approach, c.settings,
                                                       [&](const Line& in) { return pickAlong(c, p, in, surround); });
  if (std::abs(approach.z()) > kAxisTolerance || (sideways && sideways->touches.none())) return sideways;
  // from above the item counts as resting, and is checked against the fingers, all the way down
  std::optional<TransitionSample> above = firstLine(*p.arm, shifted(X_WT, d * kUp), -d * kUp, c.settings,
                                                    [&](const Line& in) { return pickAlong(c, p, in, 0.0); });
  if (above && (!sideways || (above->touches.subsetOf(sideways->touches) && above->touches != sideways->touches))) {
    return above;
  }
  return sideways;
}

// ---- place -----------------------------------------------------------------------------------

/// Resting orientations at a goal site: the object on each face, turned by multiples of 90
/// degrees from the region's yaw, keeping those that fill exactly the site's box (so the site
/// the search schedules stays the volume the object occupies; extents along the region's axes,
/// which tell a quarter turn apart at any region yaw). Fixed order.
std::vector<Matrix3d> placeOrientations(const Vector3d& size, const Matrix3d& R_site, double region_yaw) {
  const Matrix3d R_RW = Eigen::AngleAxisd(-region_yaw, kUp).toRotationMatrix();
  const auto extents_in_region = [&](const Matrix3d& R_WO) -> Vector3d { return (R_RW * R_WO).cwiseAbs() * size; };
  const Vector3d extents = extents_in_region(R_site);
  std::vector<Matrix3d> orientations;
  for (int k = 0; k < 3; ++k) {
    for (const bool up : {true, false}) {
      const Matrix3d R_UO = relabel(size, k, up).R_OU.transpose();
      for (int turn = 0; turn < 4; ++turn) {
        const Matrix3d R_WO =
            Eigen::AngleAxisd(region_yaw + turn * std::numbers::pi / 2, kUp).toRotationMatrix() * R_UO;
        if ((extents_in_region(R_WO) - extents).cwiseAbs().maxCoeff() <= 1e-9) orientations.push_back(R_WO);
      }
    }
  }
  return orientations;
}

/// The height above its placement of an object carried in to it down (`vertical`) or across
/// from `d` away, on piece k of the line's n, ending `release` above it.
double heightIn(double release, bool vertical, double d, std::size_t k, std::size_t n) {
  const auto pieces = static_cast<double>(n);
  return release + (vertical ? d * (pieces - static_cast<double>(k) - 1.0) / pieces : 0.0);  // after piece k
}

/// Whether the held object alone keeps clear of the static scene along the line into a
/// release pose X_WT from `d` back, where placeAlong would check it (the keys of pieces off
/// the support). Where it does not, no arm can carry it in that way: tried before any IK.
bool heldClearAlong(Context& c, const Part& p, const Pose& X_WT, double release, bool vertical, double d) {
  const Vector3d delta = d * X_WT.linear().col(2);
  const Pose X_from = backedOff(X_WT, d);
  const Pose X_TO = p.grasp.X_OT.inverse();
  const int n = lineSteps(delta, c.settings);
  const auto objectAt = [&](int k) { return shifted(X_from, delta * (static_cast<double>(k) / n)) * X_TO; };
  int checked = -1;  // the last key checked: a piece's start is the end of the piece before
  for (int k = 0; k < n; ++k) {
    if (onSupport(c, heightIn(release, vertical, d, static_cast<std::size_t>(k), static_cast<std::size_t>(n)))) continue;
    for (const int key : {k, k + 1}) {
      if (key == checked) continue;
      if (!c.checker.heldObjectFree(p.arm->robot, p.object, objectAt(key))) return false;
      checked = key;
    }
  }
  return true;
}

/// Along the line `in` to the release pose `release` above the placement, open, dwell,
/// retreat the same way with the object resting.
std::optional<TransitionSample> placeAlong(Context& c, const Part& p, double release, bool vertical, double d,
                                           const Line& in) {
  const TransitionSettings& s = c.settings;
  const Carry open{core::kFingersOpen, std::nullopt, RestingObject{p.object, p.X_WO}};
  MotionBuilder m(*p.arm, in.start, s);
  const auto n = static_cast<double>(in.keys.size());
  for (std::size_t k = 0; k < in.keys.size(); ++k) {
    const double height = heightIn(release, vertical, d, k, in.keys.size());
    m.moveTo(in.keys[k], d / n, {p.grasp.finger, heldIn(p, !onSupport(c, height)), std::nullopt});
  }
  m.grip(GripperAction::kOpen);
  m.hold(ceilMillis(s.gripper_dwell), open);
  for (std::size_t k = in.keys.size() - 1; k-- > 0;) m.moveTo(in.keys[k], d / n, open);
  m.moveTo(in.start, d / n, open);
  if (!staticFree(c, m, Check::kKeys) || !staticFree(c, m, Check::kPieces)) return std::nullopt;

  TransitionSample sample =
      sampleOf(p.hyperarc, TransitionKind::kPlace, p.object, p.X_WO, {&m}, touchedSites(c, {&m}, p.object));
  sample.grasp_before = p.grasp;
  return sample;
}

/// How far back from X_WO an object of `size` slid in along the horizontal `approach` has to
/// start to be out of the shelf it goes into, kSlideClearance in front of its open side (-x of
/// the shelf), or std::nullopt when it goes into no shelf or not through the open side.
std::optional<double> outOfShelfDistance(const core::World& world, const Vector3d& size, const Pose& X_WO,
                                         const Vector3d& approach) {
  for (const core::FixtureSpec& shelf : world.fixtures) {
    if (shelf.type != core::FixtureType::kShelf) continue;
    const Vector3d p_FO = shelf.X_WF.inverse() * X_WO.translation();  // X_WF: the shelf's bottom centre
    const Vector3d half = shelf.size / 2;
    if (std::abs(p_FO.x()) > half.x() || std::abs(p_FO.y()) > half.y() || p_FO.z() < 0 || p_FO.z() > shelf.size.z()) {
      continue;
    }
    const double in = (shelf.X_WF.linear().transpose() * approach).x();  // along the shelf's depth
    if (in < std::numbers::sqrt2 / 2) return std::nullopt;               // not in through the front
    const double depth = core::rotatedBoxExtent(shelf.X_WF.linear().transpose() * X_WO.linear(), size).x();
    return (p_FO.x() + half.x() + depth / 2 + kSlideClearance) / in;
  }
  return std::nullopt;
}

/// Start back along the held grasp's approach axis from the release pose: cartesian_distance
/// above the placement for a vertical approach (released drop_height above it),
/// slide_distance in front of it for a horizontal one (slid in and released slide_height above
/// it). A slide into a shelf through its open side that has no sample from slide_distance
/// back is tried again from nearer, kSlideShortening at a time, down to just out of the shelf
/// (outOfShelfDistance): reaching across into the slot straight in front of the other robot,
/// a robot's wrist would be over that robot's base at slide_distance back. Other approaches
/// (from below, oblique) give nothing.
std::optional<TransitionSample> placeSample(Context& c, const Part& p) {
  const TransitionSettings& s = c.settings;
  const Vector3d approach = (p.X_WO * p.grasp.X_OT).linear().col(2);
  const bool vertical = approach.z() < -1.0 + kAxisTolerance;
  if (!vertical && std::abs(approach.z()) > kAxisTolerance) return std::nullopt;
  const double release = vertical ? s.drop_height : s.slide_height;
  const Pose X_WT = shifted(p.X_WO, release * kUp) * p.grasp.X_OT;
  const auto from = [&](double distance) -> std::optional<TransitionSample> {
    if (!heldClearAlong(c, p, X_WT, release, vertical, distance)) return std::nullopt;
    return firstLine(*p.arm, backedOff(X_WT, distance), distance * approach, s,
                     [&](const Line& in) { return placeAlong(c, p, release, vertical, distance, in); });
  };
  if (vertical) return from(s.cartesian_distance);
  const std::optional<double> out =
      outOfShelfDistance(c.world, c.world.objects[static_cast<std::size_t>(p.object)].size, p.X_WO, approach);
  const double shortest = std::min(std::max(out.value_or(s.slide_distance), s.cartesian_distance), s.slide_distance);
  for (double distance = s.slide_distance;; distance = std::max(distance - kSlideShortening, shortest)) {
    if (std::optional<TransitionSample> sample = from(distance)) return sample;
    if (distance <= shortest) return std::nullopt;
  }
}

// ---- handoff ---------------------------------------------------------------------------------

/// The horizontal line between the giver's and the receiver's bases.
struct HandoffFrame {
  Vector3d along;   // horizontal unit vector, giver -> receiver
  Vector3d across;  // kUp x along
};

HandoffFrame handoffFrame(const core::World& world, int giver, int receiver) {
  const Vector3d p_g = world.robots[static_cast<std::size_t>(giver)].X_WBase.translation();
  const Vector3d p_r = world.robots[static_cast<std::size_t>(receiver)].X_WBase.translation();
  HandoffFrame frame;
  frame.along = Vector3d(p_r.x() - p_g.x(), p_r.y() - p_g.y(), 0.0);
  frame.along = frame.along.norm() > 1e-9 ? frame.along.normalized() : Vector3d::UnitX();  // bases at one spot
  frame.across = kUp.cross(frame.along);
  return frame;
}

/// The giver's TCP orientation number `index` (kHandoffPitches x kHandoffRolls): z (approach)
/// towards the receiver, pitched down; x (closing) `across` turned about z by the roll.
Matrix3d handoffRotation(const HandoffFrame& frame, int index) {
  const double pitch = kHandoffPitches[static_cast<std::size_t>(index / kHandoffRolls)];
  const double roll = (index % kHandoffRolls) * std::numbers::pi / 2;
  const Vector3d z = std::cos(pitch) * frame.along - std::sin(pitch) * kUp;
  Matrix3d R;
  R << frame.across, z.cross(frame.across), z;
  return R * Eigen::AngleAxisd(roll, Vector3d::UnitZ()).toRotationMatrix();
}

/// The giver holding the object still at a handoff pose (its part: object pose and grasp), its
/// configuration there and its retreat line back along the approach axis.
struct Giver {
  Part part;
  Line retreat;
};

/// The giver holding the object with its centre at p_WO and the TCP at orientation R_WT:
/// std::nullopt without IK for the pose and the retreat, or when it collides holding the object.
std::optional<Giver> giverAt(Context& c, const Part& giver, const Vector3d& p_WO, const Matrix3d& R_WT) {
  Part part = giver;
  part.X_WO.linear() = R_WT * giver.grasp.X_OT.linear().transpose();
  part.X_WO.translation() = p_WO;
  const Pose X_WT = part.X_WO * part.grasp.X_OT;
  return firstLine(*part.arm, X_WT, -c.settings.cartesian_distance * X_WT.linear().col(2), c.settings,
                   [&](const Line& retreat) -> std::optional<Giver> {
                     const Eigen::VectorXd q = c.scene.configuration(part.arm->robot, retreat.start, part.grasp.finger);
                     if (!c.checker.robotFree(part.arm->robot, q, {}, heldIn(part, true))) return std::nullopt;
                     return Giver{part, retreat};
                   });
}

/// Along the receiver's approach `in` (the object counts as its own once its open fingers
/// surround it), close; both hold for a dwell; the giver opens, dwells and retreats; then the
/// receiver retreats back along its approach.
std::optional<TransitionSample> handoffAlong(Context& c, const Part& receiver, const Giver& giver, const Line& in) {
  const TransitionSettings& s = c.settings;
  const double d = s.cartesian_distance;
  const double surround =
      surroundDistance(c.world.objects[static_cast<std::size_t>(receiver.object)].size, receiver.grasp);
  const HeldObject held_g = heldIn(giver.part, true);
  const HeldObject held_r = heldIn(receiver, true);
  const Millis dwell = ceilMillis(s.gripper_dwell);
  // receiver: approach, close
  MotionBuilder r(*receiver.arm, in.start, s);
  const auto n = static_cast<double>(in.keys.size());
  for (std::size_t k = 0; k < in.keys.size(); ++k) {
    const double remaining = d * (n - static_cast<double>(k) - 1.0) / n;  // after this piece
    r.moveTo(in.keys[k], d / n,
             {core::kFingersOpen, remaining < surround ? std::optional(held_r) : std::nullopt, std::nullopt});
  }
  r.grip(GripperAction::kClose);
  // giver: hold through the approach and the overlap, open, dwell, retreat
  MotionBuilder g(*giver.part.arm, giver.retreat.start, s);
  g.hold(r.now() + dwell, {giver.part.grasp.finger, held_g, std::nullopt});
  g.grip(GripperAction::kOpen);
  const Carry alone{core::kFingersOpen, std::nullopt, std::nullopt};
  g.hold(dwell, alone);
  for (const ArmConfig& q : giver.retreat.keys) g.moveTo(q, d / static_cast<double>(giver.retreat.keys.size()), alone);
  // receiver: hold until the giver is clear, retreat
  const Carry holding{receiver.grasp.finger, held_r, std::nullopt};
  r.hold(g.now() - r.now(), holding);
  const std::size_t retreat_first = r.motion.keys.size() - 1;
  for (std::size_t k = in.keys.size() - 1; k-- > 0;) r.moveTo(in.keys[k], d / n, holding);
  r.moveTo(in.start, d / n, holding);

  // each robot on its own, and robot against robot: the approach against the giver holding
  // still, every giver piece against the receiver holding still, the receiver's retreat
  // against the giver at its end
  const auto free = [&](Check check) {
    return staticFree(c, r, check) && staticFree(c, g, check) &&
           clearOf(c, r, 0, in.keys.size(), *giver.part.arm, giver.retreat.start, giver.part.grasp.finger, held_g,
                   check) &&
           clearOf(c, g, 0, g.motion.held.size(), *receiver.arm, in.keys.back(), receiver.grasp.finger, held_r,
                   check) &&
           clearOf(c, r, retreat_first, r.motion.held.size(), *giver.part.arm, g.q(), core::kFingersOpen, std::nullopt, check);
  };
  if (!free(Check::kKeys) || !free(Check::kPieces)) return std::nullopt;

  TransitionSample sample = sampleOf(receiver.hyperarc, TransitionKind::kHandoff, receiver.object, receiver.X_WO,
                                     {&g, &r}, touchedSites(c, {&g, &r}, receiver.object));
  sample.grasp_before = giver.part.grasp;
  sample.grasp_after = receiver.grasp;
  sample.action_end = g.now();
  return sample;
}

/// The receiver's pre-grasp back along its approach axis from its grasp of the object held by
/// the giver, then the handoff.
std::optional<TransitionSample> handoffSample(Context& c, const Part& receiver, const Giver& giver) {
  const Pose X_WT = receiver.X_WO * receiver.grasp.X_OT;
  const double d = c.settings.cartesian_distance;
  return firstLine(*receiver.arm, backedOff(X_WT, d), d * X_WT.linear().col(2), c.settings,
                   [&](const Line& in) { return handoffAlong(c, receiver, giver, in); });
}

/// A handoff with the object's centre at p_WO: the giver at the first orientation, in turn from
/// `first_orientation`, at which it can hold the object there; the receiver's grasps in turn
/// from `first_grasp` until one passes.
std::optional<TransitionSample> handoffAt(Context& c, const HandoffFrame& frame, const Part& giver, Part receiver,
                                          const std::vector<Grasp>& grasps, const Vector3d& p_WO, int first_orientation,
                                          std::size_t first_grasp) {
  std::optional<Giver> held;
  for (int i = 0; i < kHandoffOrientations && !held; ++i) {
    held = giverAt(c, giver, p_WO, handoffRotation(frame, (first_orientation + i) % kHandoffOrientations));
  }
  if (!held) return std::nullopt;
  receiver.X_WO = held->part.X_WO;
  for (std::size_t j = 0; j < grasps.size(); ++j) {
    receiver.grasp = grasps[(first_grasp + j) % grasps.size()];
    if (auto sample = handoffSample(c, receiver, *held)) return sample;
  }
  return std::nullopt;
}

const TransitionHyperarc& hyperarcOf(const TaskSpaceHypergraph& task_space, int hyperarc, TransitionKind kind) {
  if (hyperarc < 0 || hyperarc >= static_cast<int>(task_space.numHyperarcs())) {
    throw std::invalid_argument("hyperarc " + std::to_string(hyperarc) + " out of range");
  }
  const TransitionHyperarc& arc = task_space.hyperarcs()[static_cast<std::size_t>(hyperarc)];
  if (arc.kind != kind) {
    throw std::invalid_argument(task_space.hyperarcName(hyperarc) + " is not a " + toString(kind) + " hyperarc");
  }
  return arc;
}

}  // namespace

void TransitionSettings::validate() const {
  const auto require = [](bool ok, const char* field, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("transition settings: ") + field + ": " + what);
  };
  require(cartesian_distance > 0.0, "cartesian_distance", "must be positive");
  require(cartesian_speed > 0.0, "cartesian_speed", "must be positive");
  require(cartesian_step > 0.0, "cartesian_step", "must be positive");
  require(speed_fraction > 0.0 && speed_fraction <= 1.0, "speed_fraction", "must be in (0, 1]");
  require(max_acceleration > 0.0, "max_acceleration", "must be positive");
  require(gripper_dwell >= 0.0, "gripper_dwell", "must be >= 0");
  require(drop_height >= 0.0, "drop_height", "must be >= 0");
  require(slide_height >= 0.0, "slide_height", "must be >= 0");
  require(slide_distance > 0.0, "slide_distance", "must be positive");
  require(peak_factor >= 1.0, "peak_factor", "must be >= 1");
  require(max_step_jump > 0.0, "max_step_jump", "must be positive");
  require(singularity_margin >= 0.0 && singularity_margin < 1.0, "singularity_margin", "must be in [0, 1)");
}

TransitionSampler::TransitionSampler(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space,
                                     const CollisionScene& scene, const ObjectSites& sites,
                                     const TransitionSettings& settings)
    : world_(&world),
      task_space_(&task_space),
      scene_(&scene),
      sites_(&sites),
      settings_(settings),
      checker_(std::make_unique<CollisionChecker>(scene)) {
  settings_.validate();
}

std::vector<TransitionSample> TransitionSampler::pick(int hyperarc) {
  const TransitionHyperarc& arc = hyperarcOf(*task_space_, hyperarc, TransitionKind::kPick);
  Context c{*world_->world, *scene_, *sites_, settings_, *checker_};
  const Arm arm = armOf(*world_, arc.robot);
  const std::size_t o = static_cast<std::size_t>(arc.object);
  const std::optional<Pose>& rest = arc.rest_pose == RestPose::kAside ? sites_->aside[o] : sites_->start[o];
  if (!rest) return {};
  Part p{hyperarc, &arm, arc.object, *rest, Grasp{}};
  const Vector3d& size = c.world.objects[static_cast<std::size_t>(arc.object)].size;
  const Relabelled U = uprightFrame(p.X_WO.linear(), size);
  std::vector<TransitionSample> samples;
  for (const Grasp& grasp : graspsOf(U, size, false, topReach(c.world, c.sites, arc.object))) {
    p.grasp = grasp;
    if (auto sample = pickSample(c, p)) samples.push_back(std::move(*sample));
  }
  return samples;
}

std::vector<TransitionSample> TransitionSampler::place(int hyperarc, const Grasp& held) {
  const TransitionHyperarc& arc = hyperarcOf(*task_space_, hyperarc, TransitionKind::kPlace);
  const std::size_t o = static_cast<std::size_t>(arc.object);
  const bool aside = arc.rest_pose == RestPose::kAside;
  const std::optional<Pose>& site = aside ? sites_->aside[o] : sites_->goal[o];
  if (!site) return {};  // no goal (set-aside) site: nothing to place into
  Context c{*world_->world, *scene_, *sites_, settings_, *checker_};
  const Arm arm = armOf(*world_, arc.robot);
  Part p{hyperarc, &arm, arc.object, *site, held};
  std::vector<Matrix3d> orientations{site->linear()};  // set aside as it stood at its start: picked up so again
  if (!aside) {
    const Pose& X_WR = c.world.regions[static_cast<std::size_t>(sites_->goal_region[o])].X_WR;
    orientations = placeOrientations(c.world.objects[o].size, site->linear(), std::atan2(X_WR.linear()(1, 0), X_WR.linear()(0, 0)));
  }
  std::vector<TransitionSample> samples;
  for (const Matrix3d& R_WO : orientations) {
    p.X_WO.linear() = R_WO;
    if (auto sample = placeSample(c, p)) samples.push_back(std::move(*sample));
  }
  return samples;
}

const std::optional<core::HandoffZone>& TransitionSampler::handoffZone(int a, int b) {
  const auto key = std::minmax(a, b);
  auto it = zones_.find(key);
  if (it == zones_.end()) {
    const core::RobotSet& robots = *world_->robots;
    it = zones_.emplace(key, core::handoffZone(*world_->world, robots[static_cast<std::size_t>(key.first)],
                                               robots[static_cast<std::size_t>(key.second)], settings_.handoff))
             .first;
  }
  return it->second;
}

std::vector<Grasp> TransitionSampler::handoffGrasps(int object, const Grasp& giver) const {
  return receiverGrasps(world_->world->objects.at(static_cast<std::size_t>(object)).size, giver,
                        scene_->settings().margin, topReach(*world_->world, *sites_, object));
}

std::vector<TransitionSample> TransitionSampler::handoff(int hyperarc, const Grasp& giver_grasp, std::mt19937_64& rng,
                                                         int count) {
  const TransitionHyperarc& arc = hyperarcOf(*task_space_, hyperarc, TransitionKind::kHandoff);
  Context c{*world_->world, *scene_, *sites_, settings_, *checker_};
  const Arm giver_arm = armOf(*world_, arc.robot);
  const Arm receiver_arm = armOf(*world_, arc.receiver);
  const Part giver{hyperarc, &giver_arm, arc.object, Pose::Identity(), giver_grasp};
  const Part receiver{hyperarc, &receiver_arm, arc.object, Pose::Identity(), Grasp{}};
  const std::vector<Grasp> grasps = handoffGrasps(arc.object, giver_grasp);
  std::vector<TransitionSample> samples;
  const std::optional<core::HandoffZone>& zone = handoffZone(arc.robot, arc.receiver);
  if (grasps.empty() || !zone) return samples;
  const HandoffFrame frame = handoffFrame(c.world, arc.robot, arc.receiver);
  const core::HandoffShape& shape = settings_.handoff;
  for (int draw = 0; draw < kDrawsPerSample * count && static_cast<int>(samples.size()) < count; ++draw) {
    // one draw: the object's centre, the first orientation and the first receiver grasp tried
    const double u_along = uniform(rng), u_across = uniform(rng), u_height = uniform(rng);
    const int first_orientation = indexOf(uniform(rng), kHandoffOrientations);
    const auto first_grasp = static_cast<std::size_t>(indexOf(uniform(rng), static_cast<int>(grasps.size())));
    Vector3d p_WO = zone->mid + (2 * u_along - 1) * shape.spread * frame.along +
                    (2 * u_across - 1) * shape.spread * frame.across;
    p_WO.z() = zone->top + shape.min_height + u_height * (shape.max_height - shape.min_height);
    if (auto sample = handoffAt(c, frame, giver, receiver, grasps, p_WO, first_orientation, first_grasp)) {
      samples.push_back(std::move(*sample));
    }
  }
  return samples;
}

}  // namespace dashbed::planner
