// sweepMotion (collision_sweep.h): a motion checked item by item, skipping the samples at which
// an item is known to be free.
#include "planner/collision/internal/collision_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dashbed::planner::detail {
namespace {

// A gap skips samples only with this much of it to spare [m]: rounding, and FCL's contact
// tolerance (1e-6 m), stay far below it.
constexpr double kGapSlack = 1e-4;
// How far beyond its bounding sphere a moving body (or the held object) looks for static boxes
// [m], at most the motion's whole travel: the largest static gap it can find, against the boxes
// it visits to find it.
constexpr double kStaticReach = 0.25;
// An object is tested against the robot only when its bounding sphere, grown by this [m], reaches
// the box around the robot's bounding spheres: rounding stays on the safe side.
constexpr double kObjectSlack = 1e-6;
// A gap that says the parts collide (every other gap is >= 0).
constexpr double kHit = -1.0;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---- lower bounds on the distance between parts that a prefilter found apart [m] ----

double spheresGap(const Vector3d& a, double ra, const Vector3d& b, double rb) {
  return std::max((a - b).norm() - ra - rb - kPrefilterTolerance, 0.0);
}

double sphereObbGap(const Vector3d& c, double r, const Frame& X_WB, const Vector3d& half) {
  return std::max(sphereObbMargin(c, r, X_WB, half), 0.0);
}

double sphereAabbGap(const Vector3d& c, double r, const Vector3d& lo, const Vector3d& hi) {
  const Vector3d outside = (lo - c).cwiseMax(0.0) + (c - hi).cwiseMax(0.0);
  return std::max(outside.norm() - r - kPrefilterTolerance, 0.0);
}

// ---- the checks of CheckerState, each with a gap: kHit where the check finds a collision, else
// a lower bound on the distance (0 where only "apart" is known) ----

/// CheckerState::shapesCollide (its prefilters' largest margin when they separate the shapes).
double shapesGap(CheckerState& state, const Placed& a, const Placed& b) {
  const double margin = separation(a, b);
  if (margin > 0.0) return margin;
  return state.shapesCollide(a, b) ? kHit : 0.0;
}

/// CheckerState::bodiesCollide.
double bodiesGap(CheckerState& state, CheckerState::Slot& slot, int a, int b) {
  const Body& body_a = slot.robot->bodies[a];
  const Body& body_b = slot.robot->bodies[b];
  if (body_a.radius < 0.0 || body_b.radius < 0.0) return kInfinity;
  const Vector3d& c_b = slot.c_WB[b];
  if (spheresApart(slot.c_WB[a], body_a.radius, c_b, body_b.radius)) {
    return spheresGap(slot.c_WB[a], body_a.radius, c_b, body_b.radius);
  }
  double gap = kInfinity;
  for (int sa = body_a.shape_begin; sa < body_a.shape_end; ++sa) {
    const Placed pa = state.placedShape(slot, sa);
    if (spheresApart(pa.X_W->p, pa.radius, c_b, body_b.radius)) {
      gap = std::min(gap, spheresGap(pa.X_W->p, pa.radius, c_b, body_b.radius));
      continue;
    }
    for (int sb = body_b.shape_begin; sb < body_b.shape_end; ++sb) {
      const double g = shapesGap(state, pa, state.placedShape(slot, sb));
      if (g == kHit) return kHit;
      gap = std::min(gap, g);
    }
  }
  return gap;
}

/// CheckerState::bodyHits.
double bodyGap(CheckerState& state, CheckerState::Slot& slot, int b, const Placed& other) {
  const Body& body = slot.robot->bodies[b];
  if (body.radius < 0.0) return kInfinity;
  if (spheresApart(slot.c_WB[b], body.radius, other.X_W->p, other.radius)) {
    return spheresGap(slot.c_WB[b], body.radius, other.X_W->p, other.radius);
  }
  double gap = kInfinity;
  for (int s = body.shape_begin; s < body.shape_end; ++s) {
    const double g = shapesGap(state, state.placedShape(slot, s), other);
    if (g == kHit) return kHit;
    gap = std::min(gap, g);
  }
  return gap;
}

/// A shape against static box k.
double staticBoxGap(CheckerState& state, const Placed& shape, int k) {
  const StaticData& statics = state.scene->statics;
  if (sphereObbApart(shape.X_W->p, shape.radius, statics.frames[k], statics.half[k])) {
    return sphereObbGap(shape.X_W->p, shape.radius, statics.frames[k], statics.half[k]);
  }
  return shapesGap(state, shape, state.placedStatic(k));
}

/// Body b of the slot's robot against the static scene (CheckerState::staticHit for one body):
/// the boxes within `reach` of its bounding sphere; the gap is at most `reach`.
double bodyStaticGap(CheckerState& state, CheckerState::Slot& slot, int b, double reach) {
  const StaticData& statics = state.scene->statics;
  const int self = static_cast<int>(slot.robot - state.scene->robots.data());
  const Body& body = slot.robot->bodies[b];
  const Vector3d& c = slot.c_WB[b];
  double gap = reach;
  const bool hit = state.forStaticNear(c, body.radius + reach, [&](int k) {
    if (statics.owner[k] == self) return false;
    if (sphereObbApart(c, body.radius, statics.frames[k], statics.half[k])) {
      gap = std::min(gap, sphereObbGap(c, body.radius, statics.frames[k], statics.half[k]));
      return false;
    }
    for (int s = body.shape_begin; s < body.shape_end; ++s) {
      const double g = staticBoxGap(state, state.placedShape(slot, s), k);
      if (g == kHit) return true;
      gap = std::min(gap, g);
    }
    return false;
  });
  return hit ? kHit : gap;
}

/// The held object against the static scene (CheckerState::heldStaticBox), as bodyStaticGap.
double heldStaticGap(CheckerState& state, CheckerState::Slot& slot, double reach) {
  const StaticData& statics = state.scene->statics;
  const int self = static_cast<int>(slot.robot - state.scene->robots.data());
  const Placed held = state.placedHeld(slot);
  double gap = reach;
  const bool hit = state.forStaticNear(held.X_W->p, held.radius + reach, [&](int k) {
    if (statics.owner[k] == self) return false;
    const double g = staticBoxGap(state, held, k);
    if (g == kHit) return true;
    gap = std::min(gap, g);
    return false;
  });
  return hit ? kHit : gap;
}

/// A resting object against the robot's bodies and its held object
/// (CheckerState::oneObjectCollision), first against the box around the robot's bounding spheres
/// (the slot's bounds must be up to date).
double objectGap(CheckerState& state, CheckerState::Slot& slot, const RestingObject& resting, Frame& X_WO) {
  const ObjectData& data = state.scene->objects[resting.object];
  const double r = data.radius + kObjectSlack;
  if (sphereAabbApart(X_WO.p, r, slot.lo, slot.hi)) return sphereAabbGap(X_WO.p, r, slot.lo, slot.hi);
  const Placed object{ShapeType::kBox, data.box.get(), &X_WO, &data.half, data.radius};
  double gap = kInfinity;
  for (std::size_t b = slot.robot->bodies.size(); b-- > 0;) {
    const double g = bodyGap(state, slot, static_cast<int>(b), object);
    if (g == kHit) return kHit;
    gap = std::min(gap, g);
  }
  if (!slot.holding) return gap;
  const double g = shapesGap(state, state.placedHeld(slot), object);
  return g == kHit ? kHit : std::min(gap, g);
}

// ---- how fast the parts of an item can close in ----

/// Bound on the distance of body b's points from its origin [m].
double ownReach(const RobotData& robot, int b) {
  const Body& body = robot.bodies[b];
  double reach = 0.0;
  for (int s = body.shape_begin; s < body.shape_end; ++s) {
    reach = std::max(reach, robot.shapes[s].X_BS.p.norm() + robot.shapes[s].radius);
  }
  return reach;
}

/// The nearest body both a and b descend from (or are), -1 for none.
int commonAncestor(const RobotData& robot, int a, int b) {
  for (int x = a; x >= 0; x = robot.bodies[x].parent) {
    for (int y = b; y >= 0; y = robot.bodies[y].parent) {
      if (x == y) return x;
    }
  }
  return -1;
}

/// Adds, per configuration index, a bound on how far the points within `extent` [m] of body
/// b's origin move per unit of that position relative to body `stop`, an ancestor of b (-1: the
/// world): the joints between them, each weighted by the points' farthest distance from it
/// (as CollisionScene::motionTravel bounds the whole robot's points).
void addChainRates(const RobotData& robot, int b, double extent, int stop, std::vector<double>& rates) {
  double distance = extent;
  for (int k = b; k >= 0 && k != stop; k = robot.bodies[k].parent) {
    const Body& body = robot.bodies[k];
    const bool prismatic = body.joint_type == core::JointType::kPrismatic;
    if (body.q_index >= 0) rates[body.q_index] += prismatic ? 1.0 : distance;
    distance += body.X_PJ.p.norm() + (prismatic ? body.stroke : 0.0);
  }
}

/// One thing a motion sweep checks at every sample.
struct Item {
  enum class Kind : std::uint8_t { kBodyStatic, kHeldStatic, kBodyPair, kHeldBody, kObject };
  Kind kind;
  int a = -1;  // the body (kBodyStatic, kHeldBody), first body (kBodyPair) or object entry (kObject)
  int b = -1;  // the second body (kBodyPair)
  double closing = 0.0;  // bound on how much nearer its parts come from one sample to the next [m]
};

}  // namespace

