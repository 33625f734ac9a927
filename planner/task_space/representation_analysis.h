#pragma once
// Representation Analysis (paper, Sec. "Representation Analysis" and Fig. 2(b)): the size of
// the task space of multi-manipulator rearrangement with pick, place and handoff actions, as a
// composite graph of admissible elements and as the decoupled task-space hypergraph.
//
// Assumptions of the analysis (paper): every robot reaches every object and every other robot
// (an upper bound; reachability only removes transitions), each robot holds at most one object,
// each object is held by at most one robot, and grasps and poses are ignored: an element is
// an allocation of objects to robots.
//
// Composite graph. A vertex is an admissible element: every object rests or is held by a
// distinct robot. A directed transition changes the allocation by a non-empty set of
// simultaneous independent actions, each robot and each object taking part in at most one
// action: place (holder -> resting), handoff (holder -> a robot empty-handed before the
// transition; both robots take part) and pick (resting -> a robot empty-handed before the
// transition). Both directions are counted (Fig. 2(a): 120 directed = 60 bi-directional edges
// for 2 robots / 4 objects).
//
// Hypergraph. Vertices: each robot alone, each object resting, each robot holding each object.
// Hyperarcs: one pick and one place per (robot, object), one handoff per (object, ordered pair
// of distinct robots).

#include <cstdint>
#include <utility>
#include <vector>

namespace dashbed::planner {

/// Size of a task-space representation: vertices and directed transitions (edges or
/// hyperarcs).
struct RepresentationSize {
  std::uint64_t vertices = 0;
  std::uint64_t transitions = 0;
  bool operator==(const RepresentationSize&) const = default;
};

/// Number of admissible composite elements, paper Eq. (TotalStates):
///   S(m, n) = sum_{p=0}^{min(m,n)} C(m,p) C(n,p) p!   (choose p held objects, p holders, match them).
/// Throws std::invalid_argument for negative counts, std::overflow_error when the count does not
/// fit in 64 bits.
std::uint64_t compositeGraphVertices(int robots, int objects);

/// Directed transitions leaving one composite element in which `held` objects are held
/// (the paper's L(m, n, p), with the "no action" case subtracted once):
///   sum_{l=0}^{p} C(p,l) sum_{h=0}^{min(p-l, n-p)} C(p-l,h) C(n-p,h) h!
///                        sum_{g=0}^{min(m-p, n-p-h)} C(m-p,g) C(n-p-h,g) g!   - 1
/// with l places, h handoffs (to empty-handed robots) and g picks (by empty-handed robots not
/// receiving a handoff). Note: the printed Eq. (CountPickPlaceHandoff) puts the "-1" inside
/// G(m,n,p,h), i.e. once per (l, h); read literally that gives 68 transitions instead of 120
/// for 2 robots / 4 objects. Only the single "-1" per element reproduces Fig. 2(b), and it is
/// what the brute-force enumeration counts. Throws like compositeGraphVertices, and
/// std::invalid_argument unless 0 <= held <= min(robots, objects).
std::uint64_t compositeTransitionsFrom(int robots, int objects, int held);

/// Directed transitions of the composite graph, paper Eq. (TotalEdges):
///   T(m, n) = sum_p C(m,p) C(n,p) p! L(m, n, p).
std::uint64_t compositeGraphTransitions(int robots, int objects);

/// {compositeGraphVertices, compositeGraphTransitions}.
RepresentationSize compositeGraphSize(int robots, int objects);

/// Decoupled task-space hypergraph, paper Sec. "Hypergraph Representation":
/// vertices mn + m + n (robot holding object, object resting, robot alone);
/// hyperarcs 2mn (pick and place per robot-object pair) + mn(n-1) (handoff per object and
/// ordered robot pair) = mn^2 + mn. Throws like compositeGraphVertices.
RepresentationSize hypergraphSize(int robots, int objects);

/// The composite graph built explicitly by brute force, for checking the closed forms.
struct CompositeTaskGraph {
  /// Object not held by any robot (resting on a stable surface).
  static constexpr int kResting = -1;

  int robots = 0;
  int objects = 0;
  /// Admissible elements: holder[o] is the robot holding object o, or kResting; no robot holds
  /// two objects. Ordered lexicographically by holder (kResting first).
  std::vector<std::vector<int>> elements;
  /// Directed transitions (from, to) between indices of `elements`, sorted.
  std::vector<std::pair<int, int>> transitions;

  RepresentationSize size() const { return {elements.size(), transitions.size()}; }
};

/// True when the composite element `to` follows from `from` by one non-empty set of
/// simultaneous independent pick, place and handoff actions: the allocations differ and no
/// robot holds an object in both but different ones (a robot that places or hands off cannot
/// also pick or receive, and a receiver or picker must be empty-handed before).
bool isCompositeTransition(const std::vector<int>& from, const std::vector<int>& to);

/// Enumerates every allocation and tests every ordered pair of elements with
/// isCompositeTransition: O(S^2 (m + n)). Throws std::invalid_argument for negative counts or
/// when the graph would have more than `max_elements` elements.
CompositeTaskGraph enumerateCompositeTaskGraph(int robots, int objects, std::size_t max_elements = 20000);

}  // namespace dashbed::planner
