#include "planner/sampling/roadmap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace dashbed::planner {
namespace {

// A filtered query gives up after this many edges the filter rejected: far detours are not
// worth their cost, and the caller has other remedies.
constexpr int kMaxRejections = 25;

}  // namespace

// ================================================================================================
// Roadmap

namespace {

/// What the straight motion between two nodes does: free against the static scene or not, and
/// which sites (of objects other than the held one) it touches when free.
struct MotionCheck {
  bool free = false;
  SiteSet touches;
};

/// An undirected roadmap edge between nodes a < b; `check` is filled when first validated.
struct Edge {
  int a = -1;
  int b = -1;
  double cost = 0.0;  // metric [s]
  std::optional<MotionCheck> check;
};

/// Uniform double in [0, 1) from the top 53 bits of one draw (portable, unlike the
/// implementation-defined std::uniform_real_distribution).
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

core::ArmConfig lerp(const core::ArmConfig& a, const core::ArmConfig& b, double s) {
  core::ArmConfig q;
  for (int j = 0; j < 6; ++j) q[j] = a[j] + s * (b[j] - a[j]);
  return q;
}

/// Hash of a directed motion's ends (equal configurations hash alike: -0.0 as 0.0).
struct MotionHash {
  std::size_t operator()(const std::pair<core::ArmConfig, core::ArmConfig>& m) const {
    std::size_t h = 0x9e3779b97f4a7c15ULL;
    for (const core::ArmConfig* q : {&m.first, &m.second}) {
      for (const double x : *q) h = (h ^ std::hash<double>{}(x + 0.0)) * 0x100000001b3ULL;
    }
    return h;
  }
};

}  // namespace

struct Roadmap::Impl {
  const CollisionScene* scene;
  const ObjectSites* sites;
  int robot;
  std::optional<HeldObject> held;
  double finger;
  RoadmapSettings settings;
  std::uint64_t seed;
  std::mt19937_64 rng;
  CollisionChecker checker;
  std::array<double, 6> max_velocity{};  // the arm joints' speed limits: the metric [rad/s]
  std::array<double, 6> sample_lower{};
  std::array<double, 6> sample_upper{};
  // every existing site of the objects other than the held one, and that object there
  std::vector<int> other_sites;
  std::vector<RestingObject> other_objects;

  std::vector<core::ArmConfig> nodes;
  std::map<core::ArmConfig, int> node_ids;  // exact configuration -> id
  std::vector<Edge> edges;
  std::vector<std::vector<int>> incident;  // node -> ids of its edges, in the order added
  std::map<std::pair<int, int>, MotionCheck> direct_checks;  // node pairs (a < b) without an edge
  // every motion checked so far, by its (directed) ends
  std::unordered_map<std::pair<core::ArmConfig, core::ArmConfig>, MotionCheck, MotionHash> motion_checks;
  int validated_edges = 0;

