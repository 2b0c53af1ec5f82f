#!/usr/bin/env bash
# What line segments add to a frame's processing time (features.lines.enabled): configs/
# baseline.json with and without lines, runs interleaved (without, with, without, ...), on
# fr1_rpy_head150 from ../shared when present and a generated low-texture sequence
# (dynvo-synth --plain-room). Per sequence: the median over runs of each run's median
# processing ms, over all frames and over keyframes and other frames apart, and the lines' own
# median ms (detection on the executor, keeping, matching, refinement, new map lines).
# Writes bench/results/lines_cost.md.
#   bash bench/lines_cost.sh          (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, RUNS=5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
shared="${DYNVO_SHARED_DIR:-$root/../shared}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/lines_cost}"
runs="${RUNS:-5}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target odometry_speed dynvo-synth >/dev/null
bin="$build/bin"
mkdir -p "$work" "$root/bench/results"
rm -f "$work"/*.json

sequences=()
fr1="$shared/data/tum/rgbd_dataset_freiburg1_rpy_head150"
[ -d "$fr1" ] && sequences+=("$fr1")
plain="$work/synth_none_xyz_plain_s5"
[ -f "$plain/rgb.txt" ] || "$bin/dynvo-synth" --scenario none --camera-path xyz --frames 150 --seed 5 \
  --kinect-sensor --plain-room --out "$plain" --force >&2
sequences+=("$plain")

for seq in "${sequences[@]}"; do
  for run in $(seq "$runs"); do
    for lines in false true; do
      "$bin/odometry_speed" --dataset "$seq" --config "$root/configs/baseline.json" --runs 1 --no-peers \
        --set "features.lines.enabled=$lines" --json "$work/$(basename "$seq")_${lines}_$run.json" >&2
    done
  done
done

"${PYTHON:-/usr/bin/python3}" - "$work" "$runs" "$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)" \
  > "$root/bench/results/lines_cost.md" <<'PY'
import glob, json, os, statistics, sys
work, runs, cpu = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def figure(report, key):
    if key == "all":
        return report["methods"]["dynvo"]["median_ms"]
    stage = report["stages"].get(key)
    return stage["median_ms"] if stage else None
names = sorted({os.path.basename(p).rsplit("_", 2)[0] for p in glob.glob(os.path.join(work, "*.json"))})
print(f"Line segments' cost per frame (`bash bench/lines_cost.sh`, {runs} interleaved runs each, "
      f"configs/baseline.json without and with `features.lines.enabled`, {os.cpu_count()} cores, {cpu}): "
      "median over runs of each run's median `processing_ms`; `lines ms`: the lines' own time "
      "(detection on the executor, keeping, matching, refinement, new map lines).\n")
print("| sequence | frames | without lines ms | with lines ms | added ms | keyframes without / with ms "
      "| other frames without / with ms | lines ms |")
print("|---|---|---|---|---|---|---|---|")
for name in names:
    cells = {}
    for lines in ("false", "true"):
        reports = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(work, f"{name}_{lines}_*.json")))]
        cells[lines] = {key: statistics.median(v for v in (figure(r, key) for r in reports) if v is not None)
                        if any(figure(r, key) is not None for r in reports) else float("nan")
                        for key in ("all", "frame (keyframes)", "frame (other frames)", "lines")}
        frames = reports[0]["frames"]
    off, on = cells["false"], cells["true"]
    print(f"| {name} | {frames} | {off['all']:.2f} | {on['all']:.2f} | {on['all'] - off['all']:+.2f} "
          f"| {off['frame (keyframes)']:.2f} / {on['frame (keyframes)']:.2f} "
          f"| {off['frame (other frames)']:.2f} / {on['frame (other frames)']:.2f} | {on['lines']:.2f} |")
PY
cat "$root/bench/results/lines_cost.md"
