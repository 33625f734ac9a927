// dashbed bench sim | render | collision | plan: simulation real-time factor, offscreen frames per
// second, collision-checker timing, the paper's planner experiments (tools/bench/); --record
// writes the results into docs/benchmarks.md.

#include <chrono>
#include <ctime>
#include <cmath>
#include <iomanip>
#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/render/render_benchmark.h"
#include "tools/bench/bench_plan.h"
#include "tools/bench/bench_record.h"
#include "tools/bench/read_bench.h"
#include "tools/bench/collision_bench.h"
#include "tools/bench/sim_bench.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/planner_options.h"
#include "tools/cli/number_checks.h"

namespace dashbed::tools {
namespace {

/// The command as recorded: "dashbed bench NAME" and the options as given.
std::string commandLine(const CLI::App& command) {
  std::string line = "build/dashbed bench " + command.get_name();
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_name() == "--record" || option->get_name() == "--help") continue;
    line += " " + option->get_name();
    for (const std::string& value : option->results()) line += " " + value;
  }
  return line;
}

/// Prints `table` and, when `record` is given, writes it into that file's section `name`.
void report(const BenchTable& table, const std::string& record, const CLI::App& command, const std::string& name,
            const std::string& title) {
  std::cout << table.text();
  if (!record.empty()) {
    recordSection(record, name, title, commandLine(command), table.markdown());
    std::cout << "recorded in " << record << "\n";
  }
}

