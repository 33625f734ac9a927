#pragma once
// Report output shared by the commands that simulate (sim, run): the summary on stdout and
// the optional JSON / JUnit files.

#include <string>

#include "sim/report.h"
#include "tools/cli_fwd.h"

namespace dashbed::tools {

struct ReportOutputs {
  std::string json_file;   ///< --report
  std::string junit_file;  ///< --junit
  bool quiet = false;      ///< --quiet: no per-action lines
};

void addReportOptions(CLI::App& command, ReportOutputs& outputs);

/// Where the stills of a report go: beside --report FILE.json as FILE.stills/ ("" without --report).
std::string stillsDirectory(const ReportOutputs& outputs);

/// Prints the summary (one line per action, then the verdict) and writes the files asked for.
/// Throws std::runtime_error when a file cannot be written.
void writeReportOutputs(const sim::Report& report, const ReportOutputs& outputs);

}  // namespace dashbed::tools
