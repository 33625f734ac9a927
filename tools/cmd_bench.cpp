// dashbed bench sim: real-time factor of headless simulation.

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/monitor.h"
#include "sim/plan_executor.h"
#include "sim/simulation.h"
#include "tools/cli_support.h"
#include "tools/scenarios.h"

namespace dashbed::tools {
namespace {

struct BenchSimOptions {
  std::vector<std::string> worlds;
  std::vector<int> cubes{4, 20};
  double seconds = 10.0;
};

/// Every robot sways its shoulder pan and wrist joints around home (so the arms really move
/// and the controllers work) while the cubes rest on the table.
core::Plan swayPlan(const core::World& world, double seconds) {
  core::Plan plan;
  plan.world = world.name;
  for (const core::RobotSpec& robot : world.robots) {
    core::RobotTrajectory trajectory;
    trajectory.robot = robot.name;
    for (int k = 0; k <= static_cast<int>(seconds * 10); ++k) {
      core::TrajectoryPoint point;
      point.t = 0.1 * k;
      point.q = robot.home;
      point.q[0] += 0.3 * std::sin(point.t);
      point.q[4] += 0.4 * std::sin(1.3 * point.t);
      trajectory.points.push_back(point);
    }
    plan.trajectories.push_back(trajectory);
  }
  return plan;
}

void benchOne(const std::string& label, const core::World& world, double seconds) {
  const core::LoadedWorld loaded = core::validateWorld(world);
  const core::Plan plan = swayPlan(*loaded.world, seconds);
  sim::Simulation sim(*loaded.world, *loaded.robots);
  sim::PlanExecutor executor(sim, plan);
  sim::Monitor monitor(sim, plan, 0.0);
  const auto start = std::chrono::steady_clock::now();
  while (sim.time() < seconds) {
    executor.step();
    monitor.observe(executor);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << std::left << std::setw(34) << label << std::right << std::setw(8) << world.robots.size()
            << std::setw(8) << world.objects.size() << std::fixed << std::setprecision(1) << std::setw(10) << seconds
            << std::setw(10) << wall << std::setw(10) << seconds / wall << "x" << std::setprecision(1) << std::setw(10)
            << wall / (seconds / sim.timeStep()) * 1e6 << "\n";
}

void runBenchSim(const BenchSimOptions& options) {
  std::cout << "headless simulation real-time factor (one thread, monitor on, 1 kHz unless the world says otherwise)\n";
  std::cout << std::left << std::setw(34) << "world" << std::right << std::setw(8) << "robots" << std::setw(8)
            << "objects" << std::setw(10) << "sim [s]" << std::setw(10) << "wall [s]" << std::setw(11) << "RTF"
            << std::setw(10) << "us/step" << "\n";
  if (!options.worlds.empty()) {
    for (const std::string& file : options.worlds) benchOne(file, core::loadWorldFile(file), options.seconds);
    return;
  }
  for (const int cubes : options.cubes) {
    SortingParams params;
    params.robots = 2;
    params.cubes = cubes;
    params.start = StartLayout::kRandom;
    const core::World world = generateSorting(params);
    benchOne(world.name, world, options.seconds);
  }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks (speed is measured here, never in tests)");
  bench->require_subcommand(1);
  auto options = std::make_shared<BenchSimOptions>();
  CLI::App* sim = bench->add_subcommand(
      "sim", "Real-time factor of headless simulation: the 2-robot sorting world with 4 and 20 cubes, "
             "arms moving under PD control");
  sim->add_option("--world", options->worlds, "benchmark these world files instead");
  sim->add_option("--cubes", options->cubes, "cube counts of the generated 2-robot sorting worlds")->capture_default_str();
  sim->add_option("--seconds", options->seconds, "simulated seconds per world")->capture_default_str();
  sim->callback([options] { runGuarded("bench sim", [&] { runBenchSim(*options); }); });
}

}  // namespace dashbed::tools
