#!/usr/bin/env bash
# The benchmark suite: dev and validation splits of generated dynamic sequences (people inserted
# into real TUM frames, and synthetic scenes), each run with the baseline, paper and dynvo
# configs and compared with its twin without people. Builds the binaries, then runs
# `python3 -m dynvo_tools suite` (tools/dynvo_tools/suite.py: all the logic; its docstring tells
# the rest). Writes bench/results/suite_<split>.csv and suite_<split>.md.
#   bash bench/suite.sh [--split dev|validation|all] [--frames N] [--configs baseline,paper,dynvo]
#                       [--out DIR] [--results DIR] [--jobs N] [--set KEY=VALUE]... [--seeds N] [--update]
#                       [--sequences NAME,NAME]
#   --update keeps the other configs' rows of the CSVs in --results: after a change that moves
#   one config only, bash bench/suite.sh --configs dynvo --seeds 5 --update
#   --sequences runs only the rows whose sequence name holds one of NAME (with --update the
#   rest stay): after a new source, bash bench/suite.sh --split dev --seeds 5 --update
#   --sequences halfsphere_plain_s16
#   The configs find the person detector's model at data/models/ of the folder the suite runs in
#   (bash tools/fetch_models.sh puts it there; without it dynvo runs geometric only and ipl
#   fails). The tables of docs/results.md: from the repository root, after fetching the model,
#   bash bench/suite.sh --configs baseline,paper,dynvo,ipl --seeds 5
#   bash bench/suite.sh table --split dev      (the Markdown again from the CSV; no build, no runs:
#                                               the command suite-table)
#   bash bench/suite.sh compare BEFORE.csv AFTER.csv   (two results CSVs of one split row by row:
#                                               RPE ratios and their geometric mean; suite-compare)
#   (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, PYTHON)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"

command=suite
if [ "${1:-}" = "table" ]; then
  shift
  command=suite-table
elif [ "${1:-}" = "compare" ]; then
  shift
  command=suite-compare
else
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j "$(nproc)" --target dynvo-cli rpe ate dynvo-synth dynvo-insert-people >/dev/null
fi
DYNVO_BIN_DIR="$build/bin" PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}" \
  exec "${PYTHON:-/usr/bin/python3}" -m dynvo_tools "$command" "$@"
