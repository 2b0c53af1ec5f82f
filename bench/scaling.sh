#!/usr/bin/env bash
# How dynvo's per-frame cost grows with resolution and with the number of ORB features
# (bench/odometry_speed.cc: frames decoded into memory first, median over frames, median of
# RUNS runs).
# - Resolution: the frames resized in memory to 320x240, 640x480 and 1280x960 (--scale 0.5,
#   1, 2; depth nearest-neighbour, intrinsics scaled). Paper mode, baseline and OpenCV's
#   RgbdOdometry / ICPOdometry on the same frames, plus the per-stage split of paper mode and
#   dynvo's per-second RPE at each size (`rpe`), since its pixel-unit parameters stay as set.
# - Features: paper mode and baseline at 640x480 with features.num_features 500, 1000, 2000.
# Sequence: fr1_rpy_head150 from ../shared when present, else a generated dynamic sequence
# (two people crossing, camera along x/y/z, 150 frames). Writes bench/results/scaling.md and
# bench/results/scaling.csv.
#   bash bench/scaling.sh          (env: DYNVO_BUILD_DIR, DYNVO_SHARED_DIR, DYNVO_BENCH_DIR, RUNS=3)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DYNVO_BUILD_DIR:-$root/build}"
shared="${DYNVO_SHARED_DIR:-$root/../shared}"
work="${DYNVO_BENCH_DIR:-$root/out/bench/scaling}"
runs="${RUNS:-3}"
results="$root/bench/results"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$(nproc)" --target odometry_speed dynvo-synth rpe >/dev/null
bin="$build/bin"
mkdir -p "$work/json" "$work/trajectories" "$results"
rm -rf "$work"/json/*.json "$work"/trajectories/*

sequence="$shared/data/tum/rgbd_dataset_freiburg1_rpy_head150"
if [ ! -d "$sequence" ]; then
  sequence="$work/synth_two_crossing_xyz"
  [ -f "$sequence/rgb.txt" ] || "$bin/dynvo-synth" --scenario two_crossing --camera-path xyz \
    --frames 150 --seed 1 --out "$sequence" --force >&2
fi

speed() {  # speed OUT_NAME CONFIG [odometry_speed options...]; then dynvo's RPE per second
  local name="$1" config="$2"
  shift 2
  echo "scaling: $name" >&2
  "$bin/odometry_speed" --dataset "$sequence" --config "$root/configs/$config.json" \
    --runs "$runs" --json "$work/json/$name.json" --trajectories-out "$work/trajectories/$name" \
    "$@" >&2
  "$bin/rpe" "$sequence/groundtruth.txt" "$work/trajectories/$name/dynvo.txt" --json \
    > "$work/json/$name.rpe.json"
}

for scale in 0.5 1 2; do
  speed "resolution_${scale}_paper" paper --scale "$scale"
  speed "resolution_${scale}_baseline" baseline --scale "$scale" --no-peers
done
for count in 500 1000 2000; do
  for mode in paper baseline; do
    speed "features_${count}_${mode}" "$mode" --set "features.num_features=$count" --no-peers
  done
done

python3 - "$work/json" "$results/scaling.csv" "$runs" "$(nproc)" \
  "$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)" > "$results/scaling.md" <<'PY'
import csv, json, os, sys
folder, csv_path, runs, cores, cpu = sys.argv[1:6]
cpu = cpu or "unknown CPU"
STAGES = ["dynamic_mask", "features", "filter", "match", "pose", "map", "local_ba"]

def load(name):
    report = json.load(open(os.path.join(folder, name + ".json")))
    rpe = json.load(open(os.path.join(folder, name + ".rpe.json")))
    report["rpe_m"] = rpe["translational_error_m"]["rmse"]
    return report

resolution = {s: {m: load("resolution_%s_%s" % (s, m)) for m in ("paper", "baseline")}
              for s in ("0.5", "1", "2")}
features = {n: {m: load("features_%d_%s" % (n, m)) for m in ("paper", "baseline")}
            for n in (500, 1000, 2000)}

rows = []
def add_rows(experiment, report):
    config = os.path.basename(report["config"]).replace(".json", "")
    for method, m in report["methods"].items():
        row = {"experiment": experiment, "sequence": report["dataset"], "frames": report["frames"],
               "width": report["width"], "height": report["height"],
               "num_features": report["features"]["num_features"], "config": config,
               "method": method, "median_ms": "%.3f" % m["median_ms"],
               "mean_ms": "%.3f" % m["mean_ms"], "p90_ms": "%.3f" % m["p90_ms"]}
        if method == "dynvo":
            for stage in STAGES:
                row[stage + "_median_ms"] = "%.3f" % report["stages"][stage]["median_ms"]
                row[stage + "_mean_ms"] = "%.3f" % report["stages"][stage]["mean_ms"]
            d = report["dynvo_last_run"]
            row["features_per_frame"] = "%.1f" % d["features_total_mean"]
            row["features_removed_per_frame"] = "%.1f" % d["features_removed_mean"]
            row["dynamic_pixels_pct"] = "%.2f" % (100 * d["dynamic_ratio_mean"])
            row["pose_inliers_per_frame"] = "%.1f" % d["pose_inliers_mean"]
            row["lost_frames"] = d["lost_frames"]
            row["rpe_per_second_m"] = "%.5f" % report["rpe_m"]
        rows.append(row)
for s in resolution:
    for mode in ("paper", "baseline"):
        add_rows("resolution", resolution[s][mode])
for n in features:
    for mode in ("paper", "baseline"):
        add_rows("features", features[n][mode])
fields = ["experiment", "sequence", "frames", "width", "height", "num_features", "config",
          "method", "median_ms", "mean_ms", "p90_ms"]
fields += [s + suffix for s in STAGES for suffix in ("_median_ms", "_mean_ms")]
fields += ["features_per_frame", "features_removed_per_frame", "dynamic_pixels_pct",
           "pose_inliers_per_frame", "lost_frames", "rpe_per_second_m"]
with open(csv_path, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=fields)
    writer.writeheader()
    writer.writerows(rows)

first = resolution["1"]["paper"]
ms = lambda report, method="dynvo": report["methods"][method]["median_ms"]
print("Per-frame processing time (ms; median over frames, median of %s runs) on %s (%d frames), "
      "%s cores (%s). The frames are resized in memory from the sequence's 640x480: 320x240 by "
      "area averaging; 1280x960 by bilinear upsampling, which adds pixels but no detail, so that "
      "row measures cost, not what a 1280x960 sensor would give. Depth nearest-neighbour, "
      "intrinsics scaled. Generated by `bash bench/scaling.sh`." % (
          runs, first["dataset"], first["frames"], cores, cpu))
print()
print("| resolution | paper ms | paper vs 640x480 | baseline ms | RgbdOdometry ms | ICPOdometry ms "
      "| paper / RgbdOdometry |")
print("|---|---|---|---|---|---|---|")
for s in ("0.5", "1", "2"):
    p, b = resolution[s]["paper"], resolution[s]["baseline"]
    print("| %dx%d | %.2f | %.2fx | %.2f | %.2f | %.2f | %.2f |" % (
        p["width"], p["height"], ms(p), ms(p) / ms(first), ms(b),
        ms(p, "opencv_rgbd_odometry"), ms(p, "opencv_icp_odometry"),
        p["methods"]["dynvo"]["ratio_to_rgbd_odometry"]))
print()
print("What dynvo does at each size (last run; per-second translational RPE RMSE in m, `rpe GT EST`). "
      "Kernels, radii and thresholds are in pixels and stay as configured:")
print()
print("| resolution | config | features per frame | removed per frame | dynamic pixels | pose inliers "
      "per frame | lost frames | RPE (m/s) |")
print("|---|---|---|---|---|---|---|---|")
for s in ("0.5", "1", "2"):
    for mode in ("paper", "baseline"):
        r = resolution[s][mode]
        d = r["dynvo_last_run"]
        print("| %dx%d | %s | %.0f | %.1f | %.2f%% | %.0f | %d | %.4f |" % (
            r["width"], r["height"], mode, d["features_total_mean"], d["features_removed_mean"],
            100 * d["dynamic_ratio_mean"], d["pose_inliers_mean"], d["lost_frames"], r["rpe_m"]))
print()
print("Per-stage split of paper mode by resolution (median / mean ms per frame; local BA runs at "
      "keyframes only, so its median is 0):")
print()
print("| resolution | " + " | ".join(STAGES) + " |")
print("|---|" + "---|" * len(STAGES))
for s in ("0.5", "1", "2"):
    p = resolution[s]["paper"]
    print("| %dx%d | " % (p["width"], p["height"]) + " | ".join(
        "%.2f / %.2f" % (p["stages"][n]["median_ms"], p["stages"][n]["mean_ms"]) for n in STAGES) + " |")
print()
print("Against the number of ORB features (`--set features.num_features=N`, 640x480; median ms per "
      "frame, stage columns median / mean):")
print()
print("| num_features | paper ms | baseline ms | features per frame | features stage (paper) "
      "| match (paper) | pose (paper) | local_ba (paper) | paper RPE (m/s) | baseline RPE (m/s) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for n in (500, 1000, 2000):
    p, b = features[n]["paper"], features[n]["baseline"]
    st = lambda name: "%.2f / %.2f" % (p["stages"][name]["median_ms"], p["stages"][name]["mean_ms"])
    print("| %d | %.2f | %.2f | %.0f | %s | %s | %s | %s | %.4f | %.4f |" % (
        n, ms(p), ms(b), p["dynvo_last_run"]["features_total_mean"], st("features"), st("match"),
        st("pose"), st("local_ba"), p["rpe_m"], b["rpe_m"]))
PY
cat "$results/scaling.md"
