#pragma once
// Progress of a long run on stderr: frames done, rate and time left, at most once a second.

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace dynvo {

class ProgressMeter {
 public:
  // `total` frames expected; prints nothing when `quiet`.
  ProgressMeter(size_t total, bool quiet, std::string label = "dynvo-cli");
  // Records that `done` frames are finished; prints when a second has passed since the last line,
  // with `note()` (e.g. ", 3 loops closed") after the rate; `note` is only called then.
  void Update(size_t done, const std::function<std::string()>& note = {});
  // Prints the final line (unless quiet), with `note()` as Update does.
  void Finish(size_t done, const std::function<std::string()>& note = {});

 private:
  void Print(size_t done, const std::function<std::string()>& note);
  size_t total_;
  bool quiet_;
  std::string label_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace dynvo
