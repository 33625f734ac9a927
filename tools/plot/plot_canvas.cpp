#include "tools/plot/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sim/render/overlay.h"

namespace dashbed::tools {
namespace {

constexpr int kDash = 8;  // dash and gap length [steps]

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

}  // namespace

void drawLine(render::Image& image, double x0, double y0, double x1, double y1, const core::Color& color, int width,
              bool dashed) {
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
  const int lo = -(width - 1) / 2, hi = width / 2;
  for (int i = 0; i <= steps; ++i) {
    if (dashed && (i / kDash) % 2 == 1) continue;
    const double t = static_cast<double>(i) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
    fillRect(image, x + lo, y + lo, x + hi, y + hi, color);
  }
}

void fillCircle(render::Image& image, double cx, double cy, double radius, const core::Color& color) {
  const int r = static_cast<int>(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= radius * radius) {
        setPixel(image, static_cast<int>(std::lround(cx)) + dx, static_cast<int>(std::lround(cy)) + dy, color);
      }
    }
  }
}

double tickStep(double max, int intervals) {
  const double rough = max / intervals;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double factor : {1.0, 2.0, 5.0}) {
    if (factor * power >= rough) return factor * power;
  }
  return 10.0 * power;
}

void drawXTick(render::Image& image, const PlotArea& area, int x, std::string_view label, const core::Color& grid) {
  drawLine(image, x, area.y_lo, x, area.y_hi, grid, 1);
  render::drawText(image, x - render::textWidth(label, kPlotTextScale) / 2, area.y_lo + 10, label, kPlotInk,
                   kPlotTextScale);
}

void drawYTick(render::Image& image, const PlotArea& area, int y, std::string_view label, const core::Color& grid) {
  drawLine(image, area.x_lo, y, area.x_hi, y, grid, 1);
  render::drawText(image, area.x_lo - 10 - render::textWidth(label, kPlotTextScale), y - kPlotTextHeight / 2, label,
                   kPlotInk, kPlotTextScale);
}

void drawAxes(render::Image& image, const PlotArea& area, std::string_view x_label, std::string_view y_label,
              std::string_view title) {
  drawLine(image, area.x_lo, area.y_lo, area.x_hi, area.y_lo, kPlotInk, 2);
  drawLine(image, area.x_lo, area.y_lo, area.x_lo, area.y_hi, kPlotInk, 2);
  render::drawText(image, (area.x_lo + area.x_hi - render::textWidth(x_label, kPlotTextScale)) / 2, area.y_lo + 40,
                   x_label, kPlotInk, kPlotTextScale);
  render::drawText(image, 10, area.y_hi - 28, y_label, kPlotInk, kPlotTextScale);
  render::drawText(image, 10, 10, title, kPlotInk, kPlotTextScale);
}

}  // namespace dashbed::tools
