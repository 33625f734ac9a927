#pragma once
// Frames and video of simulated runs, shared by the commands that simulate (render, run, sim).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/plan.h"
#include "core/robot_set.h"
#include "sim/render/frame_recorder.h"
#include "sim/run_plan.h"
#include "tools/cli_fwd.h"

namespace dashbed::tools {

struct VideoOptions {
  std::string frames_dir;        ///< --out: PNG frames
  std::string video;             ///< --video: MP4
  std::string camera = "oblique";
  double fps = 30.0;
  double from = 0.0;  ///< --from: plan time of the first frame [s]
  std::optional<double> until;  ///< --until: plan time of the last frame [s] (default: the end)
  int width = 640;
  int height = 480;
  std::vector<double> eye;     ///< --eye X Y Z: a custom camera (with --target, --fov) instead of a preset
  std::vector<double> target;  ///< --target X Y Z
  double fov_deg = 45.0;       ///< --fov [deg]
  bool wanted() const { return !frames_dir.empty() || !video.empty(); }
};

/// --video, --camera, --fps, --size (and --out when `with_out_dir`).
void addVideoOptions(CLI::App& command, VideoOptions& options, bool with_out_dir);

/// A recorder for the run of `plan` whose overlays show the simulated time, the actions in
/// progress and a red marker where each failed check happened (for a second after it).
/// `plan` must outlive it. Call attach() on the run options before running.
class RunRecorder {
 public:
  RunRecorder(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
              const VideoOptions& options);
  void attach(sim::RunOptions& run_options);
  void finish();
  int framesWritten() const { return recorder_->framesWritten(); }

 private:
  const core::Plan& plan_;
  const sim::Monitor* monitor_ = nullptr;
  std::unique_ptr<render::FrameRecorder> recorder_;
};

/// sim::runPlan, recording frames and video when `video` asks for them, and, when
/// `stills_dir` is not empty, a still of every failed check as it happens (with a marker where
/// it happened) and of the final state there, referenced from the report.
sim::Report simulateAndRecord(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                              const std::string& plan_file, const VideoOptions& video,
                              const std::string& stills_dir = "");

}  // namespace dashbed::tools
