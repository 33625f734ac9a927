#pragma once
// Results of a stress campaign: success rates with Wilson score intervals, the failure
// taxonomy, the worst trials, and the files they are written to (JSON summary, JUnit XML,
// one CSV line per trial). Everything here is a pure function of the settings and the
// outcomes, so equal campaigns give equal bytes.

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tools/stress/stress.h"

namespace dashbed::tools {

/// z of a two-sided 95 % normal interval.
inline constexpr double kZ95 = 1.959963984540054;

/// A success rate with its Wilson score interval.
struct RateInterval {
  int successes = 0;
  int trials = 0;
  double rate = 0.0;   ///< successes / trials (0 without trials)
  double lower = 0.0;  ///< interval bounds, within [0, 1]; [0, 1] without trials
  double upper = 1.0;
};

/// Wilson score interval of `successes` out of `trials` for the normal quantile `z`.
RateInterval wilsonInterval(int successes, int trials, double z = kZ95);

/// Results of one sweep point (the whole campaign without a sweep).
struct PointSummary {
  double sigma_xy = 0.0;  ///< [m]
  RateInterval trials;    ///< trials that passed every check
  std::map<core::ActionType, RateInterval> per_type;  ///< actions of each type that passed (over all trials)
  std::map<std::string, RateInterval> per_action;     ///< by action id
  std::array<int, kFailureClassCount> primary{};      ///< failed trials by primary class
  std::array<int, kFailureClassCount> any{};          ///< trials in which each class occurred
  bool meets(std::optional<double> min_success) const { return !min_success || trials.rate >= *min_success; }
};

/// What the campaign is about, for the headers of the files.
struct CampaignInfo {
  std::string world;       ///< world name
  std::string world_file;  ///< as given
  std::string plan;        ///< the nominal plan file, or how it was planned
  CampaignSettings settings;
  std::optional<double> min_success;
};

/// True when every point meets info.min_success (always without one).
bool meetsAll(const CampaignInfo& info, const std::vector<PointSummary>& points);

/// Per-point summaries of `outcomes` (all trials of the campaign, any order).
std::vector<PointSummary> summarize(const CampaignSettings& settings, const std::vector<TrialOutcome>& outcomes);

/// The `count` worst failed trials: most failed actions first (planner failures, with no
/// actions, after those), then by index. Returns indices into `outcomes`.
std::vector<std::size_t> worstTrials(const std::vector<TrialOutcome>& outcomes, int count);

/// summary.json: {"dashbed_stress": 1, world, plan, mode, seed, trials_per_point,
/// perturbation, min_success, verdict, points: [...], worst_trials: [...]}.
std::string writeSummaryJson(const CampaignInfo& info, const std::vector<PointSummary>& points,
                             const std::vector<TrialOutcome>& worst);

/// junit.xml: one test case per sweep point ("success rate at sigma_xy = ..."), failed when
/// the rate is below --min-success; the text lists the rates and the failure taxonomy.
std::string writeStressJUnit(const CampaignInfo& info, const std::vector<PointSummary>& points);

/// trials.csv: one line per trial in index order: index, point, sigma_xy, seed, passed,
/// primary class, all classes ('+'-joined), failed actions, actions, then dx, dy, dyaw,
/// mass and friction scale of each object (columns named OBJECT.dx, ...).
std::string writeTrialsCsv(const core::World& world, const CampaignSettings& settings,
                           const std::vector<TrialOutcome>& outcomes);

/// The human-readable summary printed on stdout.
std::string summaryText(const CampaignInfo& info, const std::vector<PointSummary>& points);

}  // namespace dashbed::tools
