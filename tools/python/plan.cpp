// dashbed.Plan (timed trajectories, gripper commands, actions; numpy arrays out), and
// dashbed.plan(): the DaSH planner as `dashbed plan` runs it.

#include <cmath>
#include <limits>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "core/asset_paths.h"
#include "tools/planning/run_planner.h"
#include "tools/python/bindings.h"

namespace dashbed::python {
namespace {

/// The planner's result: status, reason, statistics and the plan (None unless solved).
struct PlanningResult {
  std::string status;
  std::string reason;
  nlohmann::json statistics;
  std::optional<PlanHandle> plan;
};

const core::RobotTrajectory& trajectoryOf(const PlanHandle& p, const std::string& robot) {
  for (const core::RobotTrajectory& trajectory : p.plan->trajectories) {
    if (trajectory.robot == robot) return trajectory;
  }
  throw py::key_error("the plan has no trajectory for robot '" + robot + "'");
}

/// The points' times (N), positions (N x 6) and velocities (N x 6, NaN where a point has none).
py::dict trajectoryArrays(const core::RobotTrajectory& trajectory) {
  const auto n = static_cast<py::ssize_t>(trajectory.points.size());
  py::array_t<double> times(n);
  py::array_t<double> positions({n, py::ssize_t{6}});
  py::array_t<double> velocities({n, py::ssize_t{6}});
  auto t = times.mutable_unchecked<1>();
  auto q = positions.mutable_unchecked<2>();
  auto qd = velocities.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const core::TrajectoryPoint& point = trajectory.points[static_cast<std::size_t>(i)];
    t(i) = point.t;
    for (py::ssize_t j = 0; j < 6; ++j) {
      q(i, j) = point.q[static_cast<std::size_t>(j)];
      qd(i, j) = point.qd ? (*point.qd)[static_cast<std::size_t>(j)] : std::numeric_limits<double>::quiet_NaN();
    }
  }
  py::dict d;
  d["robot"] = trajectory.robot;
  d["joint_names"] = py::cast(trajectory.joint_names);
  d["times"] = times;
  d["positions"] = positions;
  d["velocities"] = velocities;
  return d;
}

PlanningResult runPlanner(const WorldHandle& world, const tools::PlannerChoice& choice) {
  const planner::PlanResult result = tools::planWorld(*world.loaded, choice);
  PlanningResult out{planner::toString(result.status), result.reason, tools::planResultJson(result), std::nullopt};
  if (result.plan) out.plan = PlanHandle{std::make_shared<const core::Plan>(*result.plan), ""};
  return out;
}

}  // namespace

