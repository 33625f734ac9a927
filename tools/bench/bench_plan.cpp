#include "tools/bench/bench_plan.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "core/number_text.h"
#include "core/world_io.h"
#include "core/world_loader.h"
#include "sim/run_plan.h"
#include "tools/bench/bench_plot.h"
#include "tools/parallel/parallel_trials.h"
#include "tools/planning/run_planner.h"
#include "tools/scenarios/scenarios.h"

namespace dashbed::tools {
namespace {

// The DaSH paper, Table I ("Detailed results for both two and four robot sorting scenarios"):
// averages over 10 seeds for MM-DaSH and Greedy(-MM-DaSH); both share the construction stage.
// Cost is in timesteps. Shelving appears in a figure only (no numbers); SMART rows are left out.
constexpr PaperRow kPaperTable[] = {
    {2, 2, "cross", "optimal", 11.39, 0.10, 993.40, 1.00},
    {2, 2, "cross", "greedy", 11.39, 0.04, 1000.80, 1.00},
    {2, 2, "random", "optimal", 12.01, 0.04, 641.20, 1.00},
    {2, 2, "random", "greedy", 12.01, 0.03, 664.40, 1.00},
    {2, 4, "cross", "optimal", 23.32, 0.65, 1845.60, 1.00},
    {2, 4, "cross", "greedy", 23.32, 0.23, 2035.10, 1.00},
    {2, 4, "random", "optimal", 24.82, 0.24, 1059.40, 1.00},
    {2, 4, "random", "greedy", 24.82, 0.13, 1199.80, 1.00},
    {2, 6, "cross", "optimal", 40.74, 207.75, 2399.20, 1.00},
    {2, 6, "cross", "greedy", 40.74, 0.21, 2752.80, 1.00},
    {2, 6, "random", "optimal", 44.90, 59.26, 1607.30, 1.00},
    {2, 6, "random", "greedy", 44.90, 0.18, 1969.70, 1.00},
    {2, 8, "cross", "greedy", 122.55, 2.73, 3758.30, 1.00},
    {2, 8, "random", "greedy", 74.24, 1.53, 2584.60, 1.00},
    {2, 10, "cross", "greedy", 89.92, 2.87, 4612.30, 1.00},
    {2, 10, "random", "greedy", 105.59, 0.94, 3092.10, 1.00},
    {2, 12, "cross", "greedy", 163.50, 15.16, 5802.80, 1.00},
    {2, 12, "random", "greedy", 170.32, 1.08, 3880.90, 1.00},
    {2, 16, "cross", "greedy", 450.36, 31.27, 7579.80, 1.00},
    {2, 16, "random", "greedy", 263.56, 6.31, 4884.40, 1.00},
    {2, 20, "cross", "greedy", 484.06, 1767.64, 9357.20, 1.00},
    {2, 20, "random", "greedy", 651.83, 63.50, 6467.50, 1.00},
    {4, 4, "cross", "optimal", 43.45, 4.29, 1946.50, 1.00},
    {4, 4, "cross", "greedy", 43.45, 0.39, 3277.20, 1.00},
    {4, 4, "random", "optimal", 36.15, 1.21, 1269.80, 1.00},
    {4, 4, "random", "greedy", 36.15, 0.14, 1650.90, 1.00},
    {4, 8, "cross", "greedy", 568.03, 52.73, 5899.60, 1.00},
    {4, 8, "random", "greedy", 611.60, 9.56, 2857.50, 1.00},
    {4, 12, "cross", "greedy", 1701.46, 571.01, 9430.40, 1.00},
    {4, 12, "random", "greedy", 1644.71, 153.60, 5383.10, 1.00},
    {4, 16, "cross", "greedy", 3691.00, 314.17, 12285.10, 1.00},
    {4, 16, "random", "greedy", 3799.55, 174.95, 7537.70, 1.00},
};

struct Suite {
  const char* name;
  const char* kind;  // BenchCase::suite
  int robots;
  std::vector<int> objects;  // the paper's counts
};

const std::vector<Suite>& suites() {
  static const std::vector<Suite> all = {
      {"sorting2", "sorting", 2, {2, 4, 6, 8, 10, 12, 16, 20}},
      {"sorting4", "sorting", 4, {4, 8, 12, 16}},
      {"shelf", "shelving", 2, {2, 4, 6}},
  };
  return all;
}

struct Stat {
  double mean = 0.0;
  double max = 0.0;
};

Stat stat(const std::vector<RunRecord>& runs, double RunRecord::*field) {
  Stat s;
  int n = 0;
  for (const RunRecord& r : runs) {
    if (r.outcome != RunOutcome::kSolved) continue;
    s.mean += r.*field;
    s.max = std::max(s.max, r.*field);
    ++n;
  }
  if (n > 0) s.mean /= n;
  return s;
}

struct RowStats {
  int runs = 0, solved = 0, at_budget = 0, simulated = 0, sim_passed = 0;
  Stat construction, search, planning, planning_cpu, makespan;
  std::string failure;  // what the failed runs of a row without solved runs ended with
};

RowStats rowStats(const BenchRow& row) {
  RowStats s;
  s.runs = static_cast<int>(row.runs.size());
  std::vector<RunOutcome> failed;
  for (const RunRecord& r : row.runs) {
    if (r.outcome == RunOutcome::kSolved)
      ++s.solved;
    else
      failed.push_back(r.outcome);
    s.at_budget += r.at_budget ? 1 : 0;
    if (r.sim_passed) {
      ++s.simulated;
      s.sim_passed += *r.sim_passed ? 1 : 0;
    }
  }
  s.construction = stat(row.runs, &RunRecord::construction_seconds);
  s.search = stat(row.runs, &RunRecord::search_seconds);
  s.planning = stat(row.runs, &RunRecord::planning_seconds);
  s.planning_cpu = stat(row.runs, &RunRecord::planning_cpu_seconds);
  s.makespan = stat(row.runs, &RunRecord::makespan);
  if (!failed.empty()) {
    const bool same = std::all_of(failed.begin(), failed.end(), [&](RunOutcome o) { return o == failed.front(); });
    s.failure = same ? toString(failed.front()) : "failed";
  }
  return s;
}

std::string seconds(double x) {
  if (x >= 100.0) return core::fixedText(x, 0);
  if (x >= 1.0) return core::fixedText(x, 2);
  return core::significantText(x, 2);
}

std::string meanMax(const Stat& s) { return seconds(s.mean) + " / " + seconds(s.max); }

std::string methodName(const std::string& method) { return method == "greedy" ? "Greedy" : "MM-DaSH"; }

std::string scenarioName(const BenchCase& c) {
  if (c.suite == "shelving") return "Shelving";
  std::string name = c.start;
  if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  return name;
}

std::optional<double> speedUp(const BenchRow& row, const RowStats& s) {
  const std::optional<PaperRow> paper = paperRow(row.scenario);
  if (!paper || s.solved == 0 || s.planning.mean <= 0.0) return std::nullopt;
  return (paper->construction + paper->search) / s.planning.mean;
}

std::string speedUpText(double x) { return core::fixedText(x, x >= 100.0 ? 0 : 1) + "x"; }

std::string rate(int part, int whole) { return core::fixedText(static_cast<double>(part) / whole, 2); }

// a CSV field: quoted when it holds a comma, quote or line break
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string csvNumber(double x) { return core::significantText(x, 6); }

std::string rowLabel(const BenchCase& c) {
  std::string label = std::to_string(c.robots) + " robots, " + std::to_string(c.objects) +
                      (c.suite == "shelving" ? " objects, shelving" : " cubes, " + c.start);
  return label + ", " + methodName(c.method);
}

// the first failed check of a simulated run
std::string firstFailure(const sim::Report& report) {
  for (const sim::ActionReport& action : report.actions) {
    if (action.verdict == sim::Verdict::kFailed) return action.id + ": " + action.failure;
  }
  if (report.execution_verdict == sim::Verdict::kFailed) return "execution: " + report.execution_failure;
  for (const core::ReadinessCheck& c : report.readiness) {
    if (!c.passed) return "readiness: " + c.detail;
  }
  return "";
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Simulation results of this benchmark by world and plan. The simulation is deterministic, so a
// plan whose trajectories, gripper commands and actions equal those of a plan already simulated
// for the same world (MM-DaSH's plan is Greedy's on most worlds) takes that result.
class SimulationMemo {
 public:
  struct Result {
    bool passed = false;
    std::string failure;
  };
  static std::string key(const BenchCase& c, std::uint64_t seed, core::Plan plan) {
    plan.statistics = nlohmann::json::object();  // how it was found, not what it does
    plan.seed = 0;
    return c.suite + " " + std::to_string(c.robots) + " " + std::to_string(c.objects) + " " + c.start + " " +
           std::to_string(seed) + "\n" + core::writePlanJson(plan);
  }
  std::optional<Result> find(const std::string& key) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = results_.find(key);
    return it == results_.end() ? std::nullopt : std::optional<Result>(it->second);
  }
  void store(const std::string& key, Result result) {
    const std::lock_guard<std::mutex> lock(mutex_);
    results_.emplace(key, std::move(result));
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::string, Result> results_;
};

SimulationMemo::Result simulate(const core::LoadedWorld& world, const core::Plan& plan) {
  try {
    core::validatePlanForWorld(plan, *world.world, *world.robots, "plan");
    const sim::Report report = sim::runPlan(*world.world, *world.robots, plan, "plan");
    return {report.passed(), report.passed() ? "" : firstFailure(report)};
  } catch (const std::exception& e) {
    return {false, e.what()};
  }
}

RunRecord runOnce(const BenchCase& c, std::uint64_t seed, const BenchOptions& options, SimulationMemo& memo) {
  RunRecord record;
  record.seed = seed;
  std::optional<core::LoadedWorld> world;
  try {
    const core::World generated = c.suite == "shelving"
                                      ? generateShelving({c.objects, seed})
                                      : generateSorting({c.robots, c.objects, 4, parseStartLayout(c.start), seed});
    // the loader derives fixture boxes, bin regions and shelf surfaces (tools/scenarios/scenarios.h)
    world = core::validateWorld(core::parseWorldYaml(core::writeWorldYaml(generated), generated.name));
  } catch (const std::exception& e) {
    record.outcome = RunOutcome::kGenerationFailed;
    record.reason = e.what();
    return record;
  }
  PlannerChoice choice;
  choice.method = c.method;
  choice.seed = seed;
  choice.time_budget = c.method == "greedy" ? options.greedy_budget : options.optimal_budget;
  choice.max_rounds = options.max_rounds;
  choice.fallback_rounds = options.fallback_rounds;
  planner::PlanResult result;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = threadCpuSeconds();
  try {
    result = planWorld(*world, choice);
  } catch (const std::exception& e) {
    record.outcome = RunOutcome::kError;
    record.reason = e.what();
    return record;
  }
  record.planning_cpu_seconds = threadCpuSeconds() - cpu_start;
  record.planning_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.construction_seconds = result.stats.construction_seconds;
  record.search_seconds = result.stats.search_seconds + result.stats.conflict_seconds;
  record.rounds = result.stats.rounds;
  switch (result.status) {
    case planner::PlannerStatus::kSolved:
      record.outcome = RunOutcome::kSolved;
      break;
    case planner::PlannerStatus::kInfeasible:
      record.outcome = RunOutcome::kInfeasible;
      break;
    case planner::PlannerStatus::kTimeout:
      record.outcome = RunOutcome::kTimeout;
      break;
  }
  record.reason = result.reason;
  if (record.outcome == RunOutcome::kSolved && !result.plan) {
    record.outcome = RunOutcome::kError;
    record.reason = "solved without a plan";
  }
  if (record.outcome != RunOutcome::kSolved) return record;
  record.makespan = result.stats.makespan;
  record.sequential = result.stats.sequential;
  record.at_budget = record.planning_seconds >= choice.time_budget;
  if (options.simulate) {
    const std::string key = SimulationMemo::key(c, seed, *result.plan);
    std::optional<SimulationMemo::Result> simulated = memo.find(key);
    record.sim_reused = simulated.has_value();
    if (!simulated) {
      simulated = simulate(*world, *result.plan);
      memo.store(key, *simulated);
    }
    record.sim_passed = simulated->passed;
    record.sim_failure = simulated->failure;
  }
  return record;
}

// throws std::invalid_argument naming the first value that is not allowed
template <typename T>
void require(const std::vector<T>& values, const std::vector<T>& allowed, const std::string& what) {
  for (const T& v : values) {
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
      std::ostringstream message;
      message << "unknown " << what << " '" << v << "'";
      throw std::invalid_argument(message.str());
    }
  }
}

bool contains(const std::vector<std::string>& values, const std::string& v) {
  return std::find(values.begin(), values.end(), v) != values.end();
}

}  // namespace

const char* toString(RunOutcome outcome) {
  switch (outcome) {
    case RunOutcome::kSolved:
      return "solved";
    case RunOutcome::kInfeasible:
      return "infeasible";
    case RunOutcome::kTimeout:
      return "timeout";
    case RunOutcome::kGenerationFailed:
      return "generation failed";
    case RunOutcome::kError:
      break;
  }
  return "error";
}

std::vector<BenchCase> benchCases(const BenchOptions& options) {
  require<std::string>(options.suites, {"sorting2", "sorting4", "shelf", "all"}, "suite");
  require<std::string>(options.starts, {"cross", "random"}, "start layout");
  require<std::string>(options.methods, {"greedy", "optimal"}, "method");
  if (options.seeds < 1) throw std::invalid_argument("--seeds must be at least 1");
  for (const int n : options.objects) {
    if (n < 1) throw std::invalid_argument("object counts must be positive");
  }
  std::vector<BenchCase> cases;
  for (const Suite& suite : suites()) {
    if (!contains(options.suites, suite.name) && !contains(options.suites, "all")) continue;
    std::vector<int> objects = options.objects.empty() ? suite.objects : options.objects;
    std::sort(objects.begin(), objects.end());
    objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
    const std::vector<std::string> starts =
        std::string(suite.kind) == "shelving" ? std::vector<std::string>{""} : options.starts;
    for (const int n : objects) {
      for (const std::string& start : starts) {
        for (const std::string& method : {std::string("optimal"), std::string("greedy")}) {  // the paper's order
          if (contains(options.methods, method)) cases.push_back({suite.kind, suite.robots, n, start, method});
        }
      }
    }
  }
  return cases;
}

std::vector<BenchRow> runBench(const BenchOptions& options, std::ostream& progress) {
  const std::vector<BenchCase> cases = benchCases(options);
  std::vector<BenchRow> rows;
  // scenario and method -> the object count at which no seed was solved
  std::map<std::tuple<std::string, int, std::string, std::string>, int> given_up;
  SimulationMemo memo;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const BenchCase& c = cases[i];
    BenchRow row{c, {}, ""};
    const auto key = std::tuple(c.suite, c.robots, c.start, c.method);
    progress << "[" << i + 1 << "/" << cases.size() << "] " << rowLabel(c) << ": " << std::flush;
    if (const auto it = given_up.find(key); it != given_up.end()) {
      row.not_run = "not run: no seed solved with " + std::to_string(it->second) + " objects";
      progress << row.not_run << "\n";
      rows.push_back(row);
      continue;
    }
    row.runs.resize(static_cast<std::size_t>(options.seeds));
    parallelFor(row.runs.size(), options.jobs, [&](std::size_t k) { row.runs[k] = runOnce(c, k + 1, options, memo); });
    const RowStats s = rowStats(row);
    progress << s.solved << "/" << s.runs << " solved";
    if (s.solved > 0) progress << ", planning " << seconds(s.planning.mean) << " s mean";
    if (s.simulated > 0) progress << ", sim " << s.sim_passed << "/" << s.simulated << " passed";
    if (s.solved == 0) {
      progress << " (" << s.failure << ")";
      given_up.emplace(key, c.objects);
    }
    progress << "\n";
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<PaperRow> paperRow(const BenchCase& scenario) {
  if (scenario.suite != "sorting") return std::nullopt;
  for (const PaperRow& p : kPaperTable) {
    if (p.robots == scenario.robots && p.objects == scenario.objects && scenario.start == p.start &&
        scenario.method == p.method) {
      return p;
    }
  }
  return std::nullopt;
}

std::string markdownTable(const std::vector<BenchRow>& rows) {
  std::ostringstream out;
  out << "| Robots | Objects | Scenario | Method | Construction [s] | Search [s] | Planning [s] | Planning CPU [s] | "
         "Makespan [s] | "
         "Success | Sim pass | Paper constr. + search [s] | Speed-up |\n";
  out << "|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const BenchRow& row : rows) {
    const BenchCase& c = row.scenario;
    const RowStats s = rowStats(row);
    const std::optional<PaperRow> paper = paperRow(c);
    out << "| " << c.robots << " | " << c.objects << " | " << scenarioName(c) << " | " << methodName(c.method) << " | ";
    if (!row.not_run.empty()) {
      out << "not run | not run | not run | not run | not run | - | - | ";
    } else if (s.solved == 0) {
      out << s.failure << " | " << s.failure << " | " << s.failure << " | " << s.failure << " | - | 0.00 | - | ";
    } else {
      out << meanMax(s.construction) << " | " << meanMax(s.search) << " | " << meanMax(s.planning) << " | "
          << meanMax(s.planning_cpu) << " | " << meanMax(s.makespan) << " | " << rate(s.solved, s.runs)
          << (s.at_budget > 0 ? " (" + std::to_string(s.at_budget) + " at budget)" : std::string()) << " | "
          << (s.simulated > 0 ? rate(s.sim_passed, s.simulated) + " (" + std::to_string(s.sim_passed) + "/" +
                                    std::to_string(s.simulated) + ")"
                              : std::string("off"))
          << " | ";
    }
    out << (paper ? seconds(paper->construction + paper->search) : std::string("-")) << " | ";
    const std::optional<double> factor = speedUp(row, s);
    out << (factor ? speedUpText(*factor) : std::string("-")) << " |\n";
  }
  return out.str();
}

std::string benchReport(const std::vector<BenchRow>& rows, const BenchOptions& options, bool with_title) {
  std::ostringstream out;
  if (with_title) out << "# Planner benchmark (`dashbed bench plan`)\n\n";
  const std::string sub = with_title ? "## " : "### ";
  out << "Seeds 1.." << options.seeds << " (world seed = planner seed), budget per run "
      << core::significantText(options.greedy_budget, 6) << " s for Greedy, "
      << core::significantText(options.optimal_budget, 6) << " s for MM-DaSH, at most " << options.max_rounds
      << " expansion rounds (a sequential plan waits " << options.fallback_rounds
      << (options.fallback_rounds == 1 ? " round" : " rounds") << " for a direct one), "
      << options.jobs << (options.jobs == 1 ? " run" : " runs") << " at a time on "
      << std::thread::hardware_concurrency() << " hardware threads, simulation " << (options.simulate ? "on" : "off")
      << ".\n\n";
  out << "Construction: task-space and motion hypergraph. Search: hyperpath queries and conflict resolution "
         "(the paper's \"Search\"). Planning: wall clock and CPU time of the whole (single-threaded) planner "
         "call; on a loaded machine the CPU time is what a free core would take. Times and makespan (plan "
         "duration) are mean / max over the solved runs; success = solved / runs (\"at budget\": solved runs "
         "that used the whole budget, i.e. MM-DaSH's best plan so far rather than the optimum of its "
         "representation); sim pass = plans passing "
         "every physical check / simulated plans (the simulation is deterministic: a plan equal to one simulated "
         "before for the same world, e.g. MM-DaSH's and Greedy's, is simulated once). Speed-up = the paper's construction + search over our mean "
         "wall-clock planning time.\n\n";
  out << markdownTable(rows) << "\n";

  out << sub << "Runs without a passing result\n\n";
  bool any = false;
  for (const BenchRow& row : rows) {
    if (!row.not_run.empty()) {
      out << "- " << rowLabel(row.scenario) << ": " << row.not_run << "\n";
      any = true;
    }
    for (const RunRecord& r : row.runs) {
      if (r.outcome != RunOutcome::kSolved) {
        out << "- " << rowLabel(row.scenario) << ", seed " << r.seed << ": " << toString(r.outcome)
            << (r.reason.empty() ? "" : " (" + r.reason + ")") << "\n";
        any = true;
      } else if (r.sim_passed && !*r.sim_passed) {
        out << "- " << rowLabel(row.scenario) << ", seed " << r.seed << ": solved, simulation failed (" << r.sim_failure
            << ")\n";
        any = true;
      }
    }
  }
  if (!any) out << "None.\n";

  out << "\n" << sub << "Comparison with the paper\n\n";
  out << "The paper's Table I gives averages over 10 seeds on an Intel i9-10900KF at 3.7 GHz, counting a run "
         "longer than 10^4 s as failed; its success rate is 1.00 in every MM-DaSH and Greedy row. Its cost is in "
         "timesteps of unstated length, ours is the makespan in seconds, so costs are not compared. It reports "
         "MM-DaSH only up to 6 cubes (2 robots) and 4 cubes (4 robots), and shelving only in a figure (no "
         "numbers).\n\n";
  int compared = 0, fast_wall = 0, fast_cpu = 0;
  std::ostringstream slow;
  for (const BenchRow& row : rows) {
    const RowStats s = rowStats(row);
    const std::optional<double> factor = speedUp(row, s);
    if (!factor) continue;
    const double paper = paperRow(row.scenario)->construction + paperRow(row.scenario)->search;
    const double cpu_factor = paper / s.planning_cpu.mean;
    ++compared;
    fast_wall += *factor >= 100.0 ? 1 : 0;
    fast_cpu += cpu_factor >= 100.0 ? 1 : 0;
    if (*factor < 100.0) {
      slow << "- " << rowLabel(row.scenario) << ": " << speedUpText(*factor) << " wall, " << speedUpText(cpu_factor)
           << " CPU (ours " << seconds(s.planning.mean) << " s wall, " << seconds(s.planning_cpu.mean)
           << " s CPU; paper " << seconds(paper) << " s)\n";
    }
  }
  out << "Rows compared (solved, with paper numbers): " << compared
      << "; at least 100x faster than the paper: " << fast_wall << " by wall-clock time, " << fast_cpu
      << " by CPU time.\n";
  if (!slow.str().empty()) out << "\nBelow the 100x target by wall-clock time:\n\n" << slow.str();
  return out.str();
}

std::string summaryCsv(const std::vector<BenchRow>& rows) {
  std::ostringstream out;
  out << "suite,robots,objects,start,method,runs,solved,success_rate,construction_mean_s,construction_max_s,"
         "search_mean_s,search_max_s,planning_mean_s,planning_max_s,planning_cpu_mean_s,planning_cpu_max_s,"
         "makespan_mean_s,makespan_max_s,at_budget,simulated,sim_passed,paper_construction_s,paper_search_s,paper_cost_"
         "timesteps,speedup,not_run\n";
  for (const BenchRow& row : rows) {
    const BenchCase& c = row.scenario;
    const RowStats s = rowStats(row);
    const std::optional<PaperRow> paper = paperRow(c);
    const std::optional<double> factor = speedUp(row, s);
    const auto stats = [&](const Stat& x) { return s.solved > 0 ? csvNumber(x.mean) + "," + csvNumber(x.max) : ","; };
    out << c.suite << "," << c.robots << "," << c.objects << "," << c.start << "," << c.method << "," << s.runs << ","
        << s.solved << "," << (s.runs > 0 ? csvNumber(static_cast<double>(s.solved) / s.runs) : "") << ","
        << stats(s.construction) << "," << stats(s.search) << "," << stats(s.planning) << "," << stats(s.planning_cpu)
        << "," << stats(s.makespan) << "," << s.at_budget << "," << s.simulated << "," << s.sim_passed << ","
        << (paper ? csvNumber(paper->construction) : "") << "," << (paper ? csvNumber(paper->search) : "") << ","
        << (paper ? csvNumber(paper->cost) : "") << "," << (factor ? csvNumber(*factor) : "") << ","
        << csvField(row.not_run) << "\n";
  }
  return out.str();
}

std::string runsCsv(const std::vector<BenchRow>& rows) {
  std::ostringstream out;
  out << "suite,robots,objects,start,method,seed,status,construction_s,search_s,planning_s,planning_cpu_s,makespan_s,"
         "rounds,sequential,at_budget,sim,sim_reused,reason\n";
  for (const BenchRow& row : rows) {
    const BenchCase& c = row.scenario;
    for (const RunRecord& r : row.runs) {
      const bool solved = r.outcome == RunOutcome::kSolved;
      out << c.suite << "," << c.robots << "," << c.objects << "," << c.start << "," << c.method << "," << r.seed << ","
          << toString(r.outcome) << "," << csvNumber(r.construction_seconds) << "," << csvNumber(r.search_seconds)
          << "," << csvNumber(r.planning_seconds) << "," << csvNumber(r.planning_cpu_seconds) << ","
          << (solved ? csvNumber(r.makespan) : "") << "," << r.rounds << "," << (solved ? (r.sequential ? "1" : "0") : "")
          << "," << (r.at_budget ? 1 : 0) << ","
          << (r.sim_passed ? (*r.sim_passed ? "passed" : "failed") : "") << "," << (r.sim_reused ? 1 : 0) << ","
          << csvField(solved ? r.sim_failure : r.reason) << "\n";
    }
  }
  return out.str();
}

render::Image benchPlot(const std::vector<BenchRow>& rows) {
  static const core::Color kPalette[] = {{0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17}, {0.84, 0.15, 0.16},
                                         {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50},
                                         {0.74, 0.74, 0.13}, {0.09, 0.75, 0.81}};
  LinePlot plot;
  plot.title = "Planning time against objects (mean over solved runs; dashed: the paper, Table I)";
  plot.x_label = "objects";
  plot.y_label = "planning time [s], log scale";
  plot.log_y = true;
  std::vector<PlotSeries> ours, paper;
  std::map<std::tuple<std::string, int, std::string, std::string>, std::size_t> index;  // scenario -> series
  for (const BenchRow& row : rows) {
    const BenchCase& c = row.scenario;
    const auto key = std::tuple(c.suite, c.robots, c.start, c.method);
    if (!index.contains(key)) {
      index.emplace(key, ours.size());
      const std::string label =
          (c.suite == "shelving" ? std::string("shelf") : std::to_string(c.robots) + "r " + c.start) + " " +
          methodName(c.method);
      const core::Color color = kPalette[ours.size() % std::size(kPalette)];
      ours.push_back({label, color, false, {}});
      paper.push_back({label + " paper", color, true, {}});
    }
    const std::size_t k = index.at(key);
    const RowStats s = rowStats(row);
    if (s.solved > 0) ours[k].points.emplace_back(c.objects, s.planning.mean);
    if (const std::optional<PaperRow> p = paperRow(c))
      paper[k].points.emplace_back(c.objects, p->construction + p->search);
  }
  plot.series = ours;
  for (const PlotSeries& s : paper) {
    if (!s.points.empty()) plot.series.push_back(s);
  }
  return drawLinePlot(plot);
}

void writeBenchOutputs(const std::vector<BenchRow>& rows, const BenchOptions& options) {
  const std::filesystem::path dir(options.out);
  std::filesystem::create_directories(dir);
  const auto write = [&](const char* name, const std::string& text) {
    std::ofstream file(dir / name, std::ios::binary);
    file << text;
    if (!file) throw std::runtime_error("cannot write " + (dir / name).string());
  };
  write("bench_plan.md", benchReport(rows, options));
  write("bench_plan.csv", summaryCsv(rows));
  write("bench_plan_runs.csv", runsCsv(rows));
  render::writePng(benchPlot(rows), dir / "bench_plan.png");
}

}  // namespace dashbed::tools
