#!/usr/bin/env bash
# Regenerates the paper's Table 1 (Niu & Li 2019) on the sequence folders at hand: builds the
# binaries it needs (Release), then runs `python3 -m dynvo_tools table1`
# (tools/dynvo_tools/table1.py), which runs baseline and paper modes on every sequence,
# evaluates them (per-second RPE, per-frame RPE, ATE) and writes OUT/table1.md and
# OUT/table1.csv beside the paper's published columns.
#   bash tools/table1.sh                         the sequences here (generated + real ones present)
#   bash tools/table1.sh --root data/tum         every TUM folder (with rgb.txt) under data/tum
#   bash tools/table1.sh SEQ_DIR... [--root DIR] [--out DIR] [--jobs N] [--force] [--results DIR]
#   bash tools/table1.sh --frames 100            the sequences here, 100-frame synthetic ones
# Options: see `PYTHONPATH=tools python3 -m dynvo_tools table1 --help`.
# (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, PYTHON)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe ate dynvo-synth dynvo-insert-people >/dev/null
DYNVO_BIN_DIR="$build/bin" \
  PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools table1 "$@"
