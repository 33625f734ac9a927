#pragma once
// `dashbed bench read`: how fast the world and plan readers take large files. For each size it
// makes a world (cubes on a floor, one goal each) and a plan (one robot, many points) of about
// that many megabytes in memory, and times reading them from text: accepted, and refused at
// their last line (a repeated goal; a time that does not increase), which needs the whole file.

#include <vector>

#include "tools/bench/bench_table.h"

namespace dashbed::tools {

struct ReadBenchOptions {
  std::vector<double> megabytes{2.5, 5, 10, 20};  ///< sizes of the files made [MB]
};

/// Throws std::invalid_argument for a size that is not positive or above 256 MB.
BenchTable benchReading(const ReadBenchOptions& options);

}  // namespace dashbed::tools
