#!/usr/bin/env bash
# Parameter sweep of dynvo-cli over a JSON grid of config keys (see tools/dynvo_tools/sweep.py
# for the grid format and the output layout). Builds dynvo-cli and rpe, then runs
# `python3 -m dynvo_tools sweep`: every grid point on every dataset (resuming: finished runs are
# skipped), evaluates per-second RPE and mask quality, and writes OUT/sweep.csv,
# OUT/sweep_heatmap.png and OUT/sweep.md.
#   bash tools/sweep.sh GRID.json --dataset SEQ [--dataset SEQ2 ...] --out DIR [--jobs N]
#   bash tools/sweep.sh GRID.json --dataset SEQ ... --out DIR --slurm FILE   (sbatch job array)
#   bash tools/sweep.sh GRID.json --dataset SEQ ... --out DIR --collect      (after the array)
#   (--index I runs grid point I only: what each array task of the sbatch script runs)
# Env: DYNVO_BUILD_DIR (default: build), DYNVO_BIN_DIR (use these binaries, build nothing),
# PYTHON (default /usr/bin/python3, which needs numpy and matplotlib to collect).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ -z "${DYNVO_BIN_DIR:-}" ]; then
  build="${DYNVO_BUILD_DIR:-$root/build}"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe >/dev/null
  export DYNVO_BIN_DIR="$build/bin"
fi
PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools sweep "$@"
