#include "tools/stress/stress.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/json_reader.h"
#include "core/number_text.h"
#include "core/robot_set.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"

namespace dashbed::tools {
namespace {

constexpr int kMaxDraws = 1000;  // draws of one object's perturbation before giving up



ObjectPerturbation drawPerturbation(ScenarioRng& rng, const PerturbationSigmas& sigmas) {
  // always five draws in this order, so enabling one sigma does not shift the others' draws
  ObjectPerturbation p;
  p.dx = sigmas.xy * standardNormal(rng);
  p.dy = sigmas.xy * standardNormal(rng);
  p.dyaw = sigmas.yaw * standardNormal(rng);
  p.mass_scale = std::exp(sigmas.mass * standardNormal(rng));
  p.friction_scale = std::exp(sigmas.friction * standardNormal(rng));
  return p;
}

core::ObjectSpec applyPerturbation(const core::ObjectSpec& nominal, const ObjectPerturbation& p) {
  core::ObjectSpec object = nominal;
  object.X_WO.translation() += Eigen::Vector3d(p.dx, p.dy, 0.0);
  object.X_WO.linear() = nominal.X_WO.linear() * Eigen::AngleAxisd(p.dyaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  object.mass = nominal.mass * p.mass_scale;
  object.friction = nominal.friction * p.friction_scale;
  return object;
}

bool isValidStart(const core::World& world) {
  try {
    core::parseWorldYaml(core::writeWorldYaml(world), "perturbed");
    return true;
  } catch (const core::WorldError&) {
    return false;
  }
}

bool hasEvent(const std::vector<sim::ExecutionEvent>& events, const std::string& action, std::string_view kind) {
  return std::any_of(events.begin(), events.end(),
                     [&](const sim::ExecutionEvent& e) { return e.action == action && e.kind == kind; });
}

bool isCollisionEvent(const sim::ExecutionEvent& event) {
  return event.kind == "knocked object" || event.kind == "robot-robot contact" ||
         event.kind == "robot-fixture contact" || event.kind == "unplanned contact with object";
}

// the class of a failed action of this type when nothing more specific is known
FailureClass typeClass(core::ActionType type) {
  switch (type) {
    case core::ActionType::kPick:
      return FailureClass::kMissedGrasp;
    case core::ActionType::kHandoff:
      return FailureClass::kHandoffDrop;
    case core::ActionType::kPlace:
      return FailureClass::kMisplaced;
  }
  return FailureClass::kMisplaced;
}

}  // namespace

std::string_view toString(StressMode mode) { return mode == StressMode::kReplay ? "replay" : "replan"; }

StressMode parseStressMode(const std::string& text) {
  if (text == "replay") return StressMode::kReplay;
  if (text == "replan") return StressMode::kReplan;
  throw std::invalid_argument("--mode must be 'replay' or 'replan', got '" + text + "'");
}

PerturbationSigmas CampaignSettings::sigmasAt(int point) const {
  PerturbationSigmas sigmas_at = sigmas;
  if (!sweep_xy.empty()) sigmas_at.xy = sweep_xy.at(static_cast<std::size_t>(point));
  return sigmas_at;
}

void CampaignSettings::check() const {
  const auto nonNegative = [](double value, const std::string& option) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      throw std::invalid_argument(option + " must be a finite number >= 0, got " + core::shortestText(value));
    }
  };
  if (trials < 1) throw std::invalid_argument("--trials must be at least 1, got " + std::to_string(trials));
  nonNegative(sigmas.xy, "--sigma-xy");
  nonNegative(sigmas.yaw, "--sigma-yaw");
  nonNegative(sigmas.mass, "--sigma-mass");
  nonNegative(sigmas.friction, "--sigma-friction");
  for (std::size_t i = 0; i < sweep_xy.size(); ++i) {
    nonNegative(sweep_xy[i], "--sweep");
    if (i > 0 && !(sweep_xy[i] > sweep_xy[i - 1])) throw std::invalid_argument("--sweep values must increase");
  }
}

int pointOf(const CampaignSettings& settings, std::size_t index) {
  return static_cast<int>(index / static_cast<std::size_t>(settings.trials));
}

std::uint64_t trialSeed(std::uint64_t campaign_seed, std::uint64_t trial) {
  // splitmix64's finaliser (Steele, Lea, Flood 2014), applied to the campaign seed and again
  // after adding the trial index
  const auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  return mix(mix(campaign_seed) + trial);
}

