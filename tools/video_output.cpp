#include "tools/video_output.h"

#include <iostream>

#include "sim/render/overlay.h"

namespace dashbed::tools {
namespace {

std::string describe(const core::PlanAction& a) {
  switch (a.type) {
    case core::ActionType::kPick: return a.robot + " picks " + a.object;
    case core::ActionType::kPlace: return a.robot + " places " + a.object + " in " + a.region;
    case core::ActionType::kHandoff: return a.robot + " hands " + a.object + " to " + a.receiver;
  }
  return "";
}

// how long a failed check's marker stays in the video [s]
constexpr double kMarkerSeconds = 1.5;

}  // namespace

void addVideoOptions(CLI::App& command, VideoOptions& options, bool with_out_dir) {
  if (with_out_dir) command.add_option("--out", options.frames_dir, "write PNG frames into this folder");
  command.add_option("--video", options.video, "encode an MP4 video (needs ffmpeg)");
  command.add_option("--camera", options.camera, "camera preset: oblique, front, top, side:ROBOT")->capture_default_str();
  command.add_option("--fps", options.fps, "frames per second of simulated time")->capture_default_str();
  command.add_option("--width", options.width, "image width [px]")->capture_default_str();
  command.add_option("--height", options.height, "image height [px]")->capture_default_str();
}

RunRecorder::RunRecorder(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                         const VideoOptions& options)
    : plan_(plan) {
  render::RecorderSettings settings;
  settings.fps = options.fps;
  settings.camera_preset = options.camera;
  settings.width = options.width;
  settings.height = options.height;
  if (!options.frames_dir.empty()) settings.out_dir = options.frames_dir;
  if (!options.video.empty()) settings.video = options.video;
  settings.overlays = [this](const sim::Simulation&, double plan_time) {
    std::vector<render::Overlay> overlays;
    for (const core::PlanAction& a : plan_.actions) {
      if (plan_time >= a.start && plan_time <= a.end) overlays.push_back(render::textOverlay(describe(a), {1.0, 0.9, 0.4}));
    }
    if (monitor_ != nullptr) {
      for (const sim::ExecutionEvent& event : monitor_->events()) {
        if (plan_time < event.t || plan_time > event.t + kMarkerSeconds) continue;
        overlays.push_back(render::markerOverlay(event.where_W, event.kind));
        overlays.push_back(render::textOverlay(event.kind + ": " + event.detail, {1.0, 0.3, 0.3}));
      }
    }
    return overlays;
  };
  recorder_ = std::make_unique<render::FrameRecorder>(world, robots, std::move(settings));
}

void RunRecorder::attach(sim::RunOptions& run_options) {
  run_options.on_step = [this](const sim::Simulation& simulation, double plan_time, const sim::Monitor& monitor) {
    monitor_ = &monitor;
    recorder_->onStep(simulation, plan_time);
  };
}

void RunRecorder::finish() { recorder_->finish(); }

sim::Report simulateAndRecord(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                              const std::string& plan_file, const VideoOptions& video) {
  if (!video.wanted()) return sim::runPlan(world, robots, plan, plan_file);
  RunRecorder recorder(world, robots, plan, video);
  sim::RunOptions options;
  recorder.attach(options);
  sim::Report report = sim::runPlan(world, robots, plan, plan_file, options);
  recorder.finish();
  std::cout << "recorded " << recorder.framesWritten() << " frames"
            << (video.video.empty() ? "" : " to " + video.video) << "\n";
  return report;
}

}  // namespace dashbed::tools
