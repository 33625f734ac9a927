#include "sim/job/check_plan.h"

#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/asset_paths.h"
#include "core/world_loader.h"
#include "sim/motion_samples.h"
#include "sim/replay/replay_html.h"

namespace dashbed::sim {
std::string stillsDirectory(const CheckOutputs& outputs) {
  if (outputs.report_json.empty()) return "";
  return std::filesystem::path(outputs.report_json).replace_extension(".stills").string();
}

RecordedRun checkPlan(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                      const std::string& plan_file, const CheckOutputs& outputs, const StepObserver& observer) {
  core::validatePlanForWorld(plan, world, robots, plan_file);
  // the report names its plan from its own folder: the same run written elsewhere, the same bytes
  const std::string plan_name =
      outputs.report_json.empty()
          ? plan_file
          : core::pathFrom(plan_file, std::filesystem::absolute(outputs.report_json).parent_path());
  std::optional<MotionSampler> sampler;
  StepObserver observe = observer;
  if (!outputs.html.empty()) {
    sampler.emplace(world, robots, replay::kReplayRate);
    observe = chained([&](const StepState& step) { sampler->onStep(step); }, observer);
  }
  RecordedRun run = simulateAndRecord(world, robots, plan, plan_name, outputs.recording, stillsDirectory(outputs), observe);
  if (!outputs.report_json.empty()) core::writeFile(outputs.report_json, writeReportJson(run.report));
  if (sampler) replay::writeReplayHtml(outputs.html, world, robots, sampler->samples(), run.report);
  if (!outputs.junit.empty()) core::writeFile(outputs.junit, writeJUnitXml(run.report));
  return run;
}

std::string summaryText(const Report& report, bool quiet) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  if (!quiet) {
    if (report.actions_inferred) out << "  (the plan has no actions: these were inferred from its gripper commands)\n";
    for (const ActionReport& a : report.actions) {
      out << (a.verdict == Verdict::kPassed ? "  PASS " : "  FAIL ") << std::right << std::setw(7) << a.planned_start
          << "-" << std::left << std::setw(7) << a.planned_end << std::right << " " << a.id;
      if (a.verdict == Verdict::kFailed) out << ": " << a.failure;
      out << "\n";
    }
    out << (report.execution_verdict == Verdict::kPassed ? "  PASS " : "  FAIL ") << "execution";
    if (report.execution_verdict == Verdict::kFailed) out << ": " << report.execution_failure;
    out << "\n";
    if (!report.readiness.empty()) {
      out << (report.ready() ? "  PASS " : "  FAIL ") << "hardware readiness";
      const char* separator = ": ";
      for (const core::ReadinessCheck& c : report.readiness) {
        if (c.passed) continue;
        out << separator << c.detail;
        separator = "; ";
      }
      out << "\n";
    }
  }
  out << (report.passed() ? "PASSED" : "FAILED") << ": ";
  if (report.actions.empty()) {
    out << (report.actions_inferred ? "no action found in the gripper commands" : "the plan has no actions");
  } else {
    out << report.passedCount() << " of " << report.actions.size() << " actions passed";
  }
  out << ", execution " << (report.execution_verdict == Verdict::kPassed ? "clean" : "with problems");
  if (!report.readiness.empty()) out << ", hardware " << (report.ready() ? "ready" : "not ready");
  out << " (" << report.simulated_time << " s simulated)\n";
  return out.str();
}

}  // namespace dashbed::sim
