#pragma once
// Execution reports: what the simulator's monitor measured for each action of a plan, and
// the verdicts. Written as JSON (for tools) and JUnit XML (for CI dashboards).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/input_text.h"
#include "core/plan.h"
#include "core/readiness.h"

namespace dashbed::sim {

/// One measured quantity behind a verdict, e.g. {"slip", 0.0021, "m", 0.005, "<="}.
struct Measurement {
  std::string name;
  double value = 0.0;
  std::string unit;
  std::optional<double> threshold;  ///< the limit it was checked against, if any
  std::string comparison;           ///< how value must relate to threshold: "<=", ">=", "=="
  bool passed = true;
};

enum class Verdict { kPassed, kFailed };

/// "passed" / "failed".
std::string_view toString(Verdict verdict);

/// A measurement as text: "slip 0.012 m > 0.005 m" when it failed (the violated relation),
/// "slip 0.0021 m <= 0.005 m" when it passed, "max force 41.2 N" without a threshold.
/// Numbers with six significant digits.
std::string describeMeasurement(const Measurement& measurement);

/// The result of checking one planned action.
struct ActionReport {
  std::string id;                ///< e.g. "pick cube_0 by r0"
  core::ActionType type = core::ActionType::kPick;
  std::vector<std::string> robots;
  std::string object;
  std::string region;
  double planned_start = 0.0;    ///< [s]
  double planned_end = 0.0;      ///< [s]
  std::optional<double> observed_start;  ///< [s] e.g. first contact of both pads (grasp), release (place)
  std::optional<double> observed_end;    ///< [s] e.g. object lifted, object at rest in the region
  Verdict verdict = Verdict::kPassed;
  std::string failure;           ///< why it failed ("" when passed): what was measured against which threshold
  std::vector<Measurement> measurements;
};

/// An event not tied to a planned action's own checks: unplanned contacts, knocked objects.
struct ExecutionEvent {
  double t = 0.0;          ///< [s]
  std::string kind;        ///< "robot-robot contact", "robot-fixture contact", "knocked object", "drop", ...
  std::string detail;      ///< bodies involved, with the action in progress
  std::string action;      ///< id of the action it is attributed to, or ""
  Eigen::Vector3d where_W = Eigen::Vector3d::Zero();  ///< where it happened (world) [m]
  std::string still;       ///< PNG of the scene when it happened, with a marker ("" if none)
};

/// Per-robot execution quality.
struct RobotExecution {
  std::string robot;
  double max_tracking_error = 0.0;  ///< [rad] over the six arm joints and the whole run
  double torque_saturation = 0.0;   ///< fraction of control steps with some arm joint at its effort limit
  double max_effort_ratio = 0.0;    ///< max |tau| / effort limit over joints and steps
  double max_tcp_force = 0.0;       ///< [N] largest estimated external force at the TCP
  /// Largest estimated external joint torque over its protective-stop limit (1: a stop).
  double max_external_torque_ratio = 0.0;
};

struct Report {
  std::string world;
  std::string plan_file;
  std::uint64_t seed = 0;
  /// The plan had no actions: those judged were inferred from its gripper commands and what
  /// they closed on (sim/action_inference.h).
  bool actions_inferred = false;
  double time_step = 0.0;        ///< [s]
  double simulated_time = 0.0;   ///< [s]
  std::vector<ActionReport> actions;
  std::vector<ExecutionEvent> events;
  std::vector<RobotExecution> robots;
  Verdict execution_verdict = Verdict::kPassed;  ///< unplanned contacts and tracking limits
  std::string execution_failure;
  std::string final_still;       ///< PNG of the final state ("" if none was rendered)
  /// Hardware readiness of the plan (core/readiness.h): whether a UR5e with a Hand-E could run it
  /// as written; empty when it was not checked.
  std::vector<core::ReadinessCheck> readiness;

  int passedCount() const;
  int failedCount() const;
  bool ready() const;   ///< every readiness check passed
  bool passed() const;  ///< every action, the execution check and every readiness check passed
};

/// The current report format version ("dashbed_report" in the JSON).
inline constexpr int kReportFormatVersion = 1;

/// A report file that cannot be read. Message "FILE: /json/pointer: what".
class ReportError : public core::InputError {
 public:
  using core::InputError::InputError;
};

/// JSON report: {"dashbed_report": 1, "world", "plan", "seed", "time_step", "simulated_time",
/// "summary": {"actions", "passed", "failed", "execution", "execution_failure", "readiness",
/// "verdict"}, "actions": [...], "events": [...], "robots": [...], "readiness": [{"name",
/// "subject", "value", "limit", "unit", "t", "passed", "detail"}, ...]}. Deterministic bytes for equal reports;
/// numbers round-trip exactly; a non-finite number is written as null (read back as NaN, or
/// as an absent threshold / observed time).
std::string writeReportJson(const Report& report);

/// Reads what writeReportJson wrote. Unknown keys are ignored (newer writers may add some);
/// the summary must agree with the actions. Throws ReportError.
Report readReportJson(std::string_view json_text, const std::string& file_name);

/// Reads a file and calls readReportJson. Throws ReportError (also when unreadable).
Report loadReportFile(const std::filesystem::path& file);

/// JUnit XML: one <testsuite> "dashbed: WORLD / PLAN" with one <testcase> per action
/// (classname "dashbed.<type>", name = the action's id, time = planned duration), one
/// "execution" testcase, and one per readiness check (classname "dashbed.readiness", name
/// "CHECK SUBJECT", a failure of type "readiness"); a failed case has <failure message="slip 0.012 m > 0.005 m"
/// type="grasp|placement|handoff|execution"> whose text lists every measurement (execution:
/// the events). Times with millisecond decimals, other numbers with six significant digits;
/// deterministic bytes for equal reports.
std::string writeJUnitXml(const Report& report);

}  // namespace dashbed::sim
