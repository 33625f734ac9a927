#pragma once
// Seeded small edits of a text file, for tests that feed a reader broken input: a line deleted
// or repeated, a value or a number replaced by an odd one, a stray character. Only the raw
// std::mt19937 output is used (its sequence is fixed by the standard), so every platform edits
// the same way.

#include <cctype>
#include <exception>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace dashbed::test {

/// `text` with one edit chosen by `rng`; `odd` are the replacement values.
inline std::string mutateText(const std::string& text, std::mt19937& rng, const std::vector<std::string>& odd) {
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  std::vector<std::string> lines;
  for (std::size_t from = 0;;) {
    const std::size_t end = text.find('\n', from);
    lines.push_back(text.substr(from, end == std::string::npos ? std::string::npos : end - from));
    if (end == std::string::npos) break;
    from = end + 1;
  }
  const std::size_t i = pick(lines.size());
  std::string& line = lines[i];
  switch (pick(5)) {
    case 0:
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
      break;
    case 1:
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), lines[pick(lines.size())]);
      break;
    case 2: {
      const std::string stray = ":-[]{},#&*!|>'\"%@`\t0";
      std::string out = text;
      out.insert(pick(out.size() + 1), 1, stray[pick(stray.size())]);
      return out;
    }
    case 3:
      if (const std::size_t colon = line.find(": "); colon != std::string::npos) {
        line = line.substr(0, colon + 2) + odd[pick(odd.size())];
      }
      break;
    default: {  // the k-th run of digits (with its sign, point and exponent) in the line
      std::vector<std::pair<std::size_t, std::size_t>> numbers;  // begin, end
      for (std::size_t k = 0; k < line.size();) {
        if (!std::isdigit(static_cast<unsigned char>(line[k]))) {
          ++k;
          continue;
        }
        const std::size_t begin = k > 0 && line[k - 1] == '-' ? k - 1 : k;
        while (k < line.size() && (std::isdigit(static_cast<unsigned char>(line[k])) || line[k] == '.' ||
                                   line[k] == 'e' || line[k] == '-' || line[k] == '+')) {
          ++k;
        }
        numbers.emplace_back(begin, k);
      }
      if (!numbers.empty()) {
        const auto [begin, end] = numbers[pick(numbers.size())];
        line = line.substr(0, begin) + odd[pick(odd.size())] + line.substr(end);
      }
    }
  }
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k) out += (k == 0 ? "" : "\n") + lines[k];
  return out;
}

/// How a reader took edited files: accepted, refused with its error type and a message that
/// starts with the file's name, or anything else (problems).
struct EditedReads {
  int accepted = 0;
  int refused = 0;
  std::vector<std::string> problems;
};

/// `trials` edited files (1-3 edits each of the text `file(trial)` gives, under the name it
/// gives), each handed to `read(text, name)`, which throws Error on bad input.
template <class Error>
EditedReads readEdited(int trials, const std::vector<std::string>& odd,
                       const std::function<std::pair<std::string, std::string>(int)>& file,
                       const std::function<void(const std::string&, const std::string&)>& read) {
  std::mt19937 rng(2026);
  EditedReads reads;
  for (int trial = 0; trial < trials; ++trial) {
    auto [text, name] = file(trial);
    for (auto edits = 1 + rng() % 3; edits > 0; --edits) text = mutateText(text, rng, odd);
    try {
      read(text, name);
      ++reads.accepted;
    } catch (const Error& e) {
      ++reads.refused;
      if (std::string(e.what()).rfind(name + ":", 0) != 0) {
        reads.problems.push_back("message without the file's name: " + std::string(e.what()));
      }
    } catch (const std::exception& e) {
      reads.problems.push_back(name + ": " + e.what());
    }
  }
  return reads;
}

}  // namespace dashbed::test
