#!/usr/bin/env bash
# Several trajectories (dynvo's trajectory.txt, ORB-SLAM2's CameraTrajectory.txt or
# KeyFrameTrajectory.txt, any TUM-format file) against one groundtruth: one table (Markdown,
# CSV, JSON: RPE, ATE and rotational ATE, the variant in every header) and plots (aligned
# trajectories, RPE over time, error distributions) as PNG and PDF. Builds rpe and ate
# (Release), then runs `python3 -m dynvo_tools compare` (tools/dynvo_tools/compare.py).
#   bash tools/compare.sh GT EST... --out DIR [--label NAME]... [--align se3|sim3|none]
#                         [--delta 1] [--delta-unit s|f|m|rad|deg] [--title TEXT] [--force]
# Env: DYNVO_BUILD_DIR (default build/), PYTHON (default /usr/bin/python3).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"

bash "$root/tools/install_deps.sh" >&2
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target rpe ate >/dev/null
DYNVO_BIN_DIR="$build/bin" PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" \
  exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools compare "$@"
