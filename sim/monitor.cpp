#include "sim/monitor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/geometry.h"
#include "sim/grip_load.h"

namespace dashbed::sim {
namespace {

using core::ActionType;
using core::GripperAction;
using core::Pose;

// Time after both pads first touch before the object's pose in the gripper is taken as the
// reference for slip: the fingers finish squeezing within it.
constexpr double kGraspSettle = 0.1;  // [s]
// Both pads must lose the object for this long before it counts as dropped (a pad may chatter
// for a step or two when the load changes).
constexpr double kDropDebounce = 0.05;  // [s]
// Minimum time both grippers must hold the object together in a handoff.
constexpr double kMinHandoffOverlap = 0.05;  // [s]
// The grip margin written when the pads used no friction at all (the margin is unbounded).
constexpr double kNoFrictionUsed = 1e6;
// Displacement of an object at rest that counts as knocking it.
constexpr double kKnockDistance = 0.005;  // [m]
constexpr double kKnockAngle = 0.1;       // [rad]
// An unplanned contact that pauses for less than this is the same contact.
constexpr double kContactGap = 0.25;  // [s]
// After a robot opens its gripper its fingers may still brush the object it let go of.
constexpr double kReleaseGrace = 0.5;  // [s]
// A released object counts as settled after resting this long.
constexpr double kSettledAfter = 0.3;  // [s]

std::string fmt(double value, int precision = 4) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

/// An object set aside rests on a surface when its bottom is this near it: more than the
/// world loader's 2 mm for a start pose, for the contact's give in simulation [m].
constexpr double kSurfaceContact = 0.005;

double rotationAngle(const Eigen::Matrix3d& R) { return Eigen::AngleAxisd(R).angle(); }

/// Smallest angle between any object axis and the world vertical.
double tiltFromFlat(const Pose& X_WO) {
  double best = M_PI;
  for (int k = 0; k < 3; ++k) {
    best = std::min(best, std::acos(std::min(1.0, std::abs(X_WO.linear().col(k).z()))));
  }
  return best;
}

/// How far the bottom of an object at X_WO lies from the nearest stable surface under its
/// centre [m], or std::nullopt when no surface is under it.
std::optional<double> gapToSurface(const core::World& world, const Pose& X_WO, const Eigen::Vector3d& size) {
  const double bottom = X_WO.translation().z() - core::rotatedBoxExtent(X_WO.linear(), size).z() / 2;
  std::optional<double> gap;
  for (const core::StableSurface& surface : world.surfaces) {
    const Eigen::Vector3d p_S = surface.X_WS.inverse(Eigen::Isometry) * X_WO.translation();
    if (std::abs(p_S.x()) > surface.size.x() / 2 || std::abs(p_S.y()) > surface.size.y() / 2) continue;
    const double here = std::abs(bottom - surface.X_WS.translation().z());
    if (!gap || here < *gap) gap = here;
  }
  return gap;
}

struct HoldEpisode {
  int robot = -1;
  int object = -1;
  double grasp_time = 0.0;
  std::optional<double> release_time;
  bool reference_set = false;
  Pose X_TO_reference = Pose::Identity();
  double slip_time = -1.0;  // when slip first exceeded the tolerance
  /// Every step once settled: the object's slip in the gripper and the pads' grip on it.
  struct Sample {
    double t;
    double slip;          // [m]
    double angle;         // [rad]
    double friction_use;  // the grip's friction load, 1 = sliding (grip_load.h)
    double area;          // the smaller pad's contact area [m^2]
  };
  std::vector<Sample> samples;
  /// The object's velocity at the last sample, for its acceleration.
  struct Velocity {
    double t;
    Eigen::Vector3d v, w;
  };
  std::optional<Velocity> previous;

  /// The extremes over plan times [from, to]: largest slip, slip angle and friction use,
  /// smallest pad contact area (infinity when there is no sample).
  Sample worst(double from, double to) const {
    Sample w{0.0, 0.0, 0.0, 0.0, std::numeric_limits<double>::infinity()};
    for (const Sample& s : samples) {
      if (s.t < from - 1e-9 || s.t > to + 1e-9) continue;
      w.slip = std::max(w.slip, s.slip);
      w.angle = std::max(w.angle, s.angle);
      w.friction_use = std::max(w.friction_use, s.friction_use);
      w.area = std::min(w.area, s.area);
    }
    return w;
  }
  std::optional<double> lost_since;
  std::optional<double> drop_time;
};

struct ActionTrack {
  const core::PlanAction* action = nullptr;
  int robot = -1;
  int receiver = -1;
  int object = -1;
  int region = -1;
  std::optional<double> command_time;   // pick: close; place: open; handoff: receiver close
  std::optional<double> command2_time;  // handoff: giver open
  // pick
  std::optional<double> both_pads_time;
  std::optional<double> close_z;  // the object's height when the gripper is told to close [m]
  bool end_sampled = false;
  bool held_at_end = false;
  bool support_contact_at_end = false;
  double lift_height = 0.0;
  // handoff
  double overlap = 0.0;
  std::vector<std::string> foreign_contacts;
  bool giver_touching_at_end = false;
  // place
  bool placement_sampled = false;
  std::optional<double> placement_time;
  Pose placement_pose = Pose::Identity();
  double placement_speed = 0.0;
};

/// A measurement and whether it passed (`comparison`: "<=", ">=" or "==" against `threshold`;
/// passed when there is no threshold).
Measurement measure(std::string name, double value, std::string unit, std::optional<double> threshold = {},
                    std::string comparison = "") {
  Measurement m{std::move(name), value, std::move(unit), threshold, std::move(comparison), true};
  if (threshold) {
    m.passed = m.comparison == "<=" ? value <= *threshold : m.comparison == ">=" ? value >= *threshold : value == *threshold;
  }
  return m;
}

/// Contacts of one step, as the checks read them.
/// How hard a robot's two pads press on an object; the patches are filled in for a held one.
struct PadGrip {
  PadContact left, right;
};

struct StepContacts {
  std::vector<std::set<int>> left, right;               // per robot: objects its left / right finger touches
  std::vector<std::map<int, PadGrip>> pads;             // per robot: object -> its pads' grip on it
  std::vector<bool> support;                            // per object: touches scenery or another object
  std::vector<std::vector<std::string>> touched_by;     // per object: everything touching it
  std::map<std::string, Eigen::Vector3d> unplanned;     // unplanned pair -> a contact point
};

}  // namespace

struct Monitor::State {
  const Simulation& sim;
  const core::Plan& plan;
  double offset;
  const core::World& world;
  std::vector<int> left_finger, right_finger;  // model link index per robot
  std::vector<core::CollisionShape> left_pad, right_pad;  // per robot: the fingers' pad boxes
  std::vector<int> tcp;
  std::vector<ActionTrack> actions;
  std::vector<HoldEpisode> holds;               // all episodes, in order of start
  std::vector<int> active_hold;                 // per robot: index into holds or -1
  std::vector<Pose> rest_pose;                  // per object
  std::vector<bool> knocked;                    // per object: currently displaced from rest
  std::vector<bool> settling;                   // per object: manipulated, or released and not yet at rest
  std::vector<std::optional<double>> rest_since;  // per settling object: since when it is at rest
  std::vector<int> last_toucher;                // per object: robot that touched it last
  std::vector<double> start_z;                  // per object
  std::map<std::string, double> last_touch;     // unplanned pair -> plan time it last touched
  std::vector<ExecutionEvent> events;
  bool stop_recorded = false;  ///< the protective stop is among the events

