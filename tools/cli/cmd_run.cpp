// dashbed run [WORLD]: the main job on a world (the built-in default when none is given).
//
// Loads and validates the world (including that every robot is free at home), reports what each
// robot can reach and which robots can hand objects to each other, plans with DaSH
// (tools/planning/run_planner.h), executes the plan in simulation and checks it.

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/grasps.h"
#include "core/number_text.h"
#include "core/reach.h"
#include "core/world_loader.h"
#include "sim/job/check_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/planner_options.h"
#include "tools/cli/sim_options.h"
#include "tools/planning/run_planner.h"

namespace dashbed::tools {
namespace {

struct RunOptions {
  std::string world_file;
  bool json = false;
  bool validate_only = false;
  std::string plan_out;
  PlannerChoice choice;
  sim::CheckOutputs outputs;
  bool quiet = false;
};

std::string robotNames(const core::World& world, const std::vector<int>& robots) {
  if (robots.empty()) return "-";
  std::string out;
  for (const int r : robots) out += (out.empty() ? "" : ",") + world.robots[r].name;
  return out;
}

std::string vec3(const Eigen::Vector3d& v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return out.str();
}

double yawDegrees(const core::Pose& X) {
  return std::atan2(X.linear()(1, 0), X.linear()(0, 0)) * 180.0 / std::numbers::pi;
}

void printSummary(const core::LoadedWorld& loaded, const std::filesystem::path& file, const RunOptions& options) {
  const core::World& world = *loaded.world;
  const core::RobotSet& robots = *loaded.robots;

  // the heaviest each object may be for the grip to hold it by friction, standing still
  const auto holds = [&](const core::ObjectSpec& object) {
    return core::frictionHoldMass(object.friction * world.physics.pad_friction, world.controller.grip_force,
                                  world.physics.gravity.norm());
  };
  std::vector<std::pair<int, int>> handoff_pairs;
  for (std::size_t a = 0; a < robots.size(); ++a) {
    for (std::size_t b = a + 1; b < robots.size(); ++b) {
      if (core::handoffZone(world, robots[a], robots[b])) handoff_pairs.emplace_back(a, b);
    }
  }

  if (options.json) {
    nlohmann::json out;
    out["world"] = {{"name", world.name}, {"file", file.string()}};
    for (const auto& r : world.robots) {
      out["robots"].push_back({{"name", r.name}, {"model", r.model}, {"home", r.home}});
    }
    for (std::size_t o = 0; o < world.objects.size(); ++o) {
      const auto& object = world.objects[o];
      const core::Region* region = world.goalRegionOf(object);
      nlohmann::json start = nlohmann::json::array(), goal = nlohmann::json::array();
      for (int r : loaded.reach.start[o]) start.push_back(world.robots[r].name);
      for (int r : loaded.reach.goal[o]) goal.push_back(world.robots[r].name);
      out["objects"].push_back({{"name", object.name},
                                {"class", object.object_class},
                                {"goal_region", region != nullptr ? region->name : ""},
                                {"start_reached_by", start},
                                {"goal_reached_by", goal},
                                {"friction_holds_kg", holds(object)}});
    }
    out["handoff_pairs"] = nlohmann::json::array();
    for (const auto& [a, b] : handoff_pairs) out["handoff_pairs"].push_back({world.robots[a].name, world.robots[b].name});
    std::cout << jsonText(out) << "\n";
    return;
  }

  std::cout << "world " << world.name << " (" << file.string() << "): " << world.robots.size() << " robots, "
            << world.fixtures.size() << " fixtures, " << world.objects.size() << " objects, " << world.goals.size()
            << " goals\n";
  if (!world.description.empty()) std::cout << "  " << world.description << "\n";
  std::cout << "\nrobots:\n";
  for (const auto& r : world.robots) {
    std::cout << "  " << std::left << std::setw(6) << r.name << " " << r.model << "  base "
              << vec3(r.X_WBase.translation()) << " yaw " << std::fixed << std::setprecision(1)
              << yawDegrees(r.X_WBase) << " deg\n";
  }
  std::cout << "\nobjects (start reached by / goal reached by):\n";
  for (std::size_t o = 0; o < world.objects.size(); ++o) {
    const auto& object = world.objects[o];
    const core::Region* region = world.goalRegionOf(object);
    std::cout << "  " << std::left << std::setw(10) << object.name << " " << std::setw(8) << object.object_class
              << " at " << vec3(object.X_WO.translation()) << "  -> " << std::setw(14)
              << (region != nullptr ? region->name : "(no goal)") << " start: " << std::setw(8)
              << robotNames(world, loaded.reach.start[o]) << " goal: " << robotNames(world, loaded.reach.goal[o])
              << "\n";
  }
  // objects the grip cannot hold by friction even standing still: the simulation will see them slip
  for (const auto& object : world.objects) {
    if (object.mass > holds(object)) {
      std::cout << "  warning: " << object.name << " (" << core::significantText(object.mass, 3)
                << " kg) will slip: friction " << core::significantText(object.friction, 3) << " x pads "
                << core::significantText(world.physics.pad_friction, 3) << " at a " << core::significantText(world.controller.grip_force, 4)
                << " N grip holds at most " << core::significantText(holds(object), 3) << " kg\n";
    }
  }
  std::cout << "\ngoals:\n";
  for (const auto& g : world.goals) {
    std::cout << "  " << (g.object.empty() ? "class " + g.object_class : "object " + g.object) << " -> "
              << g.region << "\n";
  }
  std::cout << "\nhandoffs possible between:";
  if (handoff_pairs.empty()) std::cout << " (none)";
  for (const auto& [a, b] : handoff_pairs) std::cout << " " << world.robots[a].name << "<->" << world.robots[b].name;
  std::cout << "\n\nworld is valid: every object start and goal is within some robot's reach, every robot is free "
               "at home.\n";
}

void planAndSimulate(const core::LoadedWorld& loaded, const RunOptions& options,
                     std::shared_ptr<const planner::CollisionScene> checked_scene) {
  // --quiet: the planner's result only when it is the verdict (no plan)
  const bool quiet = options.quiet;
  if (!quiet) std::cout << "\nplanning (DaSH, " << options.choice.method << ", seed " << options.choice.seed << ")...\n";
  planner::PlanResult planned = planWorld(loaded, options.choice, std::move(checked_scene));
  if (!quiet || !planned.plan) std::cout << describePlanResult(planned);
  if (!planned.plan) throw CLI::RuntimeError(exitCodeOf(planned.status));
  const core::Plan& plan = *planned.plan;
  if (!options.plan_out.empty()) {
    std::ofstream out(options.plan_out, std::ios::binary);
    out << core::writePlanJson(plan);
    if (!out) throw std::runtime_error("cannot write " + options.plan_out);
  }
  if (!quiet) std::cout << "\nsimulating and checking...\n";
  const sim::RecordedRun run = sim::checkPlan(*loaded.world, *loaded.robots, plan,
                                             options.plan_out.empty() ? "plan" : options.plan_out, options.outputs);
  printRun(run, options.outputs, options.quiet);
  if (!run.report.passed()) throw CLI::RuntimeError(kExitCheckFailed);
}

void runJob(const RunOptions& options) {
  const std::filesystem::path file = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(file);
  // the home check is the planner's, in the scene it plans in: built and checked once
  auto scene = planner::checkedScene(loaded, plannerSettings(options.choice));
  if (!options.quiet || options.json || options.validate_only) printSummary(loaded, file, options);
  if (!options.validate_only && !options.json) planAndSimulate(loaded, options, std::move(scene));
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand(
      "run", "The main job: validate a world, plan, execute the plan in simulation and check every grasp, "
             "handoff and placement (default world: worlds/default.yaml). Exit 0 when all checks pass, 1 when "
             "any fails, 3 for bad input, 4 when planning proves the world infeasible, 5 on a planning timeout.");
  run->add_option("world", options->world_file, "world file (YAML)");
  run->add_flag("--validate-only", options->validate_only, "stop after validating the world");
  run->add_flag("--json", options->json, "print the world summary as JSON and stop");
  run->add_option("--plan-out", options->plan_out, "write the plan here (JSON)");
  addPlannerOptions(*run, options->choice);
  addReportOptions(*run, options->outputs, options->quiet);
  addRecordingOptions(*run, options->outputs.recording, /*with_out_dir=*/false);
  run->callback([options] { runGuarded("run", [&] { runJob(*options); }); });
}

}  // namespace dashbed::tools
