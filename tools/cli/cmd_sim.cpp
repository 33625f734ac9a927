// dashbed sim PLAN --world WORLD: execute a plan in physics and check it.

#include "core/asset_paths.h"
#include "core/plan.h"
#include "core/world_loader.h"
#include "sim/job/check_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/sim_options.h"

namespace dashbed::tools {
namespace {

struct SimOptions {
  std::string plan_file;
  std::string world_file;
  sim::CheckOutputs outputs;
  bool quiet = false;
};

void runSim(const SimOptions& options) {
  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  const core::Plan plan = core::loadPlanFile(options.plan_file);
  const sim::RecordedRun run = sim::checkPlan(*loaded.world, *loaded.robots, plan, options.plan_file, options.outputs);
  printRun(run, options.outputs, options.quiet);
  if (!run.report.passed()) throw CLI::RuntimeError(kExitCheckFailed);
}

}  // namespace

void addSimCommand(CLI::App& app) {
  auto options = std::make_shared<SimOptions>();
  CLI::App* sim = app.add_subcommand(
      "sim", "Execute a plan in the Bullet simulation and check every grasp, handoff and placement physically. "
             "Exit 0 when every check passes, 1 when any fails, 3 for bad input.");
  sim->add_option("plan", options->plan_file, "plan file (JSON)")->required();
  sim->add_option("--world", options->world_file, "world file (default: worlds/default.yaml)");
  addReportOptions(*sim, options->outputs, options->quiet);
  addRecordingOptions(*sim, options->outputs.recording, /*with_out_dir=*/false);
  sim->callback([options] { runGuarded("sim", [&] { runSim(*options); }); });
}

}  // namespace dashbed::tools
