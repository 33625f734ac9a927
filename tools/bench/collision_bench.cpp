#include "tools/bench/collision_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/asset_paths.h"
#include "core/grasps.h"
#include "core/world_loader.h"
#include "planner/collision/collision_checker.h"
#include "tools/bench/bench_table.h"

namespace dashbed::tools {
namespace {

using dashbed::core::Pose;
using dashbed::planner::CollisionChecker;
using dashbed::planner::CollisionScene;
using dashbed::planner::HeldObject;
using Clock = std::chrono::steady_clock;

struct Stats {
  std::size_t count = 0;
  double median = 0.0;  // [us]
  double mean = 0.0;
  double p95 = 0.0;
  double cpu_mean = -1.0;  // process CPU time per call over the whole loop [us]; < 0: not measured
};

Stats summarise(std::vector<double> us) {
  Stats s;
  s.count = us.size();
  if (us.empty()) return s;
  std::sort(us.begin(), us.end());
  s.median = us[us.size() / 2];
  double sum = 0.0;
  for (double v : us) sum += v;
  s.mean = sum / static_cast<double>(us.size());
  s.p95 = us[std::min(us.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(us.size())))];
  return s;
}

void addRow(BenchTable& table, const std::string& what, const Stats& s, const std::string& note = "") {
  table.rows.push_back({what, std::to_string(s.count), fixed(s.median, 3), fixed(s.mean, 3), fixed(s.p95, 3),
                        s.cpu_mean >= 0.0 ? fixed(s.cpu_mean, 3) : "", note});
}

/// Process CPU time [us]: unlike wall-clock time it does not count the time the process waits
/// while other processes run, so its mean is robust on a loaded machine.
double cpuMicroseconds() { return 1e6 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

/// Times `call` once; returns microseconds and stores the result.
template <class F>
double timeCall(F&& call, bool& result) {
  const auto start = Clock::now();
  result = call();
  const auto stop = Clock::now();
  return std::chrono::duration<double, std::micro>(stop - start).count();
}

Eigen::VectorXd randomConfiguration(const dashbed::core::RobotModel& model, std::mt19937_64& rng) {
  Eigen::VectorXd q(model.numPositions());
  for (int j : model.movableJoints()) {
    const auto& joint = model.joints()[j];
    q[joint.q_index] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
  }
  return q;
}

Eigen::VectorXd reachingConfiguration(const dashbed::core::PlacedRobot& robot, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (;;) {
    Pose X_WT = Pose::Identity();
    X_WT.linear() = Eigen::Quaterniond(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)))
                        .normalized()
                        .toRotationMatrix();
    X_WT.translation() = Eigen::Vector3d(0.12 * unit(rng), 0.15 * unit(rng), 0.925 + 0.125 * unit(rng));
    const auto solutions = robot.solveInWorld(X_WT, robot.spec->home);
    if (solutions.empty()) continue;
    const auto& arm = solutions[std::uniform_int_distribution<std::size_t>(0, solutions.size() - 1)(rng)];
    Eigen::VectorXd q(robot.model->numPositions());
    for (int i = 0; i < 6; ++i) q[i] = arm[i];
    for (int i = 6; i < q.size(); ++i) q[i] = 0.0125 * (1.0 + unit(rng));
    return q;
  }
}

/// Times `query` on each of `inputs` and adds three rows: all calls (with the CPU mean, the
/// share found free and the narrow-phase tests per call), the free ones and the colliding ones.
template <class Input, class Query>
void benchQueries(BenchTable& table, CollisionChecker& checker, const std::string& name,
                  const std::vector<Input>& inputs, Query&& query) {
  std::vector<double> all, free, hit;
  checker.resetCounters();
  const double cpu_start = cpuMicroseconds();
  for (const Input& input : inputs) {
    bool result = false;
    const double us = timeCall([&] { return query(input); }, result);
    all.push_back(us);
    (result ? free : hit).push_back(us);
  }
  const auto calls = static_cast<double>(inputs.size());
  const double narrow = static_cast<double>(checker.counters().narrow_phase) / calls;
  char note[128];
  std::snprintf(note, sizeof note, "%.1f%% free, %.2f FCL pair tests per call",
                100.0 * static_cast<double>(free.size()) / calls, narrow);
  Stats stats = summarise(all);
  stats.cpu_mean = (cpuMicroseconds() - cpu_start) / calls;
  addRow(table, name + ", all", stats, note);
  addRow(table, name + ", free", summarise(free));
  addRow(table, name + ", colliding", summarise(hit));
}

}  // namespace

