#include "tools/video_output.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <iomanip>
#include <sstream>

#include <CLI/CLI.hpp>

#include "sim/render/camera.h"
#include "sim/render/image.h"
#include "sim/render/overlay.h"
#include "sim/render/scene_state.h"

namespace dashbed::tools {
namespace {

std::string describe(const core::PlanAction& a) {
  switch (a.type) {
    case core::ActionType::kPick: return a.robot + " picks " + a.object;
    case core::ActionType::kPlace:
      return a.region.empty() ? a.robot + " sets " + a.object + " aside" : a.robot + " places " + a.object + " in " + a.region;
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
  const auto plan_time = [](const std::string& text) {
    double t = -1.0;
    return CLI::detail::lexical_cast(text, t) && t >= 0.0 ? std::string() : "must be a plan time >= 0 [s], got " + text;
  };
  command.add_option("--from", options.from, "record from this plan time on [s] (the run is simulated from the start)")
      ->check(plan_time)
      ->capture_default_str();
  command.add_option("--until", options.until, "record up to this plan time [s] (default: the end)")->check(plan_time);
  command.add_option("--width", options.width, "image width [px]")->capture_default_str();
  command.add_option("--height", options.height, "image height [px]")->capture_default_str();
  auto* eye = command.add_option("--eye", options.eye, "custom camera position X Y Z [m] (world)")->expected(3);
  auto* target = command.add_option("--target", options.target, "custom camera target X Y Z [m] (world)")->expected(3);
  eye->needs(target);
  target->needs(eye);
  command.add_option("--fov", options.fov_deg, "custom camera vertical field of view [deg]")->capture_default_str();
}

RunRecorder::RunRecorder(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                         const VideoOptions& options)
    : plan_(plan) {
  render::RecorderSettings settings;
  settings.fps = options.fps;
  if (options.until && *options.until < options.from) {
    std::ostringstream message;
    message << "--until " << *options.until << " is before --from " << options.from << " (plan time in seconds)";
    throw std::invalid_argument(message.str());
  }
  settings.from = options.from;
  if (options.until) settings.until = *options.until;
  settings.camera_preset = options.camera;
  settings.width = options.width;
  settings.height = options.height;
  if (!options.eye.empty()) {
    render::Camera camera;
    camera.eye = Eigen::Vector3d(options.eye[0], options.eye[1], options.eye[2]);
    camera.target = Eigen::Vector3d(options.target[0], options.target[1], options.target[2]);
    camera.fov_deg = options.fov_deg;
    camera.width = options.width;
    camera.height = options.height;
    render::validateCamera(camera);
    settings.camera = camera;
  }
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

namespace {

/// Renders a still for each new monitor event (with its marker) and one of the final state.
class StillRecorder {
 public:
  StillRecorder(const core::World& world, const core::RobotSet& robots, std::filesystem::path dir)
      : dir_(std::move(dir)), renderer_(world, robots), camera_(render::cameraPreset(world, "oblique", 640, 480)) {
    std::filesystem::create_directories(dir_);
  }

  void onStep(const sim::Simulation& simulation, double plan_time, const sim::Monitor& monitor) {
    last_state_ = render::captureScene(simulation);
    const auto& events = monitor.events();
    for (; stills_.size() < events.size();) {
      const sim::ExecutionEvent& event = events[stills_.size()];
      std::ostringstream time;
      time << "t = " << std::fixed << std::setprecision(3) << plan_time << " s";
      const std::vector<render::Overlay> overlays{render::textOverlay(time.str()),
                                                  render::textOverlay(event.kind + ": " + event.detail, {1.0, 0.3, 0.3}),
                                                  render::markerOverlay(event.where_W, event.kind)};
      std::string name = "event_" + std::to_string(stills_.size() + 1) + "_" + event.kind + ".png";
      std::replace(name.begin(), name.end(), ' ', '_');
      render::writePng(renderer_.render(last_state_, camera_, overlays), dir_ / name);
      stills_.push_back({event.t, event.kind, event.detail, (dir_ / name).string()});
    }
  }

  /// Renders the final state and writes the still files into the report.
  void finish(sim::Report& report) {
    const std::filesystem::path final_file = dir_ / "final.png";
    render::writePng(renderer_.render(last_state_, camera_, {render::textOverlay("final state")}), final_file);
    report.final_still = final_file.string();
    // the report's events are the monitor's sorted by time: match them back by content
    for (const Still& still : stills_) {
      for (sim::ExecutionEvent& event : report.events) {
        if (event.still.empty() && event.t == still.t && event.kind == still.kind && event.detail == still.detail) {
          event.still = still.file;
          break;
        }
      }
    }
  }

 private:
  struct Still {
    double t;
    std::string kind, detail, file;
  };
  std::filesystem::path dir_;
  render::SceneRenderer renderer_;
  render::Camera camera_;
  render::SceneState last_state_;
  std::vector<Still> stills_;
};

}  // namespace

sim::Report simulateAndRecord(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                              const std::string& plan_file, const VideoOptions& video, const std::string& stills_dir) {
  std::optional<RunRecorder> recorder;
  if (video.wanted()) recorder.emplace(world, robots, plan, video);
  std::optional<StillRecorder> stills;
  if (!stills_dir.empty()) stills.emplace(world, robots, stills_dir);
  sim::RunOptions options;
  if (recorder) recorder->attach(options);
  if (stills) {
    auto frames = options.on_step;
    options.on_step = [&, frames](const sim::Simulation& simulation, double plan_time, const sim::Monitor& monitor) {
      if (frames) frames(simulation, plan_time, monitor);
      stills->onStep(simulation, plan_time, monitor);
    };
  }
  sim::Report report = sim::runPlan(world, robots, plan, plan_file, options);
  if (recorder) {
    recorder->finish();
    std::cout << "recorded " << recorder->framesWritten() << " frames"
              << (video.video.empty() ? "" : " to " + video.video) << "\n";
  }
  if (stills) stills->finish(report);
  return report;
}

}  // namespace dashbed::tools
