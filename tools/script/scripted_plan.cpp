#include "tools/script/scripted_plan.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

#include "core/geometry.h"
#include "core/grasps.h"
#include "core/key_timing.h"
#include "core/kinematics.h"
#include "core/reach.h"
#include "planner/collision/collision_checker.h"
#include "planner/sampling/object_sites.h"
#include "planner/sampling/transition_sampler.h"
#include "planner/task_space/task_space_hypergraph.h"
#include "tools/script/script_parser.h"

namespace dashbed::tools {
namespace {

using core::ArmConfig;
using core::GripperAction;
using core::Pose;
using Millis = std::int64_t;  // plan time in whole milliseconds (exact sums, short JSON numbers)

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();

/// Rounds a duration up to whole milliseconds (ignoring floating-point noise below 1e-9 ms).
Millis ceilMillis(double seconds) { return static_cast<Millis>(std::ceil(seconds * 1000.0 - 1e-9)); }
double toSeconds(Millis t) { return static_cast<double>(t) / 1000.0; }

std::string fixed(double value, int digits = 3) {
  std::ostringstream out;
  const bool rounds_to_zero = std::abs(value) < 0.5 * std::pow(10.0, -digits);
  out << std::fixed << std::setprecision(digits) << (rounds_to_zero ? 0.0 : value);  // no "-0.000"
  return out.str();
}

std::string vec(const Eigen::Vector3d& v, int digits = 3) {
  std::string text = "(";  // appended, not `"(" + ...`, which trips GCC 12's -Wrestrict
  text += fixed(v.x(), digits) + ", " + fixed(v.y(), digits) + ", " + fixed(v.z(), digits) + ")";
  return text;
}

std::string describeTcp(const Pose& X_WT) {
  return "TCP at " + vec(X_WT.translation()) + " m approaching along " + vec(X_WT.linear().col(2), 2);
}

double maxAbsDifference(const ArmConfig& a, const ArmConfig& b) {
  double m = 0.0;
  for (int j = 0; j < 6; ++j) m = std::max(m, std::abs(a[j] - b[j]));
  return m;
}

Pose shifted(Pose X, const Eigen::Vector3d& delta) {
  X.translation() += delta;
  return X;
}

// ---- parsing -------------------------------------------------------------------------------


// ---- robot models and motion chains ---------------------------------------------------------

/// What the planner needs of one robot.
struct RobotContext {
  const core::PlacedRobot* placed = nullptr;
  std::array<std::string, 6> joint_names;
  std::array<double, 6> max_velocity{};  // [rad/s]
  core::KeyTimingLimits limits;          // of runs of keys: the joint speed limits, the acceleration cap
  std::vector<int> gripper_links;        // links below tool0 (coupling, housing, fingers)
};

RobotContext makeContext(const core::PlacedRobot& placed, double max_acceleration) {
  RobotContext context;
  context.placed = &placed;
  const core::RobotModel& model = *placed.model;
  for (int j = 0; j < 6; ++j) {
    const core::JointModel& joint = model.joints()[model.movableJoints()[j]];
    context.joint_names[j] = joint.name;
    context.max_velocity[j] = joint.max_velocity;
  }
  context.limits.max_velocity = context.max_velocity;
  context.limits.max_acceleration.fill(max_acceleration);
  const int tool0 = model.requireLink("tool0");
  for (int link = 0; link < static_cast<int>(model.links().size()); ++link) {
    for (int up = link; up >= 0;) {
      if (up == tool0) {
        context.gripper_links.push_back(link);
        break;
      }
      const int joint = model.links()[up].parent_joint;
      up = joint < 0 ? -1 : model.joints()[joint].parent_link;
    }
  }
  return context;
}

/// A sequence of motions, gripper commands and dwells of one robot, built before it is placed
/// on the robot's timeline (so that alternatives can be compared). Times are relative to
/// the start of the chain. The first failure is kept in `error` and makes later calls no-ops.
class Chain {
 public:
  struct Move {
    Millis start;
    Millis duration;
    ArmConfig q;
    bool rests;  ///< the arm comes to rest at q (the end of a run)
  };
  struct Grip {
    Millis t;
    GripperAction action;
  };