  State(const Simulation& s, const core::Plan& p, double o) : sim(s), plan(p), offset(o), world(s.world()) {}

  double planTime() const { return sim.time() - offset; }

  int robotIndex(const std::string& name) const {
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      if (world.robots[r].name == name) return static_cast<int>(r);
    }
    return -1;
  }
  int objectIndex(const std::string& name) const {
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
      if (world.objects[o].name == name) return static_cast<int>(o);
    }
    return -1;
  }

  std::string bodyName(const BodyRef& ref) const {
    switch (ref.kind) {
      case BodyRef::Kind::kFloor: return "floor";
      case BodyRef::Kind::kFixture: return world.fixtures[ref.index].name;
      case BodyRef::Kind::kObject: return world.objects[ref.index].name;
      case BodyRef::Kind::kRobot:
        return world.robots[ref.index].name + "/" + sim.robots()[ref.index].model->links()[ref.link].name;
    }
    return "?";
  }

  /// Name of the joint at position q_index of robot r's model.
  std::string jointName(int r, int q_index) const {
    const core::RobotModel& model = *sim.robots()[r].model;
    return model.joints()[model.movableJoints().at(static_cast<std::size_t>(q_index))].name;
  }

  bool isFinger(const BodyRef& ref) const {
    return ref.kind == BodyRef::Kind::kRobot &&
           (ref.link == left_finger[ref.index] || ref.link == right_finger[ref.index]);
  }

  /// True when robot r is in an action on object o at plan time t.
  bool inActionWith(int r, int o, double t) const {
    for (const ActionTrack& a : actions) {
      if (a.object != o || (a.robot != r && a.receiver != r)) continue;
      if (t >= a.action->start - 1e-9 && t <= a.action->end + 1e-9) return true;
    }
    return false;
  }

  /// The action an event on object o (or by robot r) at time t belongs to: one in progress,
  /// else the next one of the object, else the last one before.
  const ActionTrack* attribute(int r, int o, double t) const {
    const ActionTrack* next = nullptr;
    const ActionTrack* previous = nullptr;
    for (const ActionTrack& a : actions) {
      const bool involved = (o >= 0 && a.object == o) || (o < 0 && (a.robot == r || a.receiver == r));
      if (!involved) continue;
      if (t >= a.action->start - 1e-9 && t <= a.action->end + 1e-9) return &a;
      if (a.action->start > t && (next == nullptr || a.action->start < next->action->start)) next = &a;
      if (a.action->end < t && (previous == nullptr || a.action->end > previous->action->end)) previous = &a;
    }
    return next != nullptr ? next : previous;
  }

  void addEvent(double t, std::string kind, std::string detail, const ActionTrack* action,
                const Eigen::Vector3d& where_W) {
    ExecutionEvent event;
    event.t = t;
    event.where_W = where_W;
    event.kind = std::move(kind);
    event.detail = std::move(detail);
    if (action != nullptr) event.action = actionId(*action->action);
    events.push_back(std::move(event));
  }

  /// True when robot r let go of object o less than kReleaseGrace ago.
  bool releasedRecently(int r, int o, double t) const {
    for (auto it = holds.rbegin(); it != holds.rend(); ++it) {
      if (it->robot != r || it->object != o) continue;
      return it->release_time && t - *it->release_time < kReleaseGrace;
    }
    return false;
  }

  /// True when robot r opening its gripper on object o at time t is part of a plan action:
  /// a place by r or a handoff given by r in progress.
  bool releaseIsPlanned(int r, int o, double t) const {
    for (const ActionTrack& a : actions) {
      if (a.object != o || a.robot != r) continue;
      if (a.action->type == ActionType::kPick) continue;
      if (t >= a.action->start - 1e-9 && t <= a.action->end + 1e-9) return true;
    }
    return false;
  }

  /// Who touches what after the step just taken.
  StepContacts contactsNow(double t) {
    StepContacts now;
    now.left.resize(world.robots.size());
    now.right.resize(world.robots.size());
    now.pads.resize(world.robots.size());
    now.support.assign(world.objects.size(), false);
    now.touched_by.resize(world.objects.size());
    auto& [left, right, pads, support, touched_by, unplanned_now] = now;
    for (const Contact& c : sim.contacts()) {
      for (int side = 0; side < 2; ++side) {
        const BodyRef& a = side == 0 ? c.a : c.b;
        const BodyRef& b = side == 0 ? c.b : c.a;
        if (a.kind != BodyRef::Kind::kObject) continue;
        touched_by[a.index].push_back(bodyName(b));
        if (b.kind == BodyRef::Kind::kRobot) {
          last_toucher[a.index] = b.index;
          if (b.link == left_finger[b.index]) left[b.index].insert(a.index);
          if (b.link == right_finger[b.index]) right[b.index].insert(a.index);
          if (isFinger(b)) {
            PadGrip& grip = pads[b.index][a.index];
            (b.link == left_finger[b.index] ? grip.left : grip.right).normal_force = c.normal_force;
          }
          const bool planned = isFinger(b) && (inActionWith(b.index, a.index, t) ||
                                                 (active_hold[b.index] >= 0 && holds[active_hold[b.index]].object == a.index) ||
                                                 releasedRecently(b.index, a.index, t));
          if (!planned) unplanned_now.emplace(bodyName(b) + " touches " + bodyName(a), c.point_W);
        } else {
          support[a.index] = true;
        }
      }
      if (c.a.kind == BodyRef::Kind::kRobot || c.b.kind == BodyRef::Kind::kRobot) {
        const BodyRef& robot = c.a.kind == BodyRef::Kind::kRobot ? c.a : c.b;
        const BodyRef& other = c.a.kind == BodyRef::Kind::kRobot ? c.b : c.a;
        if (other.kind == BodyRef::Kind::kRobot && other.index != robot.index) {
          unplanned_now.emplace("robot-robot contact: " + bodyName(c.a) + " touches " + bodyName(c.b), c.point_W);
        } else if (other.kind == BodyRef::Kind::kFixture || other.kind == BodyRef::Kind::kFloor) {
          unplanned_now.emplace("robot-fixture contact: " + bodyName(robot) + " touches " + bodyName(other), c.point_W);
        }
      }
    }
    return now;
  }

  /// An unplanned contact becomes an event when its pair starts touching after a while apart.
  void reportUnplannedContacts(const StepContacts& now, double t) {
    // an unplanned pair is reported when it starts touching after a while apart (contacts
    // chatter for a few steps while bodies push against each other)
    for (const auto& [pair, point_W] : now.unplanned) {
      const auto last = last_touch.find(pair);
      const bool ongoing = last != last_touch.end() && t - last->second < kContactGap;
      last_touch[pair] = t;
      if (ongoing) continue;
      const auto colon = pair.find(':');
      const std::string kind = colon == std::string::npos ? "unplanned contact with object" : pair.substr(0, colon);
      const std::string detail = colon == std::string::npos ? pair : pair.substr(colon + 2);
      // attribute to an action of the first robot named in the pair
      int robot = -1;
      for (std::size_t r = 0; r < world.robots.size() && robot < 0; ++r) {
        if (detail.rfind(world.robots[r].name + "/", 0) == 0) robot = static_cast<int>(r);
      }
      addEvent(t, kind, detail, robot >= 0 ? attribute(robot, -1, t) : nullptr, point_W);
    }

  }

  /// The friction load on robot r's grip of the object `hold` holds (grip_load.h), its motion
  /// from the change of its velocity since the last step; 0 on the first step of a hold. Fills
  /// in the pads' patches on the object.
  double gripUse(HoldEpisode& hold, PadGrip& pads, int r, double t) {
    const core::ObjectSpec& object = world.objects[hold.object];
    const Pose X_WO = sim.objectPose(hold.object);
    const auto ri = static_cast<std::size_t>(r);
    for (auto [pad, finger, shape] : {std::tuple(&pads.left, left_finger[ri], &left_pad[ri]),
                                      std::tuple(&pads.right, right_finger[ri], &right_pad[ri])}) {
      const Patch patch = padPatch(padFace(sim.linkPose(r, finger), *shape), X_WO, object.size);
      pad->area = patch.area;
      pad->mean_radius = patch.mean_radius;
      pad->centre_W = patch.centre_W;
    }
    const Eigen::Vector3d v = sim.objectLinearVelocity(hold.object), w = sim.objectAngularVelocity(hold.object);
    const std::optional<HoldEpisode::Velocity> previous = hold.previous;
    hold.previous = HoldEpisode::Velocity{t, v, w};
    if (!previous || t <= previous->t) return 0.0;
    const Eigen::Vector3d& e = object.size;
    const Eigen::Vector3d box = object.mass / 12.0 * Eigen::Vector3d(e.y() * e.y() + e.z() * e.z(),
                                                                    e.x() * e.x() + e.z() * e.z(),
                                                                    e.x() * e.x() + e.y() * e.y());
    HeldMotion motion;
    motion.mass = object.mass;
    motion.inertia_W = X_WO.linear() * box.asDiagonal() * X_WO.linear().transpose();
    motion.com_W = X_WO.translation();
    motion.acceleration_W = (v - previous->v) / (t - previous->t);
    motion.angular_velocity_W = w;
    motion.angular_acceleration_W = (w - previous->w) / (t - previous->t);
    const Eigen::Vector3d closing_W = sim.linkPose(r, tcp[static_cast<std::size_t>(r)]).linear().col(0);
    return gripLoad(pads.left, pads.right, closing_W, object.friction * world.physics.pad_friction, motion,
                    world.physics.gravity)
        .use;
  }

  /// Grasp episodes: a closed gripper with both pads on an object holds it; its slip in the TCP
  /// frame is sampled every step; opening it outside a place or handoff, or losing the object
  /// while closed, is a drop.
  void trackHolds(const PlanExecutor& executor, const StepContacts& now, double t) {
    const auto& left = now.left;
    const auto& right = now.right;
    // grasp episodes
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      const bool closed = executor.gripper(static_cast<int>(r)).state() == GripperAction::kClose;
      int& active = active_hold[r];
      if (active < 0) {
        if (!closed) continue;
        for (int o : left[r]) {
          if (right[r].count(o) == 0) continue;
          HoldEpisode episode;
          episode.robot = static_cast<int>(r);
          episode.object = o;
          episode.grasp_time = t;
          holds.push_back(episode);
          active = static_cast<int>(holds.size()) - 1;
          break;
        }
        continue;
      }
      HoldEpisode& hold = holds[active];
      if (!closed) {
        hold.release_time = t;
        active = -1;
        if (!releaseIsPlanned(static_cast<int>(r), hold.object, t)) {
          hold.drop_time = t;
          addEvent(t, "drop",
                     world.robots[r].name + " opened its gripper holding " + world.objects[hold.object].name +
                         " outside any place or handoff",
                     attribute(static_cast<int>(r), hold.object, t), sim.objectPose(hold.object).translation());
        }
        continue;
      }
      const bool both = left[r].count(hold.object) != 0 && right[r].count(hold.object) != 0;
      const Pose X_TO = sim.linkPose(static_cast<int>(r), tcp[r]).inverse() * sim.objectPose(hold.object);
      if (both) {
        hold.lost_since.reset();
        if (!hold.reference_set && t - hold.grasp_time >= kGraspSettle) {
          hold.reference_set = true;
          hold.X_TO_reference = X_TO;
        }
        if (hold.reference_set) {
          const double slip = (X_TO.translation() - hold.X_TO_reference.translation()).norm();
          const double angle = rotationAngle(hold.X_TO_reference.linear().transpose() * X_TO.linear());
          const auto grip = now.pads[r].find(hold.object);
          PadGrip pads = grip != now.pads[r].end() ? grip->second : PadGrip{};
          const double use = gripUse(hold, pads, static_cast<int>(r), t);
          hold.samples.push_back({t, slip, angle, use, std::min(pads.left.area, pads.right.area)});
          if (hold.slip_time < 0 && (slip > world.checks.slip_tolerance || angle > world.checks.slip_angle_tolerance)) {
            hold.slip_time = t;
            addEvent(t, "slip",
                       world.objects[hold.object].name + " slipped " + fmt(slip * 1e3) + " mm / " + fmt(angle) +
                           " rad in the gripper of " + world.robots[r].name,
                       attribute(static_cast<int>(r), hold.object, t), sim.objectPose(hold.object).translation());
          }
        }
      } else {
        if (!hold.lost_since) hold.lost_since = t;
        if (t - *hold.lost_since >= kDropDebounce) {
          hold.drop_time = *hold.lost_since;
          addEvent(*hold.lost_since, "drop",
                     world.robots[r].name + " lost " + world.objects[hold.object].name + " with its gripper closed",
                     attribute(static_cast<int>(r), hold.object, *hold.lost_since),
                     sim.objectPose(hold.object).translation());
          active = -1;
        }
      }
    }

  }

  /// Knocked objects: an object nobody is manipulating moves away from where it rested.
  void trackRestingObjects(const StepContacts& now, double t) {
    const auto& touched_by = now.touched_by;
    // knocked objects: an object nobody is manipulating moves away from where it rested
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
      const int oi = static_cast<int>(o);
      bool manipulated = false;
      for (std::size_t r = 0; r < world.robots.size(); ++r) {
        if ((active_hold[r] >= 0 && holds[active_hold[r]].object == oi) || inActionWith(static_cast<int>(r), oi, t)) {
          manipulated = true;
        }
      }
      const Pose X = sim.objectPose(oi);
      const double speed = sim.objectLinearVelocity(oi).norm();
      // while manipulated, and after a release until the object comes to rest, its rest pose
      // follows it: only an object that has settled can be knocked
      if (manipulated) {
        settling[o] = true;
        rest_since[o].reset();
      }
      if (settling[o]) {
        rest_pose[o] = X;
        knocked[o] = false;
        // settled once it has stayed at rest for kSettledAfter (a released object may hang
        // still for a moment before it falls)
        if (manipulated || speed >= world.checks.rest_speed) {
          rest_since[o].reset();
        } else if (!rest_since[o]) {
          rest_since[o] = t;
        } else if (t - *rest_since[o] >= kSettledAfter) {
          settling[o] = false;
        }
        continue;
      }
      const double moved = (X.translation() - rest_pose[o].translation()).norm();
      const double turned = rotationAngle(rest_pose[o].linear().transpose() * X.linear());
      if (!knocked[o] && (moved > kKnockDistance || turned > kKnockAngle)) {
        knocked[o] = true;
        const int toucher = last_toucher[o];
        std::string detail = world.objects[o].name + " moved " + fmt(moved * 1e3) + " mm / turned " + fmt(turned) + " rad from rest";
        if (toucher >= 0) detail += " (last touched by " + world.robots[toucher].name + ")";
        addEvent(t, "knocked object", detail, toucher >= 0 ? attribute(toucher, -1, t) : attribute(-1, oi, t),
                   X.translation());
      }
      // at rest and untouched by robots: this is its new rest pose
      const bool robot_touching = std::any_of(touched_by[o].begin(), touched_by[o].end(), [&](const std::string& name) {
        return name.find('/') != std::string::npos;
      });
      if (speed < world.checks.rest_speed && !robot_touching && !knocked[o]) rest_pose[o] = X;
    }

  }

  /// What each action's checks need from this step: pads on the object, lift, handoff overlap and
  /// foreign contacts, the placement after its settle time.
  void observeActions(const StepContacts& now, double t) {
    const double dt = sim.timeStep();
    const auto& left = now.left;
    const auto& right = now.right;
    const auto& support = now.support;
    const auto& touched_by = now.touched_by;
    // per-action observations
    for (ActionTrack& a : actions) {
      if (a.object < 0) continue;
      const core::PlanAction& action = *a.action;
      switch (action.type) {
        case ActionType::kPick: {
          if (a.command_time && !a.close_z && t >= *a.command_time) a.close_z = sim.objectPose(a.object).translation().z();
          if (a.command_time && !a.both_pads_time && t >= *a.command_time && a.robot >= 0 &&
              left[a.robot].count(a.object) != 0 && right[a.robot].count(a.object) != 0) {
            a.both_pads_time = t;
          }
          if (!a.end_sampled && t >= action.end) {
            a.end_sampled = true;
            a.held_at_end = a.robot >= 0 && left[a.robot].count(a.object) != 0 && right[a.robot].count(a.object) != 0;
            a.support_contact_at_end = support[a.object];
            // from where this pick found it (a second pick of a placed object starts elsewhere)
            a.lift_height = sim.objectPose(a.object).translation().z() - a.close_z.value_or(start_z[a.object]);
          }
          break;
        }
        case ActionType::kHandoff: {
          if (t < action.start || t > action.end || a.robot < 0 || a.receiver < 0) break;
          const bool giver = left[a.robot].count(a.object) && right[a.robot].count(a.object);
          const bool receiver = left[a.receiver].count(a.object) && right[a.receiver].count(a.object);
          // holding together until the giver is told to open (its pads count as touching while
          // within 1 mm, some milliseconds after)
          if (giver && receiver && (!a.command2_time || t < *a.command2_time)) a.overlap += dt;
          for (const std::string& name : touched_by[a.object]) {
            const bool gripper = name.rfind(world.robots[a.robot].name + "/", 0) == 0 ||
                                 name.rfind(world.robots[a.receiver].name + "/", 0) == 0;
            if (!gripper && std::find(a.foreign_contacts.begin(), a.foreign_contacts.end(), name) == a.foreign_contacts.end()) {
              a.foreign_contacts.push_back(name);
            }
          }
          a.giver_touching_at_end = left[a.robot].count(a.object) || right[a.robot].count(a.object);
          a.held_at_end = receiver;
          break;
        }
        case ActionType::kPlace: {
          if (!a.command_time || a.placement_sampled) break;
          if (t >= std::max(*a.command_time + world.checks.settle_time, action.end)) {
            a.placement_sampled = true;
            a.placement_time = t;
            a.placement_pose = sim.objectPose(a.object);
            a.placement_speed = sim.objectLinearVelocity(a.object).norm();
          }
          break;
        }
      }
    }
  }

  /// The hold of `object` by `robot` that started within [from, to], or null.
  const HoldEpisode* episodeOf(int robot, int object, double from, double to) const {
    for (const HoldEpisode& h : holds) {
      if (h.robot == robot && h.object == object && h.grasp_time >= from - 1e-9 && h.grasp_time <= to + 1e-9) return &h;
    }
    return nullptr;
  }

  /// Whether X_WO's origin is inside `region` within the placement tolerance; `outside`: by how far not.
  bool insideRegion(const core::Region& region, const Pose& X_WO, double& outside) const {
    outside = core::distanceOutside(region, X_WO.translation(), world.checks.placement_tolerance);
    return outside <= 0.0;
  }

  /// The largest slip of `hold` from its grasp to `until` against the slip tolerances; `who`
  /// names the holder in the measurements and messages ("" in a pick, "receiver" in a handoff).
  void judgeSlip(const HoldEpisode& hold, double until, const std::string& who, ActionReport& r,
                 std::vector<std::string>& failures) const {
    const core::CheckSettings& checks = world.checks;
    const HoldEpisode::Sample worst = hold.worst(hold.grasp_time, until);
    const std::string key = who.empty() ? "slip" : who + "_slip";
    const std::string words = who.empty() ? "slip" : who + " slip";
    r.measurements.push_back(measure(key, worst.slip, "m", checks.slip_tolerance, "<="));
    r.measurements.push_back(measure(key + "_angle", worst.angle, "rad", checks.slip_angle_tolerance, "<="));
    if (worst.slip > checks.slip_tolerance) {
      failures.push_back(words + " " + fmt(worst.slip * 1e3) + " mm > " + fmt(checks.slip_tolerance * 1e3) + " mm");
    }
    if (worst.angle > checks.slip_angle_tolerance) {
      failures.push_back(words + " angle " + fmt(worst.angle) + " rad > " + fmt(checks.slip_angle_tolerance) + " rad");
    }
    if (std::isinf(worst.area)) return;  // never settled in the gripper: nothing to judge
    // the grip's margin: the friction the pads could give over what the hold used at its worst
    const std::string prefix = who.empty() ? "" : who + "_";
    const double margin = worst.friction_use > 0.0 ? 1.0 / worst.friction_use : kNoFrictionUsed;
    r.measurements.push_back(measure(prefix + "grip_margin", margin, "ratio", checks.grip_margin, ">="));
    r.measurements.push_back(measure(prefix + "pad_contact_area", worst.area, "m^2", checks.pad_contact_area, ">="));
    if (margin < checks.grip_margin) {
      failures.push_back((who.empty() ? "" : who + " ") + "grip margin " + fmt(margin) + " < " + fmt(checks.grip_margin) +
                         ": the load took " + fmt(100.0 * worst.friction_use) + " % of what the pads' friction resists");
    }
    if (worst.area < checks.pad_contact_area) {
      failures.push_back((who.empty() ? "" : who + " ") + "pad contact " + fmt(worst.area * 1e6) + " mm^2 < " +
                         fmt(checks.pad_contact_area * 1e6) + " mm^2");
    }
  }

  /// Pick: both pads on the object after the close command; at the pick's end held, off its
  /// support, lifted by the lift clearance, and within the slip tolerances while lifting.
  void judgePick(const ActionTrack& a, ActionReport& r, std::vector<std::string>& failures) const {
    const core::CheckSettings& checks = world.checks;
    const core::PlanAction& action = *a.action;
    const std::string& object = action.object;
    if (!a.command_time) {
      failures.push_back("grasp: the plan does not close " + action.robot + "'s gripper during the pick");
      return;
    }
    r.measurements.push_back(measure("both_pads_contact", a.both_pads_time ? 1.0 : 0.0, "bool", 1.0, "=="));
    if (!a.both_pads_time) {
      failures.push_back("grasp: after closing at " + fmt(*a.command_time) + " s the pads of " + action.robot +
                         " never both touched " + object);
      return;
    }
    r.observed_start = *a.both_pads_time;
    const HoldEpisode* hold = episodeOf(a.robot, a.object, *a.command_time, action.end);
    r.measurements.push_back(measure("held_at_end", a.held_at_end ? 1.0 : 0.0, "bool", 1.0, "=="));
    r.measurements.push_back(measure("support_contact_at_end", a.support_contact_at_end ? 1.0 : 0.0, "bool", 0.0, "=="));
    r.measurements.push_back(measure("lift_height", a.lift_height, "m", checks.lift_clearance, ">="));
    if (!a.held_at_end) failures.push_back("grasp: " + object + " not held by both pads at the end of the pick");
    if (a.support_contact_at_end) failures.push_back("lift: " + object + " still touches its support at " + fmt(action.end) + " s");
    if (a.lift_height < checks.lift_clearance) {
      failures.push_back("lift: " + object + " raised " + fmt(a.lift_height * 1e3) + " mm < " +
                         fmt(checks.lift_clearance * 1e3) + " mm");
    }
    if (hold != nullptr) {
      // slip while lifting; later slip is judged by the action then in progress
      judgeSlip(*hold, action.end, "", r, failures);
      if (a.held_at_end && !a.support_contact_at_end) r.observed_end = action.end;
    }
  }

  /// Handoff: both grippers hold the object together for the minimum overlap before the giver
  /// opens; then the receiver holds it within the slip tolerances, the giver no longer touches it,
  /// and nothing but the two grippers touched it meanwhile.
  void judgeHandoff(const ActionTrack& a, ActionReport& r, std::vector<std::string>& failures) const {
    const core::PlanAction& action = *a.action;
    const std::string& object = action.object;
    if (!a.command_time || !a.command2_time || *a.command2_time <= *a.command_time) {
      failures.push_back("handoff: the plan must close " + action.receiver + "'s gripper before opening " +
                         action.robot + "'s during the handoff");
      return;
    }
    r.measurements.push_back(measure("overlap", a.overlap, "s", kMinHandoffOverlap, ">="));
    r.measurements.push_back(measure("receiver_holds_at_end", a.held_at_end ? 1.0 : 0.0, "bool", 1.0, "=="));
    r.measurements.push_back(measure("giver_touches_at_end", a.giver_touching_at_end ? 1.0 : 0.0, "bool", 0.0, "=="));
    r.measurements.push_back(measure("foreign_contacts", static_cast<double>(a.foreign_contacts.size()), "count", 0.0, "=="));
    if (a.overlap < kMinHandoffOverlap) {
      failures.push_back("overlap: both grippers held " + object + " together for " + fmt(a.overlap) + " s < " +
                         fmt(kMinHandoffOverlap) + " s");
    }
    if (!a.held_at_end) failures.push_back("transfer: " + action.receiver + " does not hold " + object + " at the end");
    if (a.giver_touching_at_end) failures.push_back("transfer: " + action.robot + " still touches " + object + " at the end");
    for (const std::string& name : a.foreign_contacts) failures.push_back("handoff: " + object + " touched " + name);
    const HoldEpisode* hold = episodeOf(a.receiver, a.object, action.start, action.end);
    if (hold != nullptr) {
      r.observed_start = hold->grasp_time;
      judgeSlip(*hold, action.end, "receiver", r, failures);
    }
    if (a.held_at_end) r.observed_end = *a.command2_time;
  }

  /// A place without a region sets the object aside on a stable surface, to be picked up again:
  /// a settle time after release it is at rest there, flat on a face.
  void judgeSetAside(const ActionTrack& a, ActionReport& r, std::vector<std::string>& failures) const {
    const core::CheckSettings& checks = world.checks;
    const std::string& object = a.action->object;
    if (!a.placement_sampled) {
      failures.push_back("set aside: the run ended before the settle time after release");
      return;
    }
    const double tilt = tiltFromFlat(a.placement_pose);
    const std::optional<double> gap =
        gapToSurface(world, a.placement_pose, world.objects[static_cast<std::size_t>(a.object)].size);
    r.measurements.push_back(measure("speed_after_settle", a.placement_speed, "m/s", checks.rest_speed, "<="));
    r.measurements.push_back(measure("tilt", tilt, "rad", checks.upright_tolerance, "<="));
    r.measurements.push_back(measure("gap_to_surface", gap.value_or(std::numeric_limits<double>::infinity()), "m",
                                     kSurfaceContact, "<="));
    if (a.placement_speed > checks.rest_speed) {
      failures.push_back("set aside: " + object + " still moving at " + fmt(a.placement_speed) + " m/s > " +
                         fmt(checks.rest_speed) + " m/s");
    }
    if (tilt > checks.upright_tolerance) {
      failures.push_back("set aside: " + object + " tilted " + fmt(tilt) + " rad > " + fmt(checks.upright_tolerance) + " rad");
    }
    if (!gap || *gap > kSurfaceContact) {
      failures.push_back("set aside: " + object + (gap ? " rests " + fmt(*gap * 1e3) + " mm off" : " is over no") +
                         " stable surface");
    }
    if (failures.empty()) r.observed_end = *a.placement_time;
  }

  /// Place: a settle time after release the object is at rest inside its region, upright within
  /// the tolerance, and still inside at the end.
  void judgePlace(const ActionTrack& a, ActionReport& r, std::vector<std::string>& failures) const {
    const core::CheckSettings& checks = world.checks;
    const core::PlanAction& action = *a.action;
    const std::string& object = action.object;
    if (!a.command_time) {
      failures.push_back("placement: the plan does not open " + action.robot + "'s gripper during the place");
      return;
    }
    r.observed_start = *a.command_time;
    if (action.region.empty()) {  // set aside on a surface, to be picked up again
      judgeSetAside(a, r, failures);
      return;
    }
    if (a.region < 0) {
      failures.push_back("placement: unknown region " + action.region);
      return;
    }
    if (!a.placement_sampled) {
      failures.push_back("placement: the run ended before the settle time after release");
      return;
    }
    const core::Region& region = world.regions[a.region];
    double outside = 0.0;
    const bool inside = insideRegion(region, a.placement_pose, outside);
    const double tilt = tiltFromFlat(a.placement_pose);
    double final_outside = 0.0;
    const bool stays = insideRegion(region, sim.objectPose(a.object), final_outside);
    r.measurements.push_back(measure("distance_outside_region", outside, "m", 0.0, "<="));
    r.measurements.push_back(measure("speed_after_settle", a.placement_speed, "m/s", checks.rest_speed, "<="));
    r.measurements.push_back(measure("tilt", tilt, "rad", checks.upright_tolerance, "<="));
    r.measurements.push_back(measure("distance_outside_region_at_end", final_outside, "m", 0.0, "<="));
    if (!inside) failures.push_back("placement: " + object + " is " + fmt(outside * 1e3) + " mm outside " + region.name);
    if (a.placement_speed > checks.rest_speed) {
      failures.push_back("placement: " + object + " still moving at " + fmt(a.placement_speed) + " m/s > " +
                         fmt(checks.rest_speed) + " m/s");
    }
    if (tilt > checks.upright_tolerance) {
      failures.push_back("placement: " + object + " tilted " + fmt(tilt) + " rad > " + fmt(checks.upright_tolerance) + " rad");
    }
    if (inside && !stays) failures.push_back("placement: " + object + " left " + region.name + " before the end");
    if (inside && a.placement_speed <= checks.rest_speed) r.observed_end = *a.placement_time;
  }

  /// Records the cell's protective stop as an event, once, when it happens.
  void observeProtectiveStop(const PlanExecutor& executor) {
    const std::optional<ProtectiveStop>& stop = executor.protectiveStop();
    if (!stop || stop_recorded) return;
    stop_recorded = true;
    const controllers::ProtectiveStopTrip& trip = stop->trip;
    const std::string& robot = world.robots[static_cast<std::size_t>(stop->robot)].name;
    const std::string what =
        controllers::describeTrip(trip, trip.joint >= 0 ? jointName(stop->robot, trip.joint) : std::string());
    addEvent(stop->t, "protective stop", robot + " " + what + "; the cell stopped", attribute(stop->robot, -1, stop->t),
             stop->tcp_W);
  }

  /// The execution: no event but slips (judged by the actions; a joint off its path by more
  /// than the tracking limit is a protective stop event), and every object the world's goals
  /// send to a region inside it at the end. Returns the failures; fills the report's per-robot
  /// execution numbers.
  std::vector<std::string> judgeExecution(const PlanExecutor& executor, Report& report) const {
    std::vector<std::string> failures;
    for (std::size_t r = 0; r < world.robots.size(); ++r) {
      const TrackingStats& stats = executor.tracking(static_cast<int>(r));
      RobotExecution execution;
      execution.robot = world.robots[r].name;
      execution.max_tracking_error = stats.max_tracking_error;
      execution.torque_saturation = stats.steps > 0 ? static_cast<double>(stats.saturated_steps) / static_cast<double>(stats.steps) : 0.0;
      execution.max_effort_ratio = stats.max_effort_ratio;
      execution.max_tcp_force = executor.collisionDetection(static_cast<int>(r)).maxTcpForce();
      execution.max_external_torque_ratio = executor.collisionDetection(static_cast<int>(r)).maxTorqueRatio();
      report.robots.push_back(execution);
    }
    for (const ExecutionEvent& event : events) {
      if (event.kind == "slip") continue;  // judged by the grasp and handoff checks
      failures.push_back(event.kind + " at " + fmt(event.t) + " s: " + event.detail);
    }
    // the world's goals: every object sent to a region ends inside it, placed by the plan or not
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
      const core::ObjectSpec& object = world.objects[o];
      const core::Region* region = world.goalRegionOf(object);
      double outside = 0.0;
      if (region != nullptr && !insideRegion(*region, sim.objectPose(static_cast<int>(o)), outside)) {
        failures.push_back("goal: " + object.name + " ends " + fmt(outside * 1e3) + " mm outside " + region->name);
      }
    }
    return failures;
  }

  static std::string actionId(const core::PlanAction& a) {
    switch (a.type) {
      case ActionType::kPick: return "pick " + a.object + " by " + a.robot;
      case ActionType::kPlace:
        return a.region.empty() ? "set aside " + a.object + " by " + a.robot
                                : "place " + a.object + " in " + a.region + " by " + a.robot;
      case ActionType::kHandoff: return "handoff " + a.object + " from " + a.robot + " to " + a.receiver;
    }
    return "?";
  }
};

