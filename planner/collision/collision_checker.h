#pragma once
// Collision checking for the DaSH planner: robots (UR5e + Hand-E) against the fixtures, the
// resting objects, each other and themselves, with a held object moving with its gripper.
//
// Model / state split: a CollisionScene is built once from a World and its RobotSet and never
// changes; a CollisionChecker holds the scratch state of the queries (body poses, the FCL
// narrow-phase solver, counters). A checker must not be shared between threads: make one per
// thread, all reading the same scene.
//
// Geometry. Robots: the URDF's convex primitives (box, cylinder, sphere) of every link, each
// grown by CollisionSettings::margin on every side (box: edges + 2 margin; cylinder: radius +
// margin, length + 2 margin; sphere: radius + margin). A held object is the object's box, grown
// by the same margin. Fixtures: the world's fixture boxes (FixtureSpec::boxes) plus a floor
// (top face at z = 0). Resting objects: their boxes, not grown. The exact decision for every
// pair of shapes is FCL's primitive narrow phase (the GJK/libccd solver that fcl::collide uses
// by default, with its dedicated box-box, sphere-box, sphere-cylinder routines). In front of it:
// a broad phase (FCL's dynamic AABB tree over the static boxes, queried with each robot body's
// bounding sphere), bounding spheres per body and per shape, and separating-axis tests with the
// shapes' exact projections, which only skip pairs at least 10 um apart; a shape whose centre
// lies inside the other shape is a hit without FCL. So the answer is the same as running
// fcl::collide on every pair (tests/planner/test_collision_checker.cpp checks this against such
// a brute-force loop on thousands of random configurations), just faster: FK of the eight
// bodies (links joined by fixed joints merged), then mostly sphere tests.
//
// What is checked (and what not):
//  - robot links against the static scene, except the links that no joint moves (the base,
//    which stands on its support by construction);
//  - robot links against the resting objects passed to the query;
//  - self-collision between link groups that are not ignored: links joined by fixed joints
//    form one rigid body; a body pair is ignored when the bodies are joined by one joint
//    (adjacent), or collide at the robot's home configuration with the fingers open or closed
//    (e.g. the two fingers, whose pads touch when closed), or collide in at least
//    `self_pair_always_fraction` of `self_pair_samples` seeded random configurations
//    (overlapping by construction). CollisionScene::ignoredSelfPairs lists them with reasons;
//  - robot against robot: every body pair except base against base, held objects included;
//  - a held object against the static scene (unless HeldObject::check_static is false), the
//    resting objects, its robot's bodies except the fingers it is held by, and the other
//    robot; when two robots hold the same object (a handoff) the object is not checked
//    against either robot's fingers.
//
// Motions are straight lines in joint space, or curves on which every joint is monotone (a
// transition's key curve, CurvePiece), checked at samples spaced so that no point of
// the robot (held object included) travels more than CollisionSettings::motion_step between
// two samples. The bound on a point's travel is sum_j R_j |dq_j|, where R_j bounds the distance
// of any point moved by joint j from that joint's origin (1 for prismatic joints, whose points
// move by |dq_j|). Every point of the swept volume between two samples is then within
// motion_step / 2 of its place at the nearer sample, so with motion_step <= 2 margin the grown
// shapes at the samples cover the true shapes everywhere between them: the discrete check
// misses no collision of the true geometry. The defaults (margin 1.5 mm, step 3 mm) satisfy it.
// The margin is below 2 mm because the handoff that holds in simulation (receiver from above,
// closing along the giver's approach axis) passes the receiver's open finger 4 mm from the
// giver's housing: two robots grown by 2 mm each would never be allowed to do it.
// For the UR5e + Hand-E the bounds R_j are 1.23, 1.23, 0.81, 0.39, 0.29, 0.19 m (sum 4.1 m):
// a turn of the base alone is sampled every 2.4 mrad, all six joints turning together every
// 0.7 mrad (0.5 rad on every joint: about 690 samples).
// A single robot's motion (motionFree, motionCheck, motionObjectHits) is not evaluated at all of
// them (collision_sweep.h): each body against the static scene, each checked body pair, the held
// object and each resting object is an item of its own; where a sample finds an item apart, the
// prefilters that separate it also bound the gap, and the samples at which the joints between
// the item's parts cannot have closed that gap are known free. The answers are those of checking
// every sample.

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "core/robot_set.h"
#include "core/world.h"

namespace dashbed::planner {

/// Settings of the collision checker. Lengths in metres.
struct CollisionSettings {
  /// Growth of every moving shape (robot links, held objects) [m]; larger is safer and rules out
  /// close handoffs.
  double margin = 0.0015;
  /// Largest travel of any robot point between two motion samples [m]; checks miss nothing while
  /// it is <= 2 x margin.
  double motion_step = 0.003;
  /// Random configurations used to find the body pairs that always collide (ignored pairs).
  int self_pair_samples = 1000;
  /// Body pairs colliding in at least this fraction of those configurations are ignored, in (0, 1].
  double self_pair_always_fraction = 0.95;
  /// Seed of those configurations.
  std::uint64_t self_pair_seed = 1;