  Chain(const RobotContext& robot, const ScriptSettings& settings, const ArmConfig& q)
      : robot_(&robot), settings_(&settings), q_(q), X_WT_(robot.placed->tcpPoseInWorld(q)) {}

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  Millis elapsed() const { return elapsed_; }
  const ArmConfig& q() const { return q_; }
  const Pose& tcp() const { return X_WT_; }
  const std::vector<Move>& moves() const { return moves_; }
  const std::vector<Grip>& grips() const { return grips_; }
  /// Configurations reached by the moves, in order (for geometric checks).
  std::vector<ArmConfig> waypoints() const {
    std::vector<ArmConfig> qs;
    for (const Move& m : moves_) qs.push_back(m.q);
    return qs;
  }

  /// Joint-space move to the IK solution of X_WT nearest the current configuration that is
  /// clear of elbow and wrist singularities.
  void jointTo(const Pose& X_WT, const std::string& what) {
    if (!ok()) return;
    for (const ArmConfig& q : robot_->placed->solveInWorld(X_WT, q_)) {
      if (!regular(q)) continue;
      jointToConfig(q);
      X_WT_ = X_WT;
      return;
    }
    error_ = "no IK solution clear of singularities for the " + what + ", " + describeTcp(X_WT);
  }

  /// Joint-space move to q from rest to rest (nothing when already there).
  void jointToConfig(const ArmConfig& q) {
    if (!ok() || q == q_) return;
    double seconds = settings_->min_segment_time;
    for (int j = 0; j < 6; ++j) {
      seconds = std::max(seconds, std::abs(q[j] - q_[j]) * settings_->peak_factor /
                                      (settings_->speed_fraction * robot_->max_velocity[j]));
    }
    endRun();
    push(q, seconds);
    endRun();
    X_WT_ = robot_->placed->tcpPoseInWorld(q);
  }

  /// Straight TCP line by delta_W [m] at constant orientation: IK waypoints every
  /// cartesian_step, each the solution nearest the previous one.
  void straight(const Eigen::Vector3d& delta_W, const std::string& what) {
    if (!ok()) return;
    const double length = delta_W.norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(length / settings_->cartesian_step - 1e-9)));
    const Pose X_start = X_WT_;
    for (int k = 1; k <= steps; ++k) {
      const Pose X_WT = shifted(X_start, delta_W * (static_cast<double>(k) / steps));
      const std::vector<ArmConfig> solutions = robot_->placed->solveInWorld(X_WT, q_);
      if (solutions.empty()) {
        error_ = "the " + what + " leaves the workspace: no IK solution for the " + describeTcp(X_WT);
        return;
      }
      const ArmConfig& q = solutions.front();
      if (!regular(q)) {
        error_ = "the " + what + " passes near an elbow or wrist singularity at the " + describeTcp(X_WT);
        return;
      }
      const double jump = maxAbsDifference(q, q_);
      if (jump > settings_->max_step_jump) {
        error_ = "the " + what + " would make the arm jump " + fixed(jump, 2) + " rad between waypoints (joint limit or " +
                 "branch change) at the " + describeTcp(X_WT);
        return;
      }
      double seconds = length / steps / settings_->cartesian_speed;
      for (int j = 0; j < 6; ++j) {
        seconds = std::max(seconds, std::abs(q[j] - q_[j]) * settings_->peak_factor /
                                        (settings_->speed_fraction * robot_->max_velocity[j]));
      }
      push(q, seconds);
      X_WT_ = X_WT;
    }
  }

  void grip(GripperAction action) {
    if (!ok()) return;
    endRun();
    grips_.push_back({elapsed_, action});
  }
  void dwell(Millis duration) {
    if (!ok()) return;
    endRun();
    elapsed_ += duration;
    run_start_ = elapsed_;
  }

 private:
  bool regular(const ArmConfig& q) const {
    return std::abs(std::sin(q[2])) >= settings_->singularity_margin &&
           std::abs(std::sin(q[4])) >= settings_->singularity_margin;
  }
  /// Appends a key at pace `seconds` to the current run, which ends at rest there, and retimes
  /// the run (core/key_timing.h).
  void push(const ArmConfig& q, double seconds) {
    if (run_pace_.empty()) run_from_ = q_;
    run_pace_.push_back(seconds);
    moves_.push_back({elapsed_, 0, q, true});
    if (run_pace_.size() > 1) moves_[moves_.size() - 2].rests = false;
    q_ = q;
    std::vector<ArmConfig> keys{run_from_};
    const std::size_t first = moves_.size() - run_pace_.size();
    for (std::size_t k = first; k < moves_.size(); ++k) keys.push_back(moves_[k].q);
    const std::vector<Millis> times = core::restToRestKeyTimes(keys, run_pace_, robot_->limits);
    for (std::size_t k = first; k < moves_.size(); ++k) {
      moves_[k].start = run_start_ + times[k - first];
      moves_[k].duration = times[k - first + 1] - times[k - first];
    }
    elapsed_ = run_start_ + times.back();
  }
  /// The arm rests here: the next key starts a new run.
  void endRun() {
    run_pace_.clear();
    run_start_ = elapsed_;
  }

