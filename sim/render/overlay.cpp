#include "sim/render/overlay.h"

#include <algorithm>
#include <cmath>

namespace dashbed::render {

namespace {

// The 5x7 font, one glyph per printable ASCII character from ' ' (32) to '~' (126); each
// glyph is 7 rows of 5 columns, '#' marks a lit pixel. Lower-case letters sit on rows 2-6;
// those with descenders (kDescending) are drawn two rows lower, into the line spacing.
constexpr int kFirstGlyph = 32;
constexpr std::string_view kDescending = "gpqy";
constexpr int kLastGlyph = 126;
constexpr const char* kGlyphs[kLastGlyph - kFirstGlyph + 1][7] = {
    {".....", ".....", ".....", ".....", ".....", ".....", "....."},  // ' '
    {"..#..", "..#..", "..#..", "..#..", "..#..", ".....", "..#.."},  // !
    {".#.#.", ".#.#.", ".....", ".....", ".....", ".....", "....."},  // "
    {".#.#.", ".#.#.", "#####", ".#.#.", "#####", ".#.#.", ".#.#."},  // #
    {"..#..", ".####", "#.#..", ".###.", "..#.#", "####.", "..#.."},  // $
    {"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"},  // %
    {".##..", "#..#.", "#.#..", ".#...", "#.#.#", "#..#.", ".##.#"},  // &
    {"..#..", "..#..", ".....", ".....", ".....", ".....", "....."},  // '
    {"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."},  // (
    {".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."},  // )
    {".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", "....."},  // *
    {".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."},  // +
    {".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."},  // ,
    {".....", ".....", ".....", "#####", ".....", ".....", "....."},  // -
    {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."},  // .
    {".....", "....#", "...#.", "..#..", ".#...", "#....", "....."},  // /
    {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."},  // 0
    {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."},  // 1
    {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"},  // 2
    {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."},  // 3
    {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."},  // 4
    {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."},  // 5
    {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."},  // 6
    {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."},  // 7
    {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."},  // 8
    {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."},  // 9
    {".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."},  // :
    {".....", ".##..", ".##..", ".....", ".##..", "..#..", ".#..."},  // ;
    {"...#.", "..#..", ".#...", "#....", ".#...", "..#..", "...#."},  // <
    {".....", ".....", "#####", ".....", "#####", ".....", "....."},  // =
    {".#...", "..#..", "...#.", "....#", "...#.", "..#..", ".#..."},  // >
    {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."},  // ?
    {".###.", "#...#", "....#", ".##.#", "#.#.#", "#.#.#", ".###."},  // @
    {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"},  // A
    {"####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."},  // B
    {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."},  // C
    {"###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."},  // D
    {"#####", "#....", "#....", "####.", "#....", "#....", "#####"},  // E
    {"#####", "#....", "#....", "####.", "#....", "#....", "#...."},  // F
    {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"},  // G
    {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"},  // H
    {".###.", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."},  // I
    {"..###", "...#.", "...#.", "...#.", "...#.", "#..#.", ".##.."},  // J
    {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"},  // K
    {"#....", "#....", "#....", "#....", "#....", "#....", "#####"},  // L
    {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"},  // M
    {"#...#", "#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#"},  // N
    {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."},  // O
    {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."},  // P
    {".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"},  // Q
    {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"},  // R
    {".####", "#....", "#....", ".###.", "....#", "....#", "####."},  // S
    {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."},  // T
    {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."},  // U
    {"#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."},  // V
    {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "#.#.#", ".#.#."},  // W
    {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"},  // X
    {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."},  // Y
    {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"},  // Z
    {".###.", ".#...", ".#...", ".#...", ".#...", ".#...", ".###."},  // [
    {".....", "#....", ".#...", "..#..", "...#.", "....#", "....."},  // backslash
    {".###.", "...#.", "...#.", "...#.", "...#.", "...#.", ".###."},  // ]
    {"..#..", ".#.#.", "#...#", ".....", ".....", ".....", "....."},  // ^
    {".....", ".....", ".....", ".....", ".....", ".....", "#####"},  // _
    {".#...", "..#..", ".....", ".....", ".....", ".....", "....."},  // `
    {".....", ".....", ".###.", "....#", ".####", "#...#", ".####"},  // a
    {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "####."},  // b
    {".....", ".....", ".###.", "#....", "#....", "#...#", ".###."},  // c
    {"....#", "....#", ".##.#", "#..##", "#...#", "#...#", ".####"},  // d
    {".....", ".....", ".###.", "#...#", "#####", "#....", ".###."},  // e
    {"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#..."},  // f
    {".####", "#...#", "#...#", ".####", "....#", "....#", ".###."},  // g (descends)
    {"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#"},  // h
    {"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."},  // i
    {"...#.", ".....", "..##.", "...#.", "...#.", "#..#.", ".##.."},  // j
    {"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."},  // k
    {".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."},  // l
    {".....", ".....", "##.#.", "#.#.#", "#.#.#", "#...#", "#...#"},  // m
    {".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"},  // n
    {".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."},  // o
    {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."},  // p (descends)
    {".####", "#...#", "#...#", ".####", "....#", "....#", "....#"},  // q (descends)
    {".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."},  // r
    {".....", ".....", ".###.", "#....", ".###.", "....#", "####."},  // s
    {".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##."},  // t
    {".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"},  // u
    {".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."},  // v
    {".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."},  // w
    {".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"},  // x
    {"#...#", "#...#", "#...#", ".####", "....#", "#...#", ".###."},  // y (descends)
    {".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"},  // z
    {"...#.", "..#..", "..#..", ".#...", "..#..", "..#..", "...#."},  // {
    {"..#..", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."},  // |
    {".#...", "..#..", "..#..", "...#.", "..#..", "..#..", ".#..."},  // }
    {".....", ".....", ".#...", "#.#.#", "...#.", ".....", "....."},  // ~
};

struct Rgb {
  std::uint8_t r, g, b;
};

std::uint8_t toByte(double c) { return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

Rgb toRgb(const core::Color& color) { return {toByte(color.r), toByte(color.g), toByte(color.b)}; }

void setPixel(Image& image, int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = image.pixel(x, y);
  p[0] = c.r;
  p[1] = c.g;
  p[2] = c.b;
}

// Darkens the rectangle [x0, x1) x [y0, y1) to 45 % (clipped), a band behind text.
void darkenRect(Image& image, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width);
  y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(p[k] * 45 / 100);
    }
  }
}

// A ring of pixels whose centres lie within [radius - thickness/2, radius + thickness/2].
void drawRing(Image& image, double cx, double cy, double radius, double thickness, Rgb c) {
  const int x0 = static_cast<int>(std::floor(cx - radius - thickness));
  const int x1 = static_cast<int>(std::ceil(cx + radius + thickness));
  const int y0 = static_cast<int>(std::floor(cy - radius - thickness));
  const int y1 = static_cast<int>(std::ceil(cy + radius + thickness));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
      if (std::abs(d - radius) <= 0.5 * thickness) setPixel(image, x, y, c);
    }
  }
}

constexpr int kScale = 2;
constexpr int kGlyphRows = 9;    // 7 rows and 2 for descenders
constexpr int kMargin = 6;       // from the image border [px]
constexpr int kPad = 3;          // band around text [px]
constexpr double kMarkerRadius = 14.0;

}  // namespace

Overlay textOverlay(std::string text, core::Color color) {
  Overlay overlay;
  overlay.kind = Overlay::kText;
  overlay.text = std::move(text);
  overlay.color = color;
  return overlay;
}

Overlay markerOverlay(const Eigen::Vector3d& p_W, std::string label, core::Color color) {
  Overlay overlay;
  overlay.kind = Overlay::kMarker;
  overlay.text = std::move(label);
  overlay.position_W = p_W;
  overlay.color = color;
  return overlay;
}

int textWidth(std::string_view text, int scale) { return static_cast<int>(text.size()) * kGlyphCellWidth * scale; }

void drawText(Image& image, int x, int y, std::string_view text, const core::Color& color, int scale) {
  const Rgb c = toRgb(color);
  for (std::size_t i = 0; i < text.size(); ++i) {
    int code = static_cast<unsigned char>(text[i]);
    if (code < kFirstGlyph || code > kLastGlyph) code = '?';
    const auto& glyph = kGlyphs[code - kFirstGlyph];
    const int gx = x + static_cast<int>(i) * kGlyphCellWidth * scale;
    const int gy = y + (kDescending.find(static_cast<char>(code)) != std::string_view::npos ? 2 * scale : 0);
    for (int row = 0; row < 7; ++row) {
      for (int col = 0; col < 5; ++col) {
        if (glyph[row][col] != '#') continue;
        for (int sy = 0; sy < scale; ++sy) {
          for (int sx = 0; sx < scale; ++sx) setPixel(image, gx + col * scale + sx, gy + row * scale + sy, c);
        }
      }
    }
  }
}

void drawOverlays(Image& image, const Camera& camera, const std::vector<Overlay>& overlays) {
  const int line_height = kGlyphRows * kScale + 2 * kPad;
  int line = 0;
  for (const Overlay& overlay : overlays) {
    if (overlay.kind != Overlay::kText) continue;
    const int y = kMargin + line * line_height;
    darkenRect(image, kMargin - kPad, y - kPad, kMargin + textWidth(overlay.text, kScale) + kPad,
               y + kGlyphRows * kScale + kPad);
    drawText(image, kMargin, y, overlay.text, overlay.color, kScale);
    ++line;
  }
  for (const Overlay& overlay : overlays) {
    if (overlay.kind != Overlay::kMarker) continue;
    Eigen::Vector2d p = project(camera, overlay.position_W);
    const double border = kMarkerRadius + 2.0;
    if (depthInCamera(camera, overlay.position_W) <= 0.0 || !p.allFinite()) {
      // behind the camera: pin it to the bottom edge below the image centre
      p = {0.5 * image.width, image.height - border};
    }
    p.x() = std::clamp(p.x(), border, std::max(border, image.width - border));
    p.y() = std::clamp(p.y(), border, std::max(border, image.height - border));
    const Rgb c = toRgb(overlay.color);
    // a dark outline under the coloured ring keeps it visible on any background
    drawRing(image, p.x(), p.y(), kMarkerRadius, 5.0, {0, 0, 0});
    drawRing(image, p.x(), p.y(), kMarkerRadius, 3.0, c);
    if (!overlay.text.empty()) {
      const int width = textWidth(overlay.text, kScale);
      int tx = static_cast<int>(std::lround(p.x() + kMarkerRadius + 6.0));
      if (tx + width + kPad > image.width) tx = static_cast<int>(std::lround(p.x() - kMarkerRadius - 6.0)) - width;
      const int ty = static_cast<int>(std::lround(p.y())) - 7 * kScale / 2;
      darkenRect(image, tx - kPad, ty - kPad, tx + width + kPad, ty + kGlyphRows * kScale + kPad);
      drawText(image, tx, ty, overlay.text, overlay.color, kScale);
    }
  }
}

}  // namespace dashbed::render
