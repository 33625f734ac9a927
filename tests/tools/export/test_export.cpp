// Exports read back: every format reproduces the plan's curve at its sample times, keeps the
// limits, carries the gripper commands, and lines the robots' handoffs up.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/hande.h"
#include "core/readiness.h"
#include "core/trajectory_interpolator.h"
#include "core/world_loader.h"
#include "tools/export/plan_export.h"
#include "tools/export/robotiq.h"
#include "tools/script/scripted_plan.h"

using namespace dashbed;
using namespace dashbed::exporting;

namespace {

const core::LoadedWorld& world() {
  static const core::LoadedWorld loaded = core::loadWorld(std::string(DASHBED_SOURCE_ROOT) + "/worlds/default.yaml");
  return loaded;
}

/// A pick, a handoff and a place: both robots move, close, open, and meet once.
const core::Plan& plan() {
  static const core::Plan p =
      tools::planFromScript(world(), "r1 picks cube_0; r1 hands cube_0 to r0; r0 places cube_0 in bin_red");
  return p;
}

const ExportFile& fileNamed(const std::vector<ExportFile>& files, const std::string& name) {
  for (const ExportFile& f : files) {
    if (f.name == name) return f;
  }
  FAIL("no file " << name);
  return files.front();
}

/// The numbers of a text, in order.
std::vector<double> numbersIn(const std::string& text) {
  static const std::regex number(R"(-?\d+(\.\d+)?([eE][-+]?\d+)?)");
  std::vector<double> values;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
    values.push_back(std::stod(it->str()));
  }
  return values;
}

double seconds(const YAML::Node& duration) {
  return duration["sec"].as<double>() + duration["nanosec"].as<double>() * 1e-9;
}

/// The quintic through (p0, v0, a0) and (p1, v1, a1) over h, at s in [0, 1]: what a joint
/// trajectory controller draws between two points with positions, velocities and accelerations.
double quintic(double p0, double v0, double a0, double p1, double v1, double a1, double h, double s) {
  const double c0 = p0, c1 = v0 * h, c2 = 0.5 * a0 * h * h;
  const double d = p1 - c0 - c1 - c2, e = v1 * h - c1 - 2 * c2, f = a1 * h * h - 2 * c2;
  const double c3 = 10 * d - 4 * e + 0.5 * f, c4 = -15 * d + 7 * e - f, c5 = 6 * d - 3 * e + 0.5 * f;
  return ((((c5 * s + c4) * s + c3) * s + c2) * s + c1) * s + c0;
}

}  // namespace

TEST_CASE("Robotiq registers: the Hand-E's ranges end to end, linear in between", "[export]") {
  CHECK(robotiqPosition(core::kHandeMaxOpening) == 0);
  CHECK(robotiqPosition(0.0) == 255);
  CHECK(robotiqSpeed(core::kHandeMinSpeed) == 0);
  CHECK(robotiqSpeed(core::kHandeMaxSpeed) == 255);
  CHECK(robotiqForce(core::kHandeMinForce) == 0);
  CHECK(robotiqForce(core::kHandeMaxForce) == 255);
  for (int r = 0; r <= 255; ++r) {
    CHECK(robotiqPosition(openingOfRobotiq(r)) == r);
    CHECK(robotiqSpeed(speedOfRobotiq(r)) == r);
    CHECK(robotiqForce(forceOfRobotiq(r)) == r);
  }
  CHECK(std::abs(forceOfRobotiq(robotiqForce(60.0)) - 60.0) <= 0.5 * (185.0 - 20.0) / 255.0);
}

TEST_CASE("the plan exported is one a UR5e could run", "[export]") {
  REQUIRE(core::checkReadiness(plan(), *world().world, *world().robots).ready());
}