  const RobotContext* robot_;
  const ScriptSettings* settings_;
  ArmConfig q_;
  Pose X_WT_;
  Millis elapsed_ = 0;
  Millis run_start_ = 0;          // when the current run left rest
  ArmConfig run_from_{};          // where it left rest
  std::vector<double> run_pace_;  // its pieces at pace [s]
  std::vector<Move> moves_;
  std::vector<Grip> grips_;
  std::string error_;
};

// ---- object geometry -------------------------------------------------------------------------

/// The object frame re-labelled so that its z axis is the object axis nearest the world
/// vertical (a right-handed permutation of the object axes): X_OU and the box size in U.
struct UprightFrame {
  Eigen::Matrix3d R_OU;
  Eigen::Vector3d size_U;
  double tilt;  // angle between U's z and the world vertical [rad]
};

UprightFrame uprightFrame(const Eigen::Matrix3d& R_WO, const Eigen::Vector3d& size) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(R_WO(2, i)) > std::abs(R_WO(2, k))) k = i;
  }
  const int a = (k + 1) % 3, b = (k + 2) % 3;
  const bool up = R_WO(2, k) > 0.0;
  UprightFrame frame;
  frame.R_OU.setZero();
  frame.R_OU(k, 2) = up ? 1.0 : -1.0;
  frame.R_OU(up ? a : b, 0) = 1.0;  // (a, b, k) and (b, a, -k) are right-handed
  frame.R_OU(up ? b : a, 1) = 1.0;
  frame.size_U = Eigen::Vector3d(size[up ? a : b], size[up ? b : a], size[k]);
  frame.tilt = std::acos(std::min(1.0, std::abs(R_WO(2, k))));
  return frame;
}

Eigen::Matrix3d yawRotation(double yaw) { return Eigen::AngleAxisd(yaw, kUp).toRotationMatrix(); }

// ---- the planner -----------------------------------------------------------------------------

struct Timeline {
  struct Point {
    Millis t;
    ArmConfig q;
    bool rests;  // written with zero velocity
  };
  std::vector<Point> points;
  Millis t = 0;        // the robot is free from here on
  ArmConfig q{};       // where it is then
  int held = -1;       // object index
  Pose X_OT = Pose::Identity();  // TCP in the held object's frame
  std::optional<GripperAction> last_command;
  bool stays = false;
};

struct ObjectState {
  Pose X_WO = Pose::Identity();
  int holder = -1;
  bool lost = false;     // released in the air by a bare "opens": pose unknown
  Millis available = 0;  // another robot may approach it from here on
};

class ScriptPlanner {
 public:
  ScriptPlanner(const core::LoadedWorld& loaded, const ScriptSettings& settings, const ScriptParser& parser)
      : loaded_(loaded), world_(*loaded.world), settings_(settings), parser_(parser) {
    for (const core::PlacedRobot& placed : loaded.robots->robots()) {
      robots_.push_back(makeContext(placed, std::min(settings.max_acceleration, world_.safety.max_joint_acceleration)));
      Timeline timeline;
      timeline.q = placed.spec->home;
      timeline.points.push_back({0, timeline.q, true});
      timelines_.push_back(std::move(timeline));
    }
    for (const core::ObjectSpec& object : world_.objects) {
      ObjectState state;
      state.X_WO = object.X_WO;
      objects_.push_back(state);
    }
  }

