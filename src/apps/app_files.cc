#include "apps/app_files.h"

#include <filesystem>
#include <fstream>
#include <iostream>

#include "apps/command_line_hint.h"
#include "core/build_info.h"
#include "core/error.h"
#include "core/json_file.h"

namespace dynvo {

int RunTool(CLI::App& app, int argc, char** argv, const std::function<int()>& run) {
  const std::string name = app.get_name();
  app.set_version_flag("--version", VersionLine(name));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << name << ": error: " << e.what() << ClosestArgumentHint(app) << " (see " << name << " --help)\n";
    return 2;
  }
  try {
    return run();
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << "\n";
    return 1;
  }
}

void WriteOutputFile(const std::string& path, const std::string& content, bool force) {
  if (!force && std::filesystem::exists(path)) ThrowFileError(path, 0, "already exists (use --force to overwrite)");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) ThrowFileError(path, 0, "cannot write file");
  out << content;
  if (!out) ThrowFileError(path, 0, "write failed");
}

Trajectory ReadNonEmptyTrajectory(const std::string& path) {
  Trajectory trajectory = ReadTrajectory(path);
  if (trajectory.empty()) ThrowFileError(path, 0, "no poses in file");
  return trajectory;
}

void PrintMetrics(bool json, nlohmann::json report, const std::string& text, const std::string& groundtruth_path,
                  const std::string& estimate_path) {
  if (!json) {
    std::cout << text;
    return;
  }
  report["groundtruth"] = groundtruth_path;
  report["estimate"] = estimate_path;
  std::cout << JsonText(report, 2) << "\n";
}

}  // namespace dynvo
