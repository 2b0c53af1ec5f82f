#pragma once
// What a slam-mode run writes after its last frame (loop/loop_closer.h): the corrected
// trajectory.txt, keyframes.txt, loops.csv and run.json's "loops" summary.

#include <string>

#include <nlohmann/json.hpp>

#include "loop/loop_closer.h"

namespace dynvo {

// Writes into `out_dir` (atomically, each file whole): trajectory.txt (a corrected pose for
// every frame processed, TUM format), keyframes.txt (the keyframes' corrected poses) and
// loops.csv (a row per candidate examined: frames, votes, verification figures, accepted,
// reason); with `with_map`, map.ply and map_top.png (loop/static_map.h). Throws InputError
// naming the file when a write fails.
void WriteLoopOutputs(const std::string& out_dir, const LoopClosingResult& result, bool with_map);

// run.json's "loops": keyframes, candidates examined, verified and accepted, the pose graph's
// outcome, and with `with_map` the map's points.
nlohmann::json LoopsJson(const LoopClosingResult& result, bool with_map);

}  // namespace dynvo
