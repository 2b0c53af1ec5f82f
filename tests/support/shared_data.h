#pragma once
// Access to ../shared (real TUM frames, reference trajectories) for tests.
// Present: tests use it. Absent: tests skip and say so; under CI=true, absence fails.

#include <string>

namespace dynvo::test {

// Path of the shared data folder, "" when it does not exist.
std::string SharedDir();

// True when CI=true is set in the environment.
bool RunningInCi();

}  // namespace dynvo::test

// Use at the top of a test that needs ../shared: binds `var` to its path, or skips the test
// (fails under CI=true) when it is missing.
#define DYNVO_REQUIRE_SHARED(var)                                                     \
  const std::string var = ::dynvo::test::SharedDir();                                 \
  if (var.empty()) {                                                                  \
    if (::dynvo::test::RunningInCi()) FAIL() << "../shared is missing under CI=true"; \
    GTEST_SKIP() << "../shared not found: test needs the shared data folder";         \
  }
