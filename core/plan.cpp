// Plan files (JSON, version 1): reading, structural checks, checks against a world, writing.
//
// Reading has two layers. parsePlanJson walks the JSON document along the format's schema
// and checks each value's type and key set, then builds the Plan; checkPlanStructure then
// checks the Plan as a whole (times, ranges, cross-references between fields). Both name
// the offending field by its RFC 6901 JSON pointer, "FILE: /robots/0/points/3/t: what".
// Pointers of in-memory plans are those the fields get in writePlanJson's output.

#include "core/plan.h"

#include "core/hande.h"
#include "core/json_pointer.h"
#include "core/json_reader.h"
#include "core/number_text.h"
#include "core/input_text.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <set>
#include <sstream>
#include <system_error>
#include <utility>

namespace dashbed::core {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr double kVelocitySlack = 1.01;   // segment speeds may exceed max_velocity by 1 %
constexpr double kLimitSlack = 1e-9;      // joint limits: rounding slack [rad]
constexpr double kTimeSlack = 1e-9;       // action ends vs. the end of the motion [s]

// ---- formatting -------------------------------------------------------------------------

// shortest text that reads back to exactly x: for values the user wrote
std::string exact(double x) { return shortestText(x); }

// six significant digits: for derived values (speeds) and model limits
std::string brief(double x) { return significantText(x, 6); }

std::string inQuotes(std::string_view text) { return "'" + std::string(text) + "'"; }

// "a, b, c" of at most `max_names` names, then ", ..."
template <typename Range, typename GetName>
std::string nameList(const Range& items, GetName get_name, std::size_t max_names = 12) {
  std::string text;
  std::size_t count = 0;
  for (const auto& item : items) {
    if (count == max_names) return text + ", ...";
    if (count++ > 0) text += ", ";
    text += get_name(item);
  }
  return text.empty() ? "none" : text;
}

// ---- JSON pointers (RFC 6901) -----------------------------------------------------------

std::string at(const std::string& pointer, std::string_view key) { return jsonPointerAt(pointer, key); }
std::string at(const std::string& pointer, std::size_t index) { return jsonPointerAt(pointer, index); }

[[noreturn]] void fail(const std::string& file, const std::string& pointer,
                       const std::string& what) {
  throw PlanError(SourceLocation{file}, pointer.empty() ? "/" : pointer, what);
}

// ---- JSON document -> Plan ----------------------------------------------------------------

using PlanReader = JsonReader<PlanError>;

// exactly six numbers; `what` e.g. "joint positions"
std::array<double, 6> sixNumbers(const PlanReader& reader, const Json& value, const std::string& pointer,
                                 std::string_view what) {
  reader.array(value, pointer);
  if (value.size() != 6) {
    reader.fail(pointer, "expected 6 " + std::string(what) + ", got " + std::to_string(value.size()));
  }
  std::array<double, 6> numbers{};
  for (std::size_t i = 0; i < 6; ++i) numbers[i] = reader.number(value[i], at(pointer, i));
  return numbers;
}

TrajectoryPoint readPoint(const PlanReader& reader, const Json& value, const std::string& pointer) {
  reader.expectObject(value, pointer, {"t", "q", "qd"});
  TrajectoryPoint point;
  point.t = reader.number(reader.required(value, pointer, "t"), at(pointer, "t"));
  point.q =
      sixNumbers(reader, reader.required(value, pointer, "q"), at(pointer, "q"), "joint positions");
  if (const Json* qd = reader.optional(value, "qd")) {
    point.qd = sixNumbers(reader, *qd, at(pointer, "qd"), "joint velocities");
  }
  return point;
}

RobotTrajectory readRobot(const PlanReader& reader, const Json& value, const std::string& pointer) {
  reader.expectObject(value, pointer, {"name", "joint_names", "points"});
  RobotTrajectory trajectory;
  trajectory.robot = reader.string(reader.required(value, pointer, "name"), at(pointer, "name"));

  const std::string names_pointer = at(pointer, "joint_names");
  const Json& names = reader.array(reader.required(value, pointer, "joint_names"), names_pointer);
  if (names.size() != 6) {
    reader.fail(names_pointer, "expected 6 joint names, got " + std::to_string(names.size()));
  }
  for (std::size_t i = 0; i < 6; ++i) {
    trajectory.joint_names[i] = reader.string(names[i], at(names_pointer, i));
  }

  const std::string points_pointer = at(pointer, "points");
  const Json& points = reader.array(reader.required(value, pointer, "points"), points_pointer);
  for (std::size_t i = 0; i < points.size(); ++i) {
    trajectory.points.push_back(readPoint(reader, points[i], at(points_pointer, i)));
  }
  return trajectory;
}

GripperCommand readGripperCommand(const PlanReader& reader, const Json& value,
                                  const std::string& pointer) {
  reader.expectObject(value, pointer, {"robot", "t", "command", "force"});
  GripperCommand command;
  command.robot = reader.string(reader.required(value, pointer, "robot"), at(pointer, "robot"));
  command.t = reader.number(reader.required(value, pointer, "t"), at(pointer, "t"));
  const std::string name =
      reader.string(reader.required(value, pointer, "command"), at(pointer, "command"));
  if (name == "open") {
    command.action = GripperAction::kOpen;
  } else if (name == "close") {
    command.action = GripperAction::kClose;
  } else {
    reader.fail(at(pointer, "command"),
                "unknown command " + inQuotes(name) + " (expected open or close)");
  }
  if (const Json* force = reader.optional(value, "force")) {
    command.force = reader.number(*force, at(pointer, "force"));
  }
  return command;
}

PlanAction readAction(const PlanReader& reader, const Json& value, const std::string& pointer) {
  reader.expectType(value, pointer, value.is_object(), "an object");
  PlanAction action;
  const std::string type =
      reader.string(reader.required(value, pointer, "type"), at(pointer, "type"));
  if (type == "pick") {
    action.type = ActionType::kPick;
    reader.expectObject(value, pointer, {"type", "robot", "object", "start", "end"});
  } else if (type == "place") {
    action.type = ActionType::kPlace;
    reader.expectObject(value, pointer, {"type", "robot", "object", "region", "start", "end"});
  } else if (type == "handoff") {
    action.type = ActionType::kHandoff;
    reader.expectObject(value, pointer, {"type", "giver", "receiver", "object", "start", "end"});
  } else {
    reader.fail(at(pointer, "type"),
                "unknown action type " + inQuotes(type) + " (expected pick, place or handoff)");
  }

  const auto text = [&](std::string_view key, std::string_view context) {
    return reader.string(reader.required(value, pointer, key, context), at(pointer, key));
  };
  if (action.type == ActionType::kHandoff) {
    action.robot = text("giver", "a handoff names its giver and receiver");
    action.receiver = text("receiver", "a handoff names its giver and receiver");
  } else {
    action.robot = text("robot", "a " + type + " names its robot");
  }
  action.object = text("object", "every action names its object");
  if (action.type == ActionType::kPlace && value.contains("region")) {  // none: set aside on a surface
    action.region = reader.string(value.at("region"), at(pointer, "region"));
    if (action.region.empty()) reader.fail(at(pointer, "region"), "a region name must not be empty (leave the field out to set the object aside)");
  }
  action.start = reader.number(reader.required(value, pointer, "start"), at(pointer, "start"));
  action.end = reader.number(reader.required(value, pointer, "end"), at(pointer, "end"));
  return action;
}

Plan readPlan(const PlanReader& reader, const Json& document) {
  if (!document.is_object()) reader.fail("", "expected a JSON object, got " + describeJsonValue(document));

  // the version first: a file of another kind or version fails on it, not on its keys
  reader.formatVersion(document, "dashbed_plan", kPlanFormatVersion, "plan");
  reader.expectObject(
      document, "",
      {"dashbed_plan", "world", "seed", "robots", "gripper", "actions", "statistics"});

  Plan plan;
  plan.world = reader.string(reader.required(document, "", "world"), "/world");
  if (const Json* seed = reader.optional(document, "seed")) {
    if (!seed->is_number_unsigned()) {
      reader.fail("/seed", "expected a non-negative integer, got " +
                               (seed->is_number() ? seed->dump() : describeJsonValue(*seed)));
    }
    plan.seed = seed->get<std::uint64_t>();
  }

  const Json& robots = reader.array(reader.required(document, "", "robots"), "/robots");
  for (std::size_t i = 0; i < robots.size(); ++i) {
    plan.trajectories.push_back(readRobot(reader, robots[i], at("/robots", i)));
  }
  const Json& gripper = reader.array(reader.required(document, "", "gripper"), "/gripper");
  for (std::size_t i = 0; i < gripper.size(); ++i) {
    plan.gripper.push_back(readGripperCommand(reader, gripper[i], at("/gripper", i)));
  }
  const Json& actions = reader.array(reader.required(document, "", "actions"), "/actions");
  for (std::size_t i = 0; i < actions.size(); ++i) {
    plan.actions.push_back(readAction(reader, actions[i], at("/actions", i)));
  }
  if (const Json* statistics = reader.optional(document, "statistics")) {
    reader.expectType(*statistics, "/statistics", statistics->is_object(), "an object");
    plan.statistics = *statistics;
  }
  return plan;
}

// ---- structural checks ------------------------------------------------------------------

std::string robotPointer(std::size_t i) { return at("/robots", i); }
std::string pointPointer(std::size_t robot, std::size_t point) {
  return at(at(robotPointer(robot), "points"), point);
}
std::string gripperPointer(std::size_t i) { return at("/gripper", i); }
std::string actionPointer(std::size_t i) { return at("/actions", i); }

// the key the acting robot has in the file: "giver" for handoffs
std::string_view robotKey(const PlanAction& action) {
  return action.type == ActionType::kHandoff ? "giver" : "robot";
}

void checkName(const std::string& file, const std::string& pointer, const std::string& name) {
  if (name.empty()) fail(file, pointer, "empty name");
}

/// Plan times beyond this are typos; a simulation of them would not end [s] (a day).
constexpr double kMaxPlanTime = 86400.0;

void checkTime(const std::string& file, const std::string& pointer, double t) {
  if (!std::isfinite(t)) fail(file, pointer, "not a finite number (" + exact(t) + ")");
  if (t < 0.0) fail(file, pointer, "negative time " + exact(t) + " s");
  if (t > kMaxPlanTime) fail(file, pointer, "time " + exact(t) + " s beyond a day (" + exact(kMaxPlanTime) + " s)");
}

void checkSix(const std::string& file, const std::string& pointer,
              const std::array<double, 6>& values) {
  for (std::size_t j = 0; j < 6; ++j) {
    if (!std::isfinite(values[j])) {
      fail(file, at(pointer, j), "not a finite number (" + exact(values[j]) + ")");
    }
  }
}

void checkTrajectories(const Plan& plan, const std::string& file) {
  std::map<std::string, std::size_t> first_entry;
  for (std::size_t r = 0; r < plan.trajectories.size(); ++r) {
    const RobotTrajectory& trajectory = plan.trajectories[r];
    const std::string pointer = robotPointer(r);
    checkName(file, at(pointer, "name"), trajectory.robot);
    const auto [it, inserted] = first_entry.emplace(trajectory.robot, r);
    if (!inserted) {
      fail(file, at(pointer, "name"),
           "duplicate robot " + inQuotes(trajectory.robot) + " (also " + robotPointer(it->second) +
               ")");
    }
    if (trajectory.points.empty()) {
      fail(file, at(pointer, "points"), "a robot needs at least one point");
    }
    for (std::size_t p = 0; p < trajectory.points.size(); ++p) {
      const TrajectoryPoint& point = trajectory.points[p];
      const std::string point_pointer = pointPointer(r, p);
      checkTime(file, at(point_pointer, "t"), point.t);
      if (p > 0 && !(point.t > trajectory.points[p - 1].t)) {
        fail(file, at(point_pointer, "t"),
             "times must increase (" + exact(point.t) + " after " +
                 exact(trajectory.points[p - 1].t) + ")");
      }
      checkSix(file, at(point_pointer, "q"), point.q);
      if (point.qd) checkSix(file, at(point_pointer, "qd"), *point.qd);
    }
  }
}

void checkGripper(const Plan& plan, const std::string& file) {
  std::map<std::pair<std::string, double>, std::size_t> first_command;  // (robot, t) -> index
  for (std::size_t i = 0; i < plan.gripper.size(); ++i) {
    const GripperCommand& command = plan.gripper[i];
    const std::string pointer = gripperPointer(i);
    checkName(file, at(pointer, "robot"), command.robot);
    checkTime(file, at(pointer, "t"), command.t);
    if (i > 0 && command.t < plan.gripper[i - 1].t) {
      fail(file, at(pointer, "t"),
           "gripper commands must be sorted by time (" + exact(command.t) + " after " +
               exact(plan.gripper[i - 1].t) + ")");
    }
    const auto [it, inserted] = first_command.emplace(std::pair{command.robot, command.t}, i);
    if (!inserted) {
      fail(file, at(pointer, "t"),
           "robot " + inQuotes(command.robot) + " already has a gripper command at " +
               exact(command.t) + " s (" + gripperPointer(it->second) + ")");
    }
    if (!std::isfinite(command.force) || command.force < 0.0 || command.force > kHandeMaxForce) {
      fail(file, at(pointer, "force"),
           exact(command.force) + " N outside [0, " + brief(kHandeMaxForce) +
               "] N (0: the world's grip force; 185 N: the Hand-E maximum)");
    }
  }
}

void checkActions(const Plan& plan, const std::string& file) {
  for (std::size_t i = 0; i < plan.actions.size(); ++i) {
    const PlanAction& action = plan.actions[i];
    const std::string pointer = actionPointer(i);
    checkName(file, at(pointer, robotKey(action)), action.robot);
    if (action.type == ActionType::kHandoff) {
      checkName(file, at(pointer, "receiver"), action.receiver);
      if (action.receiver == action.robot) {
        fail(
            file, at(pointer, "receiver"),
            "the receiver is the giver " + inQuotes(action.robot) + "; a handoff needs two robots");
      }
    } else if (!action.receiver.empty()) {
      fail(file, at(pointer, "receiver"),
           "only handoffs have a receiver, this is a " + std::string(toString(action.type)));
    }
    checkName(file, at(pointer, "object"), action.object);
    if (action.type == ActionType::kPlace) {
      if (!action.region.empty()) checkName(file, at(pointer, "region"), action.region);
    } else if (!action.region.empty()) {
      fail(file, at(pointer, "region"),
           "only place actions have a region, this is a " + std::string(toString(action.type)));
    }
    checkTime(file, at(pointer, "start"), action.start);
    checkTime(file, at(pointer, "end"), action.end);
    if (action.end < action.start) {
      fail(file, at(pointer, "end"),
           "ends at " + exact(action.end) + " s, before its start " + exact(action.start) + " s");
    }
    if (i > 0 && action.start < plan.actions[i - 1].start) {
      fail(file, at(pointer, "start"),
           "actions must be sorted by start time (" + exact(action.start) + " after " +
               exact(plan.actions[i - 1].start) + ")");
    }
  }
}

// ---- writing ------------------------------------------------------------------------------

OrderedJson sixToJson(const std::array<double, 6>& values) {
  OrderedJson array = OrderedJson::array();
  for (const double value : values) array.push_back(value);
  return array;
}

bool isScalar(const OrderedJson& value) { return !value.is_structured(); }

void formatInto(const OrderedJson& value, int indent, std::string& out) {
  const auto scalar = [](const OrderedJson& v) {
    return v.dump(-1, ' ', false, OrderedJson::error_handler_t::replace);
  };
  if (!value.is_structured()) {
    out += scalar(value);
    return;
  }
  if (value.empty()) {
    out += value.is_object() ? "{}" : "[]";
    return;
  }
  if (value.is_array() && std::all_of(value.begin(), value.end(), isScalar)) {
    out += '[';
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (i > 0) out += ", ";
      out += scalar(value[i]);
    }
    out += ']';
    return;
  }
  out += value.is_object() ? "{\n" : "[\n";
  bool first = true;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out.append(static_cast<std::size_t>(indent + 2), ' ');
    if (value.is_object()) {
      out += scalar(OrderedJson(it.key()));
      out += ": ";
    }
    formatInto(*it, indent + 2, out);
  }
  out += '\n';
  out.append(static_cast<std::size_t>(indent), ' ');
  out += value.is_object() ? '}' : ']';
}

}  // namespace

