#pragma once
// SceneRenderer: offscreen OpenGL rendering of a world's scene with OSMesa (Mesa's software
// renderer, llvmpipe): no display, X server or GPU needed.
//
// Drawn: a floor with a faint 0.5 m grid that fades into the background, the fixtures' boxes
// in their colours, the objects as boxes in theirs, hand-written goal regions as translucent
// outlined volumes (bins show their own), and the robots from their URDF visual meshes and
// colours. Lighting: a key light with a shadow map, a fill light and ambient light that is a
// little stronger from above; Lambert diffuse plus a Blinn-Phong highlight. Robots cast their
// shadows through their collision primitives (slightly shrunk), a tenth of the triangles of
// the visual meshes; the fixtures' shadows are drawn once per renderer.
//
// Each renderer owns its GL context, framebuffer and meshes; nothing is shared or global, so
// several renderers may exist, one per thread. A renderer holds its context only inside its
// constructor and render(), so it may move between threads, but one thread uses it at a time.
// Output is deterministic: the same scene and camera give byte-identical images (checked
// with llvmpipe at 0 to 4 rasterizer threads; other Mesa versions or CPUs may differ).

#include <memory>
#include <vector>

#include "core/robot_set.h"
#include "core/world.h"
#include "sim/render/camera.h"
#include "sim/render/image.h"
#include "sim/render/overlay.h"
#include "sim/render/scene_state.h"

namespace dashbed::render {

struct RenderSettings {
  bool shadows = true;               ///< key-light shadows (a shadow map)
  int shadow_map_size = 768;         ///< shadow map resolution [texels per side]
  int msaa_samples = 0;              ///< multisample anti-aliasing: 0 (off) or 4 (~2.5x the time)
  bool floor_grid = true;            ///< 0.5 m grid lines on the floor
  bool show_regions = true;          ///< hand-written goal regions (bins show themselves)
  core::Color background{0.80, 0.84, 0.89};  ///< sky colour, also the floor's far fade
};

class SceneRenderer {
 public:
  /// Creates the GL context and loads every visual mesh of the robots' models once (assimp).
  /// `world` and `robots` must outlive the renderer. Throws std::runtime_error when OSMesa
  /// cannot create a context or a mesh cannot be read (naming the file), and
  /// std::invalid_argument for bad settings.
  SceneRenderer(const core::World& world, const core::RobotSet& robots, RenderSettings settings = {});
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  /// Renders `state` seen by `camera` and draws `overlays` into the result. Throws
  /// std::invalid_argument for a bad camera (validateCamera) or a state whose robot, link or
  /// object counts do not match the world.
  Image render(const SceneState& state, const Camera& camera, const std::vector<Overlay>& overlays = {});

  const RenderSettings& settings() const { return settings_; }

 private:
  struct Impl;
  RenderSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dashbed::render
