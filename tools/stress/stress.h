#pragma once
// Stress campaigns: many trials of one world whose objects start a little off their nominal
// poses. Each trial either replays the nominal plan open-loop (how robust is this plan?) or
// re-plans from the perturbed poses (how reliable are planner and execution together?), runs
// the simulator headless and records the verdict of every action and a failure class.
//
// Determinism: a trial depends only on (campaign settings, trial index): its random stream is
// seeded by trialSeed(campaign seed, index) and every number is drawn by our own portable
// code, so a campaign gives the same outcomes for any number of threads or MPI ranks.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/plan.h"
#include "core/world.h"
#include "sim/motion_samples.h"
#include "sim/report.h"
#include "tools/parallel/parallel_trials.h"
#include "tools/planning/run_planner.h"
#include "tools/scenarios/scenarios.h"

namespace dashbed::tools {

enum class StressMode {
  kReplay,  ///< every trial executes the nominal plan open-loop
  kReplan,  ///< every trial plans again (planForRun) from its perturbed poses
};

/// "replay" / "replan".
std::string_view toString(StressMode mode);
/// Parses "replay" or "replan"; throws std::invalid_argument otherwise.
StressMode parseStressMode(const std::string& text);

/// Standard deviations of the start-pose perturbation. x and y offsets are Gaussian in the
/// world frame, yaw is Gaussian about the object's vertical axis; mass and friction are scaled
/// by exp(sigma * g) with g standard normal (log-normal: always positive, median 1).
struct PerturbationSigmas {
  double xy = 0.002;       ///< [m]
  double yaw = 0.02;       ///< [rad]
  double mass = 0.0;       ///< of the log of the mass scale [-]
  double friction = 0.0;   ///< of the log of the friction-coefficient scale [-]
};

/// What one trial did to one object.
struct ObjectPerturbation {
  double dx = 0.0;              ///< [m] world x
  double dy = 0.0;              ///< [m] world y
  double dyaw = 0.0;            ///< [rad]
  double mass_scale = 1.0;      ///< [-]
  double friction_scale = 1.0;  ///< [-]
  bool operator==(const ObjectPerturbation&) const = default;
};

/// Everything that defines a campaign's outcomes (not how it is spread over threads/ranks).
struct CampaignSettings {
  StressMode mode = StressMode::kReplay;
  int trials = 100;                 ///< per sweep point
  std::uint64_t seed = 1;           ///< campaign seed
  PerturbationSigmas sigmas;
  std::vector<double> sweep_xy;     ///< sigma_xy of each sweep point [m]; empty: one point at sigmas.xy
  PlannerChoice planner;            ///< re-plan mode (its seed is replaced by each trial's seed)

