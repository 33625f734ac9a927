// Reading trajectories and gripper timelines made elsewhere (tools/export/foreign_plan.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "core/hande.h"
#include "core/input_text.h"
#include "tools/export/foreign_plan.h"

namespace dashbed::exporting {
namespace {

using Names = std::array<std::string, 6>;

[[noreturn]] void fail(const std::string& file, int line, const std::string& field, const std::string& what) {
  throw ForeignPlanError(file + ":" + std::to_string(line) + ": " + field + ": " + what);
}

/// Position of each of `wanted` in `given`; fails naming the joint missing or the unknown one.
std::array<std::size_t, 6> jointOrder(const std::vector<std::string>& given, const Names& wanted,
                                      const std::string& file, int line, const std::string& field) {
  for (const std::string& name : given) {
    if (std::find(wanted.begin(), wanted.end(), name) == wanted.end()) fail(file, line, field, "unknown joint '" + name + "'");
  }
  std::array<std::size_t, 6> order{};
  for (std::size_t i = 0; i < 6; ++i) {
    const auto it = std::find(given.begin(), given.end(), wanted[i]);
    if (it == given.end()) fail(file, line, field, "missing joint '" + wanted[i] + "'");
    order[i] = static_cast<std::size_t>(it - given.begin());
  }
  return order;
}

void requireIncreasing(const std::vector<core::TrajectoryPoint>& points, const std::string& file, int line,
                       const std::string& field) {
  if (points.size() >= 2 && !(points.back().t > points[points.size() - 2].t)) {
    fail(file, line, field, "times must increase strictly");
  }
}

// ---- YAML ------------------------------------------------------------------------------------

int lineOf(const YAML::Node& node) { return node.Mark().line + 1; }

double yamlNumber(const YAML::Node& node, const std::string& file, const std::string& field) {
  if (!node || !node.IsScalar()) fail(file, node ? lineOf(node) : 0, field, "expected a number");
  double value = 0.0;
  if (!YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    fail(file, lineOf(node), field, "expected a finite number, got '" + node.Scalar() + "'");
  }
  return value;
}

/// {sec, nanosec} as seconds.
double yamlDuration(const YAML::Node& node, const std::string& file, const std::string& field) {
  if (!node || !node.IsMap()) fail(file, node ? lineOf(node) : 0, field, "expected {sec, nanosec}");
  return yamlNumber(node["sec"], file, field + ".sec") + 1e-9 * yamlNumber(node["nanosec"], file, field + ".nanosec");
}

std::array<double, 6> yamlJoints(const YAML::Node& list, const std::array<std::size_t, 6>& order,
                                 std::size_t count, const std::string& file, const std::string& field) {
  if (!list.IsSequence() || list.size() != count) {
    fail(file, lineOf(list), field, "expected " + std::to_string(count) + " numbers, one per joint name");
  }
  std::array<double, 6> values{};
  for (std::size_t i = 0; i < 6; ++i) values[i] = yamlNumber(list[order[i]], file, field);
  return values;
}

// The file's text, refused when it is not UTF-8 text.
std::string readText(const std::string& file, const std::string& kind) {
  std::string text = core::readTextFile<ForeignPlanError>(file, kind);
  if (const std::optional<core::TextProblem> problem = core::findTextProblem(text)) {
    fail(file, problem->line, "(text)", problem->what);
  }
  return text;
}

YAML::Node loadYaml(const std::string& file, const std::string& kind) {
  const std::string text = readText(file, kind);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    fail(file, e.mark.line + 1, "(syntax)", e.msg);
  }
}

std::vector<core::TrajectoryPoint> yamlTrajectory(const std::string& file, const Names& names) {
  YAML::Node root = loadYaml(file, "trajectory");
  const YAML::Node trajectory = root.IsMap() && root["trajectory"] ? root["trajectory"] : root;
  if (!trajectory.IsMap() || !trajectory["joint_names"] || !trajectory["points"]) {
    fail(file, lineOf(trajectory), "trajectory", "expected a JointTrajectory with joint_names and points");
  }
  const YAML::Node joint_names = trajectory["joint_names"];
  if (!joint_names.IsSequence()) fail(file, lineOf(joint_names), "joint_names", "expected a list of names");
  std::vector<std::string> given;
  for (std::size_t i = 0; i < joint_names.size(); ++i) {
    const YAML::Node name = joint_names[i];
    if (!name.IsScalar()) fail(file, lineOf(name), "joint_names[" + std::to_string(i) + "]", "expected a name");
    given.push_back(name.Scalar());
  }
  const std::array<std::size_t, 6> order = jointOrder(given, names, file, lineOf(joint_names), "joint_names");
  const YAML::Node points = trajectory["points"];
  if (!points.IsSequence() || points.size() == 0) fail(file, lineOf(points), "points", "expected a list of points");
  std::vector<core::TrajectoryPoint> result;
  bool all_velocities = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const YAML::Node point = points[i];
    const std::string field = "points[" + std::to_string(i) + "]";
    if (!point.IsMap()) fail(file, lineOf(point), field, "expected a map");
    core::TrajectoryPoint p;
    p.t = yamlDuration(point["time_from_start"], file, field + ".time_from_start");
    if (!point["positions"]) fail(file, lineOf(point), field, "missing positions");
    p.q = yamlJoints(point["positions"], order, given.size(), file, field + ".positions");
    const YAML::Node velocities = point["velocities"];
    if (velocities && velocities.IsSequence() && velocities.size() > 0) {
      p.qd = yamlJoints(velocities, order, given.size(), file, field + ".velocities");
    } else {
      all_velocities = false;
    }
    result.push_back(p);
    requireIncreasing(result, file, lineOf(point), field + ".time_from_start");
  }
  if (!all_velocities) {
    for (core::TrajectoryPoint& p : result) p.qd.reset();
  }
  return result;
}

