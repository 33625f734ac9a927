// The planner benchmark's writers on a small made-up result set: table columns and rows, CSV
// that reads back, the paper lookup, the row list of the options; and one real row of both
// methods, whose equal plans are simulated once.

#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/bench/bench_plan.h"
#include "tools/bench/bench_plot.h"

namespace dashbed::tools {
namespace {

RunRecord solved(std::uint64_t seed, double planning, bool sim_passed) {
  RunRecord r;
  r.seed = seed;
  r.construction_seconds = 0.5 * planning;
  r.search_seconds = 0.25 * planning;
  r.planning_seconds = planning;
  r.planning_cpu_seconds = 0.5 * planning;
  r.makespan = 40.0 + static_cast<double>(seed);
  r.rounds = static_cast<int>(seed) + 1;
  r.sequential = seed == 2;
  r.sim_passed = sim_passed;
  if (!sim_passed) r.sim_failure = "place cube_1 by r0: tilt 0.3 rad > 0.1 rad";
  return r;
}

RunRecord atBudget(RunRecord r) {
  r.at_budget = true;
  return r;
}

RunRecord failed(std::uint64_t seed, RunOutcome outcome, const std::string& reason) {
  RunRecord r;
  r.seed = seed;
  r.outcome = outcome;
  r.reason = reason;
  r.planning_seconds = 30.0;
  return r;
}

std::vector<BenchRow> fakeRows() {
  return {
      {{"sorting", 2, 4, "cross", "greedy"}, {solved(1, 0.2, true), solved(2, 0.6, false)}, ""},
      {{"sorting", 2, 6, "random", "optimal"},
       {failed(1, RunOutcome::kTimeout, "time budget, round 3"),
        failed(2, RunOutcome::kTimeout, "time budget, round 2")},
       ""},
      {{"sorting", 2, 8, "random", "optimal"}, {}, "not run: no seed solved with 6 objects"},
      {{"shelving", 2, 2, "", "optimal"},
       {atBudget(solved(1, 30.5, true)), failed(2, RunOutcome::kInfeasible, "no grasp of \"b0\"")},
       ""},
  };
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// cells of a Markdown table line "| a | b |"
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = line.find('|') + 1;
  for (std::size_t bar = line.find('|', start); bar != std::string::npos; bar = line.find('|', start)) {
    std::string cell = line.substr(start, bar - start);
    cell.erase(0, cell.find_first_not_of(' '));
    cell.erase(cell.find_last_not_of(' ') + 1);
    out.push_back(cell);
    start = bar + 1;
  }
  return out;
}

// RFC 4180 fields of one CSV line
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      out.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

TEST_CASE("bench plan Markdown table has the paper's columns and one line per row", "[bench_plan]") {
  const std::vector<std::string> table = lines(markdownTable(fakeRows()));
  REQUIRE(table.size() == 2 + 4);
  const std::vector<std::string> header = cells(table[0]);
  CHECK(header == std::vector<std::string>{"Robots", "Objects", "Scenario", "Method", "Construction [s]", "Search [s]",
                                           "Planning [s]", "Planning CPU [s]", "Makespan [s]", "Success", "Sim pass",
                                           "Paper constr. + search [s]", "Speed-up"});
  for (std::size_t i = 1; i < table.size(); ++i) CHECK(cells(table[i]).size() == header.size());

  const std::vector<std::string> greedy = cells(table[2]);
  CHECK(greedy[2] == "Cross");
  CHECK(greedy[3] == "Greedy");
  CHECK(greedy[4] == "0.2 / 0.3");      // construction mean / max
  CHECK(greedy[6] == "0.4 / 0.6");      // planning, wall clock
  CHECK(greedy[7] == "0.2 / 0.3");      // planning, CPU
  CHECK(greedy[8] == "41.50 / 42.00");  // makespan
  CHECK(greedy[9] == "1.00");
  CHECK(greedy[10] == "0.50 (1/2)");
  CHECK(greedy[11] == "23.55");  // paper: 23.32 + 0.23
  CHECK(greedy[12] == "58.9x");  // 23.55 / 0.4

  const std::vector<std::string> timeout = cells(table[3]);
  CHECK(timeout[3] == "MM-DaSH");
  CHECK(timeout[4] == "timeout");
  CHECK(timeout[9] == "0.00");
  CHECK(timeout[12] == "-");
  CHECK(cells(table[4])[4] == "not run");
  CHECK(cells(table[5])[2] == "Shelving");
  CHECK(cells(table[5])[9] == "0.50 (1 at budget)");
}

TEST_CASE("bench plan CSV files read back with one line per row and per run", "[bench_plan]") {
  const std::vector<BenchRow> rows = fakeRows();
  const std::vector<std::string> summary = lines(summaryCsv(rows));
  REQUIRE(summary.size() == 1 + rows.size());
  const std::vector<std::string> columns = csvFields(summary[0]);
  for (const std::string& line : summary) CHECK(csvFields(line).size() == columns.size());
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  REQUIRE(column("not_run") < columns.size());
  const std::vector<std::string> first = csvFields(summary[1]);
  CHECK(first[column("method")] == "greedy");
  CHECK(std::stod(first[column("success_rate")]) == 1.0);
  CHECK(std::stod(first[column("planning_mean_s")]) == Approx(0.4));
  CHECK(std::stod(first[column("paper_search_s")]) == Approx(0.23));
  CHECK(first[column("sim_passed")] == "1");
  CHECK(csvFields(summary[2])[column("planning_mean_s")].empty());
  CHECK(csvFields(summary[3])[column("not_run")] == "not run: no seed solved with 6 objects");
  CHECK(csvFields(summary[4])[column("at_budget")] == "1");

  const std::vector<std::string> runs = lines(runsCsv(rows));
  REQUIRE(runs.size() == 1 + 6);
  const std::vector<std::string> run_columns = csvFields(runs[0]);
  for (const std::string& line : runs) CHECK(csvFields(line).size() == run_columns.size());
  CHECK(csvFields(runs[3])[6] == "timeout");
  const auto rounds = static_cast<std::size_t>(std::find(run_columns.begin(), run_columns.end(), "rounds") -
                                               run_columns.begin());
  REQUIRE(rounds < run_columns.size());
  CHECK(csvFields(runs[2])[rounds] == std::to_string(rows[0].runs[1].rounds));
  const auto sequential = static_cast<std::size_t>(
      std::find(run_columns.begin(), run_columns.end(), "sequential") - run_columns.begin());
  REQUIRE(sequential < run_columns.size());
  CHECK(csvFields(runs[1])[sequential] == "0");
  CHECK(csvFields(runs[2])[sequential] == "1");
  CHECK(csvFields(runs[3])[sequential].empty());  // not solved
  CHECK(csvFields(runs[3]).back() == "time budget, round 3");  // quoted: holds a comma
  CHECK(csvFields(runs[6]).back() == "no grasp of \"b0\"");
  CHECK(csvFields(runs[2]).back() == "place cube_1 by r0: tilt 0.3 rad > 0.1 rad");
}

TEST_CASE("bench plan rows follow the paper's order and its table", "[bench_plan]") {
  BenchOptions options;
  options.suites = {"sorting4", "shelf"};
  const std::vector<BenchCase> cases = benchCases(options);
  REQUIRE(cases.size() == 4 * 2 * 2 + 3 * 2);
  CHECK(cases.front().robots == 4);
  CHECK(cases.front().objects == 4);
  CHECK(cases.front().start == "cross");
  CHECK(cases.front().method == "optimal");
  CHECK(cases.back().suite == "shelving");
  CHECK(cases.back().objects == 6);

  const std::optional<PaperRow> paper = paperRow({"sorting", 4, 16, "cross", "greedy"});
  REQUIRE(paper);
  CHECK(paper->construction == 3691.00);
  CHECK(paper->search == 314.17);
  CHECK_FALSE(paperRow({"sorting", 2, 8, "cross", "optimal"}));
  CHECK_FALSE(paperRow({"shelving", 2, 2, "", "greedy"}));

  options.methods = {"astar"};
  CHECK_THROWS_AS(benchCases(options), std::invalid_argument);
}

TEST_CASE("bench plan simulates a plan once when both methods find it", "[bench_plan][long]") {
  BenchOptions options;
  options.suites = {"sorting2"};
  options.objects = {2};
  options.starts = {"random"};
  options.seeds = 2;
  std::ostringstream progress;
  const std::vector<BenchRow> rows = runBench(options, progress);
  REQUIRE(rows.size() == 2);
  REQUIRE(rows[0].scenario.method == "optimal");  // the paper's order: MM-DaSH first
  for (const BenchRow& row : rows) {
    REQUIRE(row.runs.size() == 2);
    for (const RunRecord& r : row.runs) {
      REQUIRE(r.outcome == RunOutcome::kSolved);
      REQUIRE(r.sim_passed);
      CHECK(*r.sim_passed);
      CHECK(r.sim_reused == (row.scenario.method == "greedy" && r.seed == 2));
    }
  }
  // seed 1: MM-DaSH finds a shorter plan than Greedy's, which is simulated too; seed 2: both
  // find the same plan, simulated once
  CHECK(rows[0].runs[0].makespan < rows[1].runs[0].makespan);
  CHECK(rows[0].runs[1].makespan == rows[1].runs[1].makespan);
}

/// The columns of the pixels left of a plot's legend (its right 360 px) in a pure colour: channel
/// `c` (0 red, 1 green, 2 blue) above 200, the other two below 60; one entry per pixel.
std::vector<int> pureColourColumns(const render::Image& image, int c) {
  std::vector<int> columns;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width - 360; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[c] > 200 && p[(c + 1) % 3] < 60 && p[(c + 2) % 3] < 60) columns.push_back(x);
    }
  }
  return columns;
}

