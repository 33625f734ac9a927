// dashbed stress [WORLD]: many trials with perturbed object start poses, in threads and,
// under mpirun, across MPI ranks; rank 0 gathers the outcomes and writes the results.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>
#include <tuple>

#include "core/asset_paths.h"
#include "core/number_text.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tools/cli/cli_support.h"
#include "tools/cli/planner_options.h"
#include "tools/cli/number_checks.h"
#include "tools/parallel/parallel_trials.h"
#include "tools/stress/campaign.h"
#include "tools/stress/process_group.h"
#include "tools/stress/stress.h"
#include "tools/stress/stress_output.h"
#include "tools/stress/stress_summary.h"

namespace dashbed::tools {
namespace {

struct StressOptions {
  std::string world_file;
  std::string plan_file;
  std::string mode = "replay";
  std::string out_dir = "stress_out";
  std::string html;  // the campaign's page, with the worst trials' replays
  CampaignSettings settings;
  int threads = 0;  // 0: the machine's cores shared among the ranks on it
  int worst = 5;
  double min_success = -1.0;  // < 0: none
  bool progress = false;
};

// the nominal plan of a replay campaign: the given file, or the planner's plan for the world
core::Plan nominalPlan(const StressOptions& options, const core::LoadedWorld& loaded, std::string& description) {
  if (!options.plan_file.empty()) {
    description = options.plan_file;
    return core::loadPlanFile(options.plan_file);
  }
  try {
    return plannedNominal(loaded, options.settings, description);
  } catch (const PlanningFailed& e) {
    std::cerr << "dashbed stress: no nominal plan: " << e.what() << "\n";
    throw CLI::RuntimeError(e.status == PlanningStatus::kTimeout ? kExitTimeout : kExitInfeasible);
  }
}

void printWorst(const std::vector<TrialOutcome>& worst, const std::string& out_dir) {
  if (worst.empty()) return;
  std::cout << "worst trials (replay: dashbed sim " << out_dir << "/trial_N/plan.json --world " << out_dir
            << "/trial_N/world.yaml):\n";
  for (const TrialOutcome& o : worst) {
    // the first failed check; summary.json and the trial's report.json have them all
    std::cout << "  trial_" << o.index << ": " << o.failedActions() << " failed actions, "
              << (o.primary ? toString(*o.primary) : "-") << ": " << o.failure.substr(0, o.failure.find("; ")) << "\n";
  }
}

void runCampaign(const StressOptions& options, const ProcessGroup& group) {
  const auto start = std::chrono::steady_clock::now();
  CampaignSettings settings = options.settings;
  settings.mode = parseStressMode(options.mode);
  settings.check();
  if (settings.mode == StressMode::kReplan && !options.plan_file.empty()) {
    throw std::invalid_argument("--plan is for --mode replay (re-plan mode plans every trial)");
  }
  if (options.threads < 0) throw std::invalid_argument("--threads must be >= 0 (0: automatic)");
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = options.threads > 0 ? options.threads : std::max(1, cores / group.localSize());

  const std::filesystem::path world_path = worldFileOrDefault(options.world_file);
  const core::LoadedWorld loaded = core::loadWorld(world_path);
  // the files written name the world and plan files from the output folder: the same campaign
  // written elsewhere, the same bytes
  const std::string world_name = core::pathFrom(world_path, options.out_dir);
  CampaignInfo info{loaded.world->name, world_name, "", settings,
                    options.min_success >= 0.0 ? std::optional<double>(options.min_success) : std::nullopt};
  std::optional<core::Plan> plan;
  if (settings.mode == StressMode::kReplay) {
    plan = nominalPlan(options, loaded, info.plan);
    core::validatePlanForWorld(*plan, *loaded.world, *loaded.robots, info.plan);
    if (!options.plan_file.empty()) info.plan = core::pathFrom(options.plan_file, options.out_dir);
  } else {
    info.plan = "planned per trial (" + settings.planner.method + ")";
  }
  const TrialRunner runner(*loaded.world, world_path.string(), settings, plan);
  if (group.rank() == 0) prepareOutputDirectory(options.out_dir);

  // this rank's share: every size-th trial, so that each sweep point is spread over all ranks
  std::vector<std::size_t> mine;
  const auto rank = static_cast<std::size_t>(group.rank()), size = static_cast<std::size_t>(group.size());
  for (std::size_t i = rank; i < settings.totalTrials(); i += size) mine.push_back(i);
  std::optional<ProgressBar> progress;
  if (group.rank() == 0 && (options.progress || isatty(STDERR_FILENO) == 1)) {
    progress.emplace(std::cerr, mine.size(), group.size() > 1 ? "trials on rank 0" : "trials");
  }
  const std::vector<TrialOutcome> local = runTrials(runner, mine, threads, progress ? &*progress : nullptr);
  if (progress) progress->finish();

  const std::vector<std::string> parts = group.gatherToRoot(writeOutcomesJson(local));
  if (group.rank() != 0) return;
  std::vector<TrialOutcome> outcomes;
  std::string shares;  // trials per rank, "2 + 2"
  for (const std::string& part : parts) {
    std::vector<TrialOutcome> rank_outcomes = readOutcomesJson(part);
    shares += (shares.empty() ? "" : " + ") + std::to_string(rank_outcomes.size());
    for (TrialOutcome& o : rank_outcomes) outcomes.push_back(std::move(o));
  }

  const CampaignResults results = summarizeCampaign(std::move(info), std::move(outcomes), options.worst);
  writeCampaignFiles(options.out_dir, results.info, *loaded.world, results.points, results.outcomes, results.worst);
  saveTrials(options.out_dir, runner, results.worst, threads, /*replays=*/!options.html.empty());
  if (!options.html.empty()) writeCampaignPage(options.html, options.out_dir, results.info, results.points, results.worst);
  // the whole command: the nominal plan, the trials, the worst trials' files and the page
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << summaryText(results.info, results.points);
  printWorst(results.worst, options.out_dir);
  std::cout << results.outcomes.size() << " trials in " << core::fixedText(seconds, 1) << " s on " << group.size()
            << (group.size() > 1 ? " processes (" + shares + " trials)" : std::string(" process")) << " x " << threads
            << " threads: "
            << core::fixedText(3600.0 * static_cast<double>(results.outcomes.size()) / seconds, 0)
            << " trials/hour; results in " << options.out_dir << "/\n";
  if (!meetsAll(results.info, results.points)) throw CLI::RuntimeError(kExitCheckFailed);
}

// An error in an MPI job: one rank alone may have hit it while the others wait in the
// gather, so the whole job ends (with the exit code runGuarded gives the error).
[[noreturn]] void abortJob(const ProcessGroup& group) {
  int code = kExitInternal;
  try {
    runGuarded("stress", [] { throw; });  // prints the error being handled and maps it to a code
  } catch (const CLI::RuntimeError& e) {
    code = e.get_exit_code();
  } catch (const std::exception& e) {
    std::cerr << "dashbed stress (rank " << group.rank() << "): internal error: " << e.what() << "\n";
  }
  group.abort(code);
}

void runStress(const StressOptions& options) {
  const ProcessGroup group;
  if (group.size() == 1) return runCampaign(options, group);
  try {
    runCampaign(options, group);
  } catch (const CLI::RuntimeError& e) {
    if (e.get_exit_code() != kExitCheckFailed) group.abort(e.get_exit_code());  // after the gather: a clean end
    throw;
  } catch (...) {
    abortJob(group);
  }
}

}  // namespace

void addStressCommand(CLI::App& app) {
  auto options = std::make_shared<StressOptions>();
  CampaignSettings& s = options->settings;
  CLI::App* stress = app.add_subcommand(
      "stress",
      "Stress campaign: N trials with Gaussian noise on the objects' start poses (optionally mass and friction), "
      "each replaying the nominal plan open-loop or re-planning, simulated headless. Writes OUT/summary.json "
      "(success rates with Wilson 95 % intervals, failure taxonomy), OUT/junit.xml, OUT/trials.csv, "
      "OUT/trials.json and the worst trials as OUT/trial_N/{world.yaml,plan.json,report.json}. Under "
      "`mpirun -np K` the trials are shared among the ranks with identical results. Exit 0 done (failed trials "
      "alone do not fail it), 1 a success rate below --min-success, 2 bad option, 3 bad input (world, plan), "
      "4 / 5 no nominal plan (infeasible / planner timeout).");
  stress->add_option("world", options->world_file, "world file (default: worlds/default.yaml)");
  stress->add_option("--plan", options->plan_file, "replay this plan (default: plan the nominal world)");
  stress->add_option("--mode", options->mode, "replay (the nominal plan, open-loop) or replan (plan every trial)")
      ->capture_default_str();
  stress->add_option("--trials,-n", s.trials, "trials (per sweep point)")
      ->check(integerIn(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  stress->add_option("--seed", s.seed, "campaign seed; trial i uses a seed mixed from it and i")
      ->check(unsigned64())
      ->capture_default_str();
  for (const auto& [name, sigma, help] :
       {std::tuple("--sigma-xy", &s.sigmas.xy, "std dev of the x and y offsets [m]"),
        std::tuple("--sigma-yaw", &s.sigmas.yaw, "std dev of the yaw offset [rad]"),
        std::tuple("--sigma-mass", &s.sigmas.mass, "std dev of log(mass scale) [-]"),
        std::tuple("--sigma-friction", &s.sigmas.friction, "std dev of log(friction scale) [-]")}) {
    stress->add_option(name, *sigma, help)->check(nonNegativeNumber())->capture_default_str();
  }
  stress->add_option("--sweep", s.sweep_xy, "sweep sigma_xy over these increasing values [m] (comma-separated); "
                                            "writes OUT/sweep.png")
      ->delimiter(',');
  // the planner's options of `dashbed plan` but --seed: each trial plans with its own seed
  stress->add_option("--method", s.planner.method, "planning method: greedy or optimal")->capture_default_str();
  stress->add_option("--time-budget", s.planner.time_budget, "planner wall-clock budget per plan [s]")
      ->capture_default_str();
  stress->add_option("--max-rounds", s.planner.max_rounds, "planner representation expansion rounds")
      ->capture_default_str();
  stress->add_option("--fallback-rounds", s.planner.fallback_rounds, kFallbackRoundsHelp)->capture_default_str();
  stress->add_option("--threads,-j", options->threads, "worker threads per process (0: the cores of the machine "
                                                       "shared among its ranks)")
      ->capture_default_str();
  stress->add_option("--out,-o", options->out_dir, "output directory")->capture_default_str();
  stress->add_option("--html", options->html,
                     "write the campaign's page here: success rates, failure taxonomy and the worst trials, each "
                     "with its HTML replay (docs/replay.md)");
  stress->add_option("--worst", options->worst, "save this many worst trials")
      ->capture_default_str()
      ->check(integerIn(0, std::numeric_limits<int>::max()));
  stress->add_option("--min-success", options->min_success, "fail (exit 1) when a success rate is below this")
      ->check(CLI::Range(0.0, 1.0));
  stress->add_flag("--progress", options->progress, "progress bar on stderr even when it is not a terminal");
  stress->callback([options] { runGuarded("stress", [&] { runStress(*options); }); });
}

}  // namespace dashbed::tools
