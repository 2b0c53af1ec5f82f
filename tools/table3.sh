#!/usr/bin/env bash
# Regenerates the second paper's Table 3 (VO against SLAM) on generated loops: builds the
# binaries it needs (Release), then runs `python3 -m dynvo_tools table3`
# (tools/dynvo_tools/table3.py), which generates each split's sequences (loops with people, a
# loop in a room of repeated wallpaper, a sequence without a loop), runs baseline, ipl and dynvo
# in slam mode, and writes bench/results/table3_<split>.csv and .md: ATE and per-second RPE of
# the online (VO) and loop-corrected trajectories, the loops accepted and the false ones, and
# the map's points on people.
#   bash tools/table3.sh                           both splits, every config
#   bash tools/table3.sh --split dev --configs dynvo --frames 540 --out DIR --results DIR --jobs N
# Options: see `PYTHONPATH=tools python3 -m dynvo_tools table3 --help`.
# (env: DYNVO_BUILD_DIR, PYTHON)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe ate dynvo-synth map_people >/dev/null
DYNVO_BIN_DIR="$build/bin" \
  PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools table3 "$@"
