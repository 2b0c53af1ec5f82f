#!/usr/bin/env bash
# rgb.txt and depth.txt for a folder of PNGs (SEQ_DIR/rgb/*.png, SEQ_DIR/depth/*.png), so that
# `dynvo-cli run --dataset SEQ_DIR` reads your own recording. Stamps from the file names when
# they are numbers of seconds, else by order at --fps (tools/dynvo_tools/lists.py).
#   bash tools/make_lists.sh SEQ_DIR [--rgb SUBDIR] [--depth SUBDIR] [--fps 30] [--force]
# Env: PYTHON (default /usr/bin/python3).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools lists "$@"
