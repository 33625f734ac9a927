#pragma once
// Running independent trials on a pool of threads, with an optional progress bar.

#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <ostream>
#include <string>

namespace dashbed::tools {

/// A one-line progress bar with the rate and the estimated time left, redrawn in place (at
/// most every 0.2 s) on a terminal stream: "[=======>      ] 120/1000 trials, 3 failed, ETA 4m12s".
class ProgressBar {
 public:
  ProgressBar(std::ostream& out, std::size_t total, std::string unit);
  /// Counts one finished item (thread-safe).
  void advance(bool failed);
  /// Draws the final state and ends the line.
  void finish();

 private:
  void draw(bool final_line);

  std::ostream& out_;
  std::size_t total_;
  std::string unit_;
  std::size_t done_ = 0;
  std::size_t failed_ = 0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  std::mutex mutex_;
};

/// Calls work(i) for every i in [0, count) on `threads` threads (each i exactly once, in no
/// particular order). If a call throws, the other threads stop taking new items and the first
/// exception is rethrown once every thread has ended.
void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& work);

}  // namespace dashbed::tools