std::optional<std::vector<char>> sweepMotion(CheckerState& state, const RobotData& robot, const MotionRef& motion,
                                             const std::optional<HeldObject>& held, int n, double step_travel,
                                             std::span<const RestingObject> objects, const SweepRequest& request) {
  using Kind = Item::Kind;
  const SceneData& scene = *state.scene;
  CheckerState::Slot& slot = state.slots[static_cast<std::size_t>(&robot - scene.robots.data())];
  // An item's parts close in per sample by at most its joints' rates times their change per
  // sample (a curve's joints move up to peak_over_mean times faster than on average).
  std::vector<double> rates(static_cast<std::size_t>(robot.num_positions));
  const auto closing = [&](auto&& add_rates) {
    std::fill(rates.begin(), rates.end(), 0.0);
    add_rates();
    double per_sample = 0.0;
    for (int j = 0; j < robot.num_positions; ++j) per_sample += rates[j] * std::abs(motion.to[j] - motion.from[j]);
    return per_sample * motion.peakOverMean() / n;
  };
  const double held_extent =
      held ? robot.X_BT.p.norm() + held->X_TO.translation().norm() + scene.objects[held->object].radius_grown : 0.0;
  std::vector<Item> items;
  if (request.check_robot) {
    for (const int b : robot.static_order) {
      const double body_closing = closing([&] { addChainRates(robot, b, ownReach(robot, b), -1, rates); });
      items.push_back({Kind::kBodyStatic, b, -1, body_closing});
    }
    if (held && held->check_static) {
      items.push_back({Kind::kHeldStatic, -1, -1,
                       closing([&] { addChainRates(robot, robot.tcp_body, held_extent, -1, rates); })});
    }
    for (const auto& [a, b] : robot.self_pairs) {
      const int common = commonAncestor(robot, a, b);
      items.push_back({Kind::kBodyPair, a, b, closing([&] {
                         addChainRates(robot, a, ownReach(robot, a), common, rates);
                         addChainRates(robot, b, ownReach(robot, b), common, rates);
                       })});
    }
    if (held) {
      for (std::size_t i = robot.bodies.size(); i-- > 0;) {
        if (robot.bodies[i].finger || robot.bodies[i].radius < 0.0) continue;
        const int b = static_cast<int>(i);
        const int common = commonAncestor(robot, b, robot.tcp_body);
        items.push_back({Kind::kHeldBody, b, -1, closing([&] {
                           addChainRates(robot, b, ownReach(robot, b), common, rates);
                           addChainRates(robot, robot.tcp_body, held_extent, common, rates);
                         })});
      }
    }
  }
  const std::size_t first_object = items.size();
  for (std::size_t k = 0; k < objects.size(); ++k) {
    items.push_back({Kind::kObject, static_cast<int>(k), -1, step_travel});
  }
  std::vector<char> hits(objects.size(), 0);
  if (items.empty()) return hits;

  // known[item * row + i]: the item is free at sample i
  const std::size_t row = static_cast<std::size_t>(n) + 1;
  std::vector<char> known(items.size() * row, 0);
  const auto settle = [&](std::size_t item, int from, int to) {
    std::fill(known.begin() + static_cast<std::ptrdiff_t>(item * row) + from,
              known.begin() + static_cast<std::ptrdiff_t>(item * row) + to + 1, 1);
  };
  std::vector<Frame> poses;
  poses.reserve(objects.size());
  for (std::size_t k = 0; k < objects.size(); ++k) {
    poses.emplace_back(objects[k].X_WO);
    if (held && objects[k].object == held->object) settle(first_object + k, 0, n);  // never a hit
  }
  const ObjectData* held_data = held ? &scene.objects[held->object] : nullptr;

  for (const int i : state.bisectionOrder(n)) {
    ++state.counters->motion_samples;
    bool pending = false;
    bool objects_pending = false;
    for (std::size_t item = 0; item < items.size(); ++item) {
      if (known[item * row + i]) continue;
      pending = true;
      objects_pending = objects_pending || item >= first_object;
    }
    if (!pending) continue;
    motion.at(static_cast<double>(i) / n, state.q_a);
    state.forward(slot, robot, state.q_a, held);
    if (objects_pending) CheckerState::updateBounds(slot, held_data);
    for (std::size_t item = 0; item < items.size(); ++item) {
      if (known[item * row + i]) continue;
      const Item& it = items[item];
      // static boxes farther than the item travels in the whole motion are of no interest
      const double reach = std::min(kStaticReach, n * it.closing + 2.0 * kGapSlack);
      double gap = 0.0;
      switch (it.kind) {
        case Kind::kBodyStatic: gap = bodyStaticGap(state, slot, it.a, reach); break;
        case Kind::kHeldStatic: gap = heldStaticGap(state, slot, reach); break;
        case Kind::kBodyPair: gap = bodiesGap(state, slot, it.a, it.b); break;
        case Kind::kHeldBody: gap = bodyGap(state, slot, it.a, state.placedHeld(slot)); break;
        case Kind::kObject: gap = objectGap(state, slot, objects[it.a], poses[it.a]); break;
      }
      if (gap == kHit) {
        if (it.kind != Kind::kObject) return std::nullopt;
        hits[it.a] = 1;
        if (request.stop_at_object) return hits;
        settle(item, 0, n);
        continue;
      }
      // free at the samples j with |j - i| * closing + slack < gap
      const double r = std::ceil((gap - kGapSlack) / std::max(it.closing, 1e-12)) - 1.0;
      if (r >= 1.0) {
        const int ri = static_cast<int>(std::min(r, static_cast<double>(n)));
        settle(item, std::max(0, i - ri), std::min(n, i + ri));
      }
    }
  }
  return hits;
}

}  // namespace dashbed::planner::detail
