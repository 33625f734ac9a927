#pragma once
// A small line-plot renderer for benchmark outputs: several series of (x, y) points on a
// linear x axis and a linear or logarithmic y axis, labelled ticks, axis labels, a title and a
// legend to the right of the plot area. Text in the built-in 5x7 bitmap font of
// sim/render/overlay.h. Deterministic pixels.

#include <string>
#include <utility>
#include <vector>

#include "core/world.h"
#include "sim/render/image.h"

namespace dashbed::tools {

struct PlotSeries {
  std::string label;  ///< legend entry (ASCII)
  core::Color color;
  bool dashed = false;  ///< dashed line without markers (e.g. reference data); a lone point gets a ring,
                        ///< nested with the rings of other lone points on the same spot
  std::vector<std::pair<double, double>> points;  ///< (x, y), joined in increasing x
};

struct LinePlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_y = false;  ///< decades on y; points with y <= 0 are left out
  std::vector<PlotSeries> series;
};

/// The plot as a width x height image (the legend takes the right 360 px). Axes span the data:
/// x from 0 to a round number above the largest x; y from 0 (or the decade below the
/// smallest y when log_y) to a round number (decade) above the largest y.
render::Image drawLinePlot(const LinePlot& plot, int width = 1200, int height = 600);

}  // namespace dashbed::tools