  /// Throws std::invalid_argument naming the field when a value is out of range (margin < 0,
  /// motion_step <= 0, samples < 0, fraction outside (0, 1]).
  void validate() const;
  /// True when motion checks cannot miss a collision of the true geometry (step <= 2 margin).
  bool motionChecksConservative() const { return motion_step <= 2.0 * margin + 1e-12; }
};

/// An object held by a robot's gripper: it moves with the TCP and is part of the robot.
struct HeldObject {
  int object = -1;                           ///< index into World::objects
  core::Pose X_TO = core::Pose::Identity();  ///< object pose in the TCP frame
  /// False while the object still sits on its support (closing, lift-off, set-down): the
  /// object is then not checked against the static scene (it touches it by construction).
  bool check_static = true;
};

/// An object resting in the world during a query.
struct RestingObject {
  int object = -1;                           ///< index into World::objects
  core::Pose X_WO = core::Pose::Identity();  ///< pose of the object's centre in W
};

/// Another robot standing still at q (arm and fingers), holding `held` if given.
struct StandingRobot {
  int robot = -1;
  Eigen::VectorXd q;
  std::optional<HeldObject> held;
};

/// Every object of the world at its start pose.
std::vector<RestingObject> startPlacement(const core::World& world);

/// A timed joint path of one robot: configurations (all model positions, arm then fingers)
/// at strictly increasing times t [s], linear in between. Before t.front() the robot holds
/// q.front(), after t.back() it holds q.back().
struct TimedPath {
  std::vector<double> t;
  std::vector<Eigen::VectorXd> q;
};

/// A curved motion of one robot from `from` to `to` (all model positions, arm then fingers):
/// at(s, q) sets q to its configuration at s in [0, 1], from at 0 and to at 1. The checks rely
/// on one property of the curve: no position moves faster in s than peak_over_mean times its
/// mean rate |to - from|. Then no point travels more than peak_over_mean times the straight
/// line's bound sum_j R_j |to_j - from_j|, and peak_over_mean times as many samples as the
/// straight line's keep every step within the motion step. A transition's key curve between
/// two keys (core::TrajectoryInterpolator, planner/sampling/key_curve.h) is monotone in every
/// position, its peak_over_mean at most 3.
struct CurvePiece {
  Eigen::VectorXd from;
  Eigen::VectorXd to;
  std::function<void(double s, Eigen::VectorXd& q)> at;
  /// Must be set: at least 1 (the default, NaN, is refused).
  double peak_over_mean = std::numeric_limits<double>::quiet_NaN();
};

/// A self-collision body pair the checker never tests, and why.
struct IgnoredSelfPair {
  std::string body_a;  ///< named after the body's first link
  std::string body_b;
  std::string reason;  ///< "adjacent", "home" or "always (<fraction>)"
};

namespace detail {
struct SceneData;
struct CheckerState;
struct MotionRef;
struct SweepRequest;
}  // namespace detail

/// The immutable collision model of a world: static geometry in a broad phase, the robots'
/// link geometry grouped into rigid bodies, the object boxes, the self-collision pairs.
class CollisionScene {
 public:
  /// Builds the scene. `robots` must have been made from `world`; both must outlive the
  /// scene. Throws std::invalid_argument on bad settings or when a robot model has no `tcp`
  /// link.
  CollisionScene(const core::World& world, const core::RobotSet& robots,
                 const CollisionSettings& settings = {});
  ~CollisionScene();
  CollisionScene(const CollisionScene&) = delete;
  CollisionScene& operator=(const CollisionScene&) = delete;

  const CollisionSettings& settings() const;
  /// The robots the scene was built for (models, limits, IK).
  const core::RobotSet& robots() const;
  int numRobots() const;
  int numObjects() const;
  /// Number of configuration entries of a robot (arm joints then fingers).
  int numPositions(int robot) const;
  /// The configuration the checks take: the arm at `q`, every finger at `finger` [m].
  Eigen::VectorXd configuration(int robot, const core::ArmConfig& q, double finger) const;

  /// The static boxes in W: every fixture's boxes, then the floor (last).
  const std::vector<core::Box>& staticBoxes() const;