  Impl(const CollisionScene& scene_in, const ObjectSites& sites_in, int robot_in, std::optional<HeldObject> held_in,
       double finger_in, std::uint64_t seed_in, const RoadmapSettings& settings_in)
      : scene(&scene_in),
        sites(&sites_in),
        robot(robot_in),
        held(std::move(held_in)),
        finger(finger_in),
        settings(settings_in),
        seed(seed_in),
        rng(seed_in),
        checker(scene_in) {
    if (robot < 0 || robot >= scene->numRobots() || scene->numPositions(robot) < 6) {
      throw std::invalid_argument("roadmap: robot " + std::to_string(robot) + " is not an arm of the scene");
    }
    if (sites->numObjects() != scene->numObjects()) {
      throw std::invalid_argument("roadmap: the object sites do not belong to the scene's world");
    }
    if (held && (held->object < 0 || held->object >= scene->numObjects())) {
      throw std::invalid_argument("roadmap: held object index " + std::to_string(held->object) + " out of range");
    }
    if (settings.neighbours < 1 || !(settings.max_edge_time > 0.0) || settings.shortcut_attempts < 0) {
      throw std::invalid_argument("roadmap: neighbours and max_edge_time must be positive, shortcut_attempts >= 0");
    }
    // The sampling range: the joint limits with the +-2 pi ranges clamped to +-pi, where UrArmIk
    // puts its solutions (each angle closest to zero); one turn covers every pose. The price:
    // a region joined to the rest only across the seam is sampled but unreachable (shoulder
    // lift near pi: the upper arm backwards and down, the other way round leads through the
    // table).
    const core::RobotModel& model = *scene->robots()[static_cast<std::size_t>(robot)].model;
    for (int j = 0; j < 6; ++j) {
      const core::JointModel& joint = model.joints()[model.movableJoints()[j]];
      max_velocity[j] = joint.max_velocity;
      sample_lower[j] = std::max(joint.lower, -std::numbers::pi);
      sample_upper[j] = std::min(joint.upper, std::numbers::pi);
    }
    for (int site = 0; site < sites->numSites(); ++site) {
      const std::optional<RestingObject> resting = sites->site(site);
      if (!resting || (held && resting->object == held->object)) continue;
      other_sites.push_back(site);
      other_objects.push_back(*resting);
    }
  }

  double distance(const core::ArmConfig& a, const core::ArmConfig& b) const {
    double t = 0.0;
    for (int j = 0; j < 6; ++j) t = std::max(t, std::abs(b[j] - a[j]) / max_velocity[j]);
    return t;
  }

  Eigen::VectorXd full(const core::ArmConfig& q) const { return scene->configuration(robot, q, finger); }

  bool configurationFree(const core::ArmConfig& q) { return checker.robotFree(robot, full(q), {}, held); }

  /// The objects resting at the occupied sites (that exist and are not the held object's).
  std::vector<RestingObject> occupiedObjects(const SiteSet& occupied) const {
    std::vector<RestingObject> objects;
    for (std::size_t k = 0; k < other_sites.size(); ++k) {
      if (occupied.test(other_sites[k])) objects.push_back(other_objects[k]);
    }
    return objects;
  }

  bool motionFree(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& occupied) {
    return checker.motionFree(robot, full(a), full(b), occupiedObjects(occupied), held);
  }

  /// Static-scene check of a -> b, then the sites it touches (each other object's site on its
  /// own, in one pass over the motion's samples). Cached per direction: a motion checked
  /// from b to a is sampled at (slightly) other points.
  const MotionCheck& checkMotion(const core::ArmConfig& a, const core::ArmConfig& b) {
    const auto [it, added] = motion_checks.try_emplace(std::pair{a, b});
    if (!added) return it->second;
    MotionCheck& result = it->second;
    result.touches = SiteSet(sites->numSites());
    const std::optional<std::vector<char>> hits = checker.motionCheck(robot, full(a), full(b), other_objects, held);
    if (!hits) return result;
    result.free = true;
    for (std::size_t k = 0; k < other_sites.size(); ++k) {
      if ((*hits)[k]) result.touches.set(other_sites[k]);
    }
    return result;
  }

  /// Free against the static scene and touching none of the `occupied` sites: motionFree's
  /// answer, from the cached check.
  bool motionUsable(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& occupied) {
    return usable(checkMotion(a, b), occupied);
  }

  /// The sites of `among` that the motion a -> b touches; every one of them when the motion is
  /// not free against the static scene (as checking each on its own with motionFree says).
  SiteSet touchedSites(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& among) {
    const MotionCheck& check = checkMotion(a, b);
    SiteSet result(sites->numSites());
    for (const int site : other_sites) {
      if (among.test(site) && (!check.free || check.touches.test(site))) result.set(site);
    }
    return result;
  }

  /// The cached check of an edge, validated on first use (always from its lower node id).
  const MotionCheck& edgeCheck(int e) {
    Edge& edge = edges[e];
    if (!edge.check) {
      edge.check = checkMotion(nodes[edge.a], nodes[edge.b]);
      ++validated_edges;
    }
    return *edge.check;
  }

