#pragma once
// The transition planners of the motion hypergraph (paper: Method > Motion Hypergraph; Alg. 3's
// transition planner P_trans): IK-based samples of the pick, place and handoff transition
// hyperarcs of the task-space hypergraph, each carrying the timed motion of every robot involved.
//
//  pick    the robot starts at a pre-grasp configuration (cartesian_distance back along the
//          grasp's approach axis), approaches in a straight TCP line, closes, dwells, lifts
//          straight up. Grasps: core::boxGrasps of the object as it rests (from above and,
//          where the gripper body clears the surface, from the side; from above, an object
//          that goes into a bin is held high enough for a tall one's top to stay out of the
//          housing, any other at its centre); on an object at least
//          two fingertips long across the closing axis also shifted to either end, so that two
//          grippers fit side by side in a later handoff. A side grasp is instead approached
//          straight down from above, the open fingers passing on either side of the item, where
//          that touches fewer other objects' sites than coming in sideways (items standing close
//          together, whose neighbours a sideways approach sweeps over at their height) or where
//          coming in sideways has no sample.
//  place   the robot starts holding the object back along its approach axis from the goal
//          placement (cartesian_distance above it for a vertical approach; slide_distance in
//          front of it for a horizontal one, shelves, or nearer where that has no sample, down
//          to just out of the shelf), moves in, opens, dwells, retreats the same way. The object
//          may rest on any face whose footprint fits the region, turned by multiples of 90
//          degrees from the region's yaw, at the goal site's position (ObjectSites), as long
//          as it fills exactly the site's box (the volume the search schedules).
//  handoff the giver holds the object still at a handoff pose in the overlap of both
//          workspaces; the receiver starts at a pre-grasp configuration, approaches, closes;
//          both hold for a dwell (the overlap), the giver opens, dwells and retreats along its
//          approach axis, then the receiver retreats. The receiver's grasp closes on a
//          different face pair than the giver's, so the grippers do not collide, or on the
//          same pair apart along the object (a long object held side by side, or a tall item
//          going into a bin held end to end, the receiver at the item's bottom).
//
// Every sample is checked with the collision checker along the curve the simulator follows
// through its keys (key_curve.h): each piece between two keys is free against the static scene
// and the robot itself (held object included; the object being grasped or released counts as
// held but not against the static scene while it touches its support); for handoffs, each
// robot's pieces against the other robot, which holds still while it moves. Collisions with other objects resting at their start or goal
// sites do not reject a sample: they are recorded in `touches`, and the search schedules the
// transition while those sites are empty.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "core/plan.h"
#include "core/reach.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/object_sites.h"
#include "planner/sampling/roadmap.h"
#include "planner/task_space/task_space_hypergraph.h"
#include "planner/sampling/timing.h"
#include "planner/sampling/transition.h"
#include "planner/sampling/transition_planner.h"

namespace dashbed::planner {

struct TransitionSettings {
  /// Length of the straight approach, lift and retreat lines [m]; longer clears neighbours
  /// better but lengthens transitions and loses IK samples.
  double cartesian_distance = 0.10;
  /// Average TCP speed along those lines [m/s]; faster shortens transitions, harder contacts.
  double cartesian_speed = 0.10;
  /// Spacing of the IK keys along those lines [m]; finer tracks the line closer, more keys.
  double cartesian_step = 0.01;
  /// Joint speed cap along those lines, fraction of the velocity limit (see peak_factor).
  double speed_fraction = 0.5;
  /// Joint acceleration cap along those lines [rad/s^2]: each line eases in and out within it;
  /// higher shortens transitions, at larger torques.
  double max_acceleration = 4.0;
  /// Wait after each gripper command [s] (also the cost-to-go of an unsampled hyperarc);
  /// shorter saves time, risks an unsettled grasp.
  double gripper_dwell = 0.6;
  /// Release height above the support after a vertical descent [m].
  double drop_height = 0.002;
  /// Height above the support a held object slides in and is released at [m]; at or below
  /// CollisionSettings::margin it counts as touching the support and is not checked against it.
  double slide_height = 0.005;
  /// Length of a horizontal approach into a shelf slot [m], shortened in 2 cm steps where it has
  /// no sample; long enough to start outside the compartment, where roadmap moves reach.
  double slide_distance = 0.25;
  /// Key pieces are timed for a joint peak of peak_factor x their average within speed_fraction;
  /// the key curve peaks at <= 3x, so joints stay within speed_fraction x 3 / peak_factor.
  double peak_factor = 1.5;
  /// Largest joint change between two keys of a line [rad] (rejects IK branch flips).
  double max_step_jump = 0.3;
  /// Smallest |sin| of the elbow and wrist 2 angles accepted in a key; larger rejects more samples.
  double singularity_margin = 0.05;
  /// Box the handoff poses are drawn in (core::handoffZone); the task-space hypergraph's handoff
  /// test uses the default shape whatever this says.
  core::HandoffShape handoff;

  /// Throws std::invalid_argument naming the field when a value is out of range.
  void validate() const;
};

class TransitionSampler final : public TransitionPlanner {
 public:
  /// All references must outlive the sampler.
  TransitionSampler(const core::LoadedWorld& world, const TaskSpaceHypergraph& task_space,
                    const CollisionScene& scene, const ObjectSites& sites, const TransitionSettings& settings = {});

  /// Pick samples of pick hyperarc `hyperarc` (object at its start, or set-aside, site): one per grasp that
  /// passes the checks, IK solution nearest the robot's home configuration (a side grasp from
  /// above where that touches fewer sites). Deterministic.
  std::vector<TransitionSample> pick(int hyperarc) override;

  /// Place samples of place hyperarc `hyperarc` (object into its goal site) for a robot holding
  /// the object in `held`: one per fitting resting orientation that passes; into its set-aside
  /// site, in the orientation it started in. Deterministic.
  std::vector<TransitionSample> place(int hyperarc, const Grasp& held) override;

  /// Up to `count` handoff samples of handoff hyperarc `hyperarc` for a giver holding the
  /// object in `giver_grasp`: handoff poses drawn from `rng` (object centre in the two robots'
  /// handoff zone, core::handoffZone with the `handoff` shape; orientation such that the
  /// giver's IK exists), receiver grasps enumerated. Makes at most 20 count draws, none when
  /// the robots have no handoff zone.
  std::vector<TransitionSample> handoff(int hyperarc, const Grasp& giver_grasp, std::mt19937_64& rng, int count) override;

  /// The grasps a receiver may take of `object` from a giver holding it in `giver`: every
  /// handoff sample's receiver grasp is one of them. Deterministic, fixed order.
  std::vector<Grasp> handoffGrasps(int object, const Grasp& giver) const override;

  const TransitionSettings& settings() const { return settings_; }

 private:
  const core::LoadedWorld* world_;
  const TaskSpaceHypergraph* task_space_;
  const CollisionScene* scene_;
  const ObjectSites* sites_;
  TransitionSettings settings_;
  std::unique_ptr<CollisionChecker> checker_;  // the one checker of every sample's checks
  std::map<std::pair<int, int>, std::optional<core::HandoffZone>> zones_;  // robot pairs, lower index first

  /// The handoff zone of robots a and b (either order), computed once.
  const std::optional<core::HandoffZone>& handoffZone(int a, int b);
};

}  // namespace dashbed::planner
