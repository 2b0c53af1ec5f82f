#!/usr/bin/env bash
# Peak memory (RSS) of a whole `dynvo-cli run` in paper mode and with configs/dynvo.json on
# a generated 900-frame
# sequence (the local map is bounded: memory must not grow with sequence length), read
# from run.json ("memory.peak_rss_mb", getrusage). Writes bench/results/memory.md and memory.csv
# (`python3 -m dynvo_tools memory-table`).
#   bash bench/memory.sh          (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, FRAMES=900)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/memory}"
frames="${FRAMES:-900}"
results="$root/bench/results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli dynvo-synth >/dev/null
bin="$build/bin"
mkdir -p "$work" "$results"
seq="$work/synth_walking_across_halfsphere_$frames"
[ -f "$seq/rgb.txt" ] || "$bin/dynvo-synth" --scenario walking_across --camera-path halfsphere \
  --frames "$frames" --seed 1 --out "$seq" --force >&2

shared="${DYNVO_SHARED_DIR:-$root/../shared}"
source "$root/bench/detector_model.sh"  # dynvo with its person detector when the model is found
runs=()
for config in paper dynvo; do
  overrides=()
  [ "$config" = dynvo ] && overrides=(${detector[@]+"${detector[@]}"})
  for n in $((frames / 3)) "$frames"; do
    runs+=("$work/${config}_$n")
    "$bin/dynvo-cli" run --quiet --force --dataset "$seq" --config "$root/configs/$config.json" \
      --set run.max_frames="$n" ${overrides[@]+"${overrides[@]}"} --out "${runs[-1]}"
  done
done
PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" "${PYTHON:-/usr/bin/python3}" -m dynvo_tools memory-table \
  --csv "$results/memory.csv" "${runs[@]}" > "$results/memory.md"
cat "$results/memory.md"
