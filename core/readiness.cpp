#include "core/readiness.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/dynamics.h"
#include "core/grasps.h"
#include "core/hande.h"
#include "core/kinematics.h"
#include "core/number_text.h"
#include "core/trajectory_interpolator.h"

namespace dashbed::core {
namespace {

constexpr double kSlack = 1e-9;  // rounding slack of the comparisons

std::string text(double x) { return significantText(x, 4); }

const PlacedRobot* robotNamed(const World& world, const RobotSet& robots, const std::string& name) {
  for (std::size_t r = 0; r < world.robots.size(); ++r) {
    if (world.robots[r].name == name) return &robots[r];
  }
  return nullptr;
}

const ObjectSpec* objectNamed(const World& world, const std::string& name) {
  for (const ObjectSpec& object : world.objects) {
    if (object.name == name) return &object;
  }
  return nullptr;
}

/// The mass carried at the flange with nothing held: every link from `tool0` on (coupling,
/// gripper, fingers) [kg].
double gripperMass(const RobotModel& model) {
  const int tool0 = model.requireLink("tool0");
  double mass = 0.0;
  for (std::size_t l = 0; l < model.links().size(); ++l) {
    for (int link = static_cast<int>(l); link >= 0;) {
      if (link == tool0) {
        mass += model.links()[l].mass;
        break;
      }
      const int joint = model.links()[link].parent_joint;
      link = joint < 0 ? -1 : model.joints()[joint].parent_link;
    }
  }
  return mass;
}

/// Makes `check` the joint's when `value` is a larger fraction of its `limit` than `worst`, the
/// largest so far: "SUBJECT VERB VALUE UNIT at T s on the plan's curve, above LIMIT_WORDS ...".
void keepWorst(ReadinessCheck& check, double& worst, const std::string& subject, double value, double limit, double t,
               const char* verb, const char* limit_words) {
  if (value / limit <= worst) return;
  worst = value / limit;
  check.subject = subject;
  check.value = value;
  check.limit = limit;
  check.t = t;
  check.passed = value <= limit * (1.0 + kSlack);
  check.detail = check.passed ? "" : subject + " " + verb + " " + text(value) + " " + check.unit + " at " + text(t) +
                                         " s on the plan's curve, above " + limit_words + " " + text(limit) + " " +
                                         check.unit;
}

/// Joint position, speed and acceleration of one robot's trajectory, the worst joint of each.
void checkCurve(const RobotTrajectory& trajectory, const RobotModel& model, const SafetySettings& safety,
                std::vector<ReadinessCheck>& checks) {
  if (trajectory.points.empty()) return;
  const std::array<JointPeaks, 6> peaks = TrajectoryInterpolator(trajectory.points).peaks();
  ReadinessCheck position{"joint position", trajectory.robot, 0.0, 0.0, "rad", 0.0, true, ""};
  ReadinessCheck speed{"joint speed", trajectory.robot, 0.0, 0.0, "rad/s", 0.0, true, ""};
  ReadinessCheck acceleration{"joint acceleration", trajectory.robot, 0.0, safety.max_joint_acceleration, "rad/s^2",
                              0.0, true, ""};
  // the worst joint of each: position by how far beyond its limits [rad], the others as fractions of
  // their limits
  double worst_position = -std::numeric_limits<double>::infinity(), worst_speed = -1.0, worst_acceleration = -1.0;
  for (int j = 0; j < 6; ++j) {
    const JointModel& joint = model.joints()[model.movableJoints()[j]];
    const JointPeaks& p = peaks[j];
    const std::string subject = trajectory.robot + " " + joint.name;
    // position: how far the extremes go beyond the limits (<= 0 inside)
    const double below = joint.lower - p.q_min, above = p.q_max - joint.upper;
    const double beyond = std::max(below, above);
    if (beyond > worst_position) {
      worst_position = beyond;
      const bool low = below >= above;
      position.subject = subject;
      position.value = low ? p.q_min : p.q_max;
      position.limit = low ? joint.lower : joint.upper;
      position.t = low ? p.t_q_min : p.t_q_max;
      position.passed = beyond <= kSlack;
      position.detail = position.passed ? "" : subject + " reaches " + text(position.value) + " rad at " +
                                                   text(position.t) + " s, beyond its limit " +
                                                   text(position.limit) + " rad";
    }
    keepWorst(speed, worst_speed, subject, p.speed, joint.max_velocity, p.t_speed, "moves at", "its limit");
    keepWorst(acceleration, worst_acceleration, subject, p.acceleration, safety.max_joint_acceleration,
              p.t_acceleration, "accelerates at", "the limit");
  }
  checks.push_back(position);
  checks.push_back(speed);
  checks.push_back(acceleration);
}

/// The force [N] of `robot`'s first closing command within [from, to]: the command's own, or
/// the world's grip force for 0; the world's when there is none.
double gripForce(const Plan& plan, const World& world, const std::string& robot, double from, double to) {
  for (const GripperCommand& c : plan.gripper) {
    if (c.robot == robot && c.action == GripperAction::kClose && c.t >= from - kSlack && c.t <= to + kSlack) {
      return c.force > 0.0 ? c.force : world.controller.grip_force;
    }
  }
  return world.controller.grip_force;
}

/// What `robot` holds when: from each closing command within a pick (or a handoff it
/// receives) to its next opening command, that action's object.
struct Hold {
  double from = 0.0, to = 0.0;
  const ObjectSpec* object = nullptr;
};
std::vector<Hold> holdsOf(const Plan& plan, const World& world, const std::string& robot) {
  std::vector<Hold> holds;
  for (std::size_t i = 0; i < plan.gripper.size(); ++i) {
    const GripperCommand& close = plan.gripper[i];
    if (close.robot != robot || close.action != GripperAction::kClose) continue;
    const ObjectSpec* object = nullptr;
    for (const PlanAction& a : plan.actions) {
      const std::string& holder = a.type == ActionType::kHandoff ? a.receiver : a.robot;
      if (a.type != ActionType::kPlace && holder == robot && close.t >= a.start - kSlack && close.t <= a.end + kSlack) {
        object = objectNamed(world, a.object);
      }
    }
    if (object == nullptr) continue;
    Hold hold{close.t, std::numeric_limits<double>::infinity(), object};
    for (std::size_t k = i + 1; k < plan.gripper.size(); ++k) {
      if (plan.gripper[k].robot == robot && plan.gripper[k].action == GripperAction::kOpen) {
        hold.to = plan.gripper[k].t;
        break;
      }
    }
    holds.push_back(hold);
  }
  return holds;
}

/// Along the curve at every simulation step: the joint efforts it needs (inverse dynamics, the
/// held object a point mass at the TCP) against the model's effort limits, the worst joint; and
/// the TCP's speed against the safety limit.
void checkDynamics(const Plan& plan, const World& world, const RobotTrajectory& trajectory, const PlacedRobot& robot,
                   std::vector<ReadinessCheck>& checks) {
  if (trajectory.points.empty()) return;
  const RobotModel& model = *robot.model;
  const TrajectoryInterpolator curve(trajectory.points);
  const std::vector<Hold> holds = holdsOf(plan, world, trajectory.robot);
  const Eigen::Vector3d gravity_R = robot.spec->X_WBase.linear().transpose() * world.physics.gravity;
  const int tcp = model.requireLink("tcp");
  const int n = model.numPositions();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n), qd = Eigen::VectorXd::Zero(n), qdd = Eigen::VectorXd::Zero(n);
  for (int i = 6; i < n; ++i) q[i] = model.joints()[model.movableJoints()[i]].upper;
  ReadinessCheck effort{"joint effort", trajectory.robot, 0.0, 0.0, "Nm", 0.0, true, ""};
  ReadinessCheck tcp_speed{"tcp speed", trajectory.robot, 0.0, world.safety.tcp_speed, "m/s", 0.0, true, ""};
  double worst = -1.0;
  const double step = world.physics.time_step;
  const auto steps = static_cast<long>(std::ceil((curve.endTime() - curve.startTime()) / step));
  for (long k = 0; k <= steps; ++k) {
    const double t = std::min(curve.startTime() + static_cast<double>(k) * step, curve.endTime());
    const JointReference ref = curve.at(t);
    for (int j = 0; j < 6; ++j) q[j] = ref.q[j], qd[j] = ref.qd[j], qdd[j] = ref.qdd[j];
    Payload payload;
    const Payload* carried = nullptr;
    for (const Hold& h : holds) {
      if (t >= h.from && t < h.to) {
        payload.link = tcp;
        payload.mass = h.object->mass;
        carried = &payload;
      }
    }
    const Eigen::VectorXd tau = inverseDynamics(model, q, qd, qdd, gravity_R, carried);
    for (int j = 0; j < 6; ++j) {
      const JointModel& joint = model.joints()[model.movableJoints()[j]];
      const double ratio = std::abs(tau[j]) / joint.max_effort;
      if (ratio <= worst) continue;
      worst = ratio;
      effort.subject = trajectory.robot + " " + joint.name;
      effort.value = std::abs(tau[j]);
      effort.limit = joint.max_effort;
      effort.t = t;
    }
    const double speed = (jacobian(model, q, tcp).topRows<3>() * qd).norm();
    if (speed > tcp_speed.value) tcp_speed.value = speed, tcp_speed.t = t;
  }
  effort.passed = effort.value <= effort.limit;
  if (!effort.passed) {
    effort.detail = effort.subject + " needs " + text(effort.value) + " Nm at " + text(effort.t) +
                    " s to follow the plan's curve, above its limit " + text(effort.limit) + " Nm";
  }
  checks.push_back(effort);
  tcp_speed.passed = tcp_speed.value <= tcp_speed.limit * (1.0 + kSlack);
  if (!tcp_speed.passed) {
    tcp_speed.detail = trajectory.robot + "'s TCP moves at " + text(tcp_speed.value) + " m/s at " + text(tcp_speed.t) +
                       " s on the plan's curve, above the safety limit " + text(tcp_speed.limit) + " m/s";
  }
  checks.push_back(tcp_speed);
}

}  // namespace

