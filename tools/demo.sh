#!/usr/bin/env bash
# The run command: installs what is missing, builds (Release), and runs the odometry with the
# recommended config (dynvo), the paper's method and the baseline on a sequence, then
# evaluates each against its groundtruth.
#   bash tools/demo.sh [TUM_SEQUENCE_DIR]
# Without a sequence it first generates the default one (synthetic room, two people from
# photos walking across and around the view from the first frame as in TUM's walking
# sequences, camera moving along x/y/z: 300 frames, no download) into out/demo/sequence.
# Outputs: out/demo/{dynvo,paper,baseline}/{trajectory.txt,timing.csv,run.json} and the RPE/ATE lines.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
out="${DYNVO_OUT:-$root/out/demo}"
jobs="${DYNVO_JOBS:-$(nproc)}"

bash "$root/tools/install_deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$jobs" --target dynvo-cli rpe ate dynvo-synth
bin="$build/bin"

dataset="${1:-}"
if [ -z "$dataset" ]; then
  dataset="$out/sequence"
  if ! grep -qs "scenario tum_walking," "$dataset/rgb.txt"; then
    echo "demo: generating the default sequence in $dataset"
    "$bin/dynvo-synth" --scenario tum_walking --camera-path xyz --frames 300 --seed 1 \
      --out "$dataset" --force
  fi
fi

for mode in dynvo paper baseline; do
  echo "demo: running $mode mode"
  "$bin/dynvo-cli" run --dataset "$dataset" --config "$root/configs/$mode.json" \
    --out "$out/$mode" --force
done

if [ -f "$dataset/groundtruth.txt" ]; then
  for mode in dynvo paper baseline; do
    echo "== $mode"
    "$bin/rpe" "$dataset/groundtruth.txt" "$out/$mode/trajectory.txt" --delta 1 --delta-unit s
    "$bin/ate" "$dataset/groundtruth.txt" "$out/$mode/trajectory.txt"
  done
fi
echo "demo: outputs in $out/{dynvo,paper,baseline}"