TEST_CASE("a plot marks a dashed series of a single point, which has no line to dash", "[bench_plan]") {
  LinePlot plot;
  plot.log_y = true;
  plot.series.push_back({"ours", {0.0, 0.0, 1.0}, false, {{4, 0.5}, {8, 2.0}}});
  plot.series.push_back({"paper, one row", {1.0, 0.0, 0.0}, true, {{4, 40.0}}});
  // red pixels left of the legend: only the marker can make them
  CHECK(pureColourColumns(drawLinePlot(plot, 800, 400), 0).size() > 20);
}

TEST_CASE("two dashed single points on the same spot both stay visible, as nested rings", "[bench_plan]") {
  LinePlot plot;
  plot.log_y = true;
  plot.series.push_back({"ours", {0.0, 0.0, 1.0}, false, {{16, 30.0}}});
  plot.series.push_back({"paper cross", {1.0, 0.0, 0.0}, true, {{16, 4005.0}}});
  plot.series.push_back({"paper random", {0.0, 1.0, 0.0}, true, {{16, 3990.0}}});
  const render::Image image = drawLinePlot(plot, 800, 400);
  CHECK(pureColourColumns(image, 0).size() > 20);
  CHECK(pureColourColumns(image, 1).size() > 20);
}

TEST_CASE("a plot of a single object count draws it in the middle, not at the right edge", "[bench_plan]") {
  LinePlot plot;
  plot.log_y = true;
  plot.series.push_back({"ours", {0.0, 0.0, 1.0}, false, {{16, 30.0}}});
  // the blue marker's pixels, left of the legend: the plot area runs from x = 100 to 440
  const std::vector<int> blue = pureColourColumns(drawLinePlot(plot, 800, 400), 2);
  REQUIRE(blue.size() > 20);
  const double mean_x = std::accumulate(blue.begin(), blue.end(), 0.0) / static_cast<double>(blue.size());
  CHECK(mean_x > 180.0);
  CHECK(mean_x < 360.0);
}

}  // namespace
}  // namespace dashbed::tools
