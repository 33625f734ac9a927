#pragma once
// Overlays drawn into a rendered image: text lines at the top left (simulated time, actions in
// progress) and markers (a circle and a label at the projected position of a world point,
// e.g. where a physical check failed). Text uses a built-in 5x7 bitmap font, ASCII 32-126.

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/world.h"
#include "sim/render/camera.h"
#include "sim/render/image.h"

namespace dashbed::render {

struct Overlay {
  enum Kind { kText, kMarker };
  Kind kind = kText;
  std::string text;  ///< the line (kText) or the marker's label (kMarker); ASCII, others show as '?'
  Eigen::Vector3d position_W = Eigen::Vector3d::Zero();  ///< kMarker: marked point in W [m]
  core::Color color{1.0, 1.0, 1.0};  ///< text colour; for markers circle and label colour
};

/// A top-left text line (white by default).
Overlay textOverlay(std::string text, core::Color color = {1.0, 1.0, 1.0});

/// A marker: a circle around the projection of p_W with `label` beside it (red by default).
Overlay markerOverlay(const Eigen::Vector3d& p_W, std::string label, core::Color color = {0.9, 0.05, 0.05});

/// Pixel size of the font at scale 1: each glyph cell is 6 x 9 pixels (5 x 7 glyph, spacing,
/// and two rows below for the descenders of g, p, q, y).
inline constexpr int kGlyphCellWidth = 6;
inline constexpr int kGlyphCellHeight = 9;

/// Draws `text` with its top-left corner at pixel (x, y), glyphs magnified by `scale`;
/// clipped to the image. Newlines are not interpreted.
void drawText(Image& image, int x, int y, std::string_view text, const core::Color& color, int scale = 2);

/// Width in pixels of `text` drawn at `scale`.
int textWidth(std::string_view text, int scale = 2);

/// Draws the overlays in order: text lines stacked from the top-left corner, each on a
/// darkened band; markers as a 3-pixel circle (radius 14 px) around project(camera, p_W)
/// with the label to its right (left near the right border). Markers outside the image are
/// moved to the nearest point inside its border, markers behind the camera to the bottom
/// centre, so that every marker stays visible.
void drawOverlays(Image& image, const Camera& camera, const std::vector<Overlay>& overlays);

}  // namespace dashbed::render