TEST_CASE("CSV: the curve at every sample, the plan's points among them, and the gripper in effect", "[export]") {
  const ExportTimeline timeline = exportTimeline(plan(), *world().world);
  ExportOptions options;
  const std::vector<ExportFile> files = exportCsv(timeline, options);
  REQUIRE(files.size() == 2);
  for (const core::RobotTrajectory& trajectory : plan().trajectories) {
    std::istringstream in(fileNamed(files, trajectory.robot + ".csv").text);
    std::string line;
    std::getline(in, line);
    CHECK(line.rfind("t,shoulder_pan_joint,", 0) == 0);
    CHECK(line.find("wrist_3_joint_velocity,gripper_opening,gripper_force") != std::string::npos);
    const core::TrajectoryInterpolator curve(trajectory.points);
    std::vector<double> times;
    while (std::getline(in, line)) {
      std::vector<double> row;
      std::stringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
      REQUIRE(row.size() == 15);
      const core::JointReference ref = curve.at(row[0]);
      for (int j = 0; j < 6; ++j) {
        CHECK(std::abs(row[1 + j] - ref.q[j]) <= 1e-6);
        CHECK(std::abs(row[7 + j] - ref.qd[j]) <= 1e-6);
      }
      // the last command at or before the sample
      double opening = core::kHandeMaxOpening;
      for (const core::GripperCommand& c : plan().gripper) {
        if (c.robot == trajectory.robot && c.t <= row[0]) opening = c.action == core::GripperAction::kClose ? 0.0 : core::kHandeMaxOpening;
      }
      CHECK(row[13] == opening);
      times.push_back(row[0]);
    }
    for (std::size_t k = 1; k < times.size(); ++k) {
      CHECK(times[k] > times[k - 1]);
      CHECK(times[k] - times[k - 1] <= options.sample_step + 1e-9);
    }
    for (const core::TrajectoryPoint& p : trajectory.points) {
      CHECK(std::find(times.begin(), times.end(), p.t) != times.end());
    }
  }
}

TEST_CASE("ROS 2: a FollowJointTrajectory goal on the curve, within the limits, and its gripper timeline", "[export]") {
  const ExportTimeline timeline = exportTimeline(plan(), *world().world);
  const std::vector<ExportFile> files = exportRos2(timeline, ExportOptions{});
  REQUIRE(files.size() == 4);
  const core::RobotModel& model = *world().robots->robots().front().model;
  for (const core::RobotTrajectory& trajectory : plan().trajectories) {
    const YAML::Node goal = YAML::Load(fileNamed(files, trajectory.robot + ".trajectory.yaml").text);
    const YAML::Node names = goal["trajectory"]["joint_names"];
    REQUIRE(names.size() == 6);
    for (int j = 0; j < 6; ++j) CHECK(names[j].as<std::string>() == trajectory.joint_names[j]);
    const core::TrajectoryInterpolator curve(trajectory.points);
    const YAML::Node points = goal["trajectory"]["points"];
    REQUIRE(points.size() > trajectory.points.size());
    double previous = -1.0, worst_between = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double t = seconds(points[k]["time_from_start"]);
      CHECK(t > previous);
      previous = t;
      const core::JointReference ref = curve.at(t);
      for (int j = 0; j < 6; ++j) {
        const double q = points[k]["positions"][j].as<double>(), qd = points[k]["velocities"][j].as<double>();
        const double qdd = points[k]["accelerations"][j].as<double>();
        CHECK(std::abs(q - ref.q[j]) <= 1e-6);
        CHECK(std::abs(qd - ref.qd[j]) <= 1e-6);
        CHECK(std::abs(qd) <= model.joints()[model.movableJoints()[j]].max_velocity);
        CHECK(std::abs(qdd) <= world().world->safety.max_joint_acceleration);
      }
      // between two samples, what the controller's quintic draws against the plan's curve
      if (k + 1 < points.size()) {
        const double t1 = seconds(points[k + 1]["time_from_start"]);
        const double mid = 0.5 * (t + t1);
        const core::JointReference at_mid = curve.at(mid);
        for (int j = 0; j < 6; ++j) {
          const auto at = [&](std::size_t i, const char* field) { return points[i][field][j].as<double>(); };
          const double q = quintic(at(k, "positions"), at(k, "velocities"), at(k, "accelerations"),
                                   at(k + 1, "positions"), at(k + 1, "velocities"), at(k + 1, "accelerations"), t1 - t, 0.5);
          worst_between = std::max(worst_between, std::abs(q - at_mid.q[j]));
        }
      }
    }
    CHECK(std::abs(previous - trajectory.points.back().t) <= 1e-9);
    CHECK(worst_between <= 1e-4);

    const YAML::Node gripper = YAML::Load(fileNamed(files, trajectory.robot + ".gripper.yaml").text);
    std::vector<const core::GripperCommand*> commands;
    for (const core::GripperCommand& c : plan().gripper) {
      if (c.robot == trajectory.robot) commands.push_back(&c);
    }
    REQUIRE(gripper["gripper"].size() == commands.size());
    for (std::size_t i = 0; i < commands.size(); ++i) {
      const YAML::Node g = gripper["gripper"][i];
      CHECK(std::abs(seconds(g["time_from_start"]) - commands[i]->t) <= 1e-9);
      const bool close = commands[i]->action == core::GripperAction::kClose;
      CHECK(g["command"].as<std::string>() == (close ? "close" : "open"));
      CHECK(g["robotiq"]["position"].as<int>() == (close ? 255 : 0));
      CHECK(g["force"].as<double>() >= core::kHandeMinForce);
      CHECK(g["robotiq"]["force"].as<int>() == robotiqForce(g["force"].as<double>()));
    }
  }
}

