#pragma once
// What this build is: the project's version and the git commit it was built from, for
// `--version` and run.json.

#include <string>

namespace dynvo {

// The project version of CMakeLists.txt, e.g. "0.1.0".
std::string DynvoVersion();

// The git commit the binaries were built from (12 hex digits, "-dirty" when the tree had
// uncommitted changes), or "unknown" when built outside a git checkout.
std::string BuildCommit();

// "<program> <version> (commit <commit>)": the line `--version` prints.
std::string VersionLine(const std::string& program);

}  // namespace dynvo
