#include "support/run_tool.h"

#include <sys/wait.h>

#include <cstdlib>

#include <gtest/gtest.h>

#include "dataset/text_lines.h"

namespace dynvo::test {
ToolOutcome RunTool(const TempDir& dir, const std::string& program, const std::string& args) {
  const char* bin = std::getenv("DYNVO_BIN_DIR");
  if (!bin || !*bin) ADD_FAILURE() << "DYNVO_BIN_DIR is not set (ctest sets it)";
  const std::string exe = std::string(bin ? bin : ".") + "/" + program;
  const auto out = dir.path() / "stdout.txt", err = dir.path() / "stderr.txt";
  const std::string command = "'" + exe + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  ToolOutcome o;
  o.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  o.out = ReadTextFile(out);
  o.err = ReadTextFile(err);
  return o;
}

}  // namespace dynvo::test
