#pragma once
// The sweep plot of a stress campaign: success rate against sigma_xy, each point with its
// Wilson 95 % interval.

#include <string>
#include <vector>

#include "sim/render/image.h"
#include "tools/stress/stress_summary.h"

namespace dashbed::tools {

/// An 800 x 500 plot: x = sigma_xy [mm] from 0, y = success rate [%] from 0 to 100, one
/// marker per point joined by lines, vertical bars for the intervals, a grid with labelled
/// ticks and `title` on top. Deterministic pixels.
render::Image sweepPlot(const std::vector<PointSummary>& points, const std::string& title);

}  // namespace dashbed::tools