void bindPlan(py::module_& m) {
  py::class_<core::GripperCommand>(m, "GripperCommand", "Open or close a robot's gripper at a time.")
      .def_readonly("robot", &core::GripperCommand::robot)
      .def_readonly("t", &core::GripperCommand::t, "[s]")
      .def_property_readonly("action", [](const core::GripperCommand& c) { return std::string(core::toString(c.action)); },
                             "'open' or 'close'")
      .def_readonly("force", &core::GripperCommand::force, "closing force [N]; 0: the world's grip force");

  py::class_<core::PlanAction>(m, "Action", "A pick, place or handoff the plan carries out.")
      .def_property_readonly("type", [](const core::PlanAction& a) { return std::string(core::toString(a.type)); },
                             "'pick', 'place' or 'handoff'")
      .def_readonly("robot", &core::PlanAction::robot, "the robot (a handoff's giver)")
      .def_readonly("receiver", &core::PlanAction::receiver, "a handoff's receiver, else ''")
      .def_readonly("object", &core::PlanAction::object)
      .def_readonly("region", &core::PlanAction::region, "a place's goal region ('' to set the object aside)")
      .def_readonly("start", &core::PlanAction::start, "[s]")
      .def_readonly("end", &core::PlanAction::end, "[s]");

  py::class_<PlanHandle>(m, "Plan", "A timed multi-robot plan: one arm trajectory per robot, gripper commands, actions.")
      .def_static("load", [](const std::filesystem::path& path) {
            return PlanHandle{std::make_shared<const core::Plan>(core::loadPlanFile(path)), path.string()};
          }, py::arg("path"), "Read a plan file (JSON). Raises PlanError with file and JSON pointer.")
      .def_static("from_json", [](const std::string& text, const std::string& name) {
            return PlanHandle{std::make_shared<const core::Plan>(core::parsePlanJson(text, name)), ""};
          }, py::arg("text"), py::arg("name") = "<memory>", "Read a plan from JSON text; `name` stands for the file in messages.")
      .def("to_json", [](const PlanHandle& p) { return core::writePlanJson(*p.plan); },
           "The plan file's text: the same bytes `dashbed plan -o` writes for the same world, method and seed.")
      .def("save", [](const PlanHandle& p, const std::filesystem::path& path) {
            core::writeFile(path, core::writePlanJson(*p.plan));
            return PlanHandle{p.plan, path.string()};
          }, py::arg("path"),
           "Write the plan file. Returns the same plan naming that file (reports of it name the file); this "
           "plan is left as it is.")
      .def_property_readonly("file", [](const PlanHandle& p) { return p.file; },
                             "the file it was read from or saved to ('' for none)")
      .def_property_readonly("world", [](const PlanHandle& p) { return p.plan->world; }, "the world's name")
      .def_property_readonly("seed", [](const PlanHandle& p) { return p.plan->seed; })
      .def_property_readonly("duration", [](const PlanHandle& p) { return p.plan->duration(); },
                             "time of the last point, command or action end [s]")
      .def_property_readonly("robots", [](const PlanHandle& p) {
            std::vector<std::string> names;
            for (const core::RobotTrajectory& t : p.plan->trajectories) names.push_back(t.robot);
            return names;
          }, "the robots with a trajectory, in the plan's order")
      .def("trajectory", [](const PlanHandle& p, const std::string& robot) {
            return trajectoryArrays(trajectoryOf(p, robot));
          }, py::arg("robot"),
           "A robot's trajectory as a dict: robot, joint_names, times (N,) [s], positions (N, 6) [rad], velocities "
           "(N, 6) [rad/s] (NaN where the plan leaves them to interpolation).")
      .def_property_readonly("gripper", [](const PlanHandle& p) { return p.plan->gripper; }, "sorted by time")
      .def_property_readonly("actions", [](const PlanHandle& p) { return p.plan->actions; }, "sorted by start")
      .def_property_readonly("statistics", [](const PlanHandle& p) { return toPython(p.plan->statistics); },
                             "the planner's statistics as written in the plan file")
      .def("__repr__", [](const PlanHandle& p) {
        return "<dashbed.Plan for " + p.plan->world + ": " + std::to_string(p.plan->actions.size()) + " actions, " +
               std::to_string(p.plan->duration()) + " s>";
      });

  py::class_<PlanningResult>(m, "PlanningResult", "What the planner returned.")
      .def_readonly("status", &PlanningResult::status, "'solved', 'infeasible' or 'timeout'")
      .def_readonly("reason", &PlanningResult::reason, "why it is not solved ('' when solved)")
      .def_property_readonly("statistics", [](const PlanningResult& r) { return toPython(r.statistics); },
                             "as `dashbed plan --json` prints them (stage times, representation sizes, makespan)")
      .def_readonly("plan", &PlanningResult::plan, "the Plan, or None")
      .def_property_readonly("solved", [](const PlanningResult& r) { return r.plan.has_value(); })
      .def("__repr__", [](const PlanningResult& r) {
        return "<dashbed.PlanningResult " + r.status + (r.reason.empty() ? "" : ": " + r.reason) + ">";
      });

  const tools::PlannerChoice defaults;
  m.def(
      "plan",
      [](const WorldHandle& world, const std::string& method, std::uint64_t seed, double time_budget, int max_rounds,
         bool set_aside) {
        tools::PlannerChoice choice;
        choice.method = method;
        choice.seed = seed;
        choice.time_budget = time_budget;
        choice.max_rounds = max_rounds;
        choice.set_aside = set_aside;
        return runPlanner(world, choice);
      },
      py::arg("world"), py::arg("method") = defaults.method, py::arg("seed") = defaults.seed,
      py::arg("time_budget") = defaults.time_budget, py::arg("max_rounds") = defaults.max_rounds,
      py::arg("set_aside") = defaults.set_aside, py::call_guard<py::gil_scoped_release>(),
      "Plan a world with DaSH as `dashbed plan` does: method 'greedy' (Greedy-MM-DaSH) or 'optimal' (MM-DaSH), "
      "the sampling seed, the wall-clock budget [s], the representation expansion rounds, and whether objects in "
      "the way of another's every pick may be set aside. Returns a PlanningResult; raises ValueError for a bad "
      "choice. Releases the GIL.");
}

}  // namespace dashbed::python