  /// The cached check of the straight motion between two nodes: their edge's if they share one.
  const MotionCheck& pairCheck(int u, int v) {
    const int a = std::min(u, v), b = std::max(u, v);
    for (const int e : incident[a]) {
      if (edges[e].b == b) return edgeCheck(e);
    }
    auto it = direct_checks.find({a, b});
    if (it == direct_checks.end()) it = direct_checks.emplace(std::pair{a, b}, checkMotion(nodes[a], nodes[b])).first;
    return it->second;
  }

  static bool usable(const MotionCheck& check, const SiteSet& occupied) {
    return check.free && !check.touches.intersects(occupied);
  }

  /// Adds a node connected to its k nearest nodes within max_edge_time (ties by id); edges are
  /// not checked here. Brute-force nearest search.
  int addNode(const core::ArmConfig& q) {
    const int id = static_cast<int>(nodes.size());
    std::vector<std::pair<double, int>> near;
    for (int other = 0; other < id; ++other) {
      const double d = distance(nodes[other], q);
      if (d <= settings.max_edge_time) near.emplace_back(d, other);
    }
    const std::size_t k = std::min(near.size(), static_cast<std::size_t>(settings.neighbours));
    std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(k), near.end());
    nodes.push_back(q);
    node_ids.emplace(q, id);
    incident.emplace_back();
    for (std::size_t i = 0; i < k; ++i) {
      const int e = static_cast<int>(edges.size());
      edges.push_back(Edge{near[i].second, id, near[i].first, std::nullopt});
      incident[near[i].second].push_back(e);
      incident[id].push_back(e);
    }
    return id;
  }

  /// A* from `from` to `to` over the edges not known to be blocked (statically, by an
  /// occupied site, or `blocked` by the query's filter); heuristic: the metric to `to`.
  /// Returns the path's edge ids, in order.
  std::optional<std::vector<int>> search(int from, int to, const SiteSet& occupied,
                                         const std::vector<char>& blocked) const {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> cost(nodes.size(), inf);
    std::vector<int> via(nodes.size(), -1);  // edge reaching the node on the best path
    std::vector<char> closed(nodes.size(), 0);
    using Entry = std::pair<double, int>;  // (cost + heuristic, node): ties by node id
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    cost[from] = 0.0;
    open.emplace(distance(nodes[from], nodes[to]), from);
    while (!open.empty()) {
      const int u = open.top().second;
      open.pop();
      if (closed[u]) continue;
      closed[u] = 1;
      if (u == to) break;
      for (const int e : incident[u]) {
        const Edge& edge = edges[e];
        if ((edge.check && !usable(*edge.check, occupied)) || blocked[e]) continue;
        const int v = edge.a == u ? edge.b : edge.a;
        const double c = cost[u] + edge.cost;
        if (closed[v] || c >= cost[v]) continue;
        cost[v] = c;
        via[v] = e;
        open.emplace(c + distance(nodes[v], nodes[to]), v);
      }
    }
    if (!closed[to]) return std::nullopt;
    std::vector<int> path;
    for (int v = to; v != from;) {
      const Edge& edge = edges[via[v]];
      path.push_back(via[v]);
      v = edge.a == v ? edge.b : edge.a;
    }
    std::reverse(path.begin(), path.end());
    return path;
  }

  /// Random shortcuts: two points drawn uniformly along the path (by metric length) are joined
  /// straight when that is shorter and free of the static scene and the occupied sites. The
  /// two stubs left of the old pieces are checked as well, so that every piece of the result
  /// passes motionFree on its own (a piece of a checked motion is sampled at other points).
  /// The draws come from a generator seeded with the roadmap's seed and the query's nodes.
  void shortcut(std::vector<core::ArmConfig>& path, int from, int to, const SiteSet& occupied,
                const Roadmap::MotionFilter& clear) {
    // the filter first: a shortcut's ends are new points, so neither check is cached, and a
    // shortcut that fails mostly cuts through what the filter keeps clear of (detours)
    const auto free = [&](const core::ArmConfig& a, const core::ArmConfig& b) {
      return (!clear || clear(a, b)) && motionUsable(a, b, occupied);
    };
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to)};
    std::mt19937_64 draw(seq);
    std::vector<double> along;  // metric length from path.front() to each waypoint
    for (int attempt = 0; attempt < settings.shortcut_attempts && path.size() > 2; ++attempt) {
      along.assign(1, 0.0);
      for (std::size_t i = 1; i < path.size(); ++i) along.push_back(along.back() + distance(path[i - 1], path[i]));
      double t0 = uniform01(draw) * along.back(), t1 = uniform01(draw) * along.back();
      if (t0 > t1) std::swap(t0, t1);
      // pieces i and j hold the two points (the last piece when a point lies at the end)
      const auto piece = [&](double t) {
        const auto it = std::upper_bound(along.begin(), along.end(), t);
        return std::min(static_cast<std::size_t>(it - along.begin()), path.size() - 1) - 1;
      };
      const std::size_t i = piece(t0), j = piece(t1);
      if (i == j) continue;
      const auto point = [&](std::size_t k, double t) {
        const double length = along[k + 1] - along[k];
        return length > 0.0 ? lerp(path[k], path[k + 1], std::clamp((t - along[k]) / length, 0.0, 1.0)) : path[k];
      };
      const core::ArmConfig a = point(i, t0), b = point(j, t1);
      if (t1 - t0 - distance(a, b) <= 1e-9) continue;  // no shorter
      const bool keep_a = a != path[i], keep_b = b != path[j + 1];
      if (!free(a, b) || (keep_a && !free(path[i], a)) || (keep_b && !free(b, path[j + 1]))) {
        continue;
      }
      std::vector<core::ArmConfig> shorter(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      if (keep_a) shorter.push_back(a);
      if (keep_b) shorter.push_back(b);
      shorter.insert(shorter.end(), path.begin() + static_cast<std::ptrdiff_t>(j) + 1, path.end());
      path = std::move(shorter);
    }
  }

  /// The direct motion if usable; else lazy A*: search, validate the found path's edges in
  /// order, and search again after the first one that fails, until a path holds or none is left.
  /// Edges `clear` rejects are blocked for this query only.
  std::optional<std::vector<core::ArmConfig>> query(int from, int to, const SiteSet& occupied,
                                                    const Roadmap::MotionFilter& clear) {
    const auto passes = [&](int u, int v) { return !clear || clear(nodes[u], nodes[v]); };
    if (usable(pairCheck(from, to), occupied) && passes(from, to)) {
      if (from == to) return std::vector<core::ArmConfig>{nodes[from]};
      return std::vector<core::ArmConfig>{nodes[from], nodes[to]};
    }
    std::vector<char> blocked(edges.size(), 0);
    int rejected = 0;
    while (rejected <= kMaxRejections) {
      const std::optional<std::vector<int>> found = search(from, to, occupied, blocked);
      if (!found) return std::nullopt;
      const bool holds = std::all_of(found->begin(), found->end(), [&](int e) {
        if (!usable(edgeCheck(e), occupied)) return false;
        if (passes(edges[e].a, edges[e].b)) return true;
        blocked[e] = 1;
        ++rejected;
        return false;
      });
      if (!holds) continue;
      std::vector<core::ArmConfig> path{nodes[from]};
      int at = from;
      for (const int e : *found) {
        at = edges[e].a == at ? edges[e].b : edges[e].a;
        path.push_back(nodes[at]);
      }
      shortcut(path, from, to, occupied, clear);
      return path;
    }
    return std::nullopt;
  }

  void requireNode(int id, const char* what) const {
    if (id < 0 || id >= static_cast<int>(nodes.size())) {
      throw std::out_of_range(std::string("roadmap: ") + what + " node " + std::to_string(id) + " does not exist");
    }
  }
};

