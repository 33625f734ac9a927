// dashbed_bench_collision — timing of the planner's collision checker (planner/collision/collision_checker.h).
//
//   dashbed_bench_collision [WORLD.yaml] [--checks N] [--motions M] [--seed S]
//
// WORLD defaults to worlds/default.yaml (the 2-robot sorting scene). Prints a table of the time
// per query (median, mean, 95th percentile over individually timed calls, and the process CPU
// time per call over the whole loop, which excludes time lost to other processes) for:
//   robotFree   one robot against fixtures, resting objects (start poses) and itself, at N
//               configurations drawn uniformly within the joint limits; split by outcome;
//               also holding a cube;
//   robotsFree  robot 0 against robot 1 at N pairs of such configurations, and at N pairs
//               reaching over the table centre (IK), where they often meet;
//   motionFree  M straight motions from a free configuration by up to +-0.5 rad per arm joint.
// Timing is a benchmark, not a test: numbers depend on the machine and its load.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
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

void printRow(const std::string& what, const Stats& s, const std::string& note = "") {
  char cpu[32] = "";
  if (s.cpu_mean >= 0.0) std::snprintf(cpu, sizeof cpu, "%10.3f", s.cpu_mean);
  std::printf("%-46s %8zu %10.3f %10.3f %10.3f %10s  %s\n", what.c_str(), s.count, s.median, s.mean, s.p95, cpu,
              note.c_str());
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

/// Times `query` on each of `inputs` and prints three rows: all calls (with the CPU mean, the
/// share found free and the narrow-phase tests per call), the free ones and the colliding ones.
template <class Input, class Query>
void benchQueries(CollisionChecker& checker, const std::string& name, const std::vector<Input>& inputs,
                  Query&& query) {
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
  printRow(name + ", all", stats, note);
  printRow(name + ", free", summarise(free));
  printRow(name + ", colliding", summarise(hit));
}

int usage(const char* message) {
  std::fprintf(stderr, "%s\nusage: dashbed_bench_collision [WORLD.yaml] [--checks N] [--motions M] [--seed S]\n",
               message);
  return 2;
}

}  // namespace

int main(int argc, char** argv) try {
  std::string world_file;
  int checks = 100000;
  int motions = 2000;
  std::uint64_t seed = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--checks") {
      checks = std::stoi(value());
    } else if (arg == "--motions") {
      motions = std::stoi(value());
    } else if (arg == "--seed") {
      seed = std::stoull(value());
    } else if (arg == "-h" || arg == "--help") {
      return usage("Times the planner's collision checker.");
    } else if (!arg.empty() && arg[0] == '-') {
      return usage(("unknown option " + arg).c_str());
    } else {
      world_file = arg;
    }
  }
  if (world_file.empty()) world_file = dashbed::core::defaultWorldPath().string();
  if (checks <= 0 || motions < 0) return usage("--checks must be > 0 and --motions >= 0");

  const auto loaded = dashbed::core::loadWorld(world_file);
  const auto& world = *loaded.world;
  const auto& robots = *loaded.robots;
  if (robots.size() < 1) return usage("the world has no robot");

  const auto build_start = Clock::now();
  const CollisionScene scene(world, robots);
  const double build_ms = std::chrono::duration<double, std::milli>(Clock::now() - build_start).count();
  CollisionChecker checker(scene);
  const auto objects = dashbed::planner::startPlacement(world);
  std::mt19937_64 rng(seed);

  std::printf("world %s: %zu robots, %zu objects, %zu static boxes; scene built in %.1f ms\n", world.name.c_str(),
              robots.size(), world.objects.size(), scene.staticBoxes().size(), build_ms);
  std::printf("settings: margin %.4f m, motion step %.4f m; self pairs ignored for robot 0:", scene.settings().margin,
              scene.settings().motion_step);
  for (const auto& pair : scene.ignoredSelfPairs(0)) {
    std::printf(" %s-%s (%s);", pair.body_a.c_str(), pair.body_b.c_str(), pair.reason.c_str());
  }
  std::printf("\n\n%-46s %8s %10s %10s %10s %10s\n", "query [us per call]", "calls", "median", "mean", "p95",
              "cpu mean");

  // the timer's own cost
  {
    std::vector<double> us;
    bool result = false;
    for (int i = 0; i < 10000; ++i) us.push_back(timeCall([] { return true; }, result));
    printRow("(empty timed call)", summarise(us));
  }

  // one robot against the scene
  const auto robotBench = [&](const std::string& name, const std::optional<HeldObject>& held) {
    std::vector<Eigen::VectorXd> qs;
    qs.reserve(static_cast<std::size_t>(checks));
    for (int i = 0; i < checks; ++i) qs.push_back(randomConfiguration(*robots[0].model, rng));
    benchQueries(checker, name, qs, [&](const Eigen::VectorXd& q) { return checker.robotFree(0, q, objects, held); });
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
      benchQueries(checker, name, qs, [&](const auto& pair) {
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
    printRow("motionFree (free ends, +-0.5 rad), all", stats, note);
    printRow("motionFree, free motions", summarise(free));
    printRow("motionFree, blocked motions", summarise(hit));
    printRow("motionFree, free motions, per evaluated sample", summarise(per_sample));
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "dashbed_bench_collision: %s\n", e.what());
  return 1;
}
