#pragma once
// CPU time of the whole process, for tests that print what a stage costs (robust to a loaded
// machine, unlike wall time; they assert results, never times).

#include <ctime>

namespace dynvo::test {

// CPU milliseconds used by the process (all threads) so far.
inline double ProcessCpuMs() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

}  // namespace dynvo::test
