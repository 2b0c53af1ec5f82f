#!/usr/bin/env bash
# How much a sequence's accuracy depends on the ORB budget (fr1_rpy_head150 of the shared data by
# default): paper and baseline with features.num_features = each budget, each over RANSAC seeds
# 1..N. Builds dynvo-cli and rpe, then runs `python3 -m dynvo_tools feature-budget`, which writes
# bench/results/feature_budget.md and .csv and prints the table.
#   bash bench/feature_budget.sh [--budgets 900,950,1000,1050,1100] [--seeds 10] [--configs paper,baseline]
#                                [--dataset DIR] [--out DIR] [--results DIR] [--jobs N]
#   (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, PYTHON)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe >/dev/null
DYNVO_BIN_DIR="$build/bin" PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" \
  exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools feature-budget "$@"
