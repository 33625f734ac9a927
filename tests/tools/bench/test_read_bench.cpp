// `dashbed bench read`: its made-up files are of the asked size and read as intended (timings
// are the benchmark's business, not the test's).

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

#include "tools/bench/read_bench.h"

using namespace dashbed::tools;

TEST_CASE("bench read makes files of about the asked size, accepted and refused at their end", "[bench_read]") {
  const BenchTable table = benchReading({{0.05, 0.1}});
  REQUIRE(table.rows.size() == 8);
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& row = table.rows[i];
    INFO(row[0] << " " << row[1]);
    CHECK(row[0] == (i < 4 ? "world" : "plan"));
    const double asked = (i % 4) < 2 ? 0.05 : 0.1;
    CHECK(std::stod(row[1]) == Approx(asked).margin(0.051));  // one decimal
    CHECK(row[4] == (i % 2 == 0 ? "accepted" : "refused at its last line"));
  }
  CHECK_THROWS_AS(benchReading({{0.0}}), std::invalid_argument);
  CHECK_THROWS_AS(benchReading({{300.0}}), std::invalid_argument);
}
