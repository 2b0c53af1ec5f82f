#!/usr/bin/env bash
# Which features the pose uses while two people cross the view, by distance to the people:
# the generated two_crossing sequence (camera path rpy, scene seed 3, one of the pairs that
# stays above 1.3x in bench/scene_seeds.sh) in paper mode, in paper mode with the ground-truth
# masks, and its twin without people counted in the same image regions (the dynamic
# sequence's masks). Each run writes the feature lists of DEBUG_FRAMES (--debug-frames).
# Writes bench/results/feature_use.md; prints it.
#   bash bench/feature_use.sh    (env: DYNVO_BUILD_DIR, FRAMES=300, SCENE_SEED=3,
#   CAMERA_PATH=rpy, DEBUG_FRAMES=60-89, PYTHON=/usr/bin/python3 with numpy and PIL)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/feature_use}"
frames="${FRAMES:-300}"
seed="${SCENE_SEED:-3}"
path="${CAMERA_PATH:-rpy}"
debug_frames="${DEBUG_FRAMES:-60-89}"
results="$root/bench/results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli dynvo-synth >/dev/null
bin="$build/bin"
mkdir -p "$work" "$results"

people="$work/synth_two_crossing_$path"
twin="$work/synth_none_$path"
"$bin/dynvo-synth" --scenario two_crossing --camera-path "$path" --frames "$frames" --seed "$seed" --out "$people" --force >/dev/null
"$bin/dynvo-synth" --scenario none --camera-path "$path" --frames "$frames" --seed "$seed" --out "$twin" --force >/dev/null

run() {  # dataset out [--set ...]
  local dataset="$1" out="$2"; shift 2
  "$bin/dynvo-cli" run --quiet --force --dataset "$dataset" --config "$root/configs/paper.json" \
    --out "$out" --debug-frames "$debug_frames" "$@"
}
run "$people" "$work/paper"
run "$people" "$work/truth" --set dynamic_mask.source=ground_truth
run "$twin" "$work/twin"

{
  echo "Features of frames $debug_frames of synth_two_crossing_$path (scene seed $seed, $frames frames;"
  echo "\`bash bench/feature_use.sh\`), by distance to the nearest pixel of the frame's ground-truth"
  echo "mask, per frame; in brackets those the dynamic mask kept; then the share of all of them"
  echo "that are inliers of the frame's final pose (a removed feature is one only when readmitted). Paper:"
  echo "configs/paper.json. Ground-truth masks: the same with dynamic_mask.source=ground_truth."
  echo "Twin: the same camera path without people, counted in the dynamic sequence's regions."
  echo
  "${PYTHON:-/usr/bin/python3}" "$root/bench/feature_use_table.py" "paper:$work/paper" "ground-truth masks:$work/truth" \
    "twin:$work/twin:$people"
} > "$results/feature_use.md"
cat "$results/feature_use.md"