  void run(const Statement& s) {
    Timeline& timeline = timelines_[s.robot];
    switch (s.verb) {
      case Verb::kPick:
        pick(s);
        break;
      case Verb::kPlace:
        place(s);
        break;
      case Verb::kHand:
        handoff(s);
        break;
      case Verb::kWait:
        timeline.t += static_cast<Millis>(std::llround(s.seconds * 1000.0));
        break;
      case Verb::kMoveHome:
        moveTo(s, world_.robots[s.robot].home);
        break;
      case Verb::kMoveTo:
        moveTo(s, s.q);
        break;
      case Verb::kOpen:
        command(s.robot, timeline.t, GripperAction::kOpen);
        if (timeline.held >= 0) {  // dropped where it is: nobody knows where it lands
          objects_[timeline.held].holder = -1;
          objects_[timeline.held].lost = true;
          timeline.held = -1;
        }
        timeline.t += ceilMillis(settings_.gripper_dwell);
        break;
      case Verb::kClose:
        command(s.robot, timeline.t, GripperAction::kClose);
        timeline.t += ceilMillis(settings_.gripper_dwell);
        break;
      case Verb::kStay:
        timeline.stays = true;
        break;
    }
  }

  core::Plan finish(const std::string& script_name, std::size_t statements) {
    for (std::size_t r = 0; r < robots_.size(); ++r) {
      Timeline& timeline = timelines_[r];
      if (timeline.stays) continue;
      Chain chain(robots_[r], settings_, timeline.q);
      chain.jointToConfig(world_.robots[r].home);
      commit(static_cast<int>(r), chain, timeline.t);
    }
    core::Plan plan;
    plan.world = world_.name;
    plan.seed = 0;
    for (std::size_t r = 0; r < robots_.size(); ++r) {
      core::RobotTrajectory trajectory;
      trajectory.robot = world_.robots[r].name;
      trajectory.joint_names = robots_[r].joint_names;
      for (const Timeline::Point& p : timelines_[r].points) {
        trajectory.points.push_back({toSeconds(p.t), p.q, p.rests ? std::optional<ArmConfig>(ArmConfig{}) : std::nullopt});
      }
      plan.trajectories.push_back(std::move(trajectory));
    }
    std::stable_sort(gripper_.begin(), gripper_.end(),
                     [](const core::GripperCommand& a, const core::GripperCommand& b) { return a.t < b.t; });
    plan.gripper = gripper_;
    std::stable_sort(actions_.begin(), actions_.end(),
                     [](const core::PlanAction& a, const core::PlanAction& b) { return a.start < b.start; });
    plan.actions = actions_;
    plan.statistics = {{"generator", "dashbed script"}, {"script", script_name}, {"statements", statements}};
    return plan;
  }

 private:
  const std::string& robotName(int r) const { return world_.robots[r].name; }
  const std::string& objectName(int o) const { return world_.objects[o].name; }

  void command(int r, Millis t, GripperAction action) {
    gripper_.push_back({robotName(r), toSeconds(t), action, 0.0});
    timelines_[r].last_command = action;
  }

  /// Places a chain on robot r's timeline starting at `start`; returns the end time.
  Millis commit(int r, const Chain& chain, Millis start) {
    Timeline& timeline = timelines_[r];
    for (const Chain::Move& move : chain.moves()) {
      const Millis t0 = start + move.start;
      if (timeline.points.back().t < t0) timeline.points.push_back({t0, timeline.q, true});
      timeline.points.push_back({t0 + move.duration, move.q, move.rests});
      timeline.q = move.q;
    }
    for (const Chain::Grip& grip : chain.grips()) command(r, start + grip.t, grip.action);
    timeline.t = start + chain.elapsed();
    return timeline.t;
  }

  /// The cheapest (shortest) successful chain, or a ScriptError quoting the first failure.
  template <typename Candidate>
  const Candidate& best(const std::vector<Candidate>& candidates, const Token& at, const std::string& what) const {
    const Candidate* chosen = nullptr;
    for (const Candidate& c : candidates) {
      if (c.ok() && (chosen == nullptr || c.cost() < chosen->cost())) chosen = &c;
    }
    if (chosen == nullptr) {
      const std::string count = candidates.size() == 1 ? "" : " (tried " + std::to_string(candidates.size()) + " ways; the first fails)";
      parser_.fail(at, what + ": " + candidates.front().error() + count);
    }
    return *chosen;
  }

  /// TCP pose of a via point above X_WT: its height is the support's plus safe_height plus
  /// the TCP's height above the bottom of the held object (0 without one).
  std::optional<Pose> viaAbove(const Pose& X_WT, double support_z, double hold_height) const {
    const double z = support_z + settings_.safe_height + hold_height;
    if (z < X_WT.translation().z() + 0.01) return std::nullopt;  // already high enough
    Pose X_via = X_WT;
    X_via.translation().z() = z;
    return X_via;
  }

