#pragma once
// The files of a stress campaign's output directory: the results (summary.json, junit.xml,
// trials.csv, trials.json, sweep.png) and the worst trials, each replayable with
// `dashbed sim DIR/trial_N/plan.json --world DIR/trial_N/world.yaml`.

#include <filesystem>
#include <vector>

#include "tools/stress/stress.h"
#include "tools/stress/stress_summary.h"

namespace dashbed::tools {

/// Creates `out_dir` and removes the trial_<number> directories an earlier campaign left in
/// it (nothing else). Throws std::runtime_error naming the directory when it cannot.
void prepareOutputDirectory(const std::filesystem::path& out_dir);

/// Writes out_dir/trial_<index>/: world.yaml (the perturbed world), plan.json and report.json
/// (when the trial had a plan), trial.json (its outcome: seed, perturbation, classes) and, when
/// its motion was sampled, replay.html.
void saveTrial(const std::filesystem::path& out_dir, const TrialRun& run);

/// Runs the trials of `worst` again on `threads` threads, checks that each reproduces its
/// recorded outcome (std::logic_error otherwise: a determinism bug) and saves it, with its HTML
/// replay (replay.html, sim/replay) when `replays`. A trial without a plan (planner failure) is
/// not planned again: its world is saved.
void saveTrials(const std::filesystem::path& out_dir, const TrialRunner& runner, const std::vector<TrialOutcome>& worst,
                int threads, bool replays = false);

/// Writes the campaign's HTML page (tools/stress/stress_page.h) to `page`, linking the worst
/// trials' replays in `out_dir` (saveTrials with replays). Throws std::runtime_error naming the
/// file when it cannot be written.
void writeCampaignPage(const std::filesystem::path& page, const std::filesystem::path& out_dir,
                       const CampaignInfo& info, const std::vector<PointSummary>& points,
                       const std::vector<TrialOutcome>& worst);

/// Writes summary.json, junit.xml, trials.csv, trials.json (every outcome, with the actions'
/// measurements) and, for a sweep, sweep.png into `out_dir`.
/// Throws std::runtime_error naming a file that cannot be written.
void writeCampaignFiles(const std::filesystem::path& out_dir, const CampaignInfo& info, const core::World& world,
                        const std::vector<PointSummary>& points, const std::vector<TrialOutcome>& outcomes,
                        const std::vector<TrialOutcome>& worst);

}  // namespace dashbed::tools
