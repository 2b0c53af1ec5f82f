#!/usr/bin/env bash
# Generates the dynamic test sequences that need no download, into one folder, and prints
# the path of each sequence folder on stdout (one a line, in this order).
# People as TUM films them (articulated photo people, in view from the first frame), all with
# Kinect v1 sensor timing (motion blur, depth seen before colour, exposure drift, rolling shutter;
# dynvo-synth --kinect-sensor):
#   synth_none_xyz                  dynvo-synth, camera path xyz, no people: the static twin
#   synth_tum_<scenario>_xyz        dynvo-synth, same camera path, scenarios tum_walking,
#                                   tum_toward, tum_away, tum_sitting
#   synth_{none,tum_walking}_{rpy,halfsphere}
#                                   the other camera paths (rotation, orbit) with their twins
#   fr1_rpy_head150_tum_<preset>    dynvo-insert-people into the real fr1_rpy_head150, the four
#                                   TUM presets (only when the project's shared data is present)
# A sequence already there is kept when it is what would be generated (same scenario, camera
# path, seed and frame count, read from its rgb.txt), else it is generated again.
# Used by `python3 -m dynvo_tools table1` and the bench scripts; they build the binaries first.
#   bash tools/make_sequences.sh --out DIR [--frames 300] [--seed 1]
#   (env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin; DYNVO_SHARED_DIR, default ../shared)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${DYNVO_BIN_DIR:-${DYNVO_BUILD_DIR:-$root/build}/bin}"
shared="${DYNVO_SHARED_DIR:-$root/../shared}"

out=""
frames=300
seed=1
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "make_sequences: error: unknown argument '$1' (expected --out DIR, --frames N, --seed K)" >&2; exit 2 ;;
  esac
done
[ -n "$out" ] || { echo "make_sequences: error: --out DIR is required" >&2; exit 2; }
scenarios="tum_walking tum_toward tum_away tum_sitting"
others=tum_walking
presets="tum_walking tum_toward tum_away tum_sitting"
mkdir -p "$out"

labels_still() {  # folder: no masks, or masks that give a person not moving 128 (older ones did not)
  [ ! -f "$1/masks.txt" ] || grep -qF "128 = " "$1/masks.txt"
}

synth() {  # name scenario camera_path
  local dir="$out/$1"
  local header="# dynvo synthetic sequence: scenario $2, camera path $3, seed $seed, rolling shutter 28 ms, depth 14 ms early"
  if ! { [ -f "$dir/rgb.txt" ] && grep -qxF "$header" "$dir/rgb.txt" &&
         [ "$(grep -vc '^#' "$dir/rgb.txt")" -eq "$frames" ] && labels_still "$dir"; }; then
    "$bin/dynvo-synth" --scenario "$2" --camera-path "$3" --frames "$frames" --seed "$seed" \
      --kinect-sensor --out "$dir" --force >&2
  fi
  echo "$dir"
}

synth synth_none_xyz none xyz
for scenario in $scenarios; do
  synth "synth_${scenario}_xyz" "$scenario" xyz
done
for path in rpy halfsphere; do
  synth "synth_none_$path" none "$path"
  synth "synth_${others}_$path" "$others" "$path"
done

fr1="$shared/data/tum/rgbd_dataset_freiburg1_rpy_head150"
if [ -d "$fr1" ]; then
  for preset in $presets; do
    people="$out/fr1_rpy_head150_$preset"
    { [ -f "$people/people.txt" ] && labels_still "$people"; } || "$bin/dynvo-insert-people" --dataset "$fr1" --preset "$preset" \
      --out "$people" --force >&2
    echo "$people"
  done
else
  echo "make_sequences: $fr1 not found: no sequences with people inserted into real frames" >&2
fi
