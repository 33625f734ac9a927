#pragma once
// Raster primitives shared by the plots of the tools (bench_plot, stress_plot): thick and
// dashed lines, filled circles, round tick spacings, and the axis frame of a plot area with its
// grid lines, tick labels, axis labels and title in the 5x7 bitmap font of sim/render/overlay.h.
// Everything is clipped to the image. Deterministic pixels.

#include <string_view>

#include "core/world.h"
#include "sim/render/image.h"

namespace dashbed::tools {

inline constexpr int kPlotTextScale = 2;                    ///< magnification of the 5x7 font
inline constexpr int kPlotTextHeight = 7 * kPlotTextScale;  ///< glyph height [px]
inline constexpr core::Color kPlotInk{0.1, 0.1, 0.1};       ///< axes and text

/// Pixel bounds of a plot area [px]: x_lo left, x_hi right, y_lo bottom, y_hi top (y_lo > y_hi).
struct PlotArea {
  int x_lo = 0;
  int x_hi = 0;
  int y_lo = 0;
  int y_hi = 0;
};

/// A line from (x0, y0) to (x1, y1) [px], `width` pixels thick, stepped along its longer axis;
/// `dashed`: 8 steps drawn, 8 left out, and so on.
void drawLine(render::Image& image, double x0, double y0, double x1, double y1, const core::Color& color, int width,
              bool dashed = false);

/// A disc around (cx, cy) [px] of `radius` [px].
void fillCircle(render::Image& image, double cx, double cy, double radius, const core::Color& color);

/// A tick spacing of 1, 2 or 5 times a power of ten giving at most about `intervals` up to
/// `max` (> 0).
double tickStep(double max, int intervals);

/// A vertical grid line at pixel column `x` across `area`, `label` centred below it.
void drawXTick(render::Image& image, const PlotArea& area, int x, std::string_view label, const core::Color& grid);

/// A horizontal grid line at pixel row `y` across `area`, `label` right-aligned left of it.
void drawYTick(render::Image& image, const PlotArea& area, int y, std::string_view label, const core::Color& grid);

/// The x and y axes along the bottom and left of `area`, `x_label` centred below the x tick
/// labels, `y_label` above the area at the left and `title` in the top-left corner.
void drawAxes(render::Image& image, const PlotArea& area, std::string_view x_label, std::string_view y_label,
              std::string_view title);

}  // namespace dashbed::tools
