#pragma once
// The command-line options of the commands that simulate (sim, run, render): report files,
// frames and video; and how they print a run.

#include "sim/job/check_plan.h"
#include "tools/cli/cli_fwd.h"

namespace dashbed::tools {

/// --report, --junit and --quiet.
void addReportOptions(CLI::App& command, sim::CheckOutputs& outputs, bool& quiet);

/// --video, --camera, --fps, --from, --until, --width, --height, --eye, --target, --fov (and
/// --out when `with_out_dir`).
void addRecordingOptions(CLI::App& command, sim::RecordingOptions& options, bool with_out_dir);

/// Prints how many frames were recorded (when any were asked for), then the run's summary.
void printRun(const sim::RecordedRun& run, const sim::CheckOutputs& outputs, bool quiet);

}  // namespace dashbed::tools
