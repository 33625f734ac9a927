#pragma once
// A benchmark's results as a table: aligned text for the terminal, Markdown for
// docs/benchmarks.md (bench_record.h).

#include <string>
#include <vector>

namespace dashbed::tools {

struct BenchTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< each as many cells as the header
  std::string note;                            ///< a line or two above the table (may be empty)

  /// Columns padded to their widest cell, the first left-aligned, the others right-aligned.
  std::string text() const;
  /// A GitHub-flavoured Markdown table (first column left-aligned, the others right-aligned),
  /// the note above it.
  std::string markdown() const;
};

/// `value` with `decimals` decimals.
std::string fixed(double value, int decimals);

}  // namespace dashbed::tools