TEST_CASE("URScript: the controller's own evaluation reproduces the curve; handoffs synchronise at rest", "[export]") {
  const ExportTimeline timeline = exportTimeline(plan(), *world().world);
  ExportOptions options;
  options.header = {"hardware readiness: ready"};
  const std::vector<ExportFile> files = exportUrScript(timeline, options);
  REQUIRE(files.size() == 3);
  std::map<std::string, std::vector<std::pair<int, double>>> syncs;  // robot -> (index, t)
  for (const core::RobotTrajectory& trajectory : plan().trajectories) {
    const std::string& text = fileNamed(files, trajectory.robot + ".script").text;
    CHECK(text.find("# hardware readiness: ready") != std::string::npos);
    CHECK(text.find("servoj(q, 0, 0, 0.002000000, 0.100000000, 300.000000000)") != std::string::npos);
    const core::TrajectoryInterpolator curve(trajectory.points);
    // run the program's motion calls as the controller would: one servoj every period
    double t = 0.0, worst = 0.0;
    int ticks = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      const bool follow = line.find("dashbed_t = dashbed_follow(") != std::string::npos;
      const bool hold = line.find("dashbed_t = dashbed_hold(") != std::string::npos;
      static const std::regex sync(R"(# synchronisation (\d+): .* at t = ([-0-9.]+) s)");
      std::smatch m;
      if (std::regex_search(line, m, sync)) syncs[trajectory.robot].push_back({std::stoi(m[1]), std::stod(m[2])});
      if (!follow && !hold) continue;
      const std::vector<double> v = numbersIn(line.substr(line.find('(')));
      REQUIRE(v.size() == (follow ? 27u : 7u));
      const double until = v.back();
      while (t < until - 5e-7) {
        std::array<double, 6> q{};
        if (follow) {
          const double t0 = v[0], t1 = v[1], h = t1 - t0, s = (t - t0) / h;
          const double a = (2 * s - 3) * s * s + 1, b = ((s - 2) * s + 1) * s * h, c = (3 - 2 * s) * s * s,
                       d = (s - 1) * s * s * h;
          for (int j = 0; j < 6; ++j) q[j] = a * v[2 + j] + b * v[8 + j] + c * v[14 + j] + d * v[20 + j];
        } else {
          for (int j = 0; j < 6; ++j) q[j] = v[j];
        }
        const core::Vector6 expected = curve.position(t);
        for (int j = 0; j < 6; ++j) worst = std::max(worst, std::abs(q[j] - expected[j]));
        t += 0.002;
        ++ticks;
      }
    }
    CHECK(worst <= 1e-6);
    CHECK(t >= plan().duration() - 1e-9);
    CHECK(ticks >= static_cast<int>(plan().duration() / 0.002));
  }
  // the common start and the handoff: both programs wait at the same points, at rest there
  REQUIRE(syncs["r0"].size() == 2);
  CHECK(syncs["r0"] == syncs["r1"]);
  for (const auto& [index, t] : syncs["r0"]) {
    for (const core::RobotTrajectory& trajectory : plan().trajectories) {
      const core::JointReference ref = core::TrajectoryInterpolator(trajectory.points).at(t);
      for (int j = 0; j < 6; ++j) CHECK(std::abs(ref.qd[j]) <= 1e-9);
    }
  }
  const std::string& sync_json = fileNamed(files, "sync.json").text;
  CHECK(sync_json.find("\"why\": \"handoff cube_0 r1 -> r0\"") != std::string::npos);
}
