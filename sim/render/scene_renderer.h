#pragma once
// SceneRenderer: offscreen OpenGL rendering of a world's scene with OSMesa (Mesa's software
// renderer, llvmpipe): no display, X server or GPU needed.
//
// Drawn: a floor with a faint grid, the fixtures' boxes in their colours, the objects as boxes
// in theirs, hand-written goal regions as translucent outlined volumes, and the robots from
// their URDF visual meshes and colours. Lighting: a key light with a shadow map, a fill light
// and hemispherical ambient; Lambert diffuse plus a Blinn-Phong highlight.
//
// Each renderer owns its GL context, framebuffer and meshes; nothing is shared or global, so
// several renderers may exist, one per thread. A renderer may be used from any thread but by
// one thread at a time. Output is deterministic: the same scene and camera give the same bytes.

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
  int shadow_map_size = 1024;        ///< shadow map resolution [texels per side]
  int msaa_samples = 0;              ///< multisample anti-aliasing: 0 (off) or 4
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