  int points() const { return sweep_xy.empty() ? 1 : static_cast<int>(sweep_xy.size()); }
  std::size_t totalTrials() const { return static_cast<std::size_t>(points()) * static_cast<std::size_t>(trials); }
  PerturbationSigmas sigmasAt(int point) const;
  /// Throws std::invalid_argument naming the option for a bad value.
  void check() const;
};

/// Global trial index `index` (0 .. totalTrials-1) is trial index % trials of sweep point
/// index / trials; the trials of different points share seeds (common random numbers), so a
/// sweep compares the same draws scaled by each sigma.
int pointOf(const CampaignSettings& settings, std::size_t index);

/// The seed of trial `trial` of a campaign: splitmix64 mixing of both, so that neighbouring
/// trials and campaigns get unrelated streams.
std::uint64_t trialSeed(std::uint64_t campaign_seed, std::uint64_t trial);

/// A standard normal number from two uniforms of `rng` (Box-Muller, cosine branch):
/// portable, unlike std::normal_distribution.
double standardNormal(ScenarioRng& rng);

/// A world whose object start poses were perturbed, valid by the world file's own checks.
struct PerturbedWorld {
  core::World world;   ///< parsed back from `yaml`: exactly what a replay of the file sees
  std::string yaml;    ///< the world file (writeWorldYaml)
  std::vector<ObjectPerturbation> objects;  ///< per object of the world, in order
};

/// Perturbs every object of `nominal` with draws from `seed`'s stream. An object whose
/// perturbed start is invalid (overlapping a fixture or another object, or no longer resting
/// on a stable surface: parseWorldYaml's checks) is drawn again from the same stream, up to
/// 1000 times (then std::invalid_argument: the sigmas are too large for this world).
/// `world_file` names the world in messages and its description.
PerturbedWorld perturbWorld(const core::World& nominal, const PerturbationSigmas& sigmas, std::uint64_t seed,
                            const std::string& world_file);

/// Failure taxonomy of a trial.
enum class FailureClass {
  kMissedGrasp,     ///< a pick failed: pads not both on the object, not lifted, lost while lifting
  kSlip,            ///< the object moved in a gripper beyond tolerance or fell out while carried
  kHandoffDrop,     ///< a handoff failed: no overlap, receiver not holding, object dropped
  kMisplaced,       ///< a place failed: outside the region, not at rest, not flat, left it
  kCollision,       ///< unplanned contact (robot-robot, robot-scenery, robot-object) or knocked object
  kProtectiveStop,  ///< a protective stop: external torque or TCP force beyond the safety limits, or a joint off its path
  kNotReady,        ///< the plan fails the hardware readiness check (e.g. a perturbed mass beyond the payload or grip)
  kPlannerFailure,  ///< re-plan mode: no plan (infeasible or unreachable perturbed start)
  kPlannerTimeout,  ///< re-plan mode: the planner's budget ran out
};
inline constexpr int kFailureClassCount = 9;

/// "missed_grasp", "slip", "handoff_drop", "misplaced", "collision", "protective_stop", "not_ready",
/// "planner_failure", "planner_timeout".
std::string_view toString(FailureClass failure);
/// The inverse of toString; throws std::invalid_argument for an unknown name.
FailureClass parseFailureClass(std::string_view name);

/// The class of one failed action from its measurements and the events attributed to it.
FailureClass classifyAction(const sim::ActionReport& action, const std::vector<sim::ExecutionEvent>& events);

/// One measured value behind an action's verdict (units and thresholds are in the report).
struct MeasuredValue {
  std::string name;  ///< e.g. "slip"
  double value = 0.0;
  bool operator==(const MeasuredValue&) const = default;
};

/// One action of a trial.
struct ActionOutcome {
  core::ActionType type = core::ActionType::kPick;
  std::string id;  ///< the report's action id, e.g. "pick cube_0 by r1"
  bool passed = true;
  std::vector<MeasuredValue> measurements;  ///< the report's finite measurement values, in its order
  bool operator==(const ActionOutcome&) const = default;
};

/// The compact result of one trial: what the summary needs, small enough to gather.
struct TrialOutcome {
  std::size_t index = 0;       ///< global trial index
  int point = 0;               ///< sweep point
  std::uint64_t seed = 0;      ///< trialSeed(campaign seed, trial)
  bool passed = false;
  std::optional<FailureClass> primary;  ///< the first failed action's class (else the execution's / planner's)
  std::vector<FailureClass> classes;    ///< every class that occurred, each once, in enum order
  std::vector<ActionOutcome> actions;   ///< in plan order (empty when planning failed)
  std::string failure;                  ///< the first failed action's failure text, or the planner's message
  std::vector<ObjectPerturbation> objects;
  bool operator==(const TrialOutcome&) const = default;

  int failedActions() const;
};

/// Fills passed, primary, classes, actions and failure from a report.
void classifyReport(const sim::Report& report, TrialOutcome& outcome);

/// Outcomes as one JSON text and back (numbers round-trip exactly); used to gather outcomes
/// from MPI ranks, and written as trials.json and beside each saved trial. Throws
/// core::InputError on bad text.
std::string writeOutcomesJson(const std::vector<TrialOutcome>& outcomes);
std::vector<TrialOutcome> readOutcomesJson(std::string_view json_text);

/// A trial with everything needed to replay it.
struct TrialRun {
  TrialOutcome outcome;
  std::string world_yaml;
  std::optional<core::Plan> plan;     ///< absent when planning failed
  std::optional<sim::Report> report;  ///< absent when planning failed
  std::optional<sim::MotionSamples> motion;  ///< sampled when asked (TrialRunner::run)
};

/// Where a saved trial goes inside the output directory: "trial_<index>".
std::string trialDirectoryName(std::size_t index);

/// Runs trials of one campaign. Thread-safe: run() may be called from many threads at once
/// (each call builds its own world, robots and simulation).
class TrialRunner {
 public:
  /// `nominal_plan`: the plan every replay trial executes (validated against `nominal` by the
  /// caller); ignored in re-plan mode. `world_file` names the world in messages.
  TrialRunner(const core::World& nominal, std::string world_file, const CampaignSettings& settings,
              std::optional<core::Plan> nominal_plan);

  /// Runs global trial `index`. The report's plan file is "trial_<index>/plan.json", the name
  /// the plan is saved under in the output directory. With `sample_rate` > 0 [Hz] the motion is
  /// sampled too (TrialRun::motion), for a replay.
  TrialRun run(std::size_t index, double sample_rate = 0.0) const;

  /// Only the perturbed world of trial `index` (outcome: index, point, seed and perturbation;
  /// no plan, no report), without planning or simulating.
  TrialRun perturbedWorld(std::size_t index) const;

 private:
  PerturbedWorld perturb(std::size_t index, TrialOutcome& outcome) const;

  const core::World& nominal_;
  std::string world_file_;
  CampaignSettings settings_;
  std::optional<core::Plan> nominal_plan_;
};

/// Runs the trials `indices` of `runner` on `threads` threads and returns their outcomes in
/// the order of `indices` (independent of the scheduling). `progress` may be null.
std::vector<TrialOutcome> runTrials(const TrialRunner& runner, const std::vector<std::size_t>& indices, int threads,
                                    ProgressBar* progress = nullptr);

}  // namespace dashbed::tools
