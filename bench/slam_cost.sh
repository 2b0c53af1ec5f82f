#!/usr/bin/env bash
# What slam mode (--mode slam --map) adds to the odometry: the recommended config in vo mode and
# in slam mode with the static map, runs interleaved (vo, slam, vo, ...), on a generated
# 900-frame loop with people walking (dynvo-synth --scenario tum_walking --camera-path loop:
# two turns, so the second sees the first again). Per mode: the median over runs of each run's
# median and p90 `processing_ms` (tracking's time per frame; the loop searches run beside it on
# the executor), peak RSS, and for slam mode the map.ply size, its points and the loops
# accepted; ATE of the vo and the loop-corrected trajectory. Writes bench/results/slam_cost.md.
#   bash bench/slam_cost.sh          (env: DYNVO_BUILD_DIR, RUNS=3, FRAMES=900)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/slam_cost}"
runs="${RUNS:-3}"
frames="${FRAMES:-900}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target dynvo-cli dynvo-synth ate >/dev/null
bin="$build/bin"
mkdir -p "$work" "$root/bench/results"
seq="$work/synth_tum_walking_loop_s7_$frames"
# (generated again when its camera.json predates the rolling shutter's readout in it)
{ [ -f "$seq/rgb.txt" ] && grep -q rolling_shutter_readout_s "$seq/camera.json"; } || "$bin/dynvo-synth" --scenario tum_walking --camera-path loop --frames "$frames" --seed 7 \
  --out "$seq" --force >&2

for run in $(seq "$runs"); do
  "$bin/dynvo-cli" run --quiet --force --dataset "$seq" --config "$root/configs/dynvo.json" --out "$work/vo_$run"
  "$bin/dynvo-cli" run --quiet --force --dataset "$seq" --config "$root/configs/dynvo.json" --out "$work/slam_$run" \
    --mode slam --map
done
for run in $(seq "$runs"); do
  "$bin/ate" "$seq/groundtruth.txt" "$work/vo_$run/trajectory.txt" --json > "$work/vo_$run/ate.json"
  "$bin/ate" "$seq/groundtruth.txt" "$work/slam_$run/trajectory.txt" --json > "$work/slam_$run/ate.json"
done

"${PYTHON:-/usr/bin/python3}" - "$work" "$runs" "$frames" "$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)" \
  > "$root/bench/results/slam_cost.md" <<'PY'
import json, os, statistics, sys
work, runs, frames, cpu = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def figures(mode):
    rows = []
    for run in range(1, runs + 1):
        d = os.path.join(work, f"{mode}_{run}")
        info = json.load(open(os.path.join(d, "run.json")))
        ate = json.load(open(os.path.join(d, "ate.json")))["absolute_translational_error_m"]["rmse"]
        row = {"median": info["time"]["processing_ms"]["median"], "p90": info["time"]["processing_ms"]["p90"],
               "rss": info["memory"]["peak_rss_mb"], "ate": ate}
        if mode == "slam":
            row.update(map_mb=os.path.getsize(os.path.join(d, "map.ply")) / 1e6, points=info["loops"]["map_points"],
                       loops=info["loops"]["accepted"])
        rows.append(row)
    return {key: statistics.median(r[key] for r in rows) for key in rows[0]}
vo, slam = figures("vo"), figures("slam")
print(f"Slam mode's cost (`bash bench/slam_cost.sh`, {runs} interleaved runs per mode, configs/dynvo.json, "
      f"a generated {frames}-frame loop with people walking, {os.cpu_count()} cores, {cpu}): medians over runs of each "
      "run's median and p90 `processing_ms`, peak RSS (`run.json`), ATE (`ate GT trajectory.txt`).\n")
print("| mode | median ms | p90 ms | peak RSS MB | ATE m | map.ply MB | map points | loops |")
print("|---|---|---|---|---|---|---|---|")
print(f"| vo | {vo['median']:.2f} | {vo['p90']:.2f} | {vo['rss']:.0f} | {vo['ate']:.4f} | - | - | - |")
print(f"| slam --map | {slam['median']:.2f} | {slam['p90']:.2f} | {slam['rss']:.0f} | {slam['ate']:.4f} "
      f"| {slam['map_mb']:.1f} | {slam['points']:.0f} | {slam['loops']:.0f} |")
print(f"\nAdded by slam mode: {slam['median'] - vo['median']:+.2f} ms median per frame, "
      f"{slam['p90'] - vo['p90']:+.2f} ms p90; ATE {vo['ate'] / slam['ate']:.2f}x lower.")
PY
cat "$root/bench/results/slam_cost.md"