  void moveTo(const Statement& s, const ArmConfig& q) {
    const core::UrArmIk& ik = *robots_[s.robot].placed->ik;
    for (int j = 0; j < 6; ++j) {
      if (q[j] < ik.lower()[j] || q[j] > ik.upper()[j]) {
        parser_.fail(s.verb_token, robots_[s.robot].joint_names[j] + " at " + fixed(q[j], 4) + " rad is outside its limits [" +
                                       fixed(ik.lower()[j], 4) + ", " + fixed(ik.upper()[j], 4) + "] rad");
      }
    }
    Chain chain(robots_[s.robot], settings_, timelines_[s.robot].q);
    chain.jointToConfig(q);
    commit(s.robot, chain, timelines_[s.robot].t);
  }

  // -- pick --

  struct PickCandidate {
    Chain chain;
    Pose X_OT;
    Millis descent_start = 0, grasp = 0, lift_end = 0;
    bool ok() const { return chain.ok(); }
    Millis cost() const { return chain.elapsed(); }
    const std::string& error() const { return chain.error(); }
  };

  void pick(const Statement& s) {
    const int r = s.robot, o = s.object;
    Timeline& timeline = timelines_[r];
    ObjectState& object = objects_[o];
    const core::ObjectSpec& spec = world_.objects[o];
    const std::string& robot = robotName(r);
    if (timeline.held == o) parser_.fail(s.object_token, robot + " already holds " + spec.name);
    if (timeline.held >= 0) {
      parser_.fail(s.object_token, robot + " already holds " + objectName(timeline.held) + "; place it or hand it over before picking " + spec.name);
    }
    if (object.holder >= 0) parser_.fail(s.object_token, spec.name + " is held by " + robotName(object.holder));
    if (object.lost) parser_.fail(s.object_token, spec.name + " was dropped in the air by a bare 'opens'; its pose is unknown");
    const UprightFrame upright = uprightFrame(object.X_WO.linear(), spec.size);
    if (upright.tilt > 0.1) parser_.fail(s.object_token, spec.name + " does not rest on a face (tilted " + fixed(upright.tilt, 2) + " rad)");

    const core::GraspApproach approach = s.side ? core::GraspApproach::kSide : core::GraspApproach::kTop;
    const std::string how = s.side ? "from the side" : "from above";
    Pose X_OU = Pose::Identity();
    X_OU.linear() = upright.R_OU;
    const double bottom_z = object.X_WO.translation().z() - upright.size_U.z() / 2;

    std::vector<PickCandidate> candidates;
    for (const core::BoxGrasp& grasp : core::boxGrasps(upright.size_U)) {
      if (grasp.approach != approach) continue;
      PickCandidate c{Chain(robots_[r], settings_, timeline.q), Pose::Identity(), 0, 0, 0};
      c.X_OT = Eigen::Translation3d(s.offset) * X_OU * grasp.X_OT;
      const Pose X_WT = object.X_WO * c.X_OT;
      const Eigen::Vector3d approach_W = X_WT.linear().col(2);
      const Pose X_pre = shifted(X_WT, -settings_.cartesian_distance * approach_W);
      const double hold_height = X_WT.translation().z() - bottom_z;
      if (const auto X_via = viaAbove(X_pre, bottom_z, 0.0)) c.chain.jointTo(*X_via, "via point above " + spec.name);
      c.chain.jointTo(X_pre, "pre-grasp pose of " + spec.name);
      c.descent_start = c.chain.elapsed();
      c.chain.straight(settings_.cartesian_distance * approach_W, "approach to " + spec.name);
      c.grasp = c.chain.elapsed();
      c.chain.grip(GripperAction::kClose);
      c.chain.dwell(ceilMillis(settings_.gripper_dwell));
      c.chain.straight(settings_.cartesian_distance * kUp, "lift of " + spec.name);
      c.lift_end = c.chain.elapsed();
      if (const auto X_via = viaAbove(c.chain.tcp(), bottom_z, hold_height)) c.chain.jointTo(*X_via, "via point above " + spec.name);
      candidates.push_back(std::move(c));
    }
    if (candidates.empty()) {
      parser_.fail(s.object_token, "no grasp of " + spec.name + " " + how + " (box " + vec(upright.size_U * 1000.0, 0) +
                                       " mm): faces wider than the Hand-E opening (" + fixed(core::kHandeMaxOpening * 1000.0, 0) +
                                       " mm less clearance)" + (s.side ? " or too low for the gripper body to clear the surface" : ""));
    }
    const PickCandidate& c = best(candidates, s.object_token, robot + " cannot pick " + spec.name + " " + how);

    const Millis start = std::max(timeline.t, object.available);
    if (timeline.last_command != GripperAction::kOpen) command(r, start, GripperAction::kOpen);  // open on the way
    commit(r, c.chain, start);
    actions_.push_back({core::ActionType::kPick, robot, "", spec.name, "", toSeconds(start + c.descent_start),
                        toSeconds(start + c.lift_end)});
    timeline.held = o;
    timeline.X_OT = c.X_OT;
    object.holder = r;
  }

