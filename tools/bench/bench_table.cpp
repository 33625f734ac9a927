#include "tools/bench/bench_table.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace dashbed::tools {

std::string BenchTable::text() const {
  std::vector<std::size_t> width(header.size(), 0);
  const auto measure = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) width[c] = std::max(width[c], cells[c].size());
  };
  measure(header);
  for (const auto& row : rows) measure(row);
  std::ostringstream out;
  if (!note.empty()) out << note << "\n";
  const auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) {
      const int w = static_cast<int>(width[c]);
      out << (c == 0 ? "" : "  ") << (c == 0 ? std::left : std::right) << std::setw(w) << cells[c];
    }
    out << "\n";
  };
  line(header);
  for (const auto& row : rows) line(row);
  return out.str();
}

std::string BenchTable::markdown() const {
  std::ostringstream out;
  if (!note.empty()) out << note << "\n\n";
  const auto line = [&](const std::vector<std::string>& cells) {
    out << "|";
    for (const std::string& cell : cells) out << " " << cell << " |";
    out << "\n";
  };
  line(header);
  out << "|";
  for (std::size_t c = 0; c < header.size(); ++c) out << (c == 0 ? "---|" : "---:|");
  out << "\n";
  for (const auto& row : rows) line(row);
  return out.str();
}

std::string fixed(double value, int decimals) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

}  // namespace dashbed::tools
