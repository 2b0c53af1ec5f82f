#include "odometry/progress_meter.h"

#include <cstdio>

namespace dynvo {

ProgressMeter::ProgressMeter(size_t total, bool quiet, std::string label)
    : total_(total), quiet_(quiet), label_(std::move(label)), start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressMeter::Update(size_t done, const std::function<std::string()>& note) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(1)) return;
  last_ = now;
  Print(done, note);
}

void ProgressMeter::Finish(size_t done, const std::function<std::string()>& note) {
  if (!quiet_) Print(done, note);
}

void ProgressMeter::Print(size_t done, const std::function<std::string()>& note) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const double eta = rate > 0 && total_ > done ? (total_ - done) / rate : 0.0;
  const std::string after = note ? note() : std::string();
  std::fprintf(stderr, "%s: frame %zu/%zu (%3.0f%%), %.1f frames/s%s, ETA %.0f s\n", label_.c_str(), done, total_,
               total_ ? 100.0 * done / total_ : 100.0, rate, after.c_str(), eta);
}

}  // namespace dynvo
