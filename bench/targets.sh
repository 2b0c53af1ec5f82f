#!/usr/bin/env bash
# The odometry's targets (issue 4), met or missed, per dynamic config, from the figures the
# benchmarks last wrote to bench/results (bench/targets_table.py says which file each row reads).
# Runs no benchmark itself; bench/update_readme.sh runs it first.
# Writes bench/results/targets.md and prints it.
#   bash bench/targets.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
results="$root/bench/results"
table="$(python3 "$root/bench/targets_table.py" "$results")"
printf '%s\n' "$table" > "$results/targets.md"
cat "$results/targets.md"
