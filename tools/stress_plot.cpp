#include "tools/stress_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/number_text.h"
#include "sim/render/overlay.h"

namespace dashbed::tools {
namespace {

constexpr int kWidth = 800;
constexpr int kHeight = 500;
constexpr int kLeft = 90;    // plot area margins [px]
constexpr int kRight = 30;
constexpr int kTop = 75;
constexpr int kBottom = 70;
constexpr int kTextScale = 2;

const core::Color kAxis{0.1, 0.1, 0.1};
const core::Color kGrid{0.85, 0.85, 0.85};
const core::Color kData{0.1, 0.3, 0.8};
const core::Color kInterval{0.45, 0.6, 0.95};

void setPixel(render::Image& image, int x, int y, const core::Color& c) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = image.pixel(x, y);
  p[0] = static_cast<std::uint8_t>(std::lround(255.0 * c.r));
  p[1] = static_cast<std::uint8_t>(std::lround(255.0 * c.g));
  p[2] = static_cast<std::uint8_t>(std::lround(255.0 * c.b));
}

void fillRect(render::Image& image, int x0, int y0, int x1, int y1, const core::Color& c) {
  for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y) {
    for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) setPixel(image, x, y, c);
  }
}

// a line `width` pixels thick, stepped along its longer axis
void drawLine(render::Image& image, double x0, double y0, double x1, double y1, const core::Color& c, int width) {
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
  const int lo = -(width - 1) / 2, hi = width / 2;
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    fillRect(image, x + lo, y + lo, x + hi, y + hi, c);
  }
}

void fillCircle(render::Image& image, double cx, double cy, double radius, const core::Color& c) {
  const int r = static_cast<int>(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= radius * radius) {
        setPixel(image, static_cast<int>(std::lround(cx)) + dx, static_cast<int>(std::lround(cy)) + dy, c);
      }
    }
  }
}

// a tick spacing of 1, 2 or 5 times a power of ten giving at most about 6 intervals up to `max`
double tickStep(double max) {
  const double rough = max / 6.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= rough) return factor * power;
  }
  return 10.0 * power;
}

int textHeight() { return 7 * kTextScale; }

}  // namespace

render::Image sweepPlot(const std::vector<PointSummary>& points, const std::string& title) {
  render::Image image = render::Image::filled(kWidth, kHeight, 255, 255, 255);
  const int x_lo = kLeft, x_hi = kWidth - kRight, y_lo = kHeight - kBottom, y_hi = kTop;  // pixel bounds

  double max_mm = 0.0;
  for (const PointSummary& p : points) max_mm = std::max(max_mm, p.sigma_xy * 1e3);
  const double step = tickStep(max_mm > 0.0 ? max_mm : 1.0);
  const double x_max = step * std::ceil((max_mm > 0.0 ? max_mm : 1.0) / step);
  const auto px = [&](double mm) { return x_lo + (x_hi - x_lo) * mm / x_max; };
  const auto py = [&](double rate) { return y_lo + (y_hi - y_lo) * rate; };

  // grid and tick labels
  for (int k = 0; k * step <= x_max + 1e-9 * x_max; ++k) {
    const double mm = k * step;
    const int x = static_cast<int>(std::lround(px(mm)));
    drawLine(image, x, y_lo, x, y_hi, kGrid, 1);
    const std::string label = core::significantText(mm, 6);
    render::drawText(image, x - render::textWidth(label, kTextScale) / 2, y_lo + 10, label, kAxis, kTextScale);
  }
  for (int percent = 0; percent <= 100; percent += 20) {
    const int y = static_cast<int>(std::lround(py(percent / 100.0)));
    drawLine(image, x_lo, y, x_hi, y, kGrid, 1);
    const std::string label = std::to_string(percent);
    render::drawText(image, x_lo - 10 - render::textWidth(label, kTextScale), y - textHeight() / 2, label, kAxis,
                     kTextScale);
  }
  drawLine(image, x_lo, y_lo, x_hi, y_lo, kAxis, 2);
  drawLine(image, x_lo, y_lo, x_lo, y_hi, kAxis, 2);
  const std::string x_label = "sigma xy [mm]";
  render::drawText(image, (x_lo + x_hi - render::textWidth(x_label, kTextScale)) / 2, y_lo + 40, x_label, kAxis,
                   kTextScale);
  render::drawText(image, 10, y_hi - 28, "success [%], 95 % Wilson interval", kAxis, kTextScale);
  render::drawText(image, 10, 10, title, kAxis, kTextScale);

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
