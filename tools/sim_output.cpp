#include "tools/sim_output.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

namespace dashbed::tools {
namespace {

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace

void addReportOptions(CLI::App& command, ReportOutputs& outputs) {
  command.add_option("--report", outputs.json_file, "write the JSON report here");
  command.add_option("--junit", outputs.junit_file, "write a JUnit XML report here");
  command.add_flag("--quiet", outputs.quiet, "print only the verdict");
}

std::string stillsDirectory(const ReportOutputs& outputs) {
  if (outputs.json_file.empty()) return "";
  return std::filesystem::path(outputs.json_file).replace_extension(".stills").string();
}

void writeReportOutputs(const sim::Report& report, const ReportOutputs& outputs) {
  if (!outputs.json_file.empty()) writeFile(outputs.json_file, sim::writeReportJson(report));
  if (!outputs.junit_file.empty()) writeFile(outputs.junit_file, sim::writeJUnitXml(report));
  std::cout << std::fixed << std::setprecision(2);
  if (!outputs.quiet) {
    for (const sim::ActionReport& a : report.actions) {
      std::cout << (a.verdict == sim::Verdict::kPassed ? "  PASS " : "  FAIL ") << std::right << std::setw(7) << a.planned_start
                << "-" << std::left << std::setw(7) << a.planned_end << std::right << " " << a.id;
      if (a.verdict == sim::Verdict::kFailed) std::cout << ": " << a.failure;
      std::cout << "\n";
    }
    std::cout << (report.execution_verdict == sim::Verdict::kPassed ? "  PASS " : "  FAIL ") << "execution";
    if (report.execution_verdict == sim::Verdict::kFailed) std::cout << ": " << report.execution_failure;
    std::cout << "\n";
  }
  std::cout << (report.passed() ? "PASSED" : "FAILED") << ": " << report.passedCount() << " of "
            << report.actions.size() << " actions passed, execution "
            << (report.execution_verdict == sim::Verdict::kPassed ? "clean" : "with problems") << " ("
            << report.simulated_time << " s simulated)\n";
}

}  // namespace dashbed::tools
