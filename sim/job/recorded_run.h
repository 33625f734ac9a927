#pragma once
// A plan's run in simulation with what it leaves to look at: PNG frames and an MP4 whose
// overlays show the time, the actions in progress and a marker where a check failed, and a
// still of each failed check and of the final state, referenced from the report.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/plan.h"
#include "core/robot_set.h"
#include "sim/render/frame_recorder.h"
#include "sim/run_plan.h"

namespace dashbed::sim {

/// What to record of a run; nothing when neither frames_dir nor video is set.
struct RecordingOptions {
  std::string frames_dir;        ///< PNG frames
  std::string video;             ///< MP4 (needs ffmpeg)
  std::string camera = "oblique";  ///< preset: oblique, front, top, side:ROBOT
  double fps = 30.0;               ///< frames per second of simulated time
  double from = 0.0;               ///< plan time of the first frame [s]
  std::optional<double> until;     ///< plan time of the last frame [s] (default: the end)
  int width = 640;                 ///< [px]
  int height = 480;                ///< [px]
  std::vector<double> eye;     ///< a custom camera X Y Z [m] (world; with target, fov_deg) instead of a preset
  std::vector<double> target;  ///< the custom camera's target X Y Z [m]
  double fov_deg = 45.0;       ///< the custom camera's vertical field of view [deg]
  bool wanted() const { return !frames_dir.empty() || !video.empty(); }
};

/// Records the run of `plan` as RecordingOptions ask. `plan` must outlive it. Call attach() on
/// the run options before running, finish() after.
class RunRecorder {
 public:
  /// Throws std::invalid_argument for an until before from or a bad custom camera.
  RunRecorder(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
              const RecordingOptions& options);
  void attach(RunOptions& run_options);
  void finish();
  int framesWritten() const { return recorder_->framesWritten(); }

 private:
  const core::Plan& plan_;
  const Monitor* monitor_ = nullptr;
  std::unique_ptr<render::FrameRecorder> recorder_;
};

/// A report and how many frames were recorded for it.
struct RecordedRun {
  Report report;
  int frames_written = 0;
};

/// runPlan, recording what `recording` asks for and, when `stills_dir` is not empty, a still of
/// every failed check as it happens and of the final state there, referenced from the report
/// by paths relative to the stills folder's parent (STILLS/event_1_drop.png). `observer`, when
/// set, is called after every step as well.
RecordedRun simulateAndRecord(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                              const std::string& plan_file, const RecordingOptions& recording,
                              const std::string& stills_dir = "", const StepObserver& observer = {});

}  // namespace dashbed::sim
