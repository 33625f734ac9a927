// dashbed.simulate() / render(): a plan executed in the Bullet simulation under the monitor,
// as `dashbed sim` / `dashbed render` run it, and dashbed.Report, what the monitor found.

#include <optional>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "sim/job/check_plan.h"
#include "sim/motion_samples.h"
#include "tools/python/bindings.h"

namespace dashbed::python {
namespace {

/// A report, with what a run recorded beside it.
struct ReportHandle {
  sim::Report report;
  int frames_written = 0;
  std::optional<sim::MotionSamples> samples;
};

/// A numpy array of `shape` holding a copy of `values`.
py::array_t<double> arrayOf(const std::vector<double>& values, std::vector<py::ssize_t> shape) {
  py::array_t<double> array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}

py::dict samplesDict(const sim::MotionSamples& s) {
  const auto n = static_cast<py::ssize_t>(s.count());
  const auto robots = static_cast<py::ssize_t>(s.robots.size());
  py::dict d;
  d["rate"] = s.rate;
  d["robots"] = py::cast(s.robots);
  d["joints"] = py::cast(s.joints);
  d["links"] = py::cast(s.links);
  d["objects"] = py::cast(s.objects);
  d["times"] = arrayOf(s.times, {n});
  d["joint_positions"] = arrayOf(s.joint_positions, {n, robots, static_cast<py::ssize_t>(s.joints.size())});
  d["link_poses"] = arrayOf(s.link_poses, {n, robots, static_cast<py::ssize_t>(s.links.size()), 7});
  d["object_poses"] = arrayOf(s.object_poses, {n, static_cast<py::ssize_t>(s.objects.size()), 7});
  d["tracking_error"] = arrayOf(s.tracking_error, {n, robots});
  d["effort_ratio"] = arrayOf(s.effort_ratio, {n, robots});
  d["grip_force"] = arrayOf(s.grip_force, {n, robots});
  return d;
}

/// The run options of simulate() and render().
struct RunRequest {
  std::string report_json;
  std::string junit;
  std::string html;
  std::optional<double> sample_rate;
  sim::RecordingOptions recording;
};

ReportHandle runChecked(const WorldHandle& world, const PlanHandle& plan, const RunRequest& request) {
  sim::CheckOutputs outputs{request.report_json, request.junit, request.html, request.recording};
  std::optional<sim::MotionSampler> sampler;
  sim::StepObserver observer;
  if (request.sample_rate) {
    sampler.emplace(world.world(), *world.loaded->robots, *request.sample_rate);
    observer = [&](const sim::StepState& step) { sampler->onStep(step); };
  }
  const std::string plan_file = plan.file.empty() ? "<memory>" : plan.file;
  sim::RecordedRun run = sim::checkPlan(world.world(), *world.loaded->robots, *plan.plan, plan_file, outputs, observer);
  ReportHandle out{std::move(run.report), run.frames_written, std::nullopt};
  if (sampler) out.samples = sampler->take();
  return out;
}

std::string verdictText(sim::Verdict verdict) { return std::string(sim::toString(verdict)); }

}  // namespace

void bindSimulation(py::module_& m) {
  py::class_<sim::Measurement>(m, "Measurement", "One measured quantity behind a verdict.")
      .def_readonly("name", &sim::Measurement::name)
      .def_readonly("value", &sim::Measurement::value)
      .def_readonly("unit", &sim::Measurement::unit)
      .def_readonly("threshold", &sim::Measurement::threshold, "the limit it was checked against, or None")
      .def_readonly("comparison", &sim::Measurement::comparison, "how value must relate to threshold: <=, >=, ==")
      .def_readonly("passed", &sim::Measurement::passed)
      .def("__repr__", [](const sim::Measurement& x) { return "<dashbed.Measurement " + sim::describeMeasurement(x) + ">"; });

  py::class_<sim::ActionReport>(m, "ActionReport", "The checks of one planned action.")
      .def_readonly("id", &sim::ActionReport::id, "e.g. 'pick cube_0 by r0'")
      .def_property_readonly("type", [](const sim::ActionReport& a) { return std::string(core::toString(a.type)); })
      .def_readonly("robots", &sim::ActionReport::robots)
      .def_readonly("object", &sim::ActionReport::object)
      .def_readonly("region", &sim::ActionReport::region)
      .def_readonly("planned_start", &sim::ActionReport::planned_start, "[s]")
      .def_readonly("planned_end", &sim::ActionReport::planned_end, "[s]")
      .def_readonly("observed_start", &sim::ActionReport::observed_start, "[s] or None")
      .def_readonly("observed_end", &sim::ActionReport::observed_end, "[s] or None")
      .def_property_readonly("verdict", [](const sim::ActionReport& a) { return verdictText(a.verdict); })
      .def_property_readonly("passed", [](const sim::ActionReport& a) { return a.verdict == sim::Verdict::kPassed; })
      .def_readonly("failure", &sim::ActionReport::failure, "why it failed ('' when passed)")
      .def_readonly("measurements", &sim::ActionReport::measurements)
      .def("__repr__", [](const sim::ActionReport& a) { return "<dashbed.ActionReport " + a.id + ": " + verdictText(a.verdict) + ">"; });

  py::class_<sim::ExecutionEvent>(m, "Event", "Something not tied to an action's own checks: a contact, a drop.")
      .def_readonly("t", &sim::ExecutionEvent::t, "[s]")
      .def_readonly("kind", &sim::ExecutionEvent::kind, "e.g. 'robot-robot contact', 'knocked object', 'drop'")
      .def_readonly("detail", &sim::ExecutionEvent::detail)
      .def_readonly("action", &sim::ExecutionEvent::action, "the action it is attributed to, or ''")
      .def_readonly("where", &sim::ExecutionEvent::where_W, "where it happened (world) [m]")
      .def("__repr__", [](const sim::ExecutionEvent& e) { return "<dashbed.Event " + e.kind + ": " + e.detail + ">"; });

  py::class_<sim::RobotExecution>(m, "RobotExecution", "How well one robot tracked its trajectory.")
      .def_readonly("robot", &sim::RobotExecution::robot)
      .def_readonly("max_tracking_error", &sim::RobotExecution::max_tracking_error, "[rad]")
      .def_readonly("torque_saturation", &sim::RobotExecution::torque_saturation,
                    "fraction of control steps with a joint at its effort limit")
      .def_readonly("max_effort_ratio", &sim::RobotExecution::max_effort_ratio, "max |tau| / effort limit")
      .def_readonly("max_tcp_force", &sim::RobotExecution::max_tcp_force, "[N]")
      .def_readonly("max_external_torque_ratio", &sim::RobotExecution::max_external_torque_ratio,
                    "over the protective-stop limit (1: a stop)");

  py::class_<core::ReadinessCheck>(m, "ReadinessCheck", "Whether a UR5e with a Hand-E could run the plan as written.")
      .def_readonly("name", &core::ReadinessCheck::name, "e.g. 'joint speed', 'payload', 'grip'")
      .def_readonly("subject", &core::ReadinessCheck::subject)
      .def_readonly("value", &core::ReadinessCheck::value)
      .def_readonly("limit", &core::ReadinessCheck::limit)
      .def_readonly("unit", &core::ReadinessCheck::unit)
      .def_readonly("t", &core::ReadinessCheck::t, "plan time of the extreme [s]")
      .def_readonly("passed", &core::ReadinessCheck::passed)
      .def_readonly("detail", &core::ReadinessCheck::detail);

  py::class_<ReportHandle>(m, "Report", "What the simulator's monitor measured, and the verdicts.")
      .def_static("load", [](const std::filesystem::path& path) { return ReportHandle{sim::loadReportFile(path), 0, std::nullopt}; },
                  py::arg("path"), "Read a report file (JSON). Raises ReportError.")
      .def_property_readonly("passed", [](const ReportHandle& r) { return r.report.passed(); },
                             "every action, the execution and every readiness check passed")
      .def_property_readonly("ready", [](const ReportHandle& r) { return r.report.ready(); },
                             "every hardware readiness check passed")
      .def_property_readonly("execution_passed",
                             [](const ReportHandle& r) { return r.report.execution_verdict == sim::Verdict::kPassed; },
                             "no unplanned contact, no protective stop, tracking within its limit")
      .def_property_readonly("execution_failure", [](const ReportHandle& r) { return r.report.execution_failure; })
      .def_property_readonly("world", [](const ReportHandle& r) { return r.report.world; })
      .def_property_readonly("plan_file", [](const ReportHandle& r) { return r.report.plan_file; })
      .def_property_readonly("seed", [](const ReportHandle& r) { return r.report.seed; })
      .def_property_readonly("time_step", [](const ReportHandle& r) { return r.report.time_step; }, "[s]")
      .def_property_readonly("simulated_time", [](const ReportHandle& r) { return r.report.simulated_time; }, "[s]")
      .def_property_readonly("actions_inferred", [](const ReportHandle& r) { return r.report.actions_inferred; })
      .def_property_readonly("actions", [](const ReportHandle& r) { return r.report.actions; })
      .def_property_readonly("failed_actions", [](const ReportHandle& r) {
            std::vector<sim::ActionReport> failed;
            for (const sim::ActionReport& a : r.report.actions) {
              if (a.verdict == sim::Verdict::kFailed) failed.push_back(a);
            }
            return failed;
          })
      .def_property_readonly("events", [](const ReportHandle& r) { return r.report.events; })
      .def_property_readonly("robots", [](const ReportHandle& r) { return r.report.robots; })
      .def_property_readonly("readiness", [](const ReportHandle& r) { return r.report.readiness; })
      .def_property_readonly("summary", [](const ReportHandle& r) {
            return toPython(nlohmann::ordered_json::parse(sim::writeReportJson(r.report)).at("summary"));
          }, "the report file's summary: actions, passed, failed, execution, readiness, verdict")
      .def_property_readonly("samples", [](const ReportHandle& r) -> py::object {
            return r.samples ? py::object(samplesDict(*r.samples)) : py::object(py::none());
          },
           "with simulate(samples=RATE): a dict of numpy arrays sampled at RATE Hz of plan time: times (N,), "
           "joint_positions (N, robots, joints), link_poses (N, robots, links, 7), object_poses (N, objects, 7) "
           "(x y z [m], then the quaternion x y z w), tracking_error [rad], effort_ratio and grip_force [N] (N, robots), "
           "and the names of robots, joints, links and objects")
      .def_property_readonly("frames_written", [](const ReportHandle& r) { return r.frames_written; })
      .def("to_json", [](const ReportHandle& r) { return sim::writeReportJson(r.report); }, "the report file's text")
      .def("to_junit", [](const ReportHandle& r) { return sim::writeJUnitXml(r.report); }, "JUnit XML")
      .def("text", [](const ReportHandle& r, bool quiet) { return sim::summaryText(r.report, quiet); },
           py::arg("quiet") = false, "what `dashbed sim` prints: a line per action (unless quiet), then the verdict")
      .def("__repr__", [](const ReportHandle& r) {
        return "<dashbed.Report " + std::string(r.report.passed() ? "PASSED" : "FAILED") + ": " +
               std::to_string(r.report.passedCount()) + " of " + std::to_string(r.report.actions.size()) +
               " actions passed>";
      });

  m.def(
      "simulate",
      [](const WorldHandle& world, const PlanHandle& plan, const std::string& report, const std::string& junit,
         const std::string& html, std::optional<double> samples) {
        return runChecked(world, plan, RunRequest{report, junit, html, samples, {}});
      },
      py::arg("world"), py::arg("plan"), py::arg("report") = "", py::arg("junit") = "", py::arg("html") = "",
      py::arg("samples") = py::none(),
      py::call_guard<py::gil_scoped_release>(),
      "Execute a plan in the Bullet simulation and check every grasp, handoff and placement, as `dashbed sim` does. "
      "report / junit / html: write the JSON report (stills beside it) / JUnit XML / HTML replay there. samples: a rate [Hz] at which "
      "to sample the motion (Report.samples). Raises PlanError for a plan that does not fit the world. Releases "
      "the GIL: simulations in several threads run in parallel.");

  const sim::RecordingOptions defaults;
  m.def(
      "render",
      [](const WorldHandle& world, const PlanHandle& plan, const std::string& out, const std::string& video,
         const std::string& camera, double fps, double start, std::optional<double> until, int width, int height) {
        RunRequest request;
        request.recording.frames_dir = out;
        request.recording.video = video;
        request.recording.camera = camera;
        request.recording.fps = fps;
        request.recording.from = start;
        request.recording.until = until;
        request.recording.width = width;
        request.recording.height = height;
        if (!request.recording.wanted()) throw std::invalid_argument("render: give out (a folder) and/or video (a file)");
        return runChecked(world, plan, request);
      },
      py::arg("world"), py::arg("plan"), py::arg("out") = "", py::arg("video") = "",
      py::arg("camera") = defaults.camera, py::arg("fps") = defaults.fps, py::arg("start") = defaults.from,
      py::arg("until") = py::none(), py::arg("width") = defaults.width, py::arg("height") = defaults.height,
      py::call_guard<py::gil_scoped_release>(),
      "Simulate a plan and render it offscreen, as `dashbed render` does: PNG frames into the folder `out` and/or "
      "an MP4 `video`, fps frames per second of plan time from `start` to `until` [s]; camera: oblique, front, top "
      "or side:ROBOT. Returns the run's Report (frames_written says how many frames).");
}

}  // namespace dashbed::python
