#pragma once
// `dynvo-cli run`: the odometry over a whole TUM sequence, with its outputs.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynvo {

struct RunRequest {
  std::string dataset;                 // TUM sequence folder
  std::string config_path;             // JSON config ("" = defaults)
  std::vector<std::string> overrides;  // "key=value", applied after the file
  std::string out_dir;                 // created when missing
  bool force = false;                  // overwrite outputs of an earlier run in out_dir
  bool quiet = false;                  // no progress on stderr
  std::vector<size_t> debug_frames;    // frames whose panels go to out_dir/debug/
  int threads = 0;                     // threads the run uses (0 = the machine's cores; 1 = all
                                       // work in order on the calling thread); same results
};

// Runs the odometry on every frame and writes into out_dir: trajectory.txt (TUM format, one
// pose per frame at its RGB stamp), timing.csv (one row per frame) and run.json (config as
// used, dataset, counts, time summary, mask quality). Rows and poses are written as frames
// finish; if a frame fails to load, what was done is kept, run.json says "failed" and the
// InputError is rethrown. Bad input (dataset, config, existing outputs without `force`)
// throws InputError before anything is written. Returns the content of run.json.
nlohmann::json RunOdometry(const RunRequest& request);

}  // namespace dynvo
