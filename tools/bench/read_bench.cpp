#include "tools/bench/read_bench.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/kinematics.h"
#include "core/plan.h"
#include "core/world_io.h"

namespace dashbed::tools {
namespace {

constexpr double kMegabyte = 1e6;

// A world of about `bytes`: one robot, a 90 m floor, 40 mm cubes 60 mm apart in rows of 1000,
// each with its own goal; `refused` repeats the first goal at the end.
std::string worldText(double bytes, bool refused) {
  std::string objects = "objects:\n", goals = "goals:\n";
  for (int i = 0; static_cast<double>(objects.size() + goals.size()) < bytes; ++i) {
    // appended piece by piece: `"literal" + std::string` trips GCC 12's -Wrestrict
    const std::string name = std::string("c").append(std::to_string(i));
    objects.append("  - {name: ").append(name).append(", pose: {xyz: [");
    objects.append(std::to_string(-40 + 0.06 * (i % 1000))).append(", ");
    objects.append(std::to_string(-40 + 0.06 * (i / 1000))).append(", 0.02]}}\n");
    goals.append("  - {object: ").append(name).append(", region: area}\n");
  }
  if (refused) goals += "  - {object: c0, region: area}\n";
  return "dashbed_world: 1\n"
         "name: bench_read\n"
         "robots: [{name: r0, model: ur5e_hande, base: {xyz: [0, 0, 0]}}]\n"
         "surfaces: [{name: floor, center: [0, 0, 0], size: [90, 90]}]\n"
         "regions: [{name: area, center: [44, 44, 0], size: [1, 1, 0.1]}]\n" +
         objects + goals;
}

// A plan of about `bytes`: one robot swinging its joints slowly, a point every 0.5 s; `refused`
// gives the last point the time of the one before.
std::string planText(double bytes, bool refused) {
  core::Plan plan;
  plan.world = "bench_read";
  core::RobotTrajectory& trajectory = plan.trajectories.emplace_back();
  trajectory.robot = "r0";
  trajectory.joint_names = {"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                            "wrist_1_joint",      "wrist_2_joint",       "wrist_3_joint"};
  constexpr double kBytesPerPoint = 190.0;  // a point as the plan writer writes it, roughly
  const auto points = static_cast<int>(std::ceil(bytes / kBytesPerPoint));
  for (int i = 0; i < points; ++i) {
    core::TrajectoryPoint& p = trajectory.points.emplace_back();
    p.t = 0.5 * i;
    for (int j = 0; j < 6; ++j) p.q[j] = 0.5 * std::sin(0.01 * i + j);
  }
  if (refused && points > 1) trajectory.points.back().t = trajectory.points[points - 2].t;
  return core::writePlanJson(plan);
}

// Seconds to run `read` on `text`, and whether it threw the reader's error.
template <class Error, class Read>
std::pair<double, bool> timeRead(const std::string& text, Read&& read) {
  const auto start = std::chrono::steady_clock::now();
  bool refused = false;
  try {
    read(text);
  } catch (const Error&) {
    refused = true;
  }
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), refused};
}

}  // namespace

BenchTable benchReading(const ReadBenchOptions& options) {
  BenchTable table;
  table.header = {"file", "size [MB]", "read [s]", "rate [MB/s]", "outcome"};
  table.note = "Reading from text in memory: parsing and every check the reader makes (for a world, "
               "overlaps, resting poses and goals; for a plan, its structure and times).";
  for (const double megabytes : options.megabytes) {
    if (!(megabytes > 0.0) || megabytes > 256.0) {
      throw std::invalid_argument("--megabytes: each size must be in (0, 256], got " + fixed(megabytes, 3));
    }
  }
  const auto row = [&](const std::string& what, const std::string& text, std::pair<double, bool> timed,
                       bool should_refuse) {
    if (timed.second != should_refuse) {
      throw std::logic_error("bench read: the " + what + " was " + (timed.second ? "refused" : "accepted"));
    }
    const double size = static_cast<double>(text.size()) / kMegabyte;
    table.rows.push_back({what, fixed(size, 1), fixed(timed.first, 2), fixed(size / timed.first, 2),
                          should_refuse ? "refused at its last line" : "accepted"});
  };
  for (const double megabytes : options.megabytes) {
    for (const bool refused : {false, true}) {
      const std::string world = worldText(megabytes * kMegabyte, refused);
      row("world", world,
          timeRead<core::WorldError>(world, [](const std::string& t) { core::parseWorldYaml(t, "bench.yaml"); }),
          refused);
    }
  }
  for (const double megabytes : options.megabytes) {
    for (const bool refused : {false, true}) {
      const std::string plan = planText(megabytes * kMegabyte, refused);
      row("plan", plan,
          timeRead<core::PlanError>(plan, [](const std::string& t) { core::parsePlanJson(t, "bench.json"); }), refused);
    }
  }
  return table;
}

}  // namespace dashbed::tools
