// Stress campaigns: seeded perturbation sampling, sigma = 0 against the nominal run, a grasp at
// the edge of the cube against a centred one, thread-count independence, replay of saved
// trials, Wilson intervals, the failure taxonomy and the result files.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/asset_paths.h"
#include "core/plan.h"
#include "core/robot_set.h"
#include "core/input_text.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tests/sim/sim_test_worlds.h"
#include "tools/script/scripted_plan.h"
#include "tools/stress/stress.h"
#include "tools/stress/stress_output.h"
#include "tools/stress/stress_plot.h"
#include "tools/stress/stress_summary.h"

namespace dashbed::tools {
namespace {

// r1 takes cube_0 of the default world to the green bin: about 11 s of simulated time
constexpr const char* kCentredScript = "r1 picks cube_0; r1 places cube_0 in bin_green";
// the same with the pads 5 mm off the cube's centre across their width: the nominal run
// passes (tests/sim shows 6 mm fails), a millimetre more the wrong way fails the grasp
constexpr const char* kFragileScript = "r1 picks cube_0 offset 0 0.005 0; r1 places cube_0 in bin_green";

// the scripts move cube_0 only: the goals of the others are left out
const core::LoadedWorld& defaultWorld() { return test::defaultWorldWithoutGoals(); }

CampaignSettings replaySettings(int trials, double sigma_xy) {
  CampaignSettings settings;
  settings.trials = trials;
  settings.seed = 7;
  settings.sigmas.xy = sigma_xy;
  settings.sigmas.yaw = 0.02;
  return settings;
}

TrialRunner replayRunner(const std::string& script, const CampaignSettings& settings) {
  return TrialRunner(*defaultWorld().world, "default.yaml", settings, planFromScript(defaultWorld(), script));
}

std::vector<std::size_t> firstTrials(std::size_t count) {
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < count; ++i) indices.push_back(i);
  return indices;
}

int passedCount(const std::vector<TrialOutcome>& outcomes) {
  int passed = 0;
  for (const TrialOutcome& o : outcomes) passed += o.passed ? 1 : 0;
  return passed;
}

std::filesystem::path scratchDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("dashbed_test_stress_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

TEST_CASE("trial seeds differ between trials and campaigns", "[stress]") {
  CHECK(trialSeed(1, 0) != trialSeed(1, 1));
  CHECK(trialSeed(1, 0) != trialSeed(2, 0));
  CHECK(trialSeed(1, 1) != trialSeed(2, 0));
}

TEST_CASE("standard normal draws have mean 0 and variance 1", "[stress]") {
  ScenarioRng rng(3);
  const int n = 20000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = standardNormal(rng);
    sum += x;
    sum_sq += x * x;
  }
  // standard errors: 1/sqrt(n) = 0.007 for the mean, sqrt(2/n) = 0.01 for the variance
  CHECK(std::abs(sum / n) < 0.03);
  CHECK(std::abs(sum_sq / n - 1.0) < 0.04);
}

TEST_CASE("perturbation sampling is seeded and reproducible", "[stress]") {
  const core::World& nominal = *defaultWorld().world;
  PerturbationSigmas sigmas;
  sigmas.xy = 0.003;
  sigmas.yaw = 0.05;
  sigmas.mass = 0.1;
  sigmas.friction = 0.2;
  const PerturbedWorld a = perturbWorld(nominal, sigmas, 11, "default.yaml");
  const PerturbedWorld b = perturbWorld(nominal, sigmas, 11, "default.yaml");
  const PerturbedWorld c = perturbWorld(nominal, sigmas, 12, "default.yaml");
  CHECK(a.yaml == b.yaml);
  CHECK(a.objects == b.objects);
  CHECK(a.yaml != c.yaml);
  REQUIRE(a.objects.size() == nominal.objects.size());
  for (std::size_t k = 0; k < nominal.objects.size(); ++k) {
    // the world (as read back from its file) carries exactly the recorded perturbation
    const ObjectPerturbation& p = a.objects[k];
    const Eigen::Vector3d shift = a.world.objects[k].X_WO.translation() - nominal.objects[k].X_WO.translation();
    CHECK(shift.x() == Approx(p.dx).margin(1e-12));
    CHECK(shift.y() == Approx(p.dy).margin(1e-12));
    CHECK(shift.z() == Approx(0.0).margin(1e-12));
    const Eigen::Matrix3d turn = nominal.objects[k].X_WO.linear().transpose() * a.world.objects[k].X_WO.linear();
    CHECK(std::atan2(turn(1, 0), turn(0, 0)) == Approx(p.dyaw).margin(1e-12));
    CHECK(a.world.objects[k].mass == Approx(nominal.objects[k].mass * p.mass_scale));
    CHECK(a.world.objects[k].friction == Approx(nominal.objects[k].friction * p.friction_scale));
    CHECK(p.mass_scale != 1.0);
  }
}

TEST_CASE("a trial's world depends only on the campaign seed, its sweep point and its index", "[stress]") {
  CampaignSettings settings = replaySettings(3, 0.0);
  settings.sweep_xy = {0.001, 0.002};
  const TrialRunner runner = replayRunner(kCentredScript, settings);
  PerturbationSigmas sigmas = settings.sigmas;
  sigmas.xy = 0.002;
  const TrialRun trial = runner.perturbedWorld(4);  // point 1, its trial 1
  CHECK(trial.outcome.index == 4);
  CHECK(trial.outcome.point == 1);
  CHECK(trial.outcome.seed == trialSeed(7, 1));
  CHECK(trial.world_yaml == perturbWorld(*defaultWorld().world, sigmas, trialSeed(7, 1), "default.yaml").yaml);
  CHECK_FALSE(trial.plan);
  // the same draws at the first point, half the size
  const TrialRun same_draws = runner.perturbedWorld(1);
  REQUIRE(same_draws.outcome.objects.size() == trial.outcome.objects.size());
  CHECK(same_draws.outcome.objects[0].dx == Approx(0.5 * trial.outcome.objects[0].dx));
}

TEST_CASE("sigmas too large for the world are a clear error", "[stress]") {
  PerturbationSigmas sigmas;
  sigmas.xy = 100.0;  // every draw lands far off the table
  CHECK_THROWS_WITH(perturbWorld(*defaultWorld().world, sigmas, 1, "default.yaml"),
                    Catch::Contains("cube_0") && Catch::Contains("sigmas are too large"));
}

TEST_CASE("sigma zero reproduces the nominal run exactly", "[stress][sim]") {
  CampaignSettings settings = replaySettings(1, 0.0);
  settings.sigmas.yaw = 0.0;
  const core::Plan plan = planFromScript(defaultWorld(), kCentredScript);
  const TrialRunner runner(*defaultWorld().world, "default.yaml", settings, plan);
  const TrialRun trial = runner.run(0);
  REQUIRE(trial.report);
  const sim::Report nominal =
      sim::runPlan(*defaultWorld().world, *defaultWorld().robots, plan, trialDirectoryName(0) + "/plan.json");
  CHECK(sim::writeReportJson(*trial.report) == sim::writeReportJson(nominal));
  CHECK(trial.outcome.passed);
  CHECK(trial.outcome.classes.empty());
}

TEST_CASE("a grasp at the edge of the cube succeeds less often than a centred one", "[stress][sim]") {
  const CampaignSettings settings = replaySettings(4, 0.002);
  const std::vector<TrialOutcome> centred = runTrials(replayRunner(kCentredScript, settings), firstTrials(4), 2);
  const std::vector<TrialOutcome> fragile = runTrials(replayRunner(kFragileScript, settings), firstTrials(4), 2);
  CHECK(passedCount(fragile) < passedCount(centred));
  CHECK(passedCount(centred) >= 3);
  // the edge grasp fails as a grasp: missed or slipping
  for (const TrialOutcome& o : fragile) {
    if (o.passed) continue;
    REQUIRE(o.primary);
    CHECK((*o.primary == FailureClass::kMissedGrasp || *o.primary == FailureClass::kSlip));
    CHECK(o.failure.rfind("pick cube_0 by r1", 0) == 0);
  }
}

TEST_CASE("outcomes are the same with 1 and 2 threads", "[stress][sim]") {
  const CampaignSettings settings = replaySettings(3, 0.002);
  const TrialRunner runner = replayRunner(kFragileScript, settings);
  const std::vector<TrialOutcome> one = runTrials(runner, firstTrials(3), 1);
  const std::vector<TrialOutcome> two = runTrials(runner, firstTrials(3), 2);
  CHECK(one == two);
  CHECK(writeOutcomesJson(one) == writeOutcomesJson(two));
}

TEST_CASE("a saved trial replays to the same report", "[stress][sim]") {
  const CampaignSettings settings = replaySettings(4, 0.002);
  const TrialRunner runner = replayRunner(kFragileScript, settings);
  TrialOutcome failed;
  for (std::size_t i = 0; i < 4 && failed.actions.empty(); ++i) {
    const TrialOutcome outcome = runner.run(i).outcome;
    if (!outcome.passed) failed = outcome;
  }
  REQUIRE_FALSE(failed.actions.empty());
  const std::filesystem::path out = scratchDirectory("replay");
  prepareOutputDirectory(out);
  saveTrials(out, runner, {failed}, 1);

  // what `dashbed sim OUT/trial_N/plan.json --world OUT/trial_N/world.yaml` does
  const std::filesystem::path dir = out / trialDirectoryName(failed.index);
  const core::LoadedWorld world = core::loadWorld(dir / "world.yaml");
  const core::Plan plan = core::loadPlanFile(dir / "plan.json");
  const sim::Report replay =
      sim::runPlan(*world.world, *world.robots, plan, trialDirectoryName(failed.index) + "/plan.json");
  CHECK(sim::writeReportJson(replay) == core::readTextFile<core::InputError>(dir / "report.json", "report"));
  CHECK(readOutcomesJson(core::readTextFile<core::InputError>(dir / "trial.json", "trial")) ==
        std::vector<TrialOutcome>{failed});
  std::filesystem::remove_all(out);
}

TEST_CASE("Wilson intervals match known values", "[stress]") {
  const RateInterval half = wilsonInterval(5, 10);
  CHECK(half.rate == 0.5);
  CHECK(half.lower == Approx(0.236593).epsilon(1e-5));
  CHECK(half.upper == Approx(0.763407).epsilon(1e-5));
  const RateInterval some = wilsonInterval(81, 263);
  CHECK(some.lower == Approx(0.255289).epsilon(1e-5));
  CHECK(some.upper == Approx(0.366210).epsilon(1e-5));
  const RateInterval none = wilsonInterval(0, 10);
  CHECK(none.lower == 0.0);
  CHECK(none.upper == Approx(0.277533).epsilon(1e-5));
  const RateInterval all = wilsonInterval(10, 10);
  CHECK(all.lower == Approx(0.722467).epsilon(1e-5));
  CHECK(all.upper == 1.0);
  const RateInterval empty = wilsonInterval(0, 0);
  CHECK(empty.lower == 0.0);
  CHECK(empty.upper == 1.0);
}

sim::ActionReport failedAction(core::ActionType type, const std::string& id, const std::string& measurement) {
  sim::ActionReport action;
  action.type = type;
  action.id = id;
  action.verdict = sim::Verdict::kFailed;
  action.failure = measurement + " failed";
  sim::Measurement m;
  m.name = measurement;
  m.passed = false;
  action.measurements.push_back(m);
  return action;
}

sim::ExecutionEvent event(const std::string& kind, const std::string& action) {
  sim::ExecutionEvent e;
  e.kind = kind;
  e.action = action;
  return e;
}

TEST_CASE("failed actions are classified by the check that failed", "[stress]") {
  using core::ActionType;
  const std::vector<sim::ExecutionEvent> events{event("drop", "handoff cube_1 from r0 to r1"),
                                                event("drop", "place cube_2 in bin by r1"),
                                                event("knocked object", "pick cube_3 by r0")};
  CHECK(classifyAction(failedAction(ActionType::kPick, "pick cube_0 by r0", "both_pads_contact"), events) ==
        FailureClass::kMissedGrasp);
  CHECK(classifyAction(failedAction(ActionType::kPick, "pick cube_0 by r0", "slip_angle"), events) ==
        FailureClass::kSlip);
  CHECK(classifyAction(failedAction(ActionType::kHandoff, "handoff cube_1 from r0 to r1", "overlap"), events) ==
        FailureClass::kHandoffDrop);
  CHECK(classifyAction(failedAction(ActionType::kPlace, "place cube_2 in bin by r1", "tilt"), events) ==
        FailureClass::kSlip);
  CHECK(classifyAction(failedAction(ActionType::kPlace, "place cube_4 in bin by r1", "tilt"), events) ==
        FailureClass::kMisplaced);
  sim::ActionReport knocked = failedAction(ActionType::kPick, "pick cube_3 by r0", "lift_height");
  knocked.measurements.front().passed = true;  // its own checks passed; it knocked cube_x
  CHECK(classifyAction(knocked, events) == FailureClass::kCollision);
}

TEST_CASE("a report gives the primary class and every class of a trial", "[stress]") {
  sim::Report report;
  sim::ActionReport pick;
  pick.type = core::ActionType::kPick;
  pick.id = "pick cube_0 by r0";
  pick.measurements = {{"lift_height", 0.03, "m", 0.005, ">=", true},
                       {"slip", std::nan(""), "m", 0.005, "<=", true}};  // not finite: not recorded
  report.actions.push_back(pick);
  report.actions.push_back(failedAction(core::ActionType::kHandoff, "handoff cube_0 from r0 to r1", "overlap"));
  report.actions.push_back(failedAction(core::ActionType::kPlace, "place cube_0 in bin by r1", "tilt"));
  report.events.push_back(event("robot-fixture contact", ""));
  report.execution_verdict = sim::Verdict::kFailed;
  report.events.push_back(event("protective stop", ""));
  TrialOutcome outcome;
  classifyReport(report, outcome);
  CHECK_FALSE(outcome.passed);
  REQUIRE(outcome.primary);
  CHECK(*outcome.primary == FailureClass::kHandoffDrop);
  CHECK(outcome.classes == std::vector<FailureClass>{FailureClass::kHandoffDrop, FailureClass::kMisplaced,
                                                     FailureClass::kCollision, FailureClass::kProtectiveStop});
  CHECK(outcome.failedActions() == 2);
  REQUIRE(outcome.actions.size() == 3);
  CHECK(outcome.actions[0].measurements == std::vector<MeasuredValue>{{"lift_height", 0.03}});
  CHECK(outcome.actions[1].measurements == std::vector<MeasuredValue>{{"overlap", 0.0}});
  CHECK(outcome.failure.rfind("handoff cube_0 from r0 to r1: ", 0) == 0);
}

std::vector<TrialOutcome> madeUpOutcomes() {
  std::vector<TrialOutcome> outcomes;
  for (std::size_t i = 0; i < 10; ++i) {
    TrialOutcome o;
    o.index = i;
    o.seed = trialSeed(1, i);
    o.passed = i % 5 != 0;  // trials 0 and 5 fail
    const double lift = 0.1 / (1.0 + static_cast<double>(i));
    o.actions = {{core::ActionType::kPick, "pick cube_0 by r1", i != 0, {{"lift_height", lift}, {"slip", 3e-4}}},
                 {core::ActionType::kPlace, "place cube_0 in bin_green by r1", o.passed, {}}};
    if (!o.passed) {
      o.primary = i == 0 ? FailureClass::kMissedGrasp : FailureClass::kMisplaced;
      o.classes = {FailureClass::kMisplaced};
      if (i == 0) o.classes.insert(o.classes.begin(), FailureClass::kMissedGrasp);
      o.failure = "made up";
    }
    o.objects = {{0.001 * static_cast<double>(i), -0.002, 0.01, 1.0, 1.0}};
    outcomes.push_back(o);
  }
  return outcomes;
}

TEST_CASE("outcomes round-trip through their JSON text", "[stress]") {
  const std::vector<TrialOutcome> outcomes = madeUpOutcomes();
  CHECK(readOutcomesJson(writeOutcomesJson(outcomes)) == outcomes);
  CHECK_THROWS_WITH(readOutcomesJson("[{\"index\": 1}]"), "trial outcomes: /0/point: missing");
  CHECK_THROWS_WITH(readOutcomesJson("{}"), "trial outcomes: /: expected an array, got an object");
  // found by fuzzing: an unknown action type escaped as an exception of another kind
  nlohmann::json bad = nlohmann::json::parse(writeOutcomesJson(madeUpOutcomes()));
  bad[0]["actions"][0]["type"] = "pick8";
  CHECK_THROWS_WITH(readOutcomesJson(bad.dump()), "trial outcomes: /0/actions/0/type: unknown action type 'pick8'");
  // found by fuzzing: the parser's "last read" cut a two-byte character in half; the message
  // shows the half byte escaped
  CHECK_THROWS_WITH(readOutcomesJson("[{\"index\": 0.5\n \xD8\x82}]"),
                    "trial outcomes: /: invalid JSON: parse error at line 2, column 2: syntax error while parsing "
                    "object - invalid literal; last read: '0.5<U+000A> \\xD8'; expected '}' (byte 17)");
}

TEST_CASE("campaign summary counts rates, classes and the worst trials", "[stress]") {
  CampaignSettings settings = replaySettings(10, 0.002);
  const std::vector<TrialOutcome> outcomes = madeUpOutcomes();
  const std::vector<PointSummary> points = summarize(settings, outcomes);
  REQUIRE(points.size() == 1);
  CHECK(points[0].trials.successes == 8);
  CHECK(points[0].trials.trials == 10);
  CHECK(points[0].per_type.at(core::ActionType::kPick).successes == 9);
  CHECK(points[0].per_type.at(core::ActionType::kPlace).successes == 8);
  CHECK(points[0].primary[static_cast<std::size_t>(FailureClass::kMissedGrasp)] == 1);
  CHECK(points[0].primary[static_cast<std::size_t>(FailureClass::kMisplaced)] == 1);
  CHECK(points[0].any[static_cast<std::size_t>(FailureClass::kMisplaced)] == 2);
  CHECK(worstTrials(outcomes, 5) == std::vector<std::size_t>{0, 5});  // 2 failed actions before 1
  CHECK(worstTrials(outcomes, 1) == std::vector<std::size_t>{0});

  CampaignInfo info{"w", "w.yaml", "p.json", settings, 0.9};
  const std::string junit = writeStressJUnit(info, points);
  CHECK(junit.find("<failure message=\"success rate 80.0 % &lt; 90.0 % required\"") != std::string::npos);
  const std::string json = writeSummaryJson(info, points, {outcomes[0]});
  CHECK(json.find("\"verdict\": \"failed\"") != std::string::npos);
  CHECK(json.find("\"directory\": \"trial_0\"") != std::string::npos);
  info.min_success = 0.8;
  CHECK(writeStressJUnit(info, points).find("<failure") == std::string::npos);
  const std::string csv = writeTrialsCsv(*defaultWorld().world, settings, {outcomes[0]});
  CHECK(csv.rfind("index,point,sigma_xy,seed,passed,primary,classes,failed_actions,actions,cube_0.dx,", 0) == 0);
  const std::string line = "\n0,0,0.002," + std::to_string(trialSeed(1, 0)) +
                           ",0,missed_grasp,missed_grasp+misplaced,2,2,0,-0.002,0.01,1,1\n";
  CHECK(csv.find(line) != std::string::npos);
}

TEST_CASE("a sweep gives one point per sigma and a plot", "[stress]") {
  CampaignSettings settings = replaySettings(2, 0.0);
  settings.sweep_xy = {0.0, 0.004};
  std::vector<TrialOutcome> outcomes = madeUpOutcomes();
  outcomes.resize(4);
  for (TrialOutcome& o : outcomes) o.point = pointOf(settings, o.index);
  const std::vector<PointSummary> points = summarize(settings, outcomes);
  REQUIRE(points.size() == 2);
  CHECK(points[0].sigma_xy == 0.0);
  CHECK(points[0].trials.successes == 1);
  CHECK(points[1].sigma_xy == 0.004);
  CHECK(points[1].trials.successes == 2);
  const render::Image plot = sweepPlot(points, "test");
  CHECK(plot.width == 800);
  CHECK(plot.height == 500);
  CHECK(plot == sweepPlot(points, "test"));
  settings.sweep_xy = {0.004, 0.002};
  CHECK_THROWS_WITH(settings.check(), Catch::Contains("--sweep values must increase"));
}

}  // namespace
}  // namespace dashbed::tools
