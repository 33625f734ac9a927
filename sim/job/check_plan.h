#pragma once
// The simulate-and-check job behind `dashbed sim`, `run` and `render`: validate a plan against
// the world's robot model, execute it in simulation under the monitor with the recordings asked
// for, and write the report files.

#include <string>

#include "core/plan.h"
#include "core/robot_set.h"
#include "core/world.h"
#include "sim/job/recorded_run.h"
#include "sim/report.h"

namespace dashbed::sim {

/// The files a checked run writes ("" for none).
struct CheckOutputs {
  std::string report_json;  ///< JSON report; the stills go beside it, into FILE.stills/
  std::string junit;        ///< JUnit XML report
  std::string html;         ///< the run's HTML replay (sim/replay/replay_html.h)
  RecordingOptions recording;
};

/// Where the stills of a report go: beside FILE.json as FILE.stills/ ("" without a JSON report).
std::string stillsDirectory(const CheckOutputs& outputs);

/// Validates `plan` for `world` (throws core::PlanError naming `plan_file`), simulates it with
/// the recordings and stills asked for (the report names the plan file relative to its own folder), writes the report files (throws std::runtime_error
/// when one cannot be written) and returns the run. `observer`, when set, is called after
/// every simulation step.
RecordedRun checkPlan(const core::World& world, const core::RobotSet& robots, const core::Plan& plan,
                      const std::string& plan_file, const CheckOutputs& outputs, const StepObserver& observer = {});

/// The run for people: one line per action (unless `quiet`), then the verdict line.
std::string summaryText(const Report& report, bool quiet);

}  // namespace dashbed::sim