double standardNormal(ScenarioRng& rng) {
  const double u1 = 1.0 - rng.uniform01();  // (0, 1]: the logarithm stays finite
  const double u2 = rng.uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

PerturbedWorld perturbWorld(const core::World& nominal, const PerturbationSigmas& sigmas, std::uint64_t seed,
                            const std::string& world_file) {
  ScenarioRng rng(seed);
  core::World world = nominal;
  std::vector<ObjectPerturbation> objects(nominal.objects.size());
  // object by object: each draw is checked with the objects before it already perturbed and
  // those after it still nominal, so every accepted state, and thus the result, is valid
  for (std::size_t k = 0; k < nominal.objects.size(); ++k) {
    for (int draw = 1;; ++draw) {
      objects[k] = drawPerturbation(rng, sigmas);
      world.objects[k] = applyPerturbation(nominal.objects[k], objects[k]);
      if (isValidStart(world)) break;
      if (draw == kMaxDraws) {
        throw std::invalid_argument(world_file + ": objects[" + std::to_string(k) + "] ('" + nominal.objects[k].name +
                                    "'): no valid perturbed start pose in " + std::to_string(kMaxDraws) +
                                    " draws (seed " + std::to_string(seed) +
                                    "); the sigmas are too large for this world");
      }
    }
  }
  // named by the world's name, not its file: the same trial gives the same bytes wherever run
  world.description = "stress trial of world " + nominal.name + " (trial seed " + std::to_string(seed) + ", sigma_xy " +
                      core::shortestText(sigmas.xy) + " m, sigma_yaw " + core::shortestText(sigmas.yaw) + " rad)";
  PerturbedWorld result;
  result.yaml = core::writeWorldYaml(world);
  result.world = core::parseWorldYaml(result.yaml, world_file);
  result.objects = std::move(objects);
  return result;
}

FailureClass classifyAction(const sim::ActionReport& action, const std::vector<sim::ExecutionEvent>& events) {
  // losing the object: in a pick it was never really grasped, in a handoff it fell between the
  // grippers, while carried to a place it slipped out
  if (hasEvent(events, action.id, "drop")) {
    return action.type == core::ActionType::kPlace ? FailureClass::kSlip : typeClass(action.type);
  }
  const bool slip_measured = std::any_of(action.measurements.begin(), action.measurements.end(), [](const auto& m) {
    return !m.passed && m.name.find("slip") != std::string::npos;
  });
  if (slip_measured || hasEvent(events, action.id, "slip")) return FailureClass::kSlip;
  const bool own_check_failed = std::any_of(action.measurements.begin(), action.measurements.end(),
                                            [](const auto& m) { return !m.passed; });
  // failed only because the robot knocked another object on the way
  if (!own_check_failed && hasEvent(events, action.id, "knocked object")) return FailureClass::kCollision;
  return typeClass(action.type);
}

int TrialOutcome::failedActions() const {
  return static_cast<int>(
      std::count_if(actions.begin(), actions.end(), [](const ActionOutcome& a) { return !a.passed; }));
}

void classifyReport(const sim::Report& report, TrialOutcome& outcome) {
  outcome.passed = report.passed();
  outcome.actions.clear();
  std::array<bool, kFailureClassCount> seen{};
  for (const sim::ActionReport& action : report.actions) {
    const bool passed = action.verdict == sim::Verdict::kPassed;
    ActionOutcome& recorded = outcome.actions.emplace_back(ActionOutcome{action.type, action.id, passed, {}});
    for (const sim::Measurement& m : action.measurements) {
      if (std::isfinite(m.value)) recorded.measurements.push_back({m.name, m.value});
    }
    if (passed) continue;
    const FailureClass failure = classifyAction(action, report.events);
    seen[static_cast<std::size_t>(failure)] = true;
    if (!outcome.primary) {
      outcome.primary = failure;
      outcome.failure = action.id + ": " + action.failure;
    }
  }
  if (report.execution_verdict == sim::Verdict::kFailed) {
    const bool collided = std::any_of(report.events.begin(), report.events.end(), isCollisionEvent);
    const bool stopped = std::any_of(report.events.begin(), report.events.end(),
                                     [](const sim::ExecutionEvent& e) { return e.kind == "protective stop"; });
    if (collided) seen[static_cast<std::size_t>(FailureClass::kCollision)] = true;
    if (stopped) seen[static_cast<std::size_t>(FailureClass::kProtectiveStop)] = true;
    if (!outcome.primary && (collided || stopped)) {
      outcome.primary = collided ? FailureClass::kCollision : FailureClass::kProtectiveStop;
      outcome.failure = "execution: " + report.execution_failure;
    }
  }
  if (!report.ready()) {
    seen[static_cast<std::size_t>(FailureClass::kNotReady)] = true;
    if (!outcome.primary) {
      outcome.primary = FailureClass::kNotReady;
      for (const core::ReadinessCheck& c : report.readiness) {
        if (!c.passed && outcome.failure.empty()) outcome.failure = "readiness: " + c.detail;
      }
    }
  }
  outcome.classes.clear();
  for (int c = 0; c < kFailureClassCount; ++c) {
    if (seen[static_cast<std::size_t>(c)]) outcome.classes.push_back(static_cast<FailureClass>(c));
  }
}

std::string trialDirectoryName(std::size_t index) { return "trial_" + std::to_string(index); }

TrialRunner::TrialRunner(const core::World& nominal, std::string world_file, const CampaignSettings& settings,
                         std::optional<core::Plan> nominal_plan)
    : nominal_(nominal),
      world_file_(std::move(world_file)),
      settings_(settings),
      nominal_plan_(std::move(nominal_plan)) {
  if (settings_.mode == StressMode::kReplay && !nominal_plan_) {
    throw std::logic_error("TrialRunner: replay mode needs the nominal plan");
  }
}

PerturbedWorld TrialRunner::perturb(std::size_t index, TrialOutcome& outcome) const {
  outcome.index = index;
  outcome.point = pointOf(settings_, index);
  outcome.seed = trialSeed(settings_.seed, index % static_cast<std::size_t>(settings_.trials));
  PerturbedWorld perturbed = perturbWorld(nominal_, settings_.sigmasAt(outcome.point), outcome.seed, world_file_);
  outcome.objects = perturbed.objects;
  return perturbed;
}

TrialRun TrialRunner::perturbedWorld(std::size_t index) const {
  TrialRun run;
  run.world_yaml = perturb(index, run.outcome).yaml;
  return run;
}

TrialRun TrialRunner::run(std::size_t index, double sample_rate) const {
  TrialRun run;
  std::optional<sim::MotionSampler> sampler;
  const auto simulate = [&](const core::World& world, const core::RobotSet& robots, const std::string& plan_file) {
    sim::RunOptions options;
    if (sample_rate > 0.0) {
      sampler.emplace(world, robots, sample_rate);
      options.on_step = [&](const sim::StepState& step) { sampler->onStep(step); };
    }
    run.report = sim::runPlan(world, robots, *run.plan, plan_file, options);
    if (sampler) run.motion = sampler->take();
  };
  TrialOutcome& outcome = run.outcome;
  PerturbedWorld perturbed = perturb(index, outcome);
  run.world_yaml = perturbed.yaml;
  const std::string plan_file = trialDirectoryName(index) + "/plan.json";

  if (settings_.mode == StressMode::kReplay) {
    const core::RobotSet robots(perturbed.world);
    run.plan = nominal_plan_;
    simulate(perturbed.world, robots, plan_file);
    classifyReport(*run.report, outcome);
    return run;
  }

  try {
    // an unreachable perturbed start is the planner's problem too: no plan for this trial
    const core::LoadedWorld loaded = core::validateWorld(std::move(perturbed.world));
    PlannerChoice choice = settings_.planner;
    choice.seed = outcome.seed;
    run.plan = planForRun(loaded, choice);
    core::validatePlanForWorld(*run.plan, *loaded.world, *loaded.robots, plan_file);
    simulate(*loaded.world, *loaded.robots, plan_file);
  } catch (const PlanningFailed& e) {
    const bool timeout = e.status == PlanningStatus::kTimeout;
    outcome.primary = timeout ? FailureClass::kPlannerTimeout : FailureClass::kPlannerFailure;
    outcome.failure = std::string("planner: ") + e.what();
  } catch (const core::WorldError& e) {  // unreachable start
    outcome.primary = FailureClass::kPlannerFailure;
    outcome.failure = std::string("planner: ") + e.what();
  } catch (const core::PlanError& e) {  // a plan the simulator cannot execute
    outcome.primary = FailureClass::kPlannerFailure;
    outcome.failure = std::string("planner: invalid plan: ") + e.what();
  }
  if (!run.report) {
    run.plan.reset();
    outcome.passed = false;
    outcome.classes = {*outcome.primary};
    return run;
  }
  classifyReport(*run.report, outcome);
  return run;
}

std::vector<TrialOutcome> runTrials(const TrialRunner& runner, const std::vector<std::size_t>& indices, int threads,
                                    ProgressBar* progress) {
  std::vector<TrialOutcome> outcomes(indices.size());
  parallelFor(indices.size(), threads, [&](std::size_t i) {
    outcomes[i] = runner.run(indices[i]).outcome;
    if (progress != nullptr) progress->advance(!outcomes[i].passed);
  });
  return outcomes;
}

}  // namespace dashbed::tools
