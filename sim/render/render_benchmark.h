#pragma once
// Rendering throughput of a world's scene (for `dashbed bench render`).

#include "core/robot_set.h"
#include "core/world.h"
#include "sim/render/scene_renderer.h"

namespace dashbed::render {

/// Frames per second (wall clock) rendering `frames` frames of the world at home, seen by the
/// oblique preset at width x height, after one warm-up frame; with `with_png` each frame is
/// also encoded and written as a PNG (to a temporary file, removed afterwards). The arm joints
/// sweep a little from frame to frame so that each frame is a new scene.
double benchmarkFps(const core::World& world, const core::RobotSet& robots, int width, int height, int frames,
                    bool with_png = false, const RenderSettings& settings = {});

}  // namespace dashbed::render
