#include "planner/task_space/representation_analysis.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace dashbed::planner {
namespace {

using Count = std::uint64_t;

[[noreturn]] void throwOverflow() {
  throw std::overflow_error("representation size does not fit in 64 bits");
}

Count add(Count a, Count b) {
  Count sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) throwOverflow();
  return sum;
}

Count mul(Count a, Count b) {
  Count product = 0;
  if (__builtin_mul_overflow(a, b, &product)) throwOverflow();
  return product;
}

// C(n, k), exact: after step i the running value is C(n-k+i, i); dividing by the gcd first keeps
// every intermediate no larger than the result
Count binomial(Count n, Count k) {
  if (k > n) return 0;
  k = std::min(k, n - k);
  Count result = 1;
  for (Count i = 1; i <= k; ++i) {
    const Count g = std::gcd(result, i);
    result = mul(result / g, (n - k + i) / (i / g));
  }
  return result;
}

// n! / (n-k)!: ordered choices of k out of n (C(n,k) k!)
Count fallingFactorial(Count n, Count k) {
  if (k > n) return 0;
  Count result = 1;
  for (Count i = 0; i < k; ++i) result = mul(result, n - i);
  return result;
}

void requireCounts(int robots, int objects) {
  if (robots < 0 || objects < 0) {
    throw std::invalid_argument("representation analysis: robots and objects must be >= 0 (got " +
                                std::to_string(robots) + " robots, " + std::to_string(objects) + " objects)");
  }
}

}  // namespace

Count compositeGraphVertices(int robots, int objects) {
  requireCounts(robots, objects);
  const Count n = static_cast<Count>(robots), m = static_cast<Count>(objects);
  Count total = 0;
  // p held objects: which objects (C(m,p)), and an ordered choice of their holders (C(n,p) p!)
  for (Count p = 0; p <= std::min(m, n); ++p) total = add(total, mul(binomial(m, p), fallingFactorial(n, p)));
  return total;
}

Count compositeTransitionsFrom(int robots, int objects, int held) {
  requireCounts(robots, objects);
  if (held < 0 || held > std::min(robots, objects)) {
    throw std::invalid_argument("representation analysis: " + std::to_string(held) +
                                " held objects is impossible with " + std::to_string(robots) + " robots and " +
                                std::to_string(objects) + " objects");
  }
  const Count n = static_cast<Count>(robots), m = static_cast<Count>(objects), p = static_cast<Count>(held);
  const Count free_robots = n - p, free_objects = m - p;
  Count action_sets = 0;
  // l of the p held objects are placed
  for (Count l = 0; l <= p; ++l) {
    Count with_handoffs = 0;
    // h of the others are handed to distinct empty-handed robots
    for (Count h = 0; h <= std::min(p - l, free_robots); ++h) {
      Count with_picks = 0;
      // g resting objects are picked by distinct empty-handed robots that receive nothing
      for (Count g = 0; g <= std::min(free_objects, free_robots - h); ++g) {
        with_picks = add(with_picks, mul(binomial(free_objects, g), fallingFactorial(free_robots - h, g)));
      }
      with_handoffs = add(with_handoffs, mul(mul(binomial(p - l, h), fallingFactorial(free_robots, h)), with_picks));
    }
    action_sets = add(action_sets, mul(binomial(p, l), with_handoffs));
  }
  return action_sets - 1;  // the empty set of actions is no transition
}

Count compositeGraphTransitions(int robots, int objects) {
  requireCounts(robots, objects);
  const Count n = static_cast<Count>(robots), m = static_cast<Count>(objects);
  Count total = 0;
  for (Count p = 0; p <= std::min(m, n); ++p) {
    const Count elements = mul(binomial(m, p), fallingFactorial(n, p));
    total = add(total, mul(elements, compositeTransitionsFrom(robots, objects, static_cast<int>(p))));
  }
  return total;
}

RepresentationSize compositeGraphSize(int robots, int objects) {
  return {compositeGraphVertices(robots, objects), compositeGraphTransitions(robots, objects)};
}

