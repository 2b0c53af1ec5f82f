#!/usr/bin/env python3
"""Markdown table of the seed runs of bench/accuracy.sh: accuracy_seeds_table.py CSV > accuracy_seeds.md"""
import csv, statistics, sys
from collections import OrderedDict

rows = list(csv.DictReader(open(sys.argv[1])))
by_sequence = OrderedDict()
for r in rows:
    by_sequence.setdefault(r["sequence"], []).append(r)
modes = ("paper", "paper_strict", "tuned", "occlusion", "baseline")


def summary(values):
    return "%.4f [%.4f, %.4f] mean %.4f" % (statistics.median(values), min(values), max(values),
                                          statistics.mean(values))


def change(values, reference):
    """Median and mean of `values` against those of `reference`, in percent."""
    return "%+.1f%% (mean %+.1f%%)" % (
        100.0 * (statistics.median(values) - statistics.median(reference)) / statistics.median(reference),
        100.0 * (statistics.mean(values) - statistics.mean(reference)) / statistics.mean(reference))


medians = {}
for name, runs in by_sequence.items():
    medians[name] = {m: statistics.median(float(r[m + "_rpe"]) for r in runs) for m in modes}
seeds = len(next(iter(by_sequence.values()))) if by_sequence else 0
print("Per-second translational RPE RMSE (m/s) of the real sequences over %d RANSAC seeds "
      "(`--set ego_motion.seed=S --set pose.seed=S`, S = 1..%d): median [min, max] and mean. The inserted-people "
      "rows are compared with fr1_rpy_head150's median (their twin). Paper, strict: Otsu alone, masked "
      "features never rejoin and new map points are trusted at once (`--set "
      "dynamic_mask.min_otsu_threshold=0 --set tracking.readmit_masked_px=0 --set "
      "tracking.new_point_confirmations=0`). Occlusion: configs/occlusion.json (paper.json with the seeded "
      "map occlusion, its depth-change seeds, the depth trim, the refill, the background fill and coherent "
      "motion left out of the pose). Generated "
      "by `bash "
      "bench/accuracy.sh`."
      % (seeds, seeds))
print()
print("| sequence | paper | paper, strict | tuned | occlusion | baseline | paper / twin | strict / twin "
      "| tuned / twin | occlusion / twin | baseline / twin | paper vs baseline | strict vs baseline "
      "| occlusion vs baseline |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
twin = medians.get("fr1_rpy_head150")
for name, runs in by_sequence.items():
    cells = [summary([float(r[m + "_rpe"]) for r in runs]) for m in modes]
    if twin is not None and name.startswith("fr1_rpy_head150 +"):
        ratios = ["%.2fx" % (medians[name][m] / twin[m]) for m in modes]
    else:
        ratios = ["-"] * len(modes)
    values = {m: [float(r[m + "_rpe"]) for r in runs] for m in modes}
    print("| %s | %s | %s | %s | %s | %s |" % (name, " | ".join(cells), " | ".join(ratios),
                                              change(values["paper"], values["baseline"]),
                                              change(values["paper_strict"], values["baseline"]),
                                              change(values["occlusion"], values["baseline"])))

print()
print("Per-frame translational RPE RMSE (m, `rpe GT EST --delta 1 --delta-unit f`) of the same runs, "
      "median [min, max] and mean over the seeds: the error of each frame-to-frame step, where removing "
      "features shows before drift averages it.")
print()
print("| sequence | paper | paper, strict | tuned | occlusion | baseline | paper vs baseline | strict vs baseline "
      "| occlusion vs baseline |")
print("|---|---|---|---|---|---|---|---|---|")
for name, runs in by_sequence.items():
    values = {m: [float(r[m + "_frame_rpe"]) for r in runs] for m in modes}
    print("| %s | %s | %s | %s | %s |" % (
        name, " | ".join(summary(values[m]) for m in modes), change(values["paper"], values["baseline"]),
        change(values["paper_strict"], values["baseline"]), change(values["occlusion"], values["baseline"])))