  /// Whether the self-collision check tests links `link_a` and `link_b` of `robot` (link
  /// indices of the robot's model). False for links of the same rigid body and ignored pairs.
  bool selfPairChecked(int robot, int link_a, int link_b) const;
  /// The ignored body pairs of a robot with their reasons.
  std::vector<IgnoredSelfPair> ignoredSelfPairs(int robot) const;
  /// Whether a link is moved by some joint (links fixed to the base are not checked against
  /// the static scene).
  bool linkMoves(int robot, int link) const;
  /// Whether a held object is exempt from colliding with this link (the gripper's fingers).
  bool linkHoldsObjects(int robot, int link) const;
  /// Index of the TCP link (`tcp`) in the robot's model.
  int tcpLink(int robot) const;

  /// R_j: bound on the distance of any point that joint `q_index` moves from the joint's
  /// origin, without a held object [m] (1 for prismatic joints).
  double jointTravelRadius(int robot, int q_index) const;
  /// Number of intervals a straight joint-space motion is split into so that no robot point
  /// (held object included) travels more than settings().motion_step between samples (>= 1).
  int motionSteps(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                  const std::optional<HeldObject>& held = std::nullopt) const;
  /// The bound on any robot point's travel [m] (held object included, and the centres of the
  /// checker's bounding spheres) over the straight motion q_from -> q_to: sum_j R_j |dq_j|
  /// (motionSteps is its ceiling in motion steps).
  double motionTravel(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                      const std::optional<HeldObject>& held = std::nullopt) const;

 private:
  friend class CollisionChecker;
  std::unique_ptr<detail::SceneData> data_;
};

/// The distance between two axis-aligned boxes (min, max corners), 0 when they overlap.
double boxesGap(const std::pair<Eigen::Vector3d, Eigen::Vector3d>& a, const std::pair<Eigen::Vector3d, Eigen::Vector3d>& b);

/// Collision queries on a CollisionScene. Owns per-thread scratch state; cheap to construct.
/// Configurations q hold every model position (for the UR5e + Hand-E: six arm angles [rad],
/// then the two finger positions [m], 0 = closed, 0.025 = open). Functions throw
/// std::invalid_argument for a bad robot or object index or a q of the wrong size.
class CollisionChecker {
 public:
  /// Counts of work done, for benchmarks and tuning.
  struct Counters {
    std::uint64_t configurations = 0;  ///< robot configurations evaluated (FK + checks)
    std::uint64_t motion_samples = 0;  ///< samples of single-robot motions, evaluated or known free
    std::uint64_t narrow_phase = 0;    ///< FCL primitive pair tests
  };

  explicit CollisionChecker(const CollisionScene& scene);
  ~CollisionChecker();
  CollisionChecker(const CollisionChecker&) = delete;
  CollisionChecker& operator=(const CollisionChecker&) = delete;

  /// One robot against the static scene, the resting `objects` and itself, holding `held`
  /// if given. An entry of `objects` naming the held object is skipped. True when free.
  bool robotFree(int robot, const Eigen::VectorXd& q, std::span<const RestingObject> objects,
                 const std::optional<HeldObject>& held = std::nullopt);

  /// A held object alone at X_WO against the static scene, as robotFree checks it for `robot`
  /// holding it (HeldObject::check_static; the robot's own static boxes are not checked): true
  /// when free. No forward kinematics: a cheap first test of where an object would be carried
  /// before any arm configuration is solved for.
  bool heldObjectFree(int robot, int object, const core::Pose& X_WO);

  /// The axis-aligned box (min, max corners) around every body's bounding sphere of `robot`
  /// at q, and the held object's: robotsFree finds two robots free, without further tests,
  /// whenever their boxes are apart.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> robotBounds(int robot, const Eigen::VectorXd& q,
                                                          const std::optional<HeldObject>& held);

  /// Robot against robot only (bodies and held objects of both). True when free.
  bool robotsFree(int robot_a, const Eigen::VectorXd& q_a, const std::optional<HeldObject>& held_a,
                  int robot_b, const Eigen::VectorXd& q_b, const std::optional<HeldObject>& held_b);

  /// For messages: the first collision robotFree(robot, q, {}) finds, as "its <link> and
  /// <part>", the part being "fixture '<name>'", "the floor", "the base of robot '<name>'" or
  /// "its <link>"; empty when the robot is free.
  std::string robotContact(int robot, const Eigen::VectorXd& q);
  /// For messages: the first collision robotsFree finds between the two robots (holding
  /// nothing), as "its <link> and robot '<name>''s <link>"; empty when they are free.
  std::string robotsContact(int robot_a, const Eigen::VectorXd& q_a, int robot_b, const Eigen::VectorXd& q_b);