RepresentationSize hypergraphSize(int robots, int objects) {
  requireCounts(robots, objects);
  const Count n = static_cast<Count>(robots), m = static_cast<Count>(objects);
  const Count mn = mul(m, n);
  const Count vertices = add(add(mn, m), n);
  const Count pick_place = mul(2, mn);
  const Count handoffs = n == 0 ? 0 : mul(mn, n - 1);
  return {vertices, add(pick_place, handoffs)};
}

bool isCompositeTransition(const std::vector<int>& from, const std::vector<int>& to) {
  if (from.size() != to.size()) {
    throw std::invalid_argument("isCompositeTransition: elements of different object counts");
  }
  if (from == to) return false;
  // held[r] before and after, as object indices (or -1)
  int max_robot = -1;
  for (std::size_t o = 0; o < from.size(); ++o) max_robot = std::max({max_robot, from[o], to[o]});
  std::vector<int> held_before(static_cast<std::size_t>(max_robot + 1), -1), held_after = held_before;
  for (std::size_t o = 0; o < from.size(); ++o) {
    if (from[o] >= 0) held_before[from[o]] = static_cast<int>(o);
    if (to[o] >= 0) held_after[to[o]] = static_cast<int>(o);
  }
  for (std::size_t r = 0; r < held_before.size(); ++r) {
    if (held_before[r] >= 0 && held_after[r] >= 0 && held_before[r] != held_after[r]) return false;
  }
  return true;
}

CompositeTaskGraph enumerateCompositeTaskGraph(int robots, int objects, std::size_t max_elements) {
  requireCounts(robots, objects);
  const Count expected = compositeGraphVertices(robots, objects);
  if (expected > max_elements) {
    throw std::invalid_argument("enumerateCompositeTaskGraph: " + std::to_string(expected) +
                                " elements exceed the limit of " + std::to_string(max_elements));
  }
  CompositeTaskGraph graph;
  graph.robots = robots;
  graph.objects = objects;

  // every allocation object -> {resting, robot}, in lexicographic order, keeping those in which
  // no robot holds two objects
  std::vector<int> holder(static_cast<std::size_t>(objects), CompositeTaskGraph::kResting);
  std::vector<int> load(static_cast<std::size_t>(robots), 0);
  const auto recurse = [&](auto&& self, std::size_t o) -> void {
    if (o == holder.size()) {
      graph.elements.push_back(holder);
      return;
    }
    for (int h = CompositeTaskGraph::kResting; h < robots; ++h) {
      if (h >= 0 && load[h] > 0) continue;
      holder[o] = h;
      if (h >= 0) ++load[h];
      self(self, o + 1);
      if (h >= 0) --load[h];
    }
    holder[o] = CompositeTaskGraph::kResting;
  };
  recurse(recurse, 0);

  // isCompositeTransition on every ordered pair, with each element's held object per robot
  // computed once (elements are distinct, so a != b means the allocations differ)
  const int count = static_cast<int>(graph.elements.size());
  const auto n = static_cast<std::size_t>(robots);
  std::vector<int> held(graph.elements.size() * n, -1);
  for (std::size_t e = 0; e < graph.elements.size(); ++e) {
    for (std::size_t o = 0; o < graph.elements[e].size(); ++o) {
      if (graph.elements[e][o] >= 0) held[e * n + graph.elements[e][o]] = static_cast<int>(o);
    }
  }
  for (int a = 0; a < count; ++a) {
    const int* before = held.data() + a * n;
    for (int b = 0; b < count; ++b) {
      if (a == b) continue;
      const int* after = held.data() + b * n;
      bool single_action_per_robot = true;
      for (std::size_t r = 0; r < n && single_action_per_robot; ++r) {
        single_action_per_robot = before[r] < 0 || after[r] < 0 || before[r] == after[r];
      }
      if (single_action_per_robot) graph.transitions.emplace_back(a, b);
    }
  }
  return graph;
}

}  // namespace dashbed::planner
