#pragma once
// A transition history (paper: Method > Transition-extended Hypergraph): the transitions and
// moves taken from the virtual source, with the time each is expected to occur and the last
// known configuration of every moveable body. A history is valid when each body takes at most
// one outgoing hyperarc at a time, which holds by construction here: a transition is appended
// only when every robot and object of its tail is at the matching motion vertex.
//
// The times are an optimistic schedule: every move and transition starts as soon as the
// bodies of its tail are there (the tail weight is the latest of them, "waiting for the
// slowest"); robots may still collide with each other, which conflict resolution resolves.

#include <optional>
#include <vector>

#include "planner/motion/motion_hypergraph.h"

namespace dashbed::planner {

/// Where an object is: at its start, held, at its goal, or set aside (at its set-aside site, to
/// be picked up again).
enum class ObjectPlace { kStart, kHeld, kGoal, kAside };

/// One transition hyperarc of a history and the move hyperarcs leading each of its robots to
/// the transition's start.
struct ScheduledTransition {
  int transition = -1;  ///< MotionTransition id
  /// Per motion of the sample (same order): the moves bringing its robot to the start, in
  /// order; two when the robot parks at home on the way (QueryMode::kParkAtHome).
  std::vector<std::vector<const Move*>> moves;
  Millis start = 0;  ///< when the transition starts (every robot in place)
};

struct TransitionHistory {
  struct RobotState {
    core::ArmConfig q{};
    Millis free = 0;  ///< the robot is done with its last hyperarc
    int object = -1;  ///< held object, or -1
    int grasp = -1;
  };
  struct ObjectState {
    ObjectPlace place = ObjectPlace::kStart;
    int holder = -1;
    Millis since = 0;  ///< the object reached its current place
    bool set_aside = false;  ///< it has been set aside (once at most)
  };

  std::vector<RobotState> robots;
  std::vector<ObjectState> objects;
  std::vector<Millis> site_busy;  ///< [site] the last scheduled motion through the site ends
  std::vector<ScheduledTransition> steps;
  /// The steps run one after another, never two at a time (QueryMode::kSequential): a step's
  /// moves start once the step before has ended, and conflict resolution keeps that order
  /// unless asked to let them overlap (SequentialSteps::kOverlapping).
  bool sequential = false;
  /// In a sequential history: where the robots of other steps wait.
  IdlePose idle = IdlePose::kHome;
  /// With idle robots folded: each robot's move from home to its folded configuration, all at
  /// the start, before the first step; and back home from there once the last step and every
  /// final move have ended (nullptr: none, the robot cannot fold). Empty otherwise.
  std::vector<const Move*> fold_moves, unfold_moves;
  /// Final move of each robot to where it rests at the end (nullptr: already there), and when it
  /// starts; set when complete. Home, or with idle robots folded, the folded configuration.
  std::vector<const Move*> final_moves;
  std::vector<Millis> final_starts;

  /// The virtual source: robots alone at home, objects at their starts.
  static TransitionHistory source(const MotionHypergraph& graph);

  /// Sites occupied now: objects at their start, goal or set-aside site.
  SiteSet occupied(int sites) const;
  /// The goal sites of the objects placed so far (they stay there).
  SiteSet filledGoals(int sites) const;
  /// Every object with a goal is at it.
  bool complete(const ObjectSites& sites) const;
  /// How many objects are at their goals.
  int objectsAtGoal() const;
  /// Latest time any robot is busy (including the final moves and the unfolding once set).
  Millis makespan() const;
};

}  // namespace dashbed::planner
