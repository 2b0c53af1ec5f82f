#pragma once
// The shared shape of the data-generator programs: parse the command line, run the job, and
// report the way every dynvo program does.

#include <exception>
#include <functional>
#include <iostream>

#include <CLI/CLI.hpp>
#include <opencv2/core/utils/logger.hpp>

#include "apps/command_line_hint.h"
#include "core/build_info.h"

namespace dynvo {

// Parses `app` and runs `job`. --help prints the usage and --version the version line (exit 0); a usage error or an
// exception from the job prints one line "<prog>: error: <message>" on stderr (exit 1).
// OpenCV's own warnings (e.g. imread's on a missing file) are silenced: the error line says it.
inline int RunToolMain(const char* prog, CLI::App& app, int argc, char** argv, const std::function<void()>& job) {
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
  app.set_version_flag("--version", VersionLine(prog));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << prog << ": error: " << e.what() << ClosestArgumentHint(app) << "\n";
    return 1;
  }
  try {
    job();
  } catch (const std::exception& e) {
    std::cerr << prog << ": error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace dynvo
