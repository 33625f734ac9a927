// dashbed.stress(): a stress campaign in this process's threads, as `dashbed stress` runs it
// (the same settings and seed give the same outcomes and summary).

#include <thread>

#include <pybind11/stl.h>

#include "core/asset_paths.h"
#include "tools/python/bindings.h"
#include "tools/stress/campaign.h"
#include "tools/stress/stress_output.h"

namespace dashbed::python {
namespace {

struct StressRequest {
  tools::CampaignSettings settings;
  std::optional<PlanHandle> plan;
  int threads = 0;
  std::string out;
  std::string html;
  int worst = 5;
  std::optional<double> min_success;
};

/// The campaign's results, with summary.json's text.
struct StressResult {
  tools::CampaignResults results;
  std::string summary_json;
  bool passed = true;
};

StressResult runCampaign(const WorldHandle& world, StressRequest request) {
  tools::CampaignSettings& settings = request.settings;
  settings.check();
  if (settings.mode == tools::StressMode::kReplan && request.plan) {
    throw std::invalid_argument("plan is for mode 'replay' (mode 'replan' plans every trial)");
  }
  if (request.threads < 0) throw std::invalid_argument("threads must be >= 0 (0: one per core)");
  if (request.worst < 0) throw std::invalid_argument("worst must be >= 0");
  if (!request.html.empty() && request.out.empty()) throw std::invalid_argument("html needs out (the worst trials' folder)");
  const int threads =
      request.threads > 0 ? request.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const core::LoadedWorld& loaded = *world.loaded;
  if (request.min_success && !(*request.min_success >= 0.0 && *request.min_success <= 1.0)) {
    throw std::invalid_argument("min_success must be in [0, 1]");
  }
  const std::string& source = world.world().source_file;
  const std::string world_file = source.empty() ? "<memory>" : source;
  const std::string folder = request.out.empty() ? "." : request.out;
  tools::CampaignInfo info{world.world().name, source.empty() ? world_file : core::pathFrom(source, folder), "",
                           settings, request.min_success};
  std::optional<core::Plan> plan;
  if (settings.mode == tools::StressMode::kReplay) {
    if (request.plan) {
      plan = *request.plan->plan;
      info.plan = request.plan->file.empty() ? "<memory>" : core::pathFrom(request.plan->file, folder);
    } else {
      plan = tools::plannedNominal(loaded, settings, info.plan);
    }
    core::validatePlanForWorld(*plan, *loaded.world, *loaded.robots, info.plan);
  } else {
    info.plan = "planned per trial (" + settings.planner.method + ")";
  }
  const tools::TrialRunner runner(*loaded.world, world_file, settings, plan);
  std::vector<std::size_t> indices(settings.totalTrials());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  if (!request.out.empty()) tools::prepareOutputDirectory(request.out);
  StressResult result{tools::summarizeCampaign(info, tools::runTrials(runner, indices, threads), request.worst), "",
                      true};
  const tools::CampaignResults& r = result.results;
  result.summary_json = tools::writeSummaryJson(r.info, r.points, r.worst);
  result.passed = tools::meetsAll(r.info, r.points);
  if (!request.out.empty()) {
    tools::writeCampaignFiles(request.out, r.info, *loaded.world, r.points, r.outcomes, r.worst);
    tools::saveTrials(request.out, runner, r.worst, threads, /*replays=*/!request.html.empty());
    if (!request.html.empty()) tools::writeCampaignPage(request.html, request.out, r.info, r.points, r.worst);
  }
  return result;
}

}  // namespace

void bindStress(py::module_& m) {
  py::class_<tools::TrialOutcome>(m, "TrialOutcome", "One trial of a stress campaign.")
      .def_readonly("index", &tools::TrialOutcome::index)
      .def_readonly("point", &tools::TrialOutcome::point, "the sweep point")
      .def_readonly("seed", &tools::TrialOutcome::seed)
      .def_readonly("passed", &tools::TrialOutcome::passed)
      .def_property_readonly("primary", [](const tools::TrialOutcome& o) -> py::object {
            return o.primary ? py::object(py::str(std::string(tools::toString(*o.primary)))) : py::object(py::none());
          }, "the failure class of the first failed check ('missed_grasp', 'slip', ...), or None")
      .def_property_readonly("classes", [](const tools::TrialOutcome& o) {
            std::vector<std::string> names;
            for (const tools::FailureClass c : o.classes) names.emplace_back(tools::toString(c));
            return names;
          }, "every failure class that occurred")
      .def_readonly("failure", &tools::TrialOutcome::failure, "the first failed check's text, or the planner's")
      .def_property_readonly("failed_actions", &tools::TrialOutcome::failedActions);

  py::class_<StressResult>(m, "StressResult", "A stress campaign's results.")
      .def_property_readonly("summary", [](const StressResult& r) { return toPython(nlohmann::ordered_json::parse(r.summary_json)); },
                             "summary.json as a dict: success rates with Wilson 95 % intervals per sweep point, per "
                             "action type and action, the failure taxonomy, the worst trials")
      .def_property_readonly("outcomes", [](const StressResult& r) { return r.results.outcomes; }, "every trial, by index")
      .def_property_readonly("worst", [](const StressResult& r) { return r.results.worst; })
      .def_readonly("passed", &StressResult::passed, "every sweep point met min_success (True without one)")
      .def_property_readonly("success_rate", [](const StressResult& r) {
            std::vector<double> rates;
            for (const tools::PointSummary& p : r.results.points) rates.push_back(p.trials.rate);
            return rates;
          }, "the fraction of trials that passed, per sweep point")
      .def("text", [](const StressResult& r) { return tools::summaryText(r.results.info, r.results.points); },
           "what `dashbed stress` prints");

  const tools::CampaignSettings defaults;
  m.def(
      "stress",
      [](const WorldHandle& world, std::optional<PlanHandle> plan, const std::string& mode, int trials,
         std::uint64_t seed, double sigma_xy, double sigma_yaw, double sigma_mass, double sigma_friction,
         std::vector<double> sweep, const std::string& method, double time_budget, int threads, const std::string& out,
         const std::string& html, int worst, std::optional<double> min_success) {
        StressRequest request;
        tools::CampaignSettings& s = request.settings;
        s.mode = tools::parseStressMode(mode);
        s.trials = trials;
        s.seed = seed;
        s.sigmas = {sigma_xy, sigma_yaw, sigma_mass, sigma_friction};
        s.sweep_xy = std::move(sweep);
        s.planner.method = method;
        s.planner.time_budget = time_budget;
        request.plan = std::move(plan);
        request.threads = threads;
        request.out = out;
        request.html = html;
        request.worst = worst;
        request.min_success = min_success;
        return runCampaign(world, std::move(request));
      },
      py::arg("world"), py::arg("plan") = py::none(), py::arg("mode") = "replay", py::arg("trials") = defaults.trials,
      py::arg("seed") = defaults.seed, py::arg("sigma_xy") = defaults.sigmas.xy, py::arg("sigma_yaw") = defaults.sigmas.yaw,
      py::arg("sigma_mass") = defaults.sigmas.mass, py::arg("sigma_friction") = defaults.sigmas.friction,
      py::arg("sweep") = std::vector<double>{}, py::arg("method") = defaults.planner.method,
      py::arg("time_budget") = defaults.planner.time_budget, py::arg("threads") = 0, py::arg("out") = "", py::arg("html") = "",
      py::arg("worst") = 5, py::arg("min_success") = py::none(), py::call_guard<py::gil_scoped_release>(),
      "A stress campaign as `dashbed stress` runs it: `trials` trials (per sweep point) whose objects start off "
      "their poses by Gaussian noise (sigma_xy [m], sigma_yaw [rad]; sigma_mass and sigma_friction of the log "
      "scales), each replaying `plan` (default: the plan for the world from the campaign's seed) or, with "
      "mode='replan', planning again. sweep: sigma_xy values to sweep. threads: 0 for one per core. out: also "
      "write the campaign's files there (summary.json, junit.xml, trials.csv, the worst trials); html: also the "
      "campaign's page there, with each worst trial's replay. Releases the GIL.");
}

}  // namespace dashbed::python
