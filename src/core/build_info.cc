#include "core/build_info.h"

#include "build_commit.h"  // generated at build time by build_commit.cmake

namespace dynvo {

std::string DynvoVersion() { return DYNVO_VERSION; }

std::string BuildCommit() { return DYNVO_BUILD_COMMIT; }

std::string VersionLine(const std::string& program) {
  return program + " " + DynvoVersion() + " (commit " + BuildCommit() + ")";
}

}  // namespace dynvo
