#pragma once
// Wall time of the per-stage timings (timing.csv, run.json).

#include <chrono>

namespace dynvo {

using SteadyClock = std::chrono::steady_clock;

// Milliseconds of wall time since `start`.
inline double MillisecondsSince(SteadyClock::time_point start) {
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - start).count();
}

}  // namespace dynvo