  // -- place --

  void place(const Statement& s) {
    const int r = s.robot, o = s.object;
    Timeline& timeline = timelines_[r];
    ObjectState& object = objects_[o];
    const core::ObjectSpec& spec = world_.objects[o];
    const std::string& robot = robotName(r);
    if (timeline.held != o) {
      parser_.fail(s.object_token, robot + " does not hold " + spec.name +
                                       (object.holder >= 0 ? " (" + robotName(object.holder) + " does)" : ""));
    }
    // where the object is now, as carried by the robot
    const Pose X_WO_now = robots_[r].placed->tcpPoseInWorld(timeline.q) * timeline.X_OT.inverse();
    const UprightFrame upright = uprightFrame(X_WO_now.linear(), spec.size);
    const Eigen::Matrix3d R_UO = upright.R_OU.transpose();
    // the object keeps the face it shows downwards and turns about the vertical into line
    // with the region (or the world axes); the TCP follows through the held grasp
    const core::Region* region = s.region >= 0 ? &world_.regions[s.region] : nullptr;
    const double height = upright.size_U.z();
    const double region_yaw = region != nullptr ? std::atan2(region->X_WR.linear()(1, 0), region->X_WR.linear()(0, 0)) : 0.0;
    const Eigen::Vector3d p_WO = region != nullptr
                                     ? Eigen::Vector3d(region->X_WR * Eigen::Vector3d(0, 0, height / 2 + settings_.drop_height))
                                     : *s.at;
    const double support_z = p_WO.z() - height / 2 - (region != nullptr ? settings_.drop_height : 0.0);

    struct PlaceCandidate {
      Chain chain;
      Pose X_WO;
      Millis descent_start = 0, release = 0, retreat_end = 0;
      bool fits = true;
      bool ok() const { return chain.ok(); }
      Millis cost() const { return chain.elapsed(); }
      const std::string& error() const { return chain.error(); }
    };
    std::vector<PlaceCandidate> candidates;
    for (int k = 0; k < 4; ++k) {
      PlaceCandidate c{Chain(robots_[r], settings_, timeline.q), Pose::Identity(), 0, 0, 0, true};
      c.X_WO.linear() = yawRotation(region_yaw + k * std::numbers::pi / 2) * R_UO;
      c.X_WO.translation() = p_WO;
      if (region != nullptr) {
        const Eigen::Vector2d footprint = k % 2 == 0 ? upright.size_U.head<2>() : Eigen::Vector2d(upright.size_U.y(), upright.size_U.x());
        c.fits = footprint.x() <= region->size.x() && footprint.y() <= region->size.y();
      }
      const Pose X_WT = c.X_WO * Eigen::Translation3d(s.offset) * timeline.X_OT;  // offset: release beside the spot
      const Pose X_pre = shifted(X_WT, settings_.cartesian_distance * kUp);
      const double hold_height = X_WT.translation().z() - support_z;
      if (const auto X_via = viaAbove(X_pre, support_z, hold_height)) c.chain.jointTo(*X_via, "via point above the placement");
      c.chain.jointTo(X_pre, "pose above the placement");
      c.descent_start = c.chain.elapsed();
      c.chain.straight(-settings_.cartesian_distance * kUp, "descent to the placement");
      c.release = c.chain.elapsed();
      c.chain.grip(GripperAction::kOpen);
      c.chain.dwell(ceilMillis(settings_.gripper_dwell));
      c.chain.straight(settings_.cartesian_distance * kUp, "retreat from the placement");
      c.retreat_end = c.chain.elapsed();
      if (const auto X_via = viaAbove(c.chain.tcp(), support_z, 0.0)) c.chain.jointTo(*X_via, "via point above the placement");
      candidates.push_back(std::move(c));
    }
    // orientations whose footprint fits the region first
    if (std::any_of(candidates.begin(), candidates.end(), [](const PlaceCandidate& c) { return c.fits; })) {
      std::erase_if(candidates, [](const PlaceCandidate& c) { return !c.fits; });
    }
    const std::string where = region != nullptr ? "in " + region->name : "at " + vec(p_WO) + " m";
    const PlaceCandidate& c = best(candidates, s.object_token, robot + " cannot place " + spec.name + " " + where);

    const Millis start = timeline.t;
    commit(r, c.chain, start);
    // judged in the region named, or the one containing an explicit position; elsewhere as an
    // object set aside (a place without a region: at rest on a stable surface)
    const core::Region* judged = region;
    for (std::size_t g = 0; g < world_.regions.size() && judged == nullptr; ++g) {
      const core::Region& candidate = world_.regions[g];
      core::Box volume;
      volume.X_WB = candidate.X_WR * Eigen::Translation3d(0, 0, candidate.size.z() / 2);
      volume.size = candidate.size;
      if (core::pointInBox(p_WO, volume)) judged = &candidate;
    }
    actions_.push_back({core::ActionType::kPlace, robot, "", spec.name, judged != nullptr ? judged->name : "",
                        toSeconds(start + c.descent_start), toSeconds(start + c.retreat_end)});
    object.X_WO = c.X_WO * Eigen::Translation3d(s.offset);
    if (region != nullptr) object.X_WO.translation().z() -= settings_.drop_height;  // it settles on the floor
    object.holder = -1;
    object.available = start + c.retreat_end;
    timeline.held = -1;
  }

