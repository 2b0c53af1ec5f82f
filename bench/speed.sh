#!/usr/bin/env bash
# Per-frame processing cost of dynvo (paper, baseline, dynvo and ipl configs, with the person
# detector when its model is found; paper and dynvo also on one thread, without the
# look-ahead) against OpenCV's
# RgbdOdometry and ICPOdometry on the same in-memory frames, in the same process
# (bench/odometry_speed.cc): median over frames, median of RUNS runs, ratio to RgbdOdometry (per run, interleaved),
# and the per-stage split; then the latency of baseline, paper and dynvo fed at a live camera's
# 30 frames/s (`--rate 30`: each frame timed from its arrival). Sequences: fr1_rpy_head150 from ../shared when present, and a
# generated dynamic sequence. Writes bench/results/speed.md and speed.csv (`python3 -m dynvo_tools speed-table`).
#   bash bench/speed.sh          (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, RUNS=5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
shared="${DYNVO_SHARED_DIR:-$root/../shared}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/speed}"
runs="${RUNS:-5}"
results="$root/bench/results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target odometry_speed dynvo-synth >/dev/null
bin="$build/bin"
mkdir -p "$work" "$results"

sequences=()
fr1="$shared/data/tum/rgbd_dataset_freiburg1_rpy_head150"
[ -d "$fr1" ] && sequences+=("$fr1")
synth="$work/synth_two_crossing_xyz"
[ -f "$synth/rgb.txt" ] || "$bin/dynvo-synth" --scenario two_crossing --camera-path xyz --frames 150 \
  --seed 1 --out "$synth" --force >&2
sequences+=("$synth")

# The person detector of configs/dynvo.json and ipl.json (without its model ipl is left out);
# the table names the model a row ran with.
source "$root/bench/detector_model.sh"

rm -f "$work"/*.json  # the table is this run's alone
for seq in "${sequences[@]}"; do
  for mode in paper baseline; do
    "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/$mode.json" --runs "$runs" \
      --json "$work/$(basename "$seq")_$mode.json" >&2
  done
  for mode in dynvo ipl; do
    [ "$mode" = ipl ] && [ ${#detector[@]} -eq 0 ] && continue
    "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/$mode.json" --runs "$runs" \
      ${detector[@]+"${detector[@]}"} --json "$work/$(basename "$seq")_$mode.json" >&2
  done
  # As a live 30 Hz camera would feed them: each frame timed from its arrival (waits included).
  for mode in baseline paper dynvo; do
    model=()
    [ "$mode" = dynvo ] && model=(${detector[@]+"${detector[@]}"})
    "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/$mode.json" --runs "$runs" --rate 30 --no-peers \
      ${model[@]+"${model[@]}"} --json "$work/$(basename "$seq")_${mode}_live.json" >&2
  done
  # Paper mode and configs/dynvo.json on one thread: each frame's stages in turn, in its own
  # call (the same results).
  "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/paper.json" --runs "$runs" \
    --threads 1 --json "$work/$(basename "$seq")_paper_in_turn.json" >&2
  "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/dynvo.json" --runs "$runs" \
    ${detector[@]+"${detector[@]}"} --threads 1 --json "$work/$(basename "$seq")_dynvo_in_turn.json" >&2
done

PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" "${PYTHON:-/usr/bin/python3}" -m dynvo_tools speed-table "$work" \
  --cpu "$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)" --csv "$results/speed.csv" \
  > "$results/speed.md"
cat "$results/speed.md"