std::vector<core::GripperCommand> yamlGripper(const std::string& file, const std::string& robot) {
  YAML::Node root = loadYaml(file, "gripper timeline");
  if (!root.IsMap() || !root["gripper"] || !root["gripper"].IsSequence()) {
    fail(file, lineOf(root), "gripper", "expected a list of gripper commands under 'gripper'");
  }
  std::vector<core::GripperCommand> commands;
  for (std::size_t i = 0; i < root["gripper"].size(); ++i) {
    const YAML::Node entry = root["gripper"][i];
    const std::string field = "gripper[" + std::to_string(i) + "]";
    if (!entry.IsMap()) fail(file, lineOf(entry), field, "expected a map");
    core::GripperCommand command;
    command.robot = robot;
    command.t = yamlDuration(entry["time_from_start"], file, field + ".time_from_start");
    const std::string action = entry["command"] && entry["command"].IsScalar() ? entry["command"].Scalar() : "";
    if (action != "open" && action != "close") fail(file, lineOf(entry), field + ".command", "expected open or close");
    command.action = action == "close" ? core::GripperAction::kClose : core::GripperAction::kOpen;
    if (entry["force"]) command.force = yamlNumber(entry["force"], file, field + ".force");
    if (!commands.empty() && command.t < commands.back().t) {
      fail(file, lineOf(entry), field + ".time_from_start", "commands must be in time order");
    }
    commands.push_back(command);
  }
  return commands;
}

// ---- CSV -------------------------------------------------------------------------------------

