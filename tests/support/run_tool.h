#pragma once
// Runs one of the project's executables (from DYNVO_BIN_DIR, set by ctest) and captures
// its exit code, stdout and stderr.

#include <string>

#include "support/temp_dir.h"

namespace dynvo::test {

struct ToolOutcome {
  int exit_code = -1;  // -1 when the program did not exit normally
  std::string out;
  std::string err;
};

// Runs `bin/<program> <args>` (args already shell-quoted where needed); the captured
// streams are kept in files inside `dir`.
ToolOutcome RunTool(const TempDir& dir, const std::string& program, const std::string& args);

}  // namespace dynvo::test