BenchTable benchRender(const std::string& world_file, int frames) {
  const core::LoadedWorld loaded = core::loadWorld(worldFileOrDefault(world_file));
  BenchTable table;
  table.note = "Offscreen rendering (OSMesa), world " + loaded.world->name + ", oblique camera, " +
               std::to_string(frames) + " frames each, one thread.";
  table.header = {"size", "render fps", "render+PNG fps"};
  for (const auto& [w, h] : {std::pair{640, 480}, std::pair{1280, 720}}) {
    const double fps = render::benchmarkFps(*loaded.world, *loaded.robots, w, h, frames, false);
    const double fps_png = render::benchmarkFps(*loaded.world, *loaded.robots, w, h, frames, true);
    table.rows.push_back({std::to_string(w) + "x" + std::to_string(h), fixed(fps, 1), fixed(fps_png, 1)});
  }
  return table;
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks (speed is measured here, never in tests)");
  bench->require_subcommand(1);
  auto record = std::make_shared<std::string>();
  const auto add_record = [record](CLI::App* command) {
    command->add_option("--record", *record,
                        "also write the results into this Markdown file's section of this benchmark (e.g. "
                        "docs/benchmarks.md), with the date, version and machine");
  };
  auto options = std::make_shared<SimBenchOptions>();
  CLI::App* sim = bench->add_subcommand(
      "sim", "Real-time factor of headless simulation: the 2-robot sorting world with 4 and 20 cubes, "
             "arms moving under PD control");
  sim->add_option("--world", options->worlds, "benchmark these world files instead");
  sim->add_option("--cubes", options->cubes, "cube counts of the generated 2-robot sorting worlds")->capture_default_str();
  sim->add_option("--seconds", options->seconds, "simulated seconds per world")->capture_default_str();
  options->plan_worlds = {core::defaultWorldPath().string()};
  sim->add_option("--plan-world", options->plan_worlds,
                  "also time the execution of these worlds' Greedy plans, as `dashbed sim` runs them (default: "
                  "worlds/default.yaml)");
  add_record(sim);
  sim->callback([options, record, sim] {
    runGuarded("bench sim", [&] {
      report(benchSimulation(*options), *record, *sim, "sim", "Simulation real-time factor (`dashbed bench sim`)");
    });
  });

  auto world_file = std::make_shared<std::string>();
  auto frames = std::make_shared<int>(120);
  CLI::App* render = bench->add_subcommand("render", "Frames per second of offscreen rendering at 640x480 and 1280x720");
  render->add_option("--world", *world_file, "world file (default: worlds/default.yaml)");
  render->add_option("--frames", *frames, "frames per measurement")->capture_default_str();
  add_record(render);
  render->callback([=] {
    runGuarded("bench render", [&] {
      report(benchRender(*world_file, *frames), *record, *render, "render", "Rendering (`dashbed bench render`)");
    });
  });

  auto collision = std::make_shared<CollisionBenchOptions>();
  CLI::App* checks = bench->add_subcommand(
      "collision", "Time per query of the planner's collision checker: one robot, two robots, straight motions");
  checks->add_option("--world", collision->world, "world file (default: worlds/default.yaml)");
  checks->add_option("--checks", collision->checks, "configurations per query row")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  checks->add_option("--motions", collision->motions, "motions of the motionFree rows")
      ->check(integerIn(0, std::numeric_limits<int>::max()))
      ->capture_default_str();
  checks->add_option("--seed", collision->seed, "seed of the drawn configurations")
      ->check(unsigned64())
      ->capture_default_str();
  add_record(checks);
  checks->callback([collision, record, checks] {
    runGuarded("bench collision", [&] {
      report(benchCollision(*collision), *record, *checks, "collision",
             "Collision checking (`dashbed bench collision`)");
    });
  });

  auto read = std::make_shared<ReadBenchOptions>();
  CLI::App* reading = bench->add_subcommand(
      "read", "How fast large world and plan files are read: made in memory at each size, accepted and refused "
              "at their last line");
  reading->add_option("--megabytes", read->megabytes, "sizes of the files made [MB]")
      ->check(finiteAbove(0.0, false))
      ->capture_default_str();
  add_record(reading);
  reading->callback([read, record, reading] {
    runGuarded("bench read", [&] {
      report(benchReading(*read), *record, *reading, "read", "Reading large files (`dashbed bench read`)");
    });
  });

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
  plan->add_option("--seeds", plan_options->seeds, "seeds 1..N per row (world and planner)")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  plan->add_option("--methods", plan_options->methods, "greedy (Greedy-MM-DaSH), optimal (MM-DaSH)")
      ->delimiter(',')
      ->capture_default_str();
  plan->add_option("--greedy-budget", plan_options->greedy_budget, "wall-clock budget per Greedy run [s]")
      ->check(positiveNumber())
      ->capture_default_str();
  plan->add_option("--optimal-budget", plan_options->optimal_budget, "wall-clock budget per MM-DaSH run [s]")
      ->check(positiveNumber())
      ->capture_default_str();
  plan->add_option("--max-rounds", plan_options->max_rounds, "representation expansion rounds per run")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  plan->add_option("--fallback-rounds", plan_options->fallback_rounds, kFallbackRoundsHelp)
      ->check(integerIn(0, std::numeric_limits<int>::max()))
      ->capture_default_str();
  plan->add_flag("--simulate,!--no-simulate", plan_options->simulate,
                 "execute every solved plan in the simulator and count those passing every check (default on)");
  plan->add_option("--jobs", plan_options->jobs, "runs at a time (threads)")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  plan->add_option("--out", plan_options->out, "output directory")->capture_default_str();
  add_record(plan);
  plan->callback([plan_options, record, plan] {
    runGuarded("bench plan", [&] {
      const std::vector<BenchRow> rows = runBench(*plan_options, std::cout);
      writeBenchOutputs(rows, *plan_options);
      std::cout << "\n"
                << markdownTable(rows) << "\nwrote " << plan_options->out
                << "/bench_plan.{md,csv,png} and bench_plan_runs.csv\n";
      if (!record->empty()) {
        recordSection(*record, "plan", "Planner: the paper's experiments (`dashbed bench plan`)", commandLine(*plan),
                      benchReport(rows, *plan_options, /*with_title=*/false));
        std::cout << "recorded in " << *record << "\n";
      }
    });
  });
}

}  // namespace dashbed::tools
