// dashbed render PLAN --world WORLD --out DIR: frames (and video) of a simulated plan.

#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/job/check_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/sim_options.h"

namespace dashbed::tools {
namespace {

struct RenderOptions {
  std::string plan_file;
  std::string world_file;
  sim::CheckOutputs outputs;  // frames and video only
};

void runRender(const RenderOptions& options) {
  if (!options.outputs.recording.wanted()) throw CLI::ValidationError("render", "give --out DIR and/or --video FILE");
  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  const core::Plan plan = core::loadPlanFile(options.plan_file);
  const sim::RecordedRun run = sim::checkPlan(*loaded.world, *loaded.robots, plan, options.plan_file, options.outputs);
  printRun(run, options.outputs, /*quiet=*/true);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* render = app.add_subcommand(
      "render", "Simulate a plan and render it offscreen: PNG frames every 1/fps of simulated time (--out) "
                "and/or an MP4 (--video), with the time, the actions in progress and failed checks overlaid");
  render->add_option("plan", options->plan_file, "plan file (JSON)")->required();
  render->add_option("--world", options->world_file, "world file (default: worlds/default.yaml)");
  addRecordingOptions(*render, options->outputs.recording, /*with_out_dir=*/true);
  render->callback([options] { runGuarded("render", [&] { runRender(*options); }); });
}

}  // namespace dashbed::tools
