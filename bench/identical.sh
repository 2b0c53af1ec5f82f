#!/usr/bin/env bash
# Checks that a restructuring moved no result: runs one set of (config, sequence) cases and either
# records their trajectories (--record DIR) or compares them byte for byte with a recording
# (--compare DIR). The cases: configs/paper.json, configs/baseline.json and configs/dynvo.json on
# the two real sequences in ../shared/data/tum (skipped when absent) and three generated ones
# (generated once, into the recording, so that both sides read the same frames). Each case's
# command line is stored with its trajectory; a case may be given an older command line with
# --old-cases FILE (lines "name|dynvo-cli run arguments"), for a recording made before keys moved.
# Usage: bash bench/identical.sh --record DIR [--bin build/bin] [--old-cases FILE]
#        bash bench/identical.sh --compare DIR [--bin build/bin]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mode="" dir="" bin="build/bin" old_cases=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --record|--compare) mode="${1#--}"; dir="$2"; shift 2 ;;
    --bin) bin="$2"; shift 2 ;;
    --old-cases) old_cases="$2"; shift 2 ;;
    *) echo "identical.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[[ -n "$mode" ]] || { echo "identical.sh: give --record DIR or --compare DIR" >&2; exit 2; }
shared="../shared/data/tum"

sequences() {
  for s in rgbd_dataset_freiburg1_rpy_head150 rgbd_dataset_freiburg2_desk_head50; do
    [[ -d "$shared/$s" ]] && echo "real_$s|$shared/$s"
  done
  echo "synth_walking_xyz|$dir/seq/walking_xyz"
  echo "synth_toward_rpy|$dir/seq/toward_rpy"
  echo "synth_sitting_halfsphere|$dir/seq/sitting_halfsphere"
}

generate() {
  mkdir -p "$dir/seq"
  local spec
  for spec in "walking_xyz tum_walking xyz" "toward_rpy tum_toward rpy" "sitting_halfsphere tum_sitting halfsphere"; do
    set -- $spec
    [[ -f "$dir/seq/$1/rgb.txt" ]] || "$bin/dynvo-synth" --scenario "$2" --camera-path "$3" --frames 90 \
      --seed 3 --out "$dir/seq/$1" >/dev/null
  done
}

# The dynvo-cli run arguments of each config case (the current key names).
cases() {
  echo "paper|--config configs/paper.json"
  echo "baseline|--config configs/baseline.json"
  echo "dynvo|--config configs/dynvo.json"
}

arguments_of() {  # case name -> its arguments, from --old-cases when it names the case
  local name="$1" line
  if [[ -n "$old_cases" ]]; then
    line=$(grep "^$name|" "$old_cases" || true)
    [[ -n "$line" ]] && { echo "${line#*|}"; return; }
  fi
  line=$(cases | grep "^$name|")
  echo "${line#*|}"
}

[[ "$mode" == record ]] && generate
differ=0 total=0
while IFS='|' read -r seq_name seq_path; do
  [[ -f "$seq_path/rgb.txt" ]] || { echo "identical.sh: $seq_path missing (record first)" >&2; exit 1; }
  while IFS='|' read -r case_name _; do
    out=$(mktemp -d)
    # shellcheck disable=SC2046
    "$bin/dynvo-cli" run --dataset "$seq_path" $(arguments_of "$case_name") --out "$out" --quiet
    ref="$dir/traj/${case_name}_${seq_name}.txt"
    total=$((total + 1))
    if [[ "$mode" == record ]]; then
      mkdir -p "$dir/traj"
      cp "$out/trajectory.txt" "$ref"
    elif cmp -s "$out/trajectory.txt" "$ref"; then
      echo "identical  $case_name on $seq_name"
    else
      echo "DIFFERENT  $case_name on $seq_name"
      differ=$((differ + 1))
    fi
    rm -rf "$out"
  done < <(cases)
done < <(sequences)
if [[ "$mode" == record ]]; then
  echo "recorded $total trajectories in $dir/traj"
else
  echo "$((total - differ)) of $total trajectories identical"
  [[ $differ -eq 0 ]]
fi