// ---- public -------------------------------------------------------------------------------

double Plan::duration() const {
  double end = 0.0;
  for (const RobotTrajectory& trajectory : trajectories) {
    if (!trajectory.points.empty()) end = std::max(end, trajectory.points.back().t);
  }
  for (const GripperCommand& command : gripper) end = std::max(end, command.t);
  for (const PlanAction& action : actions) end = std::max(end, action.end);
  return end;
}

std::string_view toString(ActionType type) {
  switch (type) {
    case ActionType::kPick:
      return "pick";
    case ActionType::kPlace:
      return "place";
    case ActionType::kHandoff:
      return "handoff";
  }
  return "unknown";
}

std::string_view toString(GripperAction action) {
  switch (action) {
    case GripperAction::kOpen:
      return "open";
    case GripperAction::kClose:
      return "close";
  }
  return "unknown";
}

void checkPlanStructure(const Plan& plan, const std::string& file_name) {
  checkName(file_name, "/world", plan.world);
  checkTrajectories(plan, file_name);
  checkGripper(plan, file_name);
  checkActions(plan, file_name);
}

Plan parsePlanJson(std::string_view json_text, const std::string& file_name) {
  const PlanReader reader(file_name);
  const Json document = reader.parse(json_text);
  Plan plan = readPlan(reader, document);
  checkPlanStructure(plan, file_name);
  return plan;
}

