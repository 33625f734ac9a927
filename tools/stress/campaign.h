#pragma once
// A stress campaign's results gathered in one process: what `dashbed stress` writes and prints,
// and what the Python API's stress() returns.

#include <string>
#include <vector>

#include "core/world_loader.h"

#include "tools/stress/stress.h"
#include "tools/stress/stress_summary.h"

namespace dashbed::tools {

struct CampaignResults {
  CampaignInfo info;
  std::vector<TrialOutcome> outcomes;  ///< every trial, by index
  std::vector<PointSummary> points;    ///< one per sweep point
  std::vector<TrialOutcome> worst;     ///< the worst failed trials, worst first
};

/// The nominal plan of a replay campaign without a plan file: the planner's plan for the
/// world from the campaign's seed (its method and budget as `settings.planner`). Sets
/// `description` to how it was planned. Throws PlanningFailed when there is none.
core::Plan plannedNominal(const core::LoadedWorld& world, const CampaignSettings& settings, std::string& description);

/// Sorts `outcomes` (every trial of the campaign, gathered in any order) by index, summarises
/// each sweep point and picks the `worst_count` worst failed trials (worstTrials).
CampaignResults summarizeCampaign(CampaignInfo info, std::vector<TrialOutcome> outcomes, int worst_count);

}  // namespace dashbed::tools
