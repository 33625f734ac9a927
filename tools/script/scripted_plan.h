#pragma once
// Scripted plans: a short action script -> a timed core::Plan, without the planner's search.
//
// The tool exists so that the simulator can be validated independently of the planner's
// search. Each statement becomes IK waypoints joined by straight joint-space segments;
// approaches, lifts and retreats are straight Cartesian lines sampled every centimetre. A
// handoff is one of the planner's handoff samples, checked as the planner checks it; other
// collisions between robots and with the scenery are NOT checked (the simulator's monitor
// reports them).
//
// Script language (statements separated by ';' or newlines, '#' starts a comment):
//   r0 picks cube_1                      top grasp (the default; also "from above")
//   r0 picks cube_1 from the side        side grasp, horizontal approach
//   r0 places cube_1 in bin_red          on the region floor (+ a small drop height)
//   r0 places cube_1 at X Y Z            object centre at (X, Y, Z) in W [m]
//   r0 hands cube_1 to r1                handoff in the air, with the planner's handoff sampler
//   r0 waits 0.5                         [s]
//   r0 moves home | r0 moves to Q1 .. Q6 joint move (the latter: [rad], no checks but limits)
//   r0 opens | r0 closes                 a bare gripper command (then a dwell)
//   r0 stays                             r0 does not return home at the end of the script
// A pick or place may end with "offset DX DY DZ": the TCP is displaced by that vector [m],
// expressed in the object frame (to script bad grasps on purpose).
//
// Timing: each robot has its own timeline; its statements run in order, other robots' in
// parallel. A handoff starts when both robots are free; an object released by one robot can
// be picked by another once the release is complete. Every robot ends at home unless it
// `stays`.

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/plan.h"
#include "core/world_loader.h"
#include "tools/script/script_parser.h"

namespace dashbed::tools {

/// Motion and timing parameters of scripted plans. The defaults: half the UR5e joint speed,
/// slow straight approaches, Hand-E dwell times.
struct ScriptSettings {
  double speed_fraction = 0.5;       ///< peak joint speed as a fraction of each joint's limit
  double peak_factor = 1.5;          ///< peak / average speed of a cubic segment resting at both ends
  double min_segment_time = 0.3;     ///< shortest joint-space move [s]
  double max_acceleration = 4.0;     ///< joint acceleration cap [rad/s^2] (at most the world's safety limit)
  double cartesian_distance = 0.10;  ///< length of approaches, lifts and retreats [m]
  double cartesian_speed = 0.10;     ///< average TCP speed along them [m/s]
  double cartesian_step = 0.01;      ///< spacing of their IK waypoints [m]
  double gripper_dwell = 0.6;        ///< wait after each gripper command [s]
  double safe_height = 0.20;         ///< height of transit via points above the support [m]
  double drop_height = 0.002;        ///< release height of a placed object above its support [m]
  double max_step_jump = 0.3;        ///< largest joint change between Cartesian waypoints [rad]
  double singularity_margin = 0.05;  ///< smallest |sin| of elbow and wrist 2 accepted
};

/// Turns `script` into a timed plan for `world`. Trajectories have one point per waypoint;
/// joint-space moves go from rest to rest, each straight line is one run from rest to rest
/// (core/key_timing.h: paced for peak_factor x the average speed, eased within
/// max_acceleration), and the points where the arm rests carry zero velocities. Times are
/// whole milliseconds. The result passes core::validatePlan and is deterministic.
/// Throws ScriptError ("NAME:LINE:COLUMN: ...") for syntax errors, unknown robots, objects,
/// regions or verbs, placing or handing an object the robot does not hold, picking with a
/// full gripper, unreachable poses (naming the robot and the pose) and handoffs for which
/// the planner's handoff sampler (planner/sampling/transition_sampler.h, fixed seed) finds no
/// sample.
core::Plan planFromScript(const core::LoadedWorld& world, std::string_view script,
                          const std::string& script_name = "script", const ScriptSettings& settings = {});

}  // namespace dashbed::tools
