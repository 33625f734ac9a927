// dashbed view REPORT.json -o FILE.html: the HTML replay of a saved run. The run is simulated
// again from the report's plan (deterministic: the same world and plan give the same run) and
// must reproduce the report's verdicts and measurements.

#include <filesystem>
#include <iostream>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/job/check_plan.h"
#include "tools/cli/cli_support.h"

namespace dashbed::tools {
namespace {

struct ViewOptions {
  std::string report_file;
  std::string world_file;
  std::string output;
};

/// Where the first difference between two runs' verdicts and measurements is, or "".
std::string firstDifference(const sim::Report& saved, const sim::Report& again) {
  if (saved.actions.size() != again.actions.size()) {
    return std::to_string(saved.actions.size()) + " actions in the report, " + std::to_string(again.actions.size()) +
           " in the run";
  }
  for (std::size_t i = 0; i < saved.actions.size(); ++i) {
    const sim::ActionReport& a = saved.actions[i];
    const sim::ActionReport& b = again.actions[i];
    const bool same_measurements =
        a.measurements.size() == b.measurements.size() &&
        std::equal(a.measurements.begin(), a.measurements.end(), b.measurements.begin(),
                   [](const auto& x, const auto& y) { return x.name == y.name && x.value == y.value; });
    if (a.id != b.id || a.verdict != b.verdict || !same_measurements) return "action " + a.id;
  }
  if (saved.execution_verdict != again.execution_verdict || saved.events.size() != again.events.size()) {
    return "the execution's events";
  }
  return "";
}

void runView(const ViewOptions& options) {
  const sim::Report saved = sim::loadReportFile(options.report_file);
  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  if (loaded.world->name != saved.world) {
    throw std::invalid_argument(options.report_file + " is a run of world '" + saved.world + "', not of " +
                                world_path.string() + " ('" + loaded.world->name + "'): give its world with --world");
  }
  // the report names its plan relative to its own folder
  const std::filesystem::path plan_file =
      std::filesystem::path(options.report_file).parent_path() / std::filesystem::path(saved.plan_file);
  const core::Plan plan = core::loadPlanFile(plan_file);
  sim::CheckOutputs outputs;
  outputs.html = options.output;
  // named as the report names it: the replay is the one `--html` wrote beside the report
  const sim::RecordedRun run = sim::checkPlan(*loaded.world, *loaded.robots, plan, saved.plan_file, outputs);
  if (const std::string difference = firstDifference(saved, run.report); !difference.empty()) {
    std::filesystem::remove(options.output);
    throw std::runtime_error("the run of " + plan_file.string() + " does not reproduce " + options.report_file +
                             " (" + difference + " differs): another world file, or another build of dashbed");
  }
  std::cout << "wrote " << options.output << ": " << (run.report.passed() ? "PASSED" : "FAILED") << ", "
            << run.report.passedCount() << " of " << run.report.actions.size() << " actions passed\n";
}

}  // namespace

void addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* view = app.add_subcommand(
      "view", "Write the interactive HTML replay of a saved run: the report's plan is simulated again (it must "
              "reproduce the report) and written as one self-contained HTML file (docs/replay.md)");
  view->add_option("report", options->report_file, "report file (JSON) of `dashbed sim` or `run`")->required();
  view->add_option("--world", options->world_file, "the run's world file (default: worlds/default.yaml)");
  view->add_option("-o,--output", options->output, "the HTML file to write")->required();
  view->callback([options] { runGuarded("view", [&] { runView(*options); }); });
}

}  // namespace dashbed::tools
