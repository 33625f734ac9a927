#pragma once
// A sampled transition hyperarc of the motion hypergraph (paper: Method > Motion Hypergraph >
// Transition Hyperarc Planning): each robot's timed keys through a pick, place or handoff,
// and the grasps before and after it. The transition sampler makes them; the key curve, the
// search and conflict resolution read them.

#include <optional>
#include <utility>
#include <vector>

#include "core/plan.h"
#include "core/pose.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/object_sites.h"
#include "planner/sampling/timing.h"
#include "planner/task_space/task_space_hypergraph.h"

namespace dashbed::planner {

/// How a robot holds an object: the TCP in the object's frame, and the finger position when
/// closed on it (half the object's width along the closing axis, TCP x) [m].
struct Grasp {
  core::Pose X_OT = core::Pose::Identity();
  double finger = 0.0;
};

/// True when two grasps are the same to 1e-9 (rotation and translation).
bool sameGrasp(const Grasp& a, const Grasp& b);

/// One robot's part of a transition: timed keys, which the simulator passes on a
/// shape-preserving cubic (keyCurve, key_curve.h), each joint monotone between two keys.
struct TransitionMotion {
  struct Key {
    Millis t = 0;           ///< from the transition's start
    core::ArmConfig q{};
  };
  int robot = -1;
  std::vector<Key> keys;  ///< keys.front().t == 0; strictly increasing t
  /// Per piece i (keys[i] -> keys[i+1]): finger position [m] and held object during the piece.
  std::vector<double> finger;
  std::vector<std::optional<HeldObject>> held;
  /// Gripper commands, times from the transition's start.
  std::vector<std::pair<Millis, core::GripperAction>> grips;

  const core::ArmConfig& start() const { return keys.front().q; }
  const core::ArmConfig& end() const { return keys.back().q; }
};

/// A sampled transition hyperarc of the motion hypergraph.
struct TransitionSample {
  int hyperarc = -1;  ///< the task-space hyperarc it samples
  TransitionKind kind = TransitionKind::kPick;
  int object = -1;
  /// pick / place: one motion (the robot); handoff: the giver's, then the receiver's.
  std::vector<TransitionMotion> motions;
  Millis duration = 0;  ///< every motion ends by then; a robot holds its last key until then
  /// The grasp the transition needs the (giving / placing) robot to hold the object in;
  /// std::nullopt for a pick.
  std::optional<Grasp> grasp_before;
  /// The grasp the (picking / receiving) robot holds the object in afterwards; std::nullopt
  /// for a place.
  std::optional<Grasp> grasp_after;
  core::Pose X_WO = core::Pose::Identity();  ///< object pose: at rest (pick, place) or in the air (handoff)
  SiteSet touches;  ///< sites of *other* objects that some piece of some motion would touch
  /// The window of the plan action (core::PlanAction start/end), from the transition's start.
  Millis action_start = 0;
  Millis action_end = 0;

  /// The robot holding the object once the transition is done (the picking or receiving
  /// robot), or -1 after a place.
  int holderAfter() const { return kind == TransitionKind::kPlace ? -1 : motions.back().robot; }
};

}  // namespace dashbed::planner
