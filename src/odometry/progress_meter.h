#pragma once
// Progress of a long run on stderr: frames done, rate and time left, at most once a second.

#include <chrono>
#include <cstddef>
#include <string>

namespace dynvo {

class ProgressMeter {
 public:
  // `total` frames expected; prints nothing when `quiet`.
  ProgressMeter(size_t total, bool quiet, std::string label = "dynvo-cli");
  // Records that `done` frames are finished; prints when a second has passed since the last line.
  void Update(size_t done);
  // Prints the final line (unless quiet).
  void Finish(size_t done);

 private:
  void Print(size_t done);
  size_t total_;
  bool quiet_;
  std::string label_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace dynvo