Roadmap::Roadmap(const CollisionScene& scene, const ObjectSites& sites, int robot, std::optional<HeldObject> held,
                 double finger, std::uint64_t seed, const RoadmapSettings& settings)
    : impl_(std::make_unique<Impl>(scene, sites, robot, std::move(held), finger, seed, settings)) {}

Roadmap::~Roadmap() = default;
Roadmap::Roadmap(Roadmap&&) noexcept = default;
Roadmap& Roadmap::operator=(Roadmap&&) noexcept = default;

// Samples uniformly in the sampling range until one is free, at most 100 draws per sample.
int Roadmap::grow(int samples) {
  Impl& m = *impl_;
  int added = 0;
  for (int n = 0; n < samples; ++n) {
    for (int draw = 0; draw < 100; ++draw) {
      core::ArmConfig q;
      for (int j = 0; j < 6; ++j) q[j] = m.sample_lower[j] + (m.sample_upper[j] - m.sample_lower[j]) * uniform01(m.rng);
      if (!m.configurationFree(q)) continue;
      m.addNode(q);
      ++added;
      break;
    }
  }
  return added;
}

int Roadmap::growNear(const core::ArmConfig& center, int samples, double spread) {
  Impl& m = *impl_;
  int added = 0;
  for (int n = 0; n < samples; ++n) {
    for (int draw = 0; draw < 100; ++draw) {
      core::ArmConfig q;
      for (int j = 0; j < 6; ++j) {
        // within the sampled range, widened to reach the centre (e.g. a node added outside it)
        const double lo = std::min(m.sample_lower[j], center[j]), hi = std::max(m.sample_upper[j], center[j]);
        q[j] = std::clamp(center[j] + spread * (2.0 * uniform01(m.rng) - 1.0), lo, hi);
      }
      if (!m.configurationFree(q)) continue;
      m.addNode(q);
      ++added;
      break;
    }
  }
  return added;
}

