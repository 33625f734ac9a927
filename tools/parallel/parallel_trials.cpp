#include "tools/parallel/parallel_trials.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

namespace dashbed::tools {
namespace {

constexpr int kBarWidth = 30;
constexpr auto kRedrawInterval = std::chrono::milliseconds(200);

std::string duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) return std::to_string(s / 3600) + "h" + std::to_string(s % 3600 / 60) + "m";
  if (s >= 60) return std::to_string(s / 60) + "m" + std::to_string(s % 60) + "s";
  return std::to_string(s) + "s";
}

}  // namespace

ProgressBar::ProgressBar(std::ostream& out, std::size_t total, std::string unit)
    : out_(out), total_(total), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()), last_draw_(start_) {
  draw(false);
}

void ProgressBar::advance(bool failed) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  failed_ += failed ? 1 : 0;
  if (std::chrono::steady_clock::now() - last_draw_ >= kRedrawInterval) draw(false);
}

void ProgressBar::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  draw(true);
}

void ProgressBar::draw(bool final_line) {
  const auto now = std::chrono::steady_clock::now();
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total_ == 0 ? 1.0 : static_cast<double>(done_) / static_cast<double>(total_);
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string bar(static_cast<std::size_t>(filled), '=');
  if (filled < kBarWidth) bar += '>' + std::string(static_cast<std::size_t>(kBarWidth - filled - 1), ' ');
  std::string line = "\r[" + bar + "] " + std::to_string(done_) + "/" + std::to_string(total_) + " " + unit_ + ", " +
                     std::to_string(failed_) + " failed, ";
  if (final_line) {
    line += duration(elapsed) + "       \n";
  } else if (done_ == 0) {
    line += "ETA -        ";
  } else {
    const double left = elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
    line += "ETA " + duration(left) + "        ";
  }
  out_ << line << std::flush;
}

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& work) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto worker = [&] {
    while (!stop) {
      const std::size_t i = next++;
      if (i >= count) return;
      try {
        work(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        stop = true;
      }
    }
  };
  const std::size_t pool =
      std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), std::max<std::size_t>(count, 1));
  std::vector<std::thread> others;
  for (std::size_t t = 1; t < pool; ++t) others.emplace_back(worker);
  worker();  // the calling thread works too
  for (std::thread& t : others) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace dashbed::tools