Plan loadPlanFile(const std::filesystem::path& file) {
  return parsePlanJson(readTextFile<PlanError>(file, "plan"), file.string());
}

void validatePlan(const Plan& plan, const World& world,
                  const std::array<std::string, 6>& arm_joint_names,
                  const std::array<double, 6>& lower, const std::array<double, 6>& upper,
                  const std::array<double, 6>& max_velocity, const std::string& file_name) {
  checkPlanStructure(plan, file_name);
  const std::string& file = file_name;

  if (plan.world != world.name) {
    fail(file, "/world",
         "the plan is for world " + inQuotes(plan.world) + ", not " + inQuotes(world.name));
  }
  const auto robot_names = [&] {
    return nameList(world.robots, [](const RobotSpec& r) { return r.name; });
  };
  const auto checkRobot = [&](const std::string& pointer, const std::string& name) {
    if (world.findRobot(name) == nullptr) {
      fail(file, pointer,
           "unknown robot " + inQuotes(name) + " (world " + inQuotes(world.name) + " has " +
               robot_names() + ")");
    }
  };

  for (std::size_t r = 0; r < plan.trajectories.size(); ++r) {
    const RobotTrajectory& trajectory = plan.trajectories[r];
    const std::string pointer = robotPointer(r);
    checkRobot(at(pointer, "name"), trajectory.robot);
    for (std::size_t j = 0; j < 6; ++j) {
      if (trajectory.joint_names[j] != arm_joint_names[j]) {
        fail(file, at(at(pointer, "joint_names"), j),
             "expected " + inQuotes(arm_joint_names[j]) + ", got " +
                 inQuotes(trajectory.joint_names[j]) + " (the model's arm joints in order: " +
                 nameList(arm_joint_names, [](const std::string& n) { return n; }) + ")");
      }
    }
    for (std::size_t p = 0; p < trajectory.points.size(); ++p) {
      const TrajectoryPoint& point = trajectory.points[p];
      const std::string point_pointer = pointPointer(r, p);
      for (std::size_t j = 0; j < 6; ++j) {
        const double q = point.q[j];
        if (q < lower[j] - kLimitSlack || q > upper[j] + kLimitSlack) {
          fail(file, at(at(point_pointer, "q"), j),
               arm_joint_names[j] + " at " + exact(q) + " rad outside its limits [" +
                   brief(lower[j]) + ", " + brief(upper[j]) + "] rad");
        }
        if (point.qd && std::abs((*point.qd)[j]) > max_velocity[j] * kVelocitySlack) {
          fail(file, at(at(point_pointer, "qd"), j),
               arm_joint_names[j] + " velocity " + exact((*point.qd)[j]) +
                   " rad/s above its limit " + brief(max_velocity[j]) + " rad/s");
        }
      }
      if (p == 0) continue;
      // the straight segment from the previous point must respect the speed limits
      const TrajectoryPoint& previous = trajectory.points[p - 1];
      const double dt = point.t - previous.t;
      for (std::size_t j = 0; j < 6; ++j) {
        const double dq = std::abs(point.q[j] - previous.q[j]);
        if (dq > max_velocity[j] * kVelocitySlack * dt) {
          fail(file, point_pointer,
               arm_joint_names[j] + " moves " + brief(dq) + " rad in " + brief(dt) +
                   " s from point " + std::to_string(p - 1) + ": " + brief(dq / dt) +
                   " rad/s above its limit " + brief(max_velocity[j]) + " rad/s");
        }
      }
    }
  }

  for (std::size_t i = 0; i < plan.gripper.size(); ++i) {
    checkRobot(at(gripperPointer(i), "robot"), plan.gripper[i].robot);
  }

  // actions must happen while the plan runs: before its last point or gripper command
  double motion_end = 0.0;
  for (const RobotTrajectory& trajectory : plan.trajectories) {
    motion_end = std::max(motion_end, trajectory.points.back().t);
  }
  for (const GripperCommand& command : plan.gripper) motion_end = std::max(motion_end, command.t);

  for (std::size_t i = 0; i < plan.actions.size(); ++i) {
    const PlanAction& action = plan.actions[i];
    const std::string pointer = actionPointer(i);
    checkRobot(at(pointer, robotKey(action)), action.robot);
    if (action.type == ActionType::kHandoff) checkRobot(at(pointer, "receiver"), action.receiver);
    if (world.findObject(action.object) == nullptr) {
      fail(file, at(pointer, "object"),
           "unknown object " + inQuotes(action.object) + " (world " + inQuotes(world.name) +
               " has " + nameList(world.objects, [](const ObjectSpec& o) { return o.name; }) + ")");
    }
    if (action.type == ActionType::kPlace && !action.region.empty() && world.findRegion(action.region) == nullptr) {
      fail(file, at(pointer, "region"),
           "unknown region " + inQuotes(action.region) + " (world " + inQuotes(world.name) +
               " has " + nameList(world.regions, [](const Region& g) { return g.name; }) + ")");
    }
    if (action.end > motion_end + kTimeSlack) {
      fail(file, at(pointer, "end"),
           "ends at " + exact(action.end) +
               " s, after the plan's last trajectory point or "
               "gripper command at " +
               exact(motion_end) + " s");
    }
  }
}