int Roadmap::addConfiguration(const core::ArmConfig& q) {
  if (const auto it = impl_->node_ids.find(q); it != impl_->node_ids.end()) return it->second;
  if (!impl_->configurationFree(q)) return -1;
  return impl_->addNode(q);
}

std::optional<std::vector<core::ArmConfig>> Roadmap::query(int from, int to, const SiteSet& occupied) {
  impl_->requireNode(from, "query start");
  impl_->requireNode(to, "query goal");
  return impl_->query(from, to, occupied, {});
}

std::optional<std::vector<core::ArmConfig>> Roadmap::query(int from, int to, const SiteSet& occupied,
                                                           const MotionFilter& clear) {
  impl_->requireNode(from, "query start");
  impl_->requireNode(to, "query goal");
  return impl_->query(from, to, occupied, clear);
}

bool Roadmap::motionFree(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& occupied) {
  return impl_->motionFree(a, b, occupied);
}

SiteSet Roadmap::touchedSites(const core::ArmConfig& a, const core::ArmConfig& b, const SiteSet& among) {
  return impl_->touchedSites(a, b, among);
}

int Roadmap::robot() const { return impl_->robot; }
const std::optional<HeldObject>& Roadmap::held() const { return impl_->held; }
int Roadmap::numNodes() const { return static_cast<int>(impl_->nodes.size()); }
int Roadmap::numEdges() const { return static_cast<int>(impl_->edges.size()); }
int Roadmap::numValidatedEdges() const { return impl_->validated_edges; }

const core::ArmConfig& Roadmap::node(int id) const {
  impl_->requireNode(id, "requested");
  return impl_->nodes[id];
}

Eigen::VectorXd Roadmap::fullConfiguration(const core::ArmConfig& q) const { return impl_->full(q); }

}  // namespace dashbed::planner
