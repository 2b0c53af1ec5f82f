#!/usr/bin/env bash
# The paper's figures as PNG: RPE over time, paper mode vs baseline (Fig. 6); trajectory top
# view against the groundtruth; dynamic-mask panels of chosen frames (Fig. 1 / Fig. 3).
# Installs what is missing, builds the tools (Release), then runs `python3 -m dynvo_tools
# figures` (tools/dynvo_tools/figures.py) with Debian's python3 (numpy + matplotlib). Without
# --dataset it generates a dynamic sequence (two people crossing, camera moving along x/y/z,
# 300 frames), so no download is needed.
#   bash tools/figures.sh [--dataset TUM_DIR] [--out DIR] [--work DIR] [--frames-to-show 75,225]
#                         [--paper-run RUN_DIR] [--baseline-run RUN_DIR]
#                         [--trajectory FILE [--label NAME]]... [--force]
# The figures of docs/results.md: bash tools/figures.sh --out bench/results --force
# Env: DYNVO_BUILD_DIR (default build/), PYTHON (default /usr/bin/python3).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"

bash "$root/tools/install_deps.sh" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe ate dynvo-synth >/dev/null
DYNVO_BIN_DIR="$build/bin" PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" \
  exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools figures "$@"
