#include "tools/cli/sim_options.h"
#include "tools/cli/number_checks.h"

#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

namespace dashbed::tools {

void addReportOptions(CLI::App& command, sim::CheckOutputs& outputs, bool& quiet) {
  command.add_option("--report", outputs.report_json, "write the JSON report here");
  command.add_option("--junit", outputs.junit, "write a JUnit XML report here");
  command.add_option("--html", outputs.html,
                     "write the run's interactive replay here: one self-contained HTML file (docs/replay.md)");
  command.add_flag("--quiet", quiet, "print only the verdict");
}

void addRecordingOptions(CLI::App& command, sim::RecordingOptions& options, bool with_out_dir) {
  if (with_out_dir) command.add_option("--out", options.frames_dir, "write PNG frames into this folder");
  command.add_option("--video", options.video, "encode an MP4 video (needs ffmpeg)");
  command.add_option("--camera", options.camera, "camera preset: oblique, front, top, side:ROBOT")->capture_default_str();
  command.add_option("--fps", options.fps, "frames per second of simulated time")
      ->check(positiveNumber())
      ->capture_default_str();
  command.add_option("--from", options.from, "record from this plan time on [s] (the run is simulated from the start)")
      ->check(nonNegativeNumber())
      ->capture_default_str();
  command.add_option("--until", options.until, "record up to this plan time [s] (default: the end)")->check(nonNegativeNumber());
  command.add_option("--width", options.width, "image width [px]")->capture_default_str();
  command.add_option("--height", options.height, "image height [px]")->capture_default_str();
  auto* eye = command.add_option("--eye", options.eye, "custom camera position X Y Z [m] (world)")->expected(3);
  auto* target = command.add_option("--target", options.target, "custom camera target X Y Z [m] (world)")->expected(3);
  eye->needs(target);
  target->needs(eye);
  command.add_option("--fov", options.fov_deg, "custom camera vertical field of view [deg]")->capture_default_str();
}

void printRun(const sim::RecordedRun& run, const sim::CheckOutputs& outputs, bool quiet) {
  if (outputs.recording.wanted()) {
    std::cout << "recorded " << run.frames_written << " frames"
              << (outputs.recording.video.empty() ? "" : " to " + outputs.recording.video) << "\n";
  }
  std::cout << sim::summaryText(run.report, quiet);
}

}  // namespace dashbed::tools