std::vector<std::string> splitRow(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream row(line);
  std::string cell;
  while (std::getline(row, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double csvNumber(const std::string& cell, const std::string& file, int line, const std::string& column) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(cell, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != cell.size() || !std::isfinite(value)) {
    fail(file, line, column, "expected a finite number, got '" + cell + "'");
  }
  return value;
}

struct CsvTrajectory {
  std::vector<core::TrajectoryPoint> points;
  std::vector<core::GripperCommand> gripper;
};

CsvTrajectory csvTrajectory(const std::string& file, const Names& names, const std::string& robot) {
  std::istringstream in(readText(file, "trajectory"));
  std::string line;
  if (!std::getline(in, line)) fail(file, 1, "(header)", "the file is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const std::vector<std::string> header = splitRow(line);
  const auto column = [&](const std::string& name) -> std::optional<std::size_t> {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? std::nullopt : std::optional(static_cast<std::size_t>(it - header.begin()));
  };
  const std::optional<std::size_t> t_column = column("t");
  if (!t_column) fail(file, 1, "(header)", "missing column 't'");
  std::array<std::size_t, 6> q_column{};
  std::array<std::optional<std::size_t>, 6> qd_column{};
  for (std::size_t i = 0; i < 6; ++i) {
    const std::optional<std::size_t> c = column(names[i]);
    if (!c) fail(file, 1, "(header)", "missing column '" + names[i] + "'");
    q_column[i] = *c;
    qd_column[i] = column(names[i] + "_velocity");
  }
  const bool velocities = std::all_of(qd_column.begin(), qd_column.end(), [](const auto& c) { return c.has_value(); });
  const std::optional<std::size_t> opening_column = column("gripper_opening");
  const std::optional<std::size_t> force_column = column("gripper_force");

  CsvTrajectory result;
  double opening = core::kHandeMaxOpening, force = 0.0;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = splitRow(line);
    if (cells.size() != header.size()) {
      fail(file, number, "(row)", std::to_string(cells.size()) + " cells for " + std::to_string(header.size()) + " columns");
    }
    core::TrajectoryPoint p;
    p.t = csvNumber(cells[*t_column], file, number, "t");
    for (std::size_t i = 0; i < 6; ++i) p.q[i] = csvNumber(cells[q_column[i]], file, number, names[i]);
    if (velocities) {
      p.qd.emplace();
      for (std::size_t i = 0; i < 6; ++i) (*p.qd)[i] = csvNumber(cells[*qd_column[i]], file, number, names[i] + "_velocity");
    }
    result.points.push_back(p);
    requireIncreasing(result.points, file, number, "t");
    if (!opening_column) continue;
    const double o = csvNumber(cells[*opening_column], file, number, "gripper_opening");
    const double f = force_column ? csvNumber(cells[*force_column], file, number, "gripper_force") : 0.0;
    if (o != opening || f != force) {
      const auto action = o < 0.5 * core::kHandeMaxOpening ? core::GripperAction::kClose : core::GripperAction::kOpen;
      result.gripper.push_back({robot, p.t, action, f});
      opening = o;
      force = f;
    }
  }
  if (result.points.empty()) fail(file, 2, "(rows)", "no trajectory rows");
  return result;
}

// Runs a YAML reader of `file`; a yaml-cpp error the reader did not foresee is reported as a
// ForeignPlanError at its line instead of escaping as yaml-cpp's own exception.
template <class Read>
auto yamlSection(const std::string& file, Read&& read) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    fail(file, e.mark.line + 1, "(yaml)", e.msg);
  }
}

bool hasExtension(const std::string& file, std::initializer_list<const char*> extensions) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::any_of(extensions.begin(), extensions.end(), [&](const char* e) { return extension == e; });
}

}  // namespace

core::Plan readForeignPlan(const core::World& world, const Names& joint_names,
                           const std::vector<ForeignTrajectory>& robots) {
  core::Plan plan;
  plan.world = world.name;
  for (const ForeignTrajectory& files : robots) {
    if (world.findRobot(files.robot) == nullptr) {
      throw ForeignPlanError(files.trajectory_file + ": the world has no robot '" + files.robot + "'");
    }
    core::RobotTrajectory trajectory;
    trajectory.robot = files.robot;
    trajectory.joint_names = joint_names;
    std::vector<core::GripperCommand> gripper;
    if (hasExtension(files.trajectory_file, {".csv"})) {
      CsvTrajectory csv = csvTrajectory(files.trajectory_file, joint_names, files.robot);
      trajectory.points = std::move(csv.points);
      gripper = std::move(csv.gripper);
    } else if (hasExtension(files.trajectory_file, {".yaml", ".yml"})) {
      trajectory.points = yamlSection(files.trajectory_file, [&] { return yamlTrajectory(files.trajectory_file, joint_names); });
    } else {
      throw ForeignPlanError(files.trajectory_file + ": expected a .csv, .yaml or .yml trajectory file");
    }
    if (!files.gripper_file.empty()) {
      gripper = yamlSection(files.gripper_file, [&] { return yamlGripper(files.gripper_file, files.robot); });
    }
    plan.trajectories.push_back(std::move(trajectory));
    plan.gripper.insert(plan.gripper.end(), gripper.begin(), gripper.end());
  }
  std::stable_sort(plan.gripper.begin(), plan.gripper.end(),
                   [](const core::GripperCommand& a, const core::GripperCommand& b) { return a.t < b.t; });
  return plan;
}

}  // namespace dashbed::exporting