  /// The straight joint-space motion q_from -> q_to of one robot, checked like robotFree at
  /// CollisionScene::motionSteps samples (both ends included) in bisection order (midpoint
  /// first, then the quarter points, ...) so that blocked motions fail early.
  bool motionFree(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                  std::span<const RestingObject> objects,
                  const std::optional<HeldObject>& held = std::nullopt);
  /// motionFree along a curve, at ceil(peak_over_mean x the straight line's travel / motion
  /// step) intervals.
  bool motionFree(int robot, const CurvePiece& piece, std::span<const RestingObject> objects,
                  const std::optional<HeldObject>& held = std::nullopt);

  /// Which of `objects` the straight motion q_from -> q_to touches: entry i is true when the
  /// robot (with `held`) collides with objects[i] at some of the motion's samples (the samples
  /// motionFree checks). The static scene and self-collision are not checked: for a motion
  /// motionFree finds free against them, motionFree(..., {objects[i]}, ...) == !hits[i].
  std::vector<char> motionObjectHits(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                     std::span<const RestingObject> objects,
                                     const std::optional<HeldObject>& held = std::nullopt);
  /// motionObjectHits along a curve, at motionFree's samples of it.
  std::vector<char> motionObjectHits(int robot, const CurvePiece& piece, std::span<const RestingObject> objects,
                                     const std::optional<HeldObject>& held = std::nullopt);

  /// motionFree against the static scene and the robot itself (no objects) and, when free,
  /// motionObjectHits, in one pass over the samples: std::nullopt when not free.
  std::optional<std::vector<char>> motionCheck(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                                               std::span<const RestingObject> objects,
                                               const std::optional<HeldObject>& held = std::nullopt);

  /// Two robots moving at the same time along straight joint-space motions that start and end
  /// together, checked robot against robot only (each motion is assumed checked on its own)
  /// at common samples fine enough for both, in bisection order.
  bool motionsFree(int robot_a, const Eigen::VectorXd& q_a_from, const Eigen::VectorXd& q_a_to,
                   const std::optional<HeldObject>& held_a, int robot_b,
                   const Eigen::VectorXd& q_b_from, const Eigen::VectorXd& q_b_to,
                   const std::optional<HeldObject>& held_b);

  /// motionsFree of one robot's motion against each of `others` standing still, in one pass
  /// over the motion's samples (each evaluated once for all of them); samples within the
  /// clearance of one found free (the gap between the robots' bounds, or robotsClearance) are
  /// not evaluated. True when free of all.
  bool motionClearOf(int robot, const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                     const std::optional<HeldObject>& held, std::span<const StandingRobot> others);
  /// motionClearOf along a curve, at motionFree's samples of it.
  bool motionClearOf(int robot, const CurvePiece& piece, const std::optional<HeldObject>& held,
                     std::span<const StandingRobot> others);

  /// robotsFree, and when free a lower bound on the distance between the two robots' bounding
  /// spheres (bodies and held objects; pairs of bodies neither of which moves left out), so that
  /// robotsFree stays true while the robots' points together travel less than it [m]. Returns
  /// a negative value when they collide.
  double robotsClearance(int robot_a, const Eigen::VectorXd& q_a, const std::optional<HeldObject>& held_a,
                         int robot_b, const Eigen::VectorXd& q_b, const std::optional<HeldObject>& held_b);

  /// Two timed paths, robot against robot only: split at the union of both paths' times,
  /// each piece checked with motionsFree. Throws std::invalid_argument for an empty path,
  /// mismatched sizes or times that do not increase.
  bool timedPathsFree(int robot_a, const TimedPath& path_a, const std::optional<HeldObject>& held_a,
                      int robot_b, const TimedPath& path_b, const std::optional<HeldObject>& held_b);

  const Counters& counters() const { return counters_; }
  void resetCounters() { counters_ = {}; }

 private:
  /// Checks the arguments of a robot-against-robot query and poses both robots for it.
  void placePair(int robot_a, const Eigen::VectorXd& q_a, const std::optional<HeldObject>& held_a, int robot_b,
                 const Eigen::VectorXd& q_b, const std::optional<HeldObject>& held_b);
  /// Samples of a motion and the bound on any point's travel between two of them [m]; checks
  /// the motion's ends and held object.
  std::pair<int, double> motionSamples(int robot, const detail::MotionRef& motion,
                                       const std::optional<HeldObject>& held) const;
  bool motionFree(int robot, const detail::MotionRef& motion, std::span<const RestingObject> objects,
                  const std::optional<HeldObject>& held);
  std::optional<std::vector<char>> motionHits(int robot, const detail::MotionRef& motion,
                                              std::span<const RestingObject> objects,
                                              const std::optional<HeldObject>& held,
                                              const detail::SweepRequest& request);
  bool motionClearOf(int robot, const detail::MotionRef& motion, const std::optional<HeldObject>& held,
                     std::span<const StandingRobot> others);

  const CollisionScene* scene_;
  std::unique_ptr<detail::CheckerState> state_;
  Counters counters_;
};

}  // namespace dashbed::planner