Monitor::Monitor(const Simulation& sim, const core::Plan& plan, double plan_time_offset)
    : state_(std::make_unique<State>(sim, plan, plan_time_offset)) {
  State& s = *state_;
  for (const auto& robot : sim.robots().robots()) {
    s.left_finger.push_back(robot.model->requireLink("hande_left_finger"));
    s.right_finger.push_back(robot.model->requireLink("hande_right_finger"));
    for (const int finger : {s.left_finger.back(), s.right_finger.back()}) {
      const auto& shapes = robot.model->links()[static_cast<std::size_t>(finger)].collisions;
      const auto pad = std::find_if(shapes.begin(), shapes.end(), [](const core::CollisionShape& c) { return c.name == "pad"; });
      if (pad == shapes.end()) throw std::invalid_argument("Monitor: a finger of the robot model has no collision named 'pad'");
      (finger == s.left_finger.back() ? s.left_pad : s.right_pad).push_back(*pad);
    }
    s.tcp.push_back(robot.model->requireLink("tcp"));
  }
  s.active_hold.assign(s.world.robots.size(), -1);
  for (std::size_t o = 0; o < s.world.objects.size(); ++o) {
    s.rest_pose.push_back(sim.objectPose(static_cast<int>(o)));
    s.start_z.push_back(s.world.objects[o].X_WO.translation().z());
  }
  s.knocked.assign(s.world.objects.size(), false);
  s.settling.assign(s.world.objects.size(), false);
  s.rest_since.assign(s.world.objects.size(), std::nullopt);
  s.last_toucher.assign(s.world.objects.size(), -1);
  for (const core::PlanAction& action : plan.actions) {
    ActionTrack track;
    track.action = &action;
    track.robot = s.robotIndex(action.robot);
    track.receiver = s.robotIndex(action.receiver);
    track.object = s.objectIndex(action.object);
    if (!action.region.empty()) {
      for (std::size_t g = 0; g < s.world.regions.size(); ++g) {
        if (s.world.regions[g].name == action.region) track.region = static_cast<int>(g);
      }
    }
    // the gripper commands that carry the action out
    for (const core::GripperCommand& c : plan.gripper) {
      if (c.t < action.start - 1e-9 || c.t > action.end + 1e-9) continue;
      if (action.type == ActionType::kPick && c.robot == action.robot && c.action == GripperAction::kClose &&
          !track.command_time) {
        track.command_time = c.t;
      }
      if (action.type == ActionType::kPlace && c.robot == action.robot && c.action == GripperAction::kOpen &&
          !track.command_time) {
        track.command_time = c.t;
      }
      if (action.type == ActionType::kHandoff) {
        if (c.robot == action.receiver && c.action == GripperAction::kClose && !track.command_time) track.command_time = c.t;
        if (c.robot == action.robot && c.action == GripperAction::kOpen && !track.command2_time) track.command2_time = c.t;
      }
    }
    s.actions.push_back(track);
  }
}