BenchTable benchCollision(const CollisionBenchOptions& options) {
  const std::string world_file =
      options.world.empty() ? dashbed::core::defaultWorldPath().string() : options.world;
  const int checks = options.checks, motions = options.motions;
  if (checks <= 0 || motions < 0) throw std::invalid_argument("--checks must be > 0 and --motions >= 0");
  const auto loaded = dashbed::core::loadWorld(world_file);
  const auto& world = *loaded.world;
  const auto& robots = *loaded.robots;
  if (robots.size() < 1) throw std::invalid_argument(world_file + ": the world has no robot");

  const auto build_start = Clock::now();
  const CollisionScene scene(world, robots);
  const double build_ms = std::chrono::duration<double, std::milli>(Clock::now() - build_start).count();
  CollisionChecker checker(scene);
  const auto objects = dashbed::planner::startPlacement(world);
  std::mt19937_64 rng(options.seed);
  BenchTable table;

  char scene_line[256];
  std::snprintf(scene_line, sizeof scene_line,
                "World %s: %zu robots, %zu objects, %zu static boxes; scene built in %.1f ms; margin %.4f m, motion "
                "step %.4f m. Times in microseconds per call (median, mean, 95th percentile of individually timed "
                "calls; cpu: process CPU time per call over the whole loop).",
                world.name.c_str(), robots.size(), world.objects.size(), scene.staticBoxes().size(), build_ms,
                scene.settings().margin, scene.settings().motion_step);
  table.note = scene_line;
  table.header = {"query", "calls", "median", "mean", "p95", "cpu mean", "note"};

  // the timer's own cost
  {
    std::vector<double> us;
    bool result = false;
    for (int i = 0; i < 10000; ++i) us.push_back(timeCall([] { return true; }, result));
    addRow(table, "(empty timed call)", summarise(us));
  }

  // one robot against the scene
  const auto robotBench = [&](const std::string& name, const std::optional<HeldObject>& held) {
    std::vector<Eigen::VectorXd> qs;
    qs.reserve(static_cast<std::size_t>(checks));
    for (int i = 0; i < checks; ++i) qs.push_back(randomConfiguration(*robots[0].model, rng));
    benchQueries(table, checker, name, qs, [&](const Eigen::VectorXd& q) { return checker.robotFree(0, q, objects, held); });
  };
  robotBench("robotFree (uniform in limits)", std::nullopt);
  if (!world.objects.empty()) {
    const auto grasps = dashbed::core::boxGrasps(world.objects[0].size);
    robotBench("robotFree holding a cube", HeldObject{0, grasps.front().X_OT.inverse(), true});
  }

  // robot against robot
  if (robots.size() >= 2) {
    const auto pairBench = [&](const std::string& name, bool reaching) {
      std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> qs;
      for (int i = 0; i < checks; ++i) {
        qs.emplace_back(reaching ? reachingConfiguration(robots[0], rng) : randomConfiguration(*robots[0].model, rng),
                        reaching ? reachingConfiguration(robots[1], rng) : randomConfiguration(*robots[1].model, rng));
      }
      benchQueries(table, checker, name, qs, [&](const auto& pair) {
        return checker.robotsFree(0, pair.first, std::nullopt, 1, pair.second, std::nullopt);
      });
    };
    pairBench("robotsFree (uniform in limits)", false);
    pairBench("robotsFree (both reaching over centre)", true);
  }

  // motions from free configurations
  if (motions > 0) {
    std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> ms;
    while (static_cast<int>(ms.size()) < motions) {
      const Eigen::VectorXd a = randomConfiguration(*robots[0].model, rng);
      if (!checker.robotFree(0, a, objects)) continue;
      Eigen::VectorXd b = a;
      for (int j = 0; j < 6; ++j) b[j] += std::uniform_real_distribution<double>(-0.5, 0.5)(rng);
      if (!checker.robotFree(0, b, objects)) continue;
      ms.emplace_back(a, b);
    }
    std::vector<double> all, free, hit, per_sample;
    double steps = 0.0;
    double evaluated_total = 0.0;
    checker.resetCounters();
    const double cpu_start = cpuMicroseconds();
    for (const auto& [a, b] : ms) {
      const auto before = checker.counters().configurations;
      bool result = false;
      const double us = timeCall([&] { return checker.motionFree(0, a, b, objects); }, result);
      const auto evaluated = checker.counters().configurations - before;
      all.push_back(us);
      (result ? free : hit).push_back(us);
      if (result) per_sample.push_back(us / static_cast<double>(evaluated));
      steps += scene.motionSteps(0, a, b);
      evaluated_total += static_cast<double>(evaluated);
    }
    const double cpu_per_motion = (cpuMicroseconds() - cpu_start) / static_cast<double>(ms.size());
    char note[128];
    std::snprintf(note, sizeof note, "%.1f%% free, %.0f samples per motion on average, %.0f evaluated",
                  100.0 * static_cast<double>(free.size()) / static_cast<double>(ms.size()),
                  steps / static_cast<double>(ms.size()), evaluated_total / static_cast<double>(ms.size()));
    Stats stats = summarise(all);
    stats.cpu_mean = cpu_per_motion;
    addRow(table, "motionFree (free ends, +-0.5 rad), all", stats, note);
    addRow(table, "motionFree, free motions", summarise(free));
    addRow(table, "motionFree, blocked motions", summarise(hit));
    addRow(table, "motionFree, free motions, per evaluated sample", summarise(per_sample));
  }
  return table;
}

}  // namespace dashbed::tools