bool ReadinessReport::ready() const {
  return std::all_of(checks.begin(), checks.end(), [](const ReadinessCheck& c) { return c.passed; });
}

std::string ReadinessReport::failures() const {
  std::string text;
  for (const ReadinessCheck& c : checks) {
    if (!c.passed) text += (text.empty() ? "" : "; ") + c.detail;
  }
  return text;
}

ReadinessReport checkReadiness(const Plan& plan, const World& world, const RobotSet& robots) {
  ReadinessReport report;
  for (const RobotTrajectory& trajectory : plan.trajectories) {
    if (const PlacedRobot* robot = robotNamed(world, robots, trajectory.robot)) {
      checkCurve(trajectory, *robot->model, world.safety, report.checks);
      checkDynamics(plan, world, trajectory, *robot, report.checks);
    }
  }
  // gripper commands: a force of 0 means the world's grip force, anything else must be one the
  // Hand-E can apply
  for (std::size_t i = 0; i < plan.gripper.size(); ++i) {
    const GripperCommand& c = plan.gripper[i];
    if (c.action != GripperAction::kClose || c.force == 0.0) continue;
    ReadinessCheck check{"gripper force", "gripper command " + std::to_string(i) + " (" + c.robot + " close at " +
                                              text(c.t) + " s)",
                         c.force, c.force < kHandeMinForce ? kHandeMinForce : kHandeMaxForce, "N", c.t, true, ""};
    check.passed = c.force >= kHandeMinForce && c.force <= kHandeMaxForce;
    if (!check.passed) {
      check.detail = check.subject + " asks for " + text(c.force) + " N, outside the Hand-E's " +
                     text(kHandeMinForce) + "-" + text(kHandeMaxForce) + " N";
    }
    report.checks.push_back(check);
  }
  // what each robot picks or receives: payload at the flange, and the grip by friction
  for (const PlanAction& action : plan.actions) {
    if (action.type == ActionType::kPlace) continue;
    const std::string& holder = action.type == ActionType::kPick ? action.robot : action.receiver;
    const PlacedRobot* robot = robotNamed(world, robots, holder);
    const ObjectSpec* object = objectNamed(world, action.object);
    if (robot == nullptr || object == nullptr) continue;
    const std::string subject = holder + " holding " + object->name;
    const double carried = gripperMass(*robot->model) + object->mass;
    const double rated = world.safety.payload;
    ReadinessCheck payload{"payload", subject, carried, rated, "kg", action.start, carried <= rated, ""};
    if (!payload.passed) {
      payload.detail = subject + " carries " + text(carried) + " kg with the gripper, above the UR5e's rated " +
                       text(rated) + " kg";
    }
    report.checks.push_back(payload);
    const double force = gripForce(plan, world, holder, action.start, action.end);
    const double holds =
        frictionHoldMass(object->friction * world.physics.pad_friction, force, world.physics.gravity.norm());
    ReadinessCheck grip{"grip", subject, object->mass, holds, "kg", action.start, object->mass <= holds, ""};
    if (!grip.passed) {
      grip.detail = subject + ": " + text(object->mass) + " kg, but a " + text(force) + " N grip with friction " +
                    text(object->friction * world.physics.pad_friction) + " holds at most " + text(holds) + " kg";
    }
    report.checks.push_back(grip);
  }
  return report;
}

}  // namespace dashbed::core
