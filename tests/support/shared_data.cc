#include "support/shared_data.h"

#include <cstdlib>
#include <filesystem>

namespace dynvo::test {

std::string SharedDir() {
  if (const char* env = std::getenv("DYNVO_SHARED_DIR"); env && *env)
    return std::filesystem::is_directory(env) ? env : "";
  const std::string dir = DYNVO_DEFAULT_SHARED_DIR;
  return std::filesystem::is_directory(dir) ? dir : "";
}

bool RunningInCi() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

}  // namespace dynvo::test
