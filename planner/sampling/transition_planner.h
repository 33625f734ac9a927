#pragma once
// The transition planner P_trans of Alg. 3 (paper: Method > Motion Hypergraph > Transition
// Hyperarc Planning): what the motion hypergraph asks for samples of the task-space hypergraph's
// pick, place and handoff hyperarcs. TransitionSampler is the geometric one the planner uses;
// tests hand the hypergraph samples of their own making to pose search problems with known
// answers.

#include <random>
#include <vector>

#include "planner/sampling/transition.h"

namespace dashbed::planner {

class TransitionPlanner {
 public:
  virtual ~TransitionPlanner() = default;

  /// Samples of pick hyperarc `hyperarc`. The same every call (the hypergraph asks once, and
  /// infeasibility checks rely on no later call adding one).
  virtual std::vector<TransitionSample> pick(int hyperarc) = 0;
  /// Samples of place hyperarc `hyperarc` for a robot holding the object in `held`. The same
  /// every call, as for pick().
  virtual std::vector<TransitionSample> place(int hyperarc, const Grasp& held) = 0;
  /// Up to `count` new samples of handoff hyperarc `hyperarc` for a giver holding the object in
  /// `giver_grasp`, drawn from `rng` (asked once per round of construction).
  virtual std::vector<TransitionSample> handoff(int hyperarc, const Grasp& giver_grasp, std::mt19937_64& rng,
                                                int count) = 0;
  /// Every grasp a receiver may take `object` in from a giver holding it in `giver`: each of
  /// handoff()'s samples' receiver grasps is one of them. The same every call.
  virtual std::vector<Grasp> handoffGrasps(int object, const Grasp& giver) const = 0;
};

}  // namespace dashbed::planner
