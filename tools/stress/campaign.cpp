#include "tools/stress/campaign.h"

#include <algorithm>
#include <utility>

namespace dashbed::tools {

core::Plan plannedNominal(const core::LoadedWorld& world, const CampaignSettings& settings, std::string& description) {
  PlannerChoice choice = settings.planner;
  choice.seed = settings.seed;
  description = "planned (" + choice.method + ", seed " + std::to_string(choice.seed) + ")";
  return planForRun(world, choice);
}

CampaignResults summarizeCampaign(CampaignInfo info, std::vector<TrialOutcome> outcomes, int worst_count) {
  std::sort(outcomes.begin(), outcomes.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  CampaignResults results{std::move(info), std::move(outcomes), {}, {}};
  results.points = summarize(results.info.settings, results.outcomes);
  for (const std::size_t i : worstTrials(results.outcomes, worst_count)) results.worst.push_back(results.outcomes[i]);
  return results;
}

}  // namespace dashbed::tools
