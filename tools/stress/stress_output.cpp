#include "tools/stress/stress_output.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/asset_paths.h"
#include "core/robot_set.h"
#include "core/world_io.h"
#include "sim/render/image.h"
#include "sim/replay/replay_html.h"
#include "tools/parallel/parallel_trials.h"
#include "tools/stress/stress_page.h"
#include "tools/stress/stress_plot.h"

namespace dashbed::tools {
namespace {

bool isTrialDirectoryName(const std::string& name) {
  return name.size() > 6 && name.rfind("trial_", 0) == 0 &&
         std::all_of(name.begin() + 6, name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

void prepareOutputDirectory(const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir)) {
    throw std::runtime_error(out_dir.string() + ": cannot create the output directory" +
                             (ec ? ": " + ec.message() : ""));
  }
  for (const auto& entry : std::filesystem::directory_iterator(out_dir)) {
    if (entry.is_directory() && isTrialDirectoryName(entry.path().filename().string())) {
      std::filesystem::remove_all(entry.path());
    }
  }
}

void saveTrial(const std::filesystem::path& out_dir, const TrialRun& run) {
  const std::filesystem::path dir = out_dir / trialDirectoryName(run.outcome.index);
  std::filesystem::create_directories(dir);
  core::writeFile(dir / "world.yaml", run.world_yaml);
  if (run.plan) core::writeFile(dir / "plan.json", core::writePlanJson(*run.plan));
  if (run.report) core::writeFile(dir / "report.json", sim::writeReportJson(*run.report));
  core::writeFile(dir / "trial.json", writeOutcomesJson({run.outcome}));
  if (run.motion && run.report) {
    const core::World world = core::parseWorldYaml(run.world_yaml, (dir / "world.yaml").string());
    const core::RobotSet robots(world);
    replay::writeReplayHtml(dir / "replay.html", world, robots, *run.motion, *run.report);
  }
}

void saveTrials(const std::filesystem::path& out_dir, const TrialRunner& runner, const std::vector<TrialOutcome>& worst,
                int threads, bool replays) {
  parallelFor(worst.size(), threads, [&](std::size_t i) {
    // a trial without a plan has nothing to replay: its world is enough (and planning again
    // could take the whole planner budget)
    const bool planned = !worst[i].actions.empty();
    TrialRun run = planned ? runner.run(worst[i].index, replays ? replay::kReplayRate : 0.0)
                           : runner.perturbedWorld(worst[i].index);
    if (!planned && run.outcome.objects == worst[i].objects) run.outcome = worst[i];
    if (!(run.outcome == worst[i])) {
      throw std::logic_error("trial " + std::to_string(worst[i].index) +
                             " did not reproduce its outcome when run again (non-deterministic simulation, or a "
                             "planner stopped by its wall-clock budget)");
    }
    saveTrial(out_dir, run);
  });
}

void writeCampaignPage(const std::filesystem::path& page, const std::filesystem::path& out_dir,
                       const CampaignInfo& info, const std::vector<PointSummary>& points,
                       const std::vector<TrialOutcome>& worst) {
  const std::filesystem::path folder = std::filesystem::absolute(page).parent_path();
  const std::string trials = core::pathFrom(std::filesystem::absolute(out_dir), folder);
  core::writeFile(page, campaignHtml(info, points, worst, trials == "." ? "" : trials, /*replays=*/true));
}

void writeCampaignFiles(const std::filesystem::path& out_dir, const CampaignInfo& info, const core::World& world,
                        const std::vector<PointSummary>& points, const std::vector<TrialOutcome>& outcomes,
                        const std::vector<TrialOutcome>& worst) {
  const CampaignSettings& settings = info.settings;
  core::writeFile(out_dir / "summary.json", writeSummaryJson(info, points, worst));
  core::writeFile(out_dir / "junit.xml", writeStressJUnit(info, points));
  core::writeFile(out_dir / "trials.csv", writeTrialsCsv(world, settings, outcomes));
  core::writeFile(out_dir / "trials.json", writeOutcomesJson(outcomes));
  if (!settings.sweep_xy.empty()) {
    const std::string title = info.world + ": " + std::string(toString(settings.mode)) + ", " +
                              std::to_string(settings.trials) + " trials per point";
    render::writePng(sweepPlot(points, title), out_dir / "sweep.png");
  }
}

}  // namespace dashbed::tools
