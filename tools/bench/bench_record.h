#pragma once
// The latest results of each `dashbed bench` command in one Markdown file (docs/benchmarks.md):
// a section per benchmark, replaced by its next run, saying when, with which version and on
// which machine it was measured, and the command that measured it.

#include <filesystem>
#include <string>

namespace dashbed::tools {

/// What the numbers were measured on, read from /proc/cpuinfo, /proc/meminfo and
/// /etc/os-release (a field unknown when its file is not there).
struct MachineInfo {
  std::string cpu;     ///< model name
  int cores = 0;       ///< logical processors
  double memory_gib = 0.0;
  std::string os;      ///< PRETTY_NAME
};
MachineInfo thisMachine();

/// Replaces the section `name` of `file` (between the lines `<!-- bench:NAME -->` and
/// `<!-- /bench:NAME -->`; appended at the end when absent, the file created when missing) with
/// `title` as a heading, the date (UTC), the dashbed version and the machine, the `command`,
/// and `body` (Markdown). Throws std::runtime_error when the file cannot be read or written.
void recordSection(const std::filesystem::path& file, const std::string& name, const std::string& title,
                   const std::string& command, const std::string& body);

}  // namespace dashbed::tools
