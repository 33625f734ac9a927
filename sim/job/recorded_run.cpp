#include "sim/job/recorded_run.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <iomanip>
#include <sstream>

#include "sim/render/camera.h"
#include "sim/render/image.h"
#include "sim/render/overlay.h"
#include "sim/render/scene_state.h"

namespace dashbed::sim {
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

RunRecorder::RunRecorder(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                         const RecordingOptions& options)
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
  settings.overlays = [this](const Simulation&, double plan_time) {
    std::vector<render::Overlay> overlays;
    for (const core::PlanAction& a : plan_.actions) {
      if (plan_time >= a.start && plan_time <= a.end) overlays.push_back(render::textOverlay(describe(a), {1.0, 0.9, 0.4}));
    }
    if (monitor_ != nullptr) {
      for (const ExecutionEvent& event : monitor_->events()) {
        if (plan_time < event.t || plan_time > event.t + kMarkerSeconds) continue;
        overlays.push_back(render::markerOverlay(event.where_W, event.kind));
        overlays.push_back(render::textOverlay(event.kind + ": " + event.detail, {1.0, 0.3, 0.3}));
      }
    }
    return overlays;
  };
  recorder_ = std::make_unique<render::FrameRecorder>(world, robots, std::move(settings));
}

void RunRecorder::attach(RunOptions& run_options) {
  run_options.on_step = [this](const StepState& step) {
    monitor_ = &step.monitor;
    recorder_->onStep(step.simulation, step.plan_time);
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

  void onStep(const StepState& step) {
    const Simulation& simulation = step.simulation;
    const double plan_time = step.plan_time;
    const Monitor& monitor = step.monitor;
    last_state_ = render::captureScene(simulation);
    const auto& events = monitor.events();
    for (; stills_.size() < events.size();) {
      const ExecutionEvent& event = events[stills_.size()];
      std::ostringstream time;
      time << "t = " << std::fixed << std::setprecision(3) << plan_time << " s";
      const std::vector<render::Overlay> overlays{render::textOverlay(time.str()),
                                                  render::textOverlay(event.kind + ": " + event.detail, {1.0, 0.3, 0.3}),
                                                  render::markerOverlay(event.where_W, event.kind)};
      std::string name = "event_" + std::to_string(stills_.size() + 1) + "_" + event.kind + ".png";
      std::replace(name.begin(), name.end(), ' ', '_');
      render::writePng(renderer_.render(last_state_, camera_, overlays), dir_ / name);
      stills_.push_back({event.t, event.kind, event.detail, referenced(name)});
    }
  }

  /// How the report names a still: relative to the folder holding the stills' folder (the
  /// report's own), so a report's bytes do not depend on where it was written.
  std::string referenced(const std::string& name) const { return (dir_.filename() / name).generic_string(); }

  /// Renders the final state and writes the still files into the report.
  void finish(Report& report) {
    const std::filesystem::path final_file = dir_ / "final.png";
    render::writePng(renderer_.render(last_state_, camera_, {render::textOverlay("final state")}), final_file);
    report.final_still = referenced("final.png");
    // the report's events are the monitor's sorted by time: match them back by content
    for (const Still& still : stills_) {
      for (ExecutionEvent& event : report.events) {
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

RecordedRun simulateAndRecord(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                              const std::string& plan_file, const RecordingOptions& video, const std::string& stills_dir,
                              const StepObserver& observer) {
  std::optional<RunRecorder> recorder;
  if (video.wanted()) recorder.emplace(world, robots, plan, video);
  std::optional<StillRecorder> stills;
  if (!stills_dir.empty()) stills.emplace(world, robots, stills_dir);
  RunOptions options;
  if (recorder) recorder->attach(options);
  if (stills) {
    options.on_step = chained(options.on_step, [&](const StepState& step) { stills->onStep(step); });
  }
  options.on_step = chained(options.on_step, observer);
  RecordedRun run{runPlan(world, robots, plan, plan_file, options), 0};
  if (recorder) {
    recorder->finish();
    run.frames_written = recorder->framesWritten();
  }
  if (stills) stills->finish(run.report);
  return run;
}

}  // namespace dashbed::sim
