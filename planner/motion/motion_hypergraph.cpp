#include "planner/motion/motion_hypergraph.h"

#include "core/kinematics.h"

#include <algorithm>
#include <chrono>
#include <random>
#include <span>
#include <stdexcept>
#include <string>

#include "planner/sampling/key_curve.h"

namespace dashbed::planner {
namespace {

/// splitmix64's finaliser: decorrelates seeds built from small integers.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::uint64_t seedOf(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  return mix(mix(mix(mix(seed) ^ a) ^ b) ^ c);
}

/// Adds the wall-clock time of its scope to a counter [s].
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(&total), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { *total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double* total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

void RepresentationSettings::validate() const {
  const auto require = [](bool ok, const char* field, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("representation settings: ") + field + ": " + what);
  };
  require(initial_roadmap_samples >= 0, "initial_roadmap_samples", "must be >= 0");
  require(roadmap_samples_per_round >= 0, "roadmap_samples_per_round", "must be >= 0");
  require(handoff_samples_per_round >= 1, "handoff_samples_per_round", "must be >= 1");
  require(move_growth_attempts >= 0, "move_growth_attempts", "must be >= 0");
  require(move_growth_samples >= 1, "move_growth_samples", "must be >= 1");
  require(move_growth_spread > 0.0, "move_growth_spread", "must be > 0");
  require(velocity_fraction > 0.0 && velocity_fraction <= 1.0, "velocity_fraction", "must be in (0, 1]");
  require(max_acceleration > 0.0, "max_acceleration", "must be positive");
  require(tcp_speed_fraction > 0.0 && tcp_speed_fraction <= 1.0, "tcp_speed_fraction", "must be in (0, 1]");
  transitions.validate();
  collision.validate();
}

MotionHypergraph::MotionHypergraph(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space,
                                   std::uint64_t seed, const RepresentationSettings& settings)
    : MotionHypergraph(world, task_space, objectSites(world), seed, settings) {}

MotionHypergraph::MotionHypergraph(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space,
                                   ObjectSites sites, std::uint64_t seed, const RepresentationSettings& settings,
                                   std::shared_ptr<const CollisionScene> scene,
                                   std::unique_ptr<TransitionPlanner> transitions)
    : world_(&world),
      task_space_(&task_space),
      seed_(seed),
      settings_(settings),
      scene_(std::move(scene)),
      sites_(std::move(sites)),
      sampler_(std::move(transitions)) {
  const ScopedTimer timer(construction_seconds_);
  settings_.validate();
  if (sites_.numObjects() != task_space.numObjects()) {
    throw std::invalid_argument("MotionHypergraph: the sites are for " + std::to_string(sites_.numObjects()) +
                                " objects, the task-space hypergraph has " + std::to_string(task_space.numObjects()));
  }
  for (const TransitionHyperarc& arc : task_space.hyperarcs()) {
    if (arc.rest_pose == RestPose::kAside && !sites_.aside[static_cast<std::size_t>(arc.object)]) {
      throw std::invalid_argument("MotionHypergraph: " + task_space.objectName(arc.object) +
                                  " has set-aside hyperarcs and no set-aside site");
    }
  }
  if (!scene_) scene_ = std::make_shared<const CollisionScene>(*world.world, *world.robots, settings_.collision);
  if (!sampler_) sampler_ = std::make_unique<TransitionSampler>(world, task_space, *scene_, sites_, settings_.transitions);
  // every robot of a world is a UR5e: the first one's limits stand for all
  const core::RobotModel& model = *world.robots->robots().front().model;
  for (int j = 0; j < 6; ++j) {
    timing_.max_velocity[j] = settings_.velocity_fraction * model.joints()[model.movableJoints()[j]].max_velocity;
    timing_.max_acceleration[j] = std::min(settings_.max_acceleration, world.world->safety.max_joint_acceleration);
  }
  grasps_.resize(world.world->objects.size());
  best_duration_.resize(task_space.numHyperarcs());
  folded_ = foldedConfigurations(*world.world, *scene_);

  // the start and goal decomposition (virtual source and target)
  for (int r = 0; r < task_space.numRobots(); ++r) {
    const int home = robotVertex(r, world.world->robots[r].home);
    source_.push_back(home);
    target_.push_back(home);
  }
  for (int o = 0; o < task_space.numObjects(); ++o) {
    source_.push_back(siteVertex(ObjectSites::startSite(o)));
    target_.push_back(siteVertex(sites_.goal[o] ? ObjectSites::goalSite(o) : ObjectSites::startSite(o)));
  }
}

MotionHypergraph::~MotionHypergraph() = default;

int MotionHypergraph::addVertex(const MotionVertex& vertex) {
  const auto key = std::make_tuple(vertex.task_vertex, vertex.grasp, vertex.site, vertex.q);
  const auto [it, added] = vertex_ids_.emplace(key, static_cast<int>(vertices_.size()));
  if (added) vertices_.push_back(vertex);
  return it->second;
}

int MotionHypergraph::robotVertex(int robot, const core::ArmConfig& q) {
  return addVertex({task_space_->robotAloneVertex(robot), q, -1, -1});
}

int MotionHypergraph::holdingVertex(int robot, int object, int grasp, const core::ArmConfig& q) {
  return addVertex({task_space_->holdingVertex(robot, object), q, grasp, -1});
}

int MotionHypergraph::siteVertex(int site) {
  return addVertex({task_space_->objectRestingVertex(ObjectSites::objectOf(site)), {}, -1, site});
}

int MotionHypergraph::graspId(int object, const Grasp& grasp) {
  std::vector<Grasp>& grasps = grasps_.at(object);
  for (std::size_t i = 0; i < grasps.size(); ++i) {
    if (sameGrasp(grasps[i], grasp)) return static_cast<int>(i);
  }
  grasps.push_back(grasp);
  return static_cast<int>(grasps.size()) - 1;
}

void MotionHypergraph::addTransition(TransitionSample sample) {
  const TransitionHyperarc& arc = task_space_->hyperarcs().at(sample.hyperarc);
  const int o = arc.object;
  MotionTransition transition;
  switch (arc.kind) {
    case TransitionKind::kPick: {
      const int grasp = graspId(o, *sample.grasp_after);
      const int site = arc.rest_pose == RestPose::kAside ? ObjectSites::asideSite(o) : ObjectSites::startSite(o);
      transition.tail = {robotVertex(arc.robot, sample.motions[0].start()), siteVertex(site)};
      transition.head = {holdingVertex(arc.robot, o, grasp, sample.motions[0].end())};
      break;
    }
    case TransitionKind::kPlace: {
      const int grasp = graspId(o, *sample.grasp_before);
      transition.tail = {holdingVertex(arc.robot, o, grasp, sample.motions[0].start())};
      const int site = arc.rest_pose == RestPose::kAside ? ObjectSites::asideSite(o) : ObjectSites::goalSite(o);
      transition.head = {robotVertex(arc.robot, sample.motions[0].end()), siteVertex(site)};
      break;
    }
    case TransitionKind::kHandoff: {
      const int before = graspId(o, *sample.grasp_before), after = graspId(o, *sample.grasp_after);
      transition.tail = {holdingVertex(arc.robot, o, before, sample.motions[0].start()),
                         robotVertex(arc.receiver, sample.motions[1].start())};
      transition.head = {robotVertex(arc.robot, sample.motions[0].end()),
                         holdingVertex(arc.receiver, o, after, sample.motions[1].end())};
      break;
    }
  }
  std::optional<Millis>& best = best_duration_[static_cast<std::size_t>(sample.hyperarc)];
  if (!best || sample.duration < *best) best = sample.duration;
  transition.sample = std::move(sample);
  transitions_.push_back(std::move(transition));
}

void MotionHypergraph::sampleHandoffs(int hyperarc, int grasp, int round) {
  const TransitionHyperarc& arc = task_space_->hyperarcs().at(hyperarc);
  std::mt19937_64 rng(seedOf(seed_, static_cast<std::uint64_t>(hyperarc), static_cast<std::uint64_t>(grasp),
                             static_cast<std::uint64_t>(round)));
  const Grasp held = grasps_.at(arc.object).at(grasp);  // a copy: sampling may add grasps
  std::vector<int>& ids = transitions_of_[{hyperarc, grasp}];
  for (TransitionSample& sample : sampler_->handoff(hyperarc, held, rng, settings_.handoff_samples_per_round)) {
    ids.push_back(static_cast<int>(transitions_.size()));
    addTransition(std::move(sample));
  }
}

const std::vector<int>& MotionHypergraph::transitionsOf(int hyperarc, int grasp) {
  const TransitionHyperarc& arc = task_space_->hyperarcs().at(hyperarc);
  const std::pair<int, int> key{hyperarc, arc.kind == TransitionKind::kPick ? -1 : grasp};
  if (const auto it = transitions_of_.find(key); it != transitions_of_.end()) return it->second;
  const ScopedTimer timer(construction_seconds_);
  if (arc.kind == TransitionKind::kHandoff) {
    // catch up with every round so far, as if the grasp had been known from the start
    for (int round = 1; round <= round_; ++round) sampleHandoffs(hyperarc, grasp, round);
    return transitions_of_[key];
  }
  std::vector<TransitionSample> samples =
      arc.kind == TransitionKind::kPick ? sampler_->pick(hyperarc) : sampler_->place(hyperarc, grasps_.at(arc.object).at(grasp));
  std::vector<int> ids;
  for (TransitionSample& sample : samples) {
    ids.push_back(static_cast<int>(transitions_.size()));
    addTransition(std::move(sample));
  }
  return transitions_of_[key] = std::move(ids);
}

Roadmap& MotionHypergraph::roadmap(int robot, int object, int grasp) {
  const auto key = std::make_tuple(robot, object, grasp);
  if (const auto it = roadmaps_.find(key); it != roadmaps_.end()) return it->second;
  std::optional<HeldObject> held;
  double finger = kFingersOpen;
  if (object >= 0) {
    const Grasp& g = grasps_.at(object).at(grasp);
    held = HeldObject{object, g.X_OT.inverse(), true};
    finger = g.finger;
  }
  Roadmap map(*scene_, sites_, robot, held, finger,
              seedOf(seed_, static_cast<std::uint64_t>(robot), static_cast<std::uint64_t>(object + 1),
                     static_cast<std::uint64_t>(grasp + 1)),
              settings_.roadmap);
  map.grow(settings_.initial_roadmap_samples + (round_ - 1) * settings_.roadmap_samples_per_round);
  return roadmaps_.emplace(key, std::move(map)).first->second;
}

const core::ArmConfig& MotionHypergraph::idleConfiguration(int robot, IdlePose pose) const {
  return pose == IdlePose::kFolded ? folded_.at(static_cast<std::size_t>(robot))
                                   : world_->world->robots.at(static_cast<std::size_t>(robot)).home;
}

const Move* MotionHypergraph::move(int robot, int object, int grasp, const core::ArmConfig& from,
                                   const core::ArmConfig& to, const SiteSet& occupied,
                                   std::optional<IdlePose> around_idle) {
  std::vector<bool> occupied_bits(static_cast<std::size_t>(sites_.numSites()));
  for (int s = 0; s < sites_.numSites(); ++s) occupied_bits[s] = occupied.test(s);
  const auto key = std::make_tuple(robot, object, grasp, from, to, occupied_bits, around_idle);
  if (const auto it = moves_.find(key); it != moves_.end()) return it->second.get();

  const ScopedTimer timer(construction_seconds_);
  std::unique_ptr<Move> result;  // none: no path
  Roadmap& map = roadmap(robot, object, grasp);
  Roadmap::MotionFilter clear;
  if (around_idle) {
    if (!checker_) checker_ = std::make_unique<CollisionChecker>(*scene_);
    std::vector<StandingRobot> idle;  // the other robots waiting
    for (int other = 0; other < scene_->numRobots(); ++other) {
      if (other != robot) {
        idle.push_back({other, scene_->configuration(other, idleConfiguration(other, *around_idle), kFingersOpen), std::nullopt});
      }
    }
    // the idle robots never move: an answer holds for the roadmap's life
    std::map<std::pair<core::ArmConfig, core::ArmConfig>, bool>& known =
        clear_of_idle_[std::make_tuple(robot, object, grasp, *around_idle)];
    clear = [this, &map, &known, robot, idle = std::move(idle)](const core::ArmConfig& a, const core::ArmConfig& b) {
      const auto [it, added] = known.try_emplace({a, b}, false);
      if (added) {
        it->second = checker_->motionClearOf(robot, map.fullConfiguration(a), map.fullConfiguration(b), map.held(), idle);
      }
      return it->second;
    };
  }
  const int a = map.addConfiguration(from), b = map.addConfiguration(to);
  std::optional<std::vector<core::ArmConfig>> path;
  if (a >= 0 && b >= 0) path = a == b ? std::vector<core::ArmConfig>{from} : map.query(a, b, occupied, clear);
  // a roadmap that does not connect them yet grows a little on the spot
  int& grown = grown_this_round_[std::make_tuple(robot, object, grasp)];
  // (uniformly, and near both ends: one of them may sit in a pocket, e.g. the arm in a shelf)
  while (!path && a >= 0 && b >= 0 && grown < settings_.move_growth_attempts * settings_.move_growth_samples) {
    const int near = settings_.move_growth_samples / 4;
    map.grow(settings_.move_growth_samples - 2 * near);
    map.growNear(from, near, settings_.move_growth_spread);
    map.growNear(to, near, settings_.move_growth_spread);
    grown += settings_.move_growth_samples;
    path = map.query(a, b, occupied, clear);
  }
  if (path) result = std::make_unique<Move>(makeMove(robot, object, grasp, std::move(*path), occupied));
  return moves_.emplace(key, std::move(result)).first->second.get();
}

TimingLimits MotionHypergraph::pieceTiming(const Move& move, std::size_t i) const {
  return withSpeedScale(timing_, i < move.speed_scale.size() ? move.speed_scale[i] : 1.0);
}

std::vector<double> MotionHypergraph::tcpSpeedScales(const std::vector<core::ArmConfig>& path) const {
  // every robot of a world is a UR5e: the first one's model stands for all. The rate is sampled
  // every kRateStep of the largest joint change; the cap's margin to the limit covers what falls
  // between samples.
  constexpr double kRateStep = 0.02;  // [rad]
  const core::RobotModel& model = *world_->robots->robots().front().model;
  const int tcp = model.requireLink("tcp");
  const double max_speed = settings_.tcp_speed_fraction * world_->world->safety.tcp_speed;
  std::vector<double> scales;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(model.numPositions());
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(model.numPositions());
  for (std::size_t i = 1; i < path.size(); ++i) {
    const core::ArmConfig& a = path[i - 1];
    const core::ArmConfig& b = path[i];
    double largest = 0.0;
    for (int j = 0; j < 6; ++j) {
      delta[j] = b[j] - a[j];
      largest = std::max(largest, std::abs(delta[j]));
    }
    const int samples = std::max(2, static_cast<int>(std::ceil(largest / kRateStep)) + 1);
    double rate = 0.0;  // [m per unit of path]
    for (int k = 0; k < samples; ++k) {
      const double s = static_cast<double>(k) / (samples - 1);
      for (int j = 0; j < 6; ++j) q[j] = a[j] + s * delta[j];
      rate = std::max(rate, (core::jacobian(model, q, tcp).topRows<3>() * delta).norm());
    }
    scales.push_back(speedScaleWithin(a, b, timing_, rate, max_speed));
  }
  return scales;
}

Move MotionHypergraph::makeMove(int robot, int object, int grasp, std::vector<core::ArmConfig> path,
                                const SiteSet& occupied) {
  Roadmap& map = roadmap(robot, object, grasp);
  Move m;
  m.robot = robot;
  m.object = object;
  m.grasp = grasp;
  m.speed_scale = tcpSpeedScales(path);
  m.duration = polylineDuration(path, timing_, m.speed_scale);
  m.occupied = occupied;
  // which unoccupied sites the path touches: the schedule keeps their objects away meanwhile.
  // Each piece's sites come from the roadmap's cached check of that motion.
  m.touches = SiteSet(sites_.numSites());
  SiteSet unoccupied(sites_.numSites());
  for (int s = 0; s < sites_.numSites(); ++s) {
    if (!occupied.test(s) && sites_.site(s) && ObjectSites::objectOf(s) != object) unoccupied.set(s);
  }
  for (std::size_t i = 1; i < path.size(); ++i) {
    const SiteSet piece = map.touchedSites(path[i - 1], path[i], unoccupied);
    for (int s = 0; s < sites_.numSites(); ++s) {
      if (piece.test(s)) m.touches.set(s);
    }
  }
  m.path = std::move(path);
  return m;
}

const Move* MotionHypergraph::detour(const Move& original, const Roadmap::MotionFilter& clear) {
  Roadmap& map = roadmap(original.robot, original.object, original.grasp);
  const int a = map.addConfiguration(original.path.front()), b = map.addConfiguration(original.path.back());
  if (a < 0 || b < 0 || a == b) return nullptr;
  std::optional<std::vector<core::ArmConfig>> path = map.query(a, b, original.occupied, clear);
  // the roadmap grows for it as for a move (within the same allowance per round)
  int& grown = grown_this_round_[std::make_tuple(original.robot, original.object, original.grasp)];
  while (!path && grown < settings_.move_growth_attempts * settings_.move_growth_samples) {
    const int near = settings_.move_growth_samples / 4;
    map.grow(settings_.move_growth_samples - 2 * near);
    map.growNear(original.path.front(), near, settings_.move_growth_spread);
    map.growNear(original.path.back(), near, settings_.move_growth_spread);
    grown += settings_.move_growth_samples;
    path = map.query(a, b, original.occupied, clear);
  }
  if (!path) return nullptr;
  detours_.push_back(makeMove(original.robot, original.object, original.grasp, std::move(*path), original.occupied));
  return &detours_.back();
}

std::optional<std::pair<const Move*, const Move*>> MotionHypergraph::parking(
    const Move& original, const std::function<bool(const core::ArmConfig&)>& clear, int attempts) {
  const core::ArmConfig& from = original.path.front();
  const core::ArmConfig& to = original.path.back();
  Roadmap& map = roadmap(original.robot, original.object, original.grasp);
  std::vector<std::pair<Millis, int>> candidates;  // (detour time, node), ties by node id
  for (int id = 0; id < map.numNodes(); ++id) {
    const core::ArmConfig& q = map.node(id);
    if (q == from || q == to || !clear(q)) continue;
    candidates.emplace_back(restToRestDuration(from, q, timing_) + restToRestDuration(q, to, timing_), id);
  }
  std::sort(candidates.begin(), candidates.end());
  if (candidates.size() > static_cast<std::size_t>(attempts)) candidates.resize(static_cast<std::size_t>(attempts));
  for (const auto& [time, id] : candidates) {
    if (auto split = parkingAt(original, map.node(id))) return split;
  }
  return std::nullopt;
}

std::optional<std::pair<const Move*, const Move*>> MotionHypergraph::parkingAt(const Move& original,
                                                                               core::ArmConfig q) {
  if (q == original.path.front() || q == original.path.back()) return std::nullopt;
  const Move* there = move(original.robot, original.object, original.grasp, original.path.front(), q, original.occupied);
  const Move* back =
      there ? move(original.robot, original.object, original.grasp, q, original.path.back(), original.occupied) : nullptr;
  if (!back) return std::nullopt;
  return std::pair{there, back};
}

bool MotionHypergraph::addSchedulingConstraint(int transition_a, int transition_b) {
  if (transition_a == transition_b || !scheduling_constraints_.emplace(std::minmax(transition_a, transition_b)).second) {
    return false;
  }
  const auto hyperarcs = std::minmax(transition(transition_a).sample.hyperarc, transition(transition_b).sample.hyperarc);
  if (hyperarcs.first != hyperarcs.second && ++hyperarc_pair_constraints_[hyperarcs] >= 2) {
    hyperarc_constraints_.insert(hyperarcs);
  }
  return true;
}

bool MotionHypergraph::schedulingConflict(int transition_a, int transition_b) const {
  if (scheduling_constraints_.contains(std::minmax(transition_a, transition_b))) return true;
  return !hyperarc_constraints_.empty() &&
         hyperarc_constraints_.contains(
             std::minmax(transition(transition_a).sample.hyperarc, transition(transition_b).sample.hyperarc));
}

bool MotionHypergraph::schedulingConstrained(int transition_id) const {
  const int hyperarc = transition(transition_id).sample.hyperarc;
  const auto in = [](const std::pair<int, int>& pair, int x) { return pair.first == x || pair.second == x; };
  return std::any_of(scheduling_constraints_.begin(), scheduling_constraints_.end(),
                     [&](const std::pair<int, int>& pair) { return in(pair, transition_id); }) ||
         std::any_of(hyperarc_constraints_.begin(), hyperarc_constraints_.end(),
                     [&](const std::pair<int, int>& pair) { return in(pair, hyperarc); });
}

bool MotionHypergraph::addHomeConstraint(int transition_id, int robot) {
  if (!home_constraints_.emplace(transition_id, robot).second) return false;
  const std::pair<int, int> key{transition(transition_id).sample.hyperarc, robot};
  if (++hyperarc_home_counts_[key] >= 2) hyperarc_home_constraints_.insert(key);
  return true;
}

bool MotionHypergraph::homeConflict(int transition_id, int robot) const {
  if (home_constraints_.empty()) return false;
  return home_constraints_.contains({transition_id, robot}) ||
         hyperarc_home_constraints_.contains({transition(transition_id).sample.hyperarc, robot});
}

bool MotionHypergraph::clearOfIdle(int transition_id, int robot, IdlePose pose) {
  const auto [it, added] = clear_of_idle_transition_.try_emplace({transition_id, robot, pose}, true);
  if (!added) return it->second;
  if (!checker_) checker_ = std::make_unique<CollisionChecker>(*scene_);
  const StandingRobot idle{robot, scene_->configuration(robot, idleConfiguration(robot, pose), kFingersOpen), std::nullopt};
  for (const TransitionMotion& motion : transition(transition_id).sample.motions) {
    const core::TrajectoryInterpolator curve = keyCurve(motion);
    for (std::size_t i = 0; i + 1 < motion.keys.size() && it->second; ++i) {
      it->second = checker_->motionClearOf(motion.robot, keyCurvePiece(*scene_, motion, curve, i), motion.held[i],
                                           std::span(&idle, 1));
    }
  }
  return it->second;
}

bool MotionHypergraph::touches(int transition_id, const RestingObject& object) {
  if (!checker_) checker_ = std::make_unique<CollisionChecker>(*scene_);
  for (const TransitionMotion& motion : transition(transition_id).sample.motions) {
    const core::TrajectoryInterpolator curve = keyCurve(motion);
    for (std::size_t i = 0; i + 1 < motion.keys.size(); ++i) {
      if (checker_->motionObjectHits(motion.robot, keyCurvePiece(*scene_, motion, curve, i), std::span(&object, 1),
                                     motion.held[i])[0]) {
        return true;
      }
    }
  }
  return false;
}

void MotionHypergraph::clearSchedulingConstraints() {
  scheduling_constraints_.clear();
  hyperarc_pair_constraints_.clear();
  hyperarc_constraints_.clear();
  home_constraints_.clear();
  hyperarc_home_counts_.clear();
  hyperarc_home_constraints_.clear();
}

int MotionHypergraph::expand() {
  const ScopedTimer timer(construction_seconds_);
  ++round_;
  std::vector<std::pair<int, int>> handoff_keys;
  for (const auto& [key, ids] : transitions_of_) {
    if (task_space_->hyperarcs().at(key.first).kind == TransitionKind::kHandoff) handoff_keys.push_back(key);
  }
  for (const auto& [hyperarc, grasp] : handoff_keys) sampleHandoffs(hyperarc, grasp, round_);
  for (auto& [key, map] : roadmaps_) map.grow(settings_.roadmap_samples_per_round);
  grown_this_round_.clear();
  // every move is planned again on the grown roadmaps (found ones kept alive, where they are,
  // for pointers still held, e.g. by a plan kept from an earlier round): a new round brings new
  // paths, not only the ones that failed
  for (auto& [key, found] : moves_) {
    if (found) retired_moves_.push_back(std::move(found));
  }
  moves_.clear();
  return round_;
}

std::size_t MotionHypergraph::numMoves() const {
  return retired_moves_.size() +
         static_cast<std::size_t>(std::count_if(moves_.begin(), moves_.end(), [](const auto& e) { return e.second != nullptr; }));
}

std::size_t MotionHypergraph::numRoadmapNodes() const {
  std::size_t nodes = 0;
  for (const auto& [key, map] : roadmaps_) nodes += static_cast<std::size_t>(map.numNodes());
  return nodes;
}

std::vector<int> MotionHypergraph::verticesOf(int task_vertex) const {
  std::vector<int> ids;
  for (std::size_t v = 0; v < vertices_.size(); ++v) {
    if (vertices_[v].task_vertex == task_vertex) ids.push_back(static_cast<int>(v));
  }
  return ids;
}

bool MotionHypergraph::neverPlaceable(int object) {
  const ScopedTimer timer(construction_seconds_);
  // every robot and grasp the object may be held in: picked (at its start, or where it may be
  // set aside), or handed over from a robot holding it (the receiver's grasp is one of
  // handoffGrasps of the giver's), and so on
  std::vector<std::pair<int, Grasp>> held;
  const auto hold = [&](int robot, const Grasp& grasp) {
    const auto same = [&](const auto& other) { return other.first == robot && sameGrasp(grasp, other.second); };
    if (std::none_of(held.begin(), held.end(), same)) held.emplace_back(robot, grasp);
  };
  std::vector<const TransitionHyperarc*> places, handoffs;
  for (std::size_t h = 0; h < task_space_->numHyperarcs(); ++h) {
    const TransitionHyperarc& arc = task_space_->hyperarcs()[h];
    if (arc.object != object) continue;
    if (arc.kind == TransitionKind::kPlace && arc.rest_pose == RestPose::kGoal) places.push_back(&arc);
    if (arc.kind == TransitionKind::kHandoff) handoffs.push_back(&arc);
    if (arc.kind != TransitionKind::kPick) continue;
    for (const int id : transitionsOf(static_cast<int>(h), -1)) hold(arc.robot, *transition(id).sample.grasp_after);
  }
  for (std::size_t i = 0; i < held.size(); ++i) {
    const auto [giver, grasp] = held[i];  // a copy: hold() may grow the list
    for (const TransitionHyperarc* arc : handoffs) {
      if (arc->robot != giver) continue;
      for (const Grasp& received : sampler_->handoffGrasps(object, grasp)) hold(arc->receiver, received);
    }
  }
  for (const TransitionHyperarc* place : places) {
    const int id = static_cast<int>(place - task_space_->hyperarcs().data());
    for (const auto& [robot, grasp] : held) {
      if (robot == place->robot && !sampler_->place(id, grasp).empty()) return false;
    }
  }
  return true;
}

bool MotionHypergraph::hasPlaceSample(int object) const {
  return std::any_of(transitions_of_.begin(), transitions_of_.end(), [&](const auto& entry) {
    const TransitionHyperarc& arc = task_space_->hyperarcs().at(static_cast<std::size_t>(entry.first.first));
    return arc.kind == TransitionKind::kPlace && arc.rest_pose == RestPose::kGoal && arc.object == object &&
           !entry.second.empty();
  });
}

std::vector<int> MotionHypergraph::unsampledHyperarcs() const {
  std::map<int, bool> sampled;  // asked for -> has a sample
  for (const auto& [key, ids] : transitions_of_) sampled[key.first] = sampled[key.first] || !ids.empty();
  std::vector<int> result;
  for (const auto& [hyperarc, any] : sampled) {
    if (!any) result.push_back(hyperarc);
  }
  return result;
}

std::optional<Millis> MotionHypergraph::bestDuration(int hyperarc) const {
  return best_duration_.at(static_cast<std::size_t>(hyperarc));
}

}  // namespace dashbed::planner