  // -- handoff --

  /// The planner's handoff sampler for this world (built on the first handoff): the script
  /// hands over with the planner's handoff geometry, IK and checks.
  planner::TransitionSampler& handoffSampler() {
    if (!handoffs_) handoffs_ = std::make_unique<HandoffSampling>(loaded_);
    return handoffs_->sampler;
  }

  /// Places the timed keys of a transition motion on robot r's timeline from `start`; the arm
  /// rests at its first and last key and wherever it holds still. Returns the end time.
  Millis commitKeys(int r, const planner::TransitionMotion& motion, Millis start) {
    Timeline& timeline = timelines_[r];
    const auto& keys = motion.keys;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const bool rests = k == 0 || k + 1 == keys.size() || keys[k].q == keys[k - 1].q || keys[k].q == keys[k + 1].q;
      const Millis t = start + keys[k].t;
      if (timeline.points.back().t < t) {
        timeline.points.push_back({t, keys[k].q, rests});
      } else {
        timeline.points.back().rests = true;  // the key the arm was brought to
      }
    }
    for (const auto& [t, action] : motion.grips) command(r, start + t, action);
    timeline.q = keys.back().q;
    timeline.t = start + keys.back().t;
    return timeline.t;
  }

  void handoff(const Statement& s) {
    const int g = s.robot, r = s.receiver, o = s.object;
    Timeline& giver = timelines_[g];
    Timeline& receiver = timelines_[r];
    const core::ObjectSpec& spec = world_.objects[o];
    const std::string& giver_name = robotName(g);
    const std::string& receiver_name = robotName(r);
    if (giver.held != o) {
      parser_.fail(s.object_token, giver_name + " does not hold " + spec.name +
                                       (objects_[o].holder >= 0 ? " (" + robotName(objects_[o].holder) + " does)" : ""));
    }
    if (receiver.held >= 0) {
      parser_.fail(s.object_token, receiver_name + " already holds " + objectName(receiver.held) + " and cannot receive " + spec.name);
    }
    planner::TransitionSampler& sampler = handoffSampler();
    const planner::TaskSpaceHypergraph& task_space = handoffs_->task_space;
    int hyperarc = -1;
    for (std::size_t h = 0; h < task_space.numHyperarcs() && hyperarc < 0; ++h) {
      const planner::TransitionHyperarc& arc = task_space.hyperarcs()[h];
      if (arc.kind == planner::TransitionKind::kHandoff && arc.robot == g && arc.receiver == r && arc.object == o) {
        hyperarc = static_cast<int>(h);
      }
    }
    if (hyperarc < 0) {
      parser_.fail(s.verb_token, giver_name + " and " + receiver_name + " cannot hand " + spec.name +
                                     " over: they have no handoff zone (no place near them both reach, clear of the fixtures)");
    }
    // the planner's handoff samples for the grasp the giver holds, drawn from a fixed seed
    planner::Grasp held{giver.X_OT, 0.5 * spec.size.dot(giver.X_OT.linear().col(0).cwiseAbs())};
    if (sampler.handoffGrasps(o, held).empty()) {
      parser_.fail(s.object_token, giver_name + " cannot hand " + spec.name + " to " + receiver_name + ": " +
                                       receiver_name + " has no face pair of " + spec.name +
                                       " to close on while " + giver_name + " holds it (docs/limits.md, handoffs)");
    }
    std::mt19937_64 rng(kHandoffSeed);
    std::optional<planner::TransitionSample> sample;
    for (int tries = 0; tries < kHandoffTries && !sample; ++tries) {
      std::vector<planner::TransitionSample> samples = sampler.handoff(hyperarc, held, rng, 1);
      if (!samples.empty()) sample = std::move(samples.front());
    }
    if (!sample) {
      parser_.fail(s.object_token, giver_name + " cannot hand " + spec.name + " to " + receiver_name +
                                       ": no handoff pose in their handoff zone where both reach the object, clear of "
                                       "each other and the fixtures, with the grasp " + giver_name + " holds");
    }
    const planner::TransitionMotion& giving = sample->motions.front();
    const planner::TransitionMotion& receiving = sample->motions.back();

    // both come to the handoff from where they are and arrive together
    Chain giver_in(robots_[g], settings_, giver.q), receiver_in(robots_[r], settings_, receiver.q);
    giver_in.jointToConfig(giving.keys.front().q);
    receiver_in.jointToConfig(receiving.keys.front().q);
    const Millis free = std::max(giver.t, receiver.t);
    const Millis arrive = free + std::max(giver_in.elapsed(), receiver_in.elapsed());
    if (receiver.last_command != GripperAction::kOpen) command(r, arrive - receiver_in.elapsed(), GripperAction::kOpen);
    commit(g, giver_in, arrive - giver_in.elapsed());
    commit(r, receiver_in, arrive - receiver_in.elapsed());
    commitKeys(g, giving, arrive);
    commitKeys(r, receiving, arrive);
    Chain giver_home(robots_[g], settings_, giver.q);
    giver_home.jointToConfig(world_.robots[g].home);
    commit(g, giver_home, giver.t);
    actions_.push_back({core::ActionType::kHandoff, giver_name, receiver_name, spec.name, "",
                        toSeconds(arrive + sample->action_start), toSeconds(arrive + sample->action_end)});
    giver.held = -1;
    receiver.held = o;
    receiver.X_OT = sample->grasp_after->X_OT;
    objects_[o].holder = r;
  }

  /// What the planner's handoff sampler stands on, built once per script.
  struct HandoffSampling {
    explicit HandoffSampling(const core::LoadedWorld& world)
        : scene(*world.world, *world.robots, planner::CollisionSettings{}),
          sites(planner::objectSites(world)),
          task_space(planner::TaskSpaceHypergraph::fromWorld(*world.world, *world.robots,
                                                             planner::placementReach(world, sites))),
          sampler(world, task_space, scene, sites) {}
    planner::CollisionScene scene;
    planner::ObjectSites sites;
    planner::TaskSpaceHypergraph task_space;
    planner::TransitionSampler sampler;
  };
  /// Seed of the handoff pose draws, and how many rounds of draws a handoff gets.
  static constexpr std::uint64_t kHandoffSeed = 1;
  static constexpr int kHandoffTries = 20;

  const core::LoadedWorld& loaded_;
  std::unique_ptr<HandoffSampling> handoffs_;
  const core::World& world_;
  const ScriptSettings& settings_;
  const ScriptParser& parser_;
  std::vector<RobotContext> robots_;
  std::vector<Timeline> timelines_;
  std::vector<ObjectState> objects_;
  std::vector<core::GripperCommand> gripper_;
  std::vector<core::PlanAction> actions_;
};

}  // namespace

core::Plan planFromScript(const core::LoadedWorld& world, std::string_view script, const std::string& script_name,
                          const ScriptSettings& settings) {
  const ScriptParser parser(*world.world, script_name);
  const std::vector<Statement> statements = parser.parse(script);
  ScriptPlanner planner(world, settings, parser);
  for (const Statement& statement : statements) planner.run(statement);
  return planner.finish(script_name, statements.size());
}

}  // namespace dashbed::tools
