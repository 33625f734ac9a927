#include "tools/bench/sim_bench.h"

#include <chrono>
#include <cmath>
#include <ctime>

#include "core/world_io.h"
#include "core/world_loader.h"
#include "sim/monitor.h"
#include "sim/plan_executor.h"
#include "sim/run_plan.h"
#include "sim/simulation.h"
#include "tools/planning/run_planner.h"
#include "tools/scenarios/scenarios.h"

namespace dashbed::tools {
namespace {

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

/// The row of `world` from `simulate`, which returns the simulated seconds; timed by wall clock
/// and (on a shared machine the wall clock also counts waiting for a core) by CPU time.
template <class Simulate>
std::vector<std::string> timedRow(const std::string& label, const core::World& world, Simulate&& simulate) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const double seconds = simulate();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return {label,
          std::to_string(world.robots.size()),
          std::to_string(world.objects.size()),
          fixed(seconds, 1),
          fixed(wall, 1),
          fixed(seconds / wall, 1) + "x",
          fixed(seconds / cpu, 1) + "x",
          fixed(cpu / (seconds / world.physics.time_step) * 1e6, 1)};
}

std::vector<std::string> benchOne(const std::string& label, const core::World& world, double seconds) {
  const core::LoadedWorld loaded = core::validateWorld(world);
  const core::Plan plan = swayPlan(*loaded.world, seconds);
  return timedRow(label, *loaded.world, [&] {
    sim::Simulation sim(*loaded.world, *loaded.robots);
    sim::PlanExecutor executor(sim, plan);
    sim::Monitor monitor(sim, plan, 0.0);
    while (sim.time() < seconds) {
      executor.step();
      monitor.observe(executor);
    }
    return sim.time();
  });
}

/// The execution of the world's Greedy plan (seed 1), as `dashbed sim` runs it.
std::vector<std::string> benchPlan(const std::string& file) {
  const core::LoadedWorld loaded = core::loadWorld(file);
  const core::Plan plan = planForRun(loaded, PlannerChoice{});
  return timedRow("plan of " + loaded.world->name, *loaded.world, [&] {
    return sim::runPlan(*loaded.world, *loaded.robots, plan, "plan.json").simulated_time;
  });
}

}  // namespace

BenchTable benchSimulation(const SimBenchOptions& options) {
  BenchTable table;
  table.note = "Headless simulation, one thread, monitor on, 1 kHz unless the world says otherwise; every robot "
               "sways around home, except in the rows \"plan of\": the world's Greedy plan (seed 1) executed as "
               "`dashbed sim` does (settling, plan, tail; monitor, readiness check).";
  table.header = {"world", "robots", "objects", "sim [s]", "wall [s]", "RTF wall", "RTF cpu", "cpu us/step"};
  if (!options.worlds.empty()) {
    for (const std::string& file : options.worlds) {
      table.rows.push_back(benchOne(file, core::loadWorldFile(file), options.seconds));
    }
  } else {
    for (const int cubes : options.cubes) {
      SortingParams params;
      params.robots = 2;
      params.cubes = cubes;
      params.start = StartLayout::kRandom;
      core::World world = generateSorting(params);
      core::deriveFixtureGeometry(world);  // the bins' walls and floors, as the loader makes them
      table.rows.push_back(benchOne(world.name, world, options.seconds));
    }
  }
  for (const std::string& file : options.plan_worlds) table.rows.push_back(benchPlan(file));
  return table;
}

}  // namespace dashbed::tools
