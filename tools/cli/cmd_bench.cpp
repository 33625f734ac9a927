// dashbed bench sim: real-time factor of headless simulation; bench render: offscreen frames per
// second; bench plan: the paper's planner experiments (tools/bench/bench_plan.h).

#include <chrono>
#include <ctime>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/monitor.h"
#include "sim/render/render_benchmark.h"
#include "sim/plan_executor.h"
#include "sim/simulation.h"
#include "tools/bench/bench_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/planner_options.h"
#include "tools/scenarios/scenarios.h"

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
  const std::clock_t cpu_start = std::clock();
  while (sim.time() < seconds) {
    executor.step();
    monitor.observe(executor);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // CPU time too: on a shared machine the wall clock also counts waiting for a core
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::cout << std::left << std::setw(34) << label << std::right << std::setw(8) << world.robots.size()
            << std::setw(8) << world.objects.size() << std::fixed << std::setprecision(1) << std::setw(10) << seconds
            << std::setw(10) << wall << std::setw(10) << seconds / wall << "x" << std::setw(10) << seconds / cpu << "x"
            << std::setw(10) << cpu / (seconds / sim.timeStep()) * 1e6 << "\n";
}

void runBenchSim(const BenchSimOptions& options) {
  std::cout << "headless simulation real-time factor (one thread, monitor on, 1 kHz unless the world says otherwise)\n";
  std::cout << std::left << std::setw(34) << "world" << std::right << std::setw(8) << "robots" << std::setw(8)
            << "objects" << std::setw(10) << "sim [s]" << std::setw(10) << "wall [s]" << std::setw(11) << "RTF wall"
            << std::setw(11) << "RTF cpu" << std::setw(12) << "cpu us/step" << "\n";
  if (!options.worlds.empty()) {
    for (const std::string& file : options.worlds) benchOne(file, core::loadWorldFile(file), options.seconds);
    return;
  }
  for (const int cubes : options.cubes) {
    SortingParams params;
    params.robots = 2;
    params.cubes = cubes;
    params.start = StartLayout::kRandom;
    core::World world = generateSorting(params);
    core::deriveFixtureGeometry(world);  // the bins' walls and floors, as the loader makes them
    benchOne(world.name, world, options.seconds);
  }
}

void runBenchRender(const std::string& world_file, int frames) {
  const core::LoadedWorld loaded =
      core::loadWorld(world_file.empty() ? core::defaultWorldPath() : std::filesystem::path(world_file));
  std::cout << "offscreen rendering (OSMesa), world " << loaded.world->name << ", oblique camera, " << frames
            << " frames each\n";
  std::cout << std::left << std::setw(12) << "size" << std::right << std::setw(14) << "render fps" << std::setw(18)
            << "render+PNG fps" << "\n";
  for (const auto& [w, h] : {std::pair{640, 480}, std::pair{1280, 720}}) {
    const double fps = render::benchmarkFps(*loaded.world, *loaded.robots, w, h, frames, false);
    const double fps_png = render::benchmarkFps(*loaded.world, *loaded.robots, w, h, frames, true);
    std::cout << std::left << std::setw(12) << (std::to_string(w) + "x" + std::to_string(h)) << std::right << std::fixed
              << std::setprecision(1) << std::setw(14) << fps << std::setw(18) << fps_png << "\n";
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

  auto world_file = std::make_shared<std::string>();
  auto frames = std::make_shared<int>(120);
  CLI::App* render = bench->add_subcommand("render", "Frames per second of offscreen rendering at 640x480 and 1280x720");
  render->add_option("--world", *world_file, "world file (default: worlds/default.yaml)");
  render->add_option("--frames", *frames, "frames per measurement")->capture_default_str();
  render->callback([=] { runGuarded("bench render", [&] { runBenchRender(*world_file, *frames); }); });

  auto plan_options = std::make_shared<BenchOptions>();
  CLI::App* plan = bench->add_subcommand(
      "plan", "The DaSH paper's planner experiments (Table I): sorting with 2 and 4 robots, shelving; Greedy and "
              "MM-DaSH; writes bench_plan.md/.csv/_runs.csv/.png into --out and prints the table");
  plan->add_option("--suite", plan_options->suites, "sorting2, sorting4, shelf or all (several: comma-separated)")
      ->delimiter(',')
      ->capture_default_str();
  plan->add_option("--cubes,--objects", plan_options->objects, "object counts (default: the paper's for each suite)")
      ->delimiter(',');
  plan->add_option("--starts", plan_options->starts, "sorting start layouts: cross, random")
      ->delimiter(',')
      ->capture_default_str();
  plan->add_option("--seeds", plan_options->seeds, "seeds 1..N per row (world and planner)")->capture_default_str();
  plan->add_option("--methods", plan_options->methods, "greedy (Greedy-MM-DaSH), optimal (MM-DaSH)")
      ->delimiter(',')
      ->capture_default_str();
  plan->add_option("--greedy-budget", plan_options->greedy_budget, "wall-clock budget per Greedy run [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  plan->add_option("--optimal-budget", plan_options->optimal_budget, "wall-clock budget per MM-DaSH run [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  plan->add_option("--max-rounds", plan_options->max_rounds, "representation expansion rounds per run")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  plan->add_option("--fallback-rounds", plan_options->fallback_rounds, kFallbackRoundsHelp)
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  plan->add_flag("--simulate,!--no-simulate", plan_options->simulate,
                 "execute every solved plan in the simulator and count those passing every check (default on)");
  plan->add_option("--jobs", plan_options->jobs, "runs at a time (threads)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  plan->add_option("--out", plan_options->out, "output directory")->capture_default_str();
  plan->callback([plan_options] {
    runGuarded("bench plan", [&] {
      const std::vector<BenchRow> rows = runBench(*plan_options, std::cout);
      writeBenchOutputs(rows, *plan_options);
      std::cout << "\n"
                << markdownTable(rows) << "\nwrote " << plan_options->out
                << "/bench_plan.{md,csv,png} and bench_plan_runs.csv\n";
    });
  });
}

}  // namespace dashbed::tools