std::string writePlanJson(const Plan& plan) {
  OrderedJson document;
  document["dashbed_plan"] = kPlanFormatVersion;
  document["world"] = plan.world;
  document["seed"] = plan.seed;

  OrderedJson robots = OrderedJson::array();
  for (const RobotTrajectory& trajectory : plan.trajectories) {
    OrderedJson robot;
    robot["name"] = trajectory.robot;
    robot["joint_names"] = trajectory.joint_names;
    OrderedJson points = OrderedJson::array();
    for (const TrajectoryPoint& point : trajectory.points) {
      OrderedJson entry;
      entry["t"] = point.t;
      entry["q"] = sixToJson(point.q);
      if (point.qd) entry["qd"] = sixToJson(*point.qd);
      points.push_back(std::move(entry));
    }
    robot["points"] = std::move(points);
    robots.push_back(std::move(robot));
  }
  document["robots"] = std::move(robots);

  OrderedJson gripper = OrderedJson::array();
  for (const GripperCommand& command : plan.gripper) {
    OrderedJson entry;
    entry["robot"] = command.robot;
    entry["t"] = command.t;
    entry["command"] = toString(command.action);
    if (command.force != 0.0) entry["force"] = command.force;
    gripper.push_back(std::move(entry));
  }
  document["gripper"] = std::move(gripper);

  OrderedJson actions = OrderedJson::array();
  for (const PlanAction& action : plan.actions) {
    OrderedJson entry;
    entry["type"] = toString(action.type);
    if (action.type == ActionType::kHandoff) {
      entry["giver"] = action.robot;
      entry["receiver"] = action.receiver;
    } else {
      entry["robot"] = action.robot;
    }
    entry["object"] = action.object;
    if (!action.region.empty()) entry["region"] = action.region;
    entry["start"] = action.start;
    entry["end"] = action.end;
    actions.push_back(std::move(entry));
  }
  document["actions"] = std::move(actions);
  document["statistics"] = OrderedJson(plan.statistics);
  return formatJson(document);
}

std::string formatJson(const nlohmann::ordered_json& value) {
  std::string out;
  formatInto(value, 0, out);
  out += '\n';
  return out;
}

}  // namespace dashbed::core
