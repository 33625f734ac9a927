// dashbed sim PLAN --world WORLD: execute a plan in physics and check it; or, with
// --trajectory ROBOT=FILE, a plan made elsewhere (tools/export/foreign_plan.h).

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/asset_paths.h"
#include "core/plan.h"
#include "core/world_loader.h"
#include "sim/job/check_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/sim_options.h"
#include "tools/export/foreign_plan.h"

namespace dashbed::tools {
namespace {

struct SimOptions {
  std::string plan_file;
  std::vector<std::string> trajectories;  // ROBOT=FILE
  std::vector<std::string> grippers;      // ROBOT=FILE
  std::string world_file;
  sim::CheckOutputs outputs;
  bool quiet = false;
};

/// ROBOT=FILE split in two; throws std::invalid_argument naming the option otherwise.
std::pair<std::string, std::string> robotAndFile(const std::string& text, const std::string& option) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == text.size()) {
    throw std::invalid_argument(option + ": expected ROBOT=FILE, got '" + text + "'");
  }
  return {text.substr(0, equals), text.substr(equals + 1)};
}

/// The plan the files made elsewhere describe, without actions.
core::Plan foreignPlan(const SimOptions& options, const core::LoadedWorld& loaded) {
  std::vector<exporting::ForeignTrajectory> robots;
  for (const std::string& text : options.trajectories) {
    const auto [robot, file] = robotAndFile(text, "--trajectory");
    robots.push_back({robot, file, ""});
  }
  for (const std::string& text : options.grippers) {
    const auto [robot, file] = robotAndFile(text, "--gripper");
    const auto it = std::find_if(robots.begin(), robots.end(), [&](const auto& r) { return r.robot == robot; });
    if (it == robots.end()) throw std::invalid_argument("--gripper: no --trajectory for robot '" + robot + "'");
    it->gripper_file = file;
  }
  const core::RobotModel& model = *(*loaded.robots)[0].model;
  std::array<std::string, 6> names;
  for (std::size_t i = 0; i < 6; ++i) names[i] = model.joints()[model.movableJoints()[i]].name;
  return exporting::readForeignPlan(*loaded.world, names, robots);
}

void runSim(const SimOptions& options) {
  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  if (options.plan_file.empty() == options.trajectories.empty()) {
    throw std::invalid_argument("give either a plan file or --trajectory ROBOT=FILE for each robot");
  }
  const bool foreign = !options.trajectories.empty();
  const core::Plan plan = foreign ? foreignPlan(options, loaded) : core::loadPlanFile(options.plan_file);
  const std::string plan_name = foreign ? robotAndFile(options.trajectories.front(), "--trajectory").second
                                        : options.plan_file;
  const sim::RecordedRun run = sim::checkPlan(*loaded.world, *loaded.robots, plan, plan_name, options.outputs);
  printRun(run, options.outputs, options.quiet);
  if (!run.report.passed()) throw CLI::RuntimeError(kExitCheckFailed);
}

}  // namespace

void addSimCommand(CLI::App& app) {
  auto options = std::make_shared<SimOptions>();
  CLI::App* sim = app.add_subcommand(
      "sim", "Execute a plan (or trajectories made elsewhere) in the Bullet simulation and check every grasp, "
             "handoff and placement physically. "
             "Exit 0 when every check passes, 1 when any fails, 3 for bad input.");
  sim->add_option("plan", options->plan_file, "plan file (JSON)");
  sim->add_option("--trajectory", options->trajectories,
                  "ROBOT=FILE: a trajectory made elsewhere instead of a plan file, one per robot: ROS 2 "
                  "JointTrajectory YAML or CSV (docs/export.md); its actions are inferred from the gripper "
                  "commands and what they close on");
  sim->add_option("--gripper", options->grippers, "ROBOT=FILE: that robot's gripper timeline (YAML)");
  sim->add_option("--world", options->world_file, "world file (default: worlds/default.yaml)");
  addReportOptions(*sim, options->outputs, options->quiet);
  addRecordingOptions(*sim, options->outputs.recording, /*with_out_dir=*/false);
  sim->callback([options] { runGuarded("sim", [&] { runSim(*options); }); });
}

}  // namespace dashbed::tools
