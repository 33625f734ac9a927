#include "sim/render/frame_recorder.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/number_text.h"
#include "sim/render/scene_state.h"
#include "sim/simulation.h"

namespace dashbed::render {
namespace {

// Frame k belongs to plan time k / fps; this tolerance [s] absorbs the rounding of summed steps.
constexpr double kFrameTimeTolerance = 1e-9;

}  // namespace

FrameRecorder::FrameRecorder(const core::World& world, const core::RobotSet& robots, RecorderSettings settings)
    : world_(world), settings_(std::move(settings)) {
  // a frame is a simulation step at most: faster would repeat frames without end
  const double step_rate = 1.0 / world.physics.time_step;
  if (!(settings_.fps > 0.0) || !(settings_.fps <= step_rate)) {
    throw std::invalid_argument("fps must be in (0, " + core::shortestText(step_rate) +
                                "] (the simulation's step rate), got " + core::shortestText(settings_.fps));
  }
  if (!(settings_.from >= 0.0) || !std::isfinite(settings_.from) || !(settings_.until >= settings_.from)) {
    throw std::invalid_argument("RecorderSettings: the time window must have 0 <= from <= until (got from " +
                                std::to_string(settings_.from) + " s, until " + std::to_string(settings_.until) + " s)");
  }
  frames_ = static_cast<int>(std::ceil(settings_.from * settings_.fps - kFrameTimeTolerance));  // first in the window
  camera_ = settings_.camera ? *settings_.camera
                             : cameraPreset(world, settings_.camera_preset, settings_.width, settings_.height);
  validateCamera(camera_);
  if (settings_.out_dir) {
    std::error_code ec;
    std::filesystem::create_directories(*settings_.out_dir, ec);
    if (ec || !std::filesystem::is_directory(*settings_.out_dir)) {
      throw std::runtime_error(settings_.out_dir->string() + ": cannot create the frame folder" +
                               (ec ? ": " + ec.message() : std::string()));
    }
  }
  renderer_ = std::make_unique<SceneRenderer>(world, robots, settings_.render);
  if (settings_.video) {
    video_ = std::make_unique<VideoWriter>(*settings_.video, camera_.width, camera_.height, settings_.fps);
  }
}

FrameRecorder::~FrameRecorder() = default;

void FrameRecorder::onStep(const sim::Simulation& simulation, double plan_time) {
  const auto due = [&](int k) { return k / settings_.fps <= plan_time + kFrameTimeTolerance; };
  const auto in_window = [&](int k) { return k / settings_.fps <= settings_.until + kFrameTimeTolerance; };
  if (plan_time < 0.0 || !due(frames_) || !in_window(frames_)) return;

  std::vector<Overlay> overlays;
  if (settings_.show_time) {
    char line[64];
    std::snprintf(line, sizeof(line), "t = %.2f s", plan_time);
    overlays.push_back(textOverlay(line));
  }
  if (settings_.overlays) {
    std::vector<Overlay> extra = settings_.overlays(simulation, plan_time);
    overlays.insert(overlays.end(), extra.begin(), extra.end());
  }
  last_frame_ = renderer_->render(captureScene(simulation), camera_, overlays);
  while (due(frames_) && in_window(frames_)) {
    if (settings_.out_dir) {
      char name[32];
      std::snprintf(name, sizeof(name), "frame_%06d.png", frames_);
      writePng(last_frame_, *settings_.out_dir / name);
    }
    if (video_) video_->add(last_frame_);
    ++frames_;
    ++written_;
  }
}

void FrameRecorder::finish() {
  if (video_) video_->finish();
}

}  // namespace dashbed::render