Monitor::~Monitor() = default;

const std::vector<ExecutionEvent>& Monitor::events() const { return state_->events; }

void Monitor::observe(const PlanExecutor& executor) {
  State& s = *state_;
  const double t = s.planTime();
  const StepContacts now = s.contactsNow(t);
  s.reportUnplannedContacts(now, t);
  s.trackHolds(executor, now, t);
  s.trackRestingObjects(now, t);
  s.observeActions(now, t);
  s.observeProtectiveStop(executor);
}

Report Monitor::finish(const PlanExecutor& executor) {
  State& s = *state_;
  Report report;
  report.world = s.world.name;
  report.seed = s.plan.seed;
  report.time_step = s.sim.timeStep();
  report.simulated_time = s.planTime();
  for (const ActionTrack& a : s.actions) {
    const core::PlanAction& action = *a.action;
    ActionReport r;
    r.id = State::actionId(action);
    r.type = action.type;
    r.robots.push_back(action.robot);
    if (!action.receiver.empty()) r.robots.push_back(action.receiver);
    r.object = action.object;
    r.region = action.region;
    r.planned_start = action.start;
    r.planned_end = action.end;
    std::vector<std::string> failures;
    switch (action.type) {
      case ActionType::kPick:
        s.judgePick(a, r, failures);
        break;
      case ActionType::kHandoff:
        s.judgeHandoff(a, r, failures);
        break;
      case ActionType::kPlace:
        s.judgePlace(a, r, failures);
        break;
    }
    // drops and slips attributed to this action fail it too
    for (const ExecutionEvent& event : s.events) {
      if (event.action == r.id && (event.kind == "drop" || event.kind == "knocked object" || event.kind == "slip")) {
        failures.push_back(event.kind + " at " + fmt(event.t) + " s: " + event.detail);
      }
    }
    r.verdict = failures.empty() ? Verdict::kPassed : Verdict::kFailed;
    for (std::size_t i = 0; i < failures.size(); ++i) r.failure += (i ? "; " : "") + failures[i];
    report.actions.push_back(std::move(r));
  }

  const std::vector<std::string> failures = s.judgeExecution(executor, report);
  std::sort(s.events.begin(), s.events.end(), [](const ExecutionEvent& x, const ExecutionEvent& y) { return x.t < y.t; });
  report.events = s.events;
  report.execution_verdict = failures.empty() ? Verdict::kPassed : Verdict::kFailed;
  for (std::size_t i = 0; i < failures.size(); ++i) report.execution_failure += (i ? "; " : "") + failures[i];
  return report;
}

}  // namespace dashbed::sim
