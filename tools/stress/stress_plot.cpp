#include "tools/stress/stress_plot.h"

#include <algorithm>
#include <cmath>

#include "core/number_text.h"
#include "tools/plot/plot_canvas.h"

namespace dashbed::tools {
namespace {

constexpr int kWidth = 800;
constexpr int kHeight = 500;
constexpr int kLeft = 90;    // plot area margins [px]
constexpr int kRight = 30;
constexpr int kTop = 75;
constexpr int kBottom = 70;

const core::Color kGrid{0.85, 0.85, 0.85};
const core::Color kData{0.1, 0.3, 0.8};
const core::Color kInterval{0.45, 0.6, 0.95};

}  // namespace

render::Image sweepPlot(const std::vector<PointSummary>& points, const std::string& title) {
  render::Image image = render::Image::filled(kWidth, kHeight, 255, 255, 255);
  const int x_lo = kLeft, x_hi = kWidth - kRight, y_lo = kHeight - kBottom, y_hi = kTop;  // pixel bounds
  const PlotArea area{x_lo, x_hi, y_lo, y_hi};

  double max_mm = 0.0;
  for (const PointSummary& p : points) max_mm = std::max(max_mm, p.sigma_xy * 1e3);
  const double step = tickStep(max_mm > 0.0 ? max_mm : 1.0, 6);
  const double x_max = step * std::ceil((max_mm > 0.0 ? max_mm : 1.0) / step);
  const auto px = [&](double mm) { return x_lo + (x_hi - x_lo) * mm / x_max; };
  const auto py = [&](double rate) { return y_lo + (y_hi - y_lo) * rate; };

  // grid and tick labels
  for (int k = 0; k * step <= x_max + 1e-9 * x_max; ++k) {
    const double mm = k * step;
    const int x = static_cast<int>(std::lround(px(mm)));
    drawXTick(image, area, x, core::significantText(mm, 6), kGrid);
  }
  for (int percent = 0; percent <= 100; percent += 20) {
    const int y = static_cast<int>(std::lround(py(percent / 100.0)));
    drawYTick(image, area, y, std::to_string(percent), kGrid);
  }
  drawAxes(image, area, "sigma xy [mm]", "success [%], 95 % Wilson interval", title);

  // intervals, the curve, the points
  for (const PointSummary& p : points) {
    const double x = px(p.sigma_xy * 1e3);
    drawLine(image, x, py(p.trials.lower), x, py(p.trials.upper), kInterval, 2);
    drawLine(image, x - 6, py(p.trials.lower), x + 6, py(p.trials.lower), kInterval, 2);
    drawLine(image, x - 6, py(p.trials.upper), x + 6, py(p.trials.upper), kInterval, 2);
  }
  for (std::size_t i = 1; i < points.size(); ++i) {
    drawLine(image, px(points[i - 1].sigma_xy * 1e3), py(points[i - 1].trials.rate), px(points[i].sigma_xy * 1e3),
             py(points[i].trials.rate), kData, 2);
  }
  for (const PointSummary& p : points) fillCircle(image, px(p.sigma_xy * 1e3), py(p.trials.rate), 5.0, kData);
  return image;
}

}  // namespace dashbed::tools
