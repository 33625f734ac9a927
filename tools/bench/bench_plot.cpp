#include "tools/bench/bench_plot.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/number_text.h"
#include "sim/render/overlay.h"
#include "tools/plot/plot_canvas.h"

namespace dashbed::tools {
namespace {

constexpr int kLegendWidth = 360;
constexpr int kLeft = 100;  // plot area margins [px]
constexpr int kTop = 60;
constexpr int kBottom = 70;

const core::Color kGrid{0.87, 0.87, 0.87};

// 10^k without an exponent: "0.001", "1", "1000"
std::string decadeText(int k) { return core::fixedText(std::pow(10.0, k), std::max(0, -k)); }

bool drawn(const LinePlot& plot, const std::pair<double, double>& p) {
  return std::isfinite(p.first) && std::isfinite(p.second) && (!plot.log_y || p.second > 0.0);
}

}  // namespace

render::Image drawLinePlot(const LinePlot& plot, int width, int height) {
  render::Image image = render::Image::filled(width, height, 255, 255, 255);
  const int x_lo = kLeft, x_hi = width - kLegendWidth, y_lo = height - kBottom, y_hi = kTop;  // pixel bounds
  const PlotArea area{x_lo, x_hi, y_lo, y_hi};

  double x_min = std::numeric_limits<double>::infinity(), x_max = 0.0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = 0.0;
  for (const PlotSeries& s : plot.series) {
    for (const auto& p : s.points) {
      if (!drawn(plot, p)) continue;
      x_min = std::min(x_min, p.first);
      x_max = std::max(x_max, p.first);
      y_min = std::min(y_min, p.second);
      y_max = std::max(y_max, p.second);
    }
  }
  if (x_max <= 0.0) x_max = 1.0;
  if (x_min == x_max) x_max *= 2.0;  // one column of points (one object count): in the middle
  const double x_step = tickStep(x_max, 10);
  x_max = x_step * std::ceil(x_max / x_step);
  const auto px = [&](double x) { return x_lo + (x_hi - x_lo) * x / x_max; };

  // y axis: value -> pixel, and the labelled ticks
  std::vector<std::pair<double, std::string>> y_ticks;  // (axis coordinate, label)
  double axis_lo = 0.0, axis_hi = 1.0;
  if (plot.log_y) {
    const int k_lo = std::isfinite(y_min) ? static_cast<int>(std::floor(std::log10(y_min))) : 0;
    const int k_hi = std::max(k_lo + 1, y_max > 0.0 ? static_cast<int>(std::ceil(std::log10(y_max))) : 1);
    axis_lo = k_lo;
    axis_hi = k_hi;
    for (int k = k_lo; k <= k_hi; ++k) y_ticks.emplace_back(k, decadeText(k));
  } else {
    const double step = tickStep(y_max > 0.0 ? y_max : 1.0, 6);
    axis_hi = step * std::ceil((y_max > 0.0 ? y_max : 1.0) / step);
    for (int k = 0; k * step <= axis_hi * (1 + 1e-9); ++k)
      y_ticks.emplace_back(k * step, core::significantText(k * step, 6));
  }
  const auto py = [&](double y) {
    const double a = plot.log_y ? std::log10(y) : y;
    return y_lo + (y_hi - y_lo) * (a - axis_lo) / (axis_hi - axis_lo);
  };

  // grid, ticks, labels
  for (int k = 0; k * x_step <= x_max * (1 + 1e-9); ++k) {
    const int x = static_cast<int>(std::lround(px(k * x_step)));
    drawXTick(image, area, x, core::significantText(k * x_step, 6), kGrid);
  }
  for (const auto& [a, label] : y_ticks) {
    const int y = static_cast<int>(std::lround(y_lo + (y_hi - y_lo) * (a - axis_lo) / (axis_hi - axis_lo)));
    drawYTick(image, area, y, label, kGrid);
  }
  drawAxes(image, area, plot.x_label, plot.y_label, plot.title);

  // the series, then the rings of lone dashed points, then the legend
  struct Ring {
    double x, y, radius;
    core::Color color;
  };
  std::vector<Ring> rings;
  for (const PlotSeries& s : plot.series) {
    std::vector<std::pair<double, double>> points;
    std::copy_if(s.points.begin(), s.points.end(), std::back_inserter(points),
                 [&](const auto& p) { return drawn(plot, p); });
    std::sort(points.begin(), points.end());
    for (std::size_t i = 1; i < points.size(); ++i) {
      drawLine(image, px(points[i - 1].first), py(points[i - 1].second), px(points[i].first), py(points[i].second),
               s.color, 2, s.dashed);
    }
    if (!s.dashed) {
      for (const auto& [x, y] : points) fillCircle(image, px(x), py(y), 4.5, s.color);
    } else if (points.size() == 1) {  // no line to dash: a ring marks the lone point
      Ring ring{px(points[0].first), py(points[0].second), 5.5, s.color};
      // rings on the same spot (e.g. two of the paper's rows at about the same time) nest
      for (const Ring& r : rings) {
        if (std::abs(r.x - ring.x) <= 6.0 && std::abs(r.y - ring.y) <= 6.0) ring.radius = std::max(ring.radius, r.radius + 3.0);
      }
      rings.push_back(ring);
    }
  }
  std::stable_sort(rings.begin(), rings.end(), [](const Ring& a, const Ring& b) { return a.radius > b.radius; });
  for (const Ring& r : rings) {  // largest first, so that an inner ring's white centre leaves the outer band
    fillCircle(image, r.x, r.y, r.radius, r.color);
    fillCircle(image, r.x, r.y, r.radius - 2.5, {1.0, 1.0, 1.0});
  }
  const int legend_x = x_hi + 20;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const int y = y_hi + static_cast<int>(i) * (kPlotTextHeight + 9) + kPlotTextHeight / 2;
    drawLine(image, legend_x, y, legend_x + 34, y, s.color, 2, s.dashed);
    if (!s.dashed) fillCircle(image, legend_x + 17, y, 4.5, s.color);
    render::drawText(image, legend_x + 44, y - kPlotTextHeight / 2, s.label, kPlotInk, kPlotTextScale);
  }
  return image;
}

}  // namespace dashbed::tools
