#pragma once
// A stress campaign's summary as one self-contained HTML page: the success rate against
// sigma_xy with its Wilson intervals, the per-type and per-action rates, the failure taxonomy,
// and the worst trials with links to their replays (docs/replay.md).

#include <string>
#include <vector>

#include "tools/stress/stress_summary.h"

namespace dashbed::tools {

/// The page. `trials_folder`: the output directory as seen from the page's folder ("" when the
/// page is in it); each worst trial links to TRIALS_FOLDER/trial_N/replay.html when `replays`.
std::string campaignHtml(const CampaignInfo& info, const std::vector<PointSummary>& points,
                         const std::vector<TrialOutcome>& worst, const std::string& trials_folder, bool replays);

}  // namespace dashbed::tools
