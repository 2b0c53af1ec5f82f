#pragma once
// The message of the InputError an action throws, for tests of error messages.

#include <functional>
#include <string>

#include "core/error.h"

namespace dynvo::test {

// Runs `action`; the what() of the InputError it throws, "" when it throws none (any other
// exception propagates and fails the test).
inline std::string InputErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dynvo::test
