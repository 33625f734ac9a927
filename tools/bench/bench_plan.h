#pragma once
// `dashbed bench plan`: the planner experiments of the DaSH paper (Sec. "Experimental
// Evaluation", Table I) on this testbed's generated worlds.
//
// What it measures: for every row (scenario, object count, start layout, method) the world
// generated with seed k and the planner with seed k, k = 1..N. Per run: the planner's stage
// times (construction; search = hyperpath queries + conflict resolution, as the paper's
// "Search" column), the wall-clock and CPU time of the whole planner call ("planning"; the
// planner is single-threaded, so on a loaded machine the CPU time is what a free core would
// take), the status, the plan's makespan [s], and with simulation on, whether the plan passes
// every physical check of the Bullet simulator (sim::runPlan). Per row: mean and max over the
// solved runs, success rate (solved / N; solved runs that used the whole budget count as "at
// budget": MM-DaSH then returns its best plan so far, not the optimum of its representation),
// sim pass rate (passing plans / simulated), the paper's numbers and the speed-up (paper
// construction + search over our mean wall-clock planning time).
//
// How: runs in row order; with jobs > 1 the seeds of a row run on that many threads (each
// planner call and simulation is independent; timings then include competition for cores).
// When no seed of a row is solved, the larger object counts of the same scenario and method
// are not run (marked "not run"). Outputs: bench_plan.md (table, failures, comparison note),
// bench_plan.csv (one line per row), bench_plan_runs.csv (one line per run), bench_plan.png
// (planning time against objects, ours and the paper's).

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "sim/render/image.h"
#include "tools/planning/run_planner.h"

namespace dashbed::tools {

/// One row: a scenario and a planning method.
struct BenchCase {
  std::string suite;  ///< "sorting" or "shelving"
  int robots = 2;
  int objects = 2;
  std::string start;   ///< sorting: "cross" or "random"; shelving: ""
  std::string method;  ///< "greedy" (Greedy-MM-DaSH) or "optimal" (MM-DaSH)
};

enum class RunOutcome { kSolved, kInfeasible, kTimeout, kGenerationFailed, kError };

/// "solved", "infeasible", "timeout", "generation failed", "error".
const char* toString(RunOutcome outcome);

/// One seed of a row.
struct RunRecord {
  std::uint64_t seed = 1;
  RunOutcome outcome = RunOutcome::kSolved;
  std::string reason;  ///< why not solved ("" when solved)
  double construction_seconds = 0.0;
  double search_seconds = 0.0;        ///< hyperpath queries + conflict resolution
  double planning_seconds = 0.0;      ///< wall clock of the whole planner call
  double planning_cpu_seconds = 0.0;  ///< CPU time of the thread that made the call
  double makespan = 0.0;              ///< [s] of the plan
  int rounds = 0;                     ///< representation rounds the planner call ran
  bool sequential = false;            ///< solved with a sequential plan (PlannerStats::sequential)
  bool at_budget = false;             ///< solved when the budget ran out: MM-DaSH's best plan so far (anytime)
  std::optional<bool> sim_passed;     ///< unset when not simulated
  std::string sim_failure;            ///< the first failed check ("" when passed)
  bool sim_reused = false;            ///< the result of an identical plan simulated before in this benchmark
};

struct BenchRow {
  BenchCase scenario;
  std::vector<RunRecord> runs;  ///< seed order; empty when not run
  std::string not_run;          ///< why the row was not run ("" when it was)
};

struct BenchOptions {
  std::vector<std::string> suites{"all"};  ///< sorting2, sorting4, shelf, all
  std::vector<int> objects;                ///< empty: the paper's counts for each suite
  std::vector<std::string> starts{"cross", "random"};
  int seeds = 10;
  std::vector<std::string> methods{"greedy", "optimal"};
  double greedy_budget = 120.0;  ///< wall-clock budget per greedy run [s] (dashbed plan's default)
  double optimal_budget = 120.0;  ///< per MM-DaSH run [s] (as Greedy's: MM-DaSH starts from Greedy's plan)
  int max_rounds = 30;
  int fallback_rounds = PlannerChoice{}.fallback_rounds;
  bool simulate = true;
  int jobs = 1;
  std::string out = "bench_plan";
};

/// The rows of the options in the paper's order (robots, objects, start, method). Throws
/// std::invalid_argument for an unknown suite, start or method, or non-positive counts.
std::vector<BenchCase> benchCases(const BenchOptions& options);

/// Runs every row (see the header comment), printing one progress line per row.
std::vector<BenchRow> runBench(const BenchOptions& options, std::ostream& progress);

/// The paper's Table I entry for a row's scenario and method, if it reports one.
struct PaperRow {
  int robots;
  int objects;
  const char* start;
  const char* method;
  double construction;  ///< average [s]
  double search;        ///< average [s]
  double cost;          ///< average [timesteps]
  double success;
};
std::optional<PaperRow> paperRow(const BenchCase& scenario);

/// The results table in Markdown: a header and one line per row.
std::string markdownTable(const std::vector<BenchRow>& rows);
/// bench_plan.md: settings, the table, the failed runs, and the comparison with the paper;
/// without the title, its sections one level down (for docs/benchmarks.md).
std::string benchReport(const std::vector<BenchRow>& rows, const BenchOptions& options, bool with_title = true);
/// One CSV line per row (numbers without units, empty where undefined), with a header.
std::string summaryCsv(const std::vector<BenchRow>& rows);
/// One CSV line per run, with a header.
std::string runsCsv(const std::vector<BenchRow>& rows);
/// Mean planning time of the solved runs against objects, one line per scenario and method,
/// the paper's construction + search dashed; log-scale y.
render::Image benchPlot(const std::vector<BenchRow>& rows);

/// Writes the four outputs into options.out (created if missing).
void writeBenchOutputs(const std::vector<BenchRow>& rows, const BenchOptions& options);

}  // namespace dashbed::tools
