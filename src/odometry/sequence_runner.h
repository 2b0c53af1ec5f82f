#pragma once
// `dynvo-cli run`: the odometry over a whole TUM sequence, with its outputs.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dynvo {

struct RunRequest {
  std::string dataset;                   // TUM sequence folder
  std::string config_path;               // JSON config ("" = defaults)
  std::vector<std::string> overrides;    // "key=value", applied after the file
  std::string out_dir;                   // created when missing
  bool force = false;                    // overwrite outputs of an earlier run in out_dir
  bool quiet = false;                    // no progress on stderr
  std::vector<size_t> debug_frames;      // frames whose panels go to out_dir/debug/
  int threads = 0;                       // threads the run uses (0 = the machine's cores; 1 = all
                                         // work in order on the calling thread); same results
  bool slam = false;                     // --mode slam: loops closed at the end (LoopCloser)
  bool map = false;                      // --map (slam only): map.ply and map_top.png
  std::function<bool()> stop_requested;  // polled before each frame; true ends the run after the
                                         // frame in hand, as "interrupted" (empty: never)
};

// How a run ended (run.json "status").
enum class RunStatus { kCompleted, kFailed, kInterrupted };
const char* ToString(RunStatus status);

// Runs the odometry on every frame and writes into out_dir: trajectory.txt (TUM format, one
// pose per frame at its RGB stamp; with `slam`, the loop-corrected poses written after the
// last frame, with trajectory_online.txt the poses as estimated at the time, keyframes.txt
// and loops.csv; with `map`, map.ply and map_top.png), timing.csv (one row per frame) and run.json (config as
// used, dataset, counts, time summary, mask quality). Rows and poses are written as frames
// finish, every write checked; run.json is written last, atomically. With `force`, an
// earlier run's outputs are removed first. If a frame fails to load or a write fails, what
// was done is kept, run.json says "failed" and the InputError is rethrown. When
// stop_requested() turns true, the frame in hand is finished and run.json says
// "interrupted". Bad input (dataset, config, existing outputs without `force`) throws
// InputError before anything is written. Returns the content of run.json.
nlohmann::json RunOdometry(const RunRequest& request);

}  // namespace dynvo
