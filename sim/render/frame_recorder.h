#pragma once
// FrameRecorder: renders a simulated plan run at a fixed frame rate of simulated plan time,
// into numbered PNG frames and/or an MP4. Hook it into sim::RunOptions::on_step:
//
//   render::FrameRecorder recorder(world, robots, settings);
//   sim::RunOptions options;
//   options.on_step = [&](const sim::StepState& step) { recorder.onStep(step.simulation, step.plan_time); };
//   sim::runPlan(world, robots, plan, plan_file, options);
//   recorder.finish();

#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/robot_set.h"
#include "core/world.h"
#include "sim/render/camera.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/video_writer.h"

namespace dashbed::sim {
class Simulation;
}

namespace dashbed::render {

struct RecorderSettings {
  double fps = 30.0;                      ///< frames per second of simulated plan time
  std::string camera_preset = "oblique";  ///< cameraPreset name, used when `camera` is unset
  std::optional<Camera> camera;           ///< a custom camera (its own width and height count)
  int width = 640;                        ///< preset cameras' image size [px]; even for video
  int height = 480;
  /// Plan-time window recorded [s]: frames k with from <= k / fps <= until (a few seconds of a
  /// long plan, to look at one handoff without rendering the rest). Files keep the index k.
  double from = 0.0;
  double until = std::numeric_limits<double>::infinity();
  std::optional<std::filesystem::path> out_dir;  ///< PNG frames frame_000000.png, ... (created)
  std::optional<std::filesystem::path> video;    ///< MP4 file
  bool show_time = true;                  ///< a first overlay line "t = 1.23 s" (plan time)
  /// Extra overlays per frame (actions in progress, failed-check markers), or empty.
  std::function<std::vector<Overlay>(const sim::Simulation&, double plan_time)> overlays;
  RenderSettings render;
};

class FrameRecorder {
 public:
  /// Sets up the renderer, the output folder and the video encoder (so a missing ffmpeg is
  /// reported before the run). `world` and `robots` must outlive the recorder. Throws
  /// std::invalid_argument for bad settings (fps, camera), std::runtime_error for an output
  /// that cannot be created (message names it) or a missing ffmpeg.
  FrameRecorder(const core::World& world, const core::RobotSet& robots, RecorderSettings settings);
  ~FrameRecorder();

  /// Records frame k = 0, 1, ... (those in the window from..until) at the first call with
  /// plan_time >= k / fps; calls with negative plan time (the settle pre-roll) are ignored.
  /// When one step passes several frame times, the frame is repeated so that the video keeps
  /// simulated time. Deterministic: the frames depend only on the simulation and the plan
  /// times passed.
  void onStep(const sim::Simulation& simulation, double plan_time);


  /// Finishes the video (throws std::runtime_error if ffmpeg failed). Calling it again does
  /// nothing.
  void finish();

  int framesWritten() const { return written_; }
  const Camera& camera() const { return camera_; }
  /// The last frame rendered (empty before the first).
  const Image& lastFrame() const { return last_frame_; }

 private:
  const core::World& world_;
  RecorderSettings settings_;
  Camera camera_;
  std::unique_ptr<SceneRenderer> renderer_;
  std::unique_ptr<VideoWriter> video_;
  int frames_ = 0;   ///< index of the next frame due
  int written_ = 0;  ///< frames recorded (in the window)
  Image last_frame_;
};

}  // namespace dashbed::render
