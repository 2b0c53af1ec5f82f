#!/usr/bin/env python3
"""Which features the pose used, by distance to the people.

feature_use_table.py LABEL:RUN_DIR[:MASK_SEQUENCE] ... > table.md

Each RUN_DIR is a `dynvo-cli run --debug-frames ...` output; its debug/frame_*_features.csv
lists every feature of a debug frame (kept, removed or readmitted; inlier of the final pose or
not). MASK_SEQUENCE (default: the run's own dataset, from run.json) is a generated sequence whose
masks.txt says where the people are: give the dynamic sequence's folder for its twin without
people to count the twin's features in the same image regions. Distances are to the nearest
ground-truth mask pixel of the frame (0 = on a person), in pixels. Prints a Markdown table:
per distance band, features per frame (of them kept by the dynamic mask) and the share of all
of them that are inliers.
"""
import csv
import glob
import json
import os
import re
import sys

import numpy as np
from PIL import Image

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from figures import FigureError, lookup, read_list  # noqa: E402  (TUM list files, as figures.py reads them)

BANDS = [(0, 0.5, "on a person"), (0.5, 5, "0-5 px"), (5, 15, "5-15 px"), (15, 30, "15-30 px"),
         (30, 60, "30-60 px"), (60, 120, "60-120 px"), (120, float("inf"), "over 120 px")]


def fail(message):
    sys.exit("feature_use_table.py: " + message)


def mask_at(sequence, masks, stamp):
    """The ground-truth mask (bool) listed in masks.txt for `stamp`."""
    name = lookup(masks, stamp)
    if name is None:
        fail(f"{sequence}/masks.txt: no mask for stamp {stamp:.6f}")
    return np.array(Image.open(os.path.join(sequence, name))) > 0


def distances_to(mask, xs, ys):
    """Distance (pixels) from each (x, y) to the nearest true pixel of `mask` (inf: none)."""
    if not mask.any():
        return np.full(len(xs), np.inf)
    # The nearest mask pixel of an outside point lies on the mask's edge.
    inner = mask.copy()
    inner[1:, :] &= mask[:-1, :]
    inner[:-1, :] &= mask[1:, :]
    inner[:, 1:] &= mask[:, :-1]
    inner[:, :-1] &= mask[:, 1:]
    ey, ex = np.nonzero(mask & ~inner)
    out = np.empty(len(xs))
    for start in range(0, len(xs), 256):
        dx = xs[start:start + 256, None] - ex[None, :]
        dy = ys[start:start + 256, None] - ey[None, :]
        out[start:start + 256] = np.sqrt((dx * dx + dy * dy).min(axis=1))
    out[mask[ys, xs]] = 0.0
    return out


def bands_of(run_dir, sequence):
    """Per band: [features, kept, inliers] summed over the debug frames; and the frame count."""
    timing = os.path.join(run_dir, "timing.csv")
    if not os.path.exists(timing):
        fail(f"{timing}: missing (not a dynvo-cli run folder?)")
    stamps = {int(row["frame"]): float(row["stamp"]) for row in csv.DictReader(open(timing))}
    masks_txt = os.path.join(sequence, "masks.txt")
    if not os.path.exists(masks_txt):
        fail(f"{masks_txt}: missing (the mask sequence must be a generated one)")
    masks = read_list(masks_txt)
    files = sorted(glob.glob(os.path.join(run_dir, "debug", "frame_*_features.csv")))
    if not files:
        fail(f"{run_dir}/debug: no frame_*_features.csv (run with --debug-frames)")
    totals = [[0, 0, 0] for _ in BANDS]
    for path in files:
        frame = int(re.search(r"frame_(\d+)_features", path).group(1))
        if frame not in stamps:
            fail(f"{run_dir}/timing.csv: no row for frame {frame} of {path}")
        mask = mask_at(sequence, masks, stamps[frame])
        rows = list(csv.DictReader(open(path)))
        xs = np.clip(np.round([float(r["x"]) for r in rows]).astype(int), 0, mask.shape[1] - 1)
        ys = np.clip(np.round([float(r["y"]) for r in rows]).astype(int), 0, mask.shape[0] - 1)
        for row, d in zip(rows, distances_to(mask, xs, ys)):
            for k, (low, high, _) in enumerate(BANDS):
                if low <= d < high:
                    totals[k][0] += 1
                    totals[k][1] += row["status"] == "kept"
                    totals[k][2] += row["inlier"] == "1"
                    break
    return totals, len(files)


def main():
    if len(sys.argv) < 2:
        fail("usage: feature_use_table.py LABEL:RUN_DIR[:MASK_SEQUENCE] ...")
    columns = []
    for spec in sys.argv[1:]:
        parts = spec.split(":")
        if len(parts) not in (2, 3):
            fail(f"'{spec}': expected LABEL:RUN_DIR[:MASK_SEQUENCE]")
        label, run_dir = parts[0], parts[1]
        if len(parts) == 3:
            sequence = parts[2]
        else:
            report = os.path.join(run_dir, "run.json")
            if not os.path.exists(report):
                fail(f"{report}: missing; give the mask sequence as LABEL:RUN_DIR:MASK_SEQUENCE")
            sequence = json.load(open(report))["dataset"]["folder"]
        columns.append((label, *bands_of(run_dir, sequence)))
    print("| distance to the people | " + " | ".join(f"{c[0]}: features (kept), inliers" for c in columns) + " |")
    print("|---|" + "---|" * len(columns))
    rows = [(name, [t[k] for _, t, _ in columns]) for k, (_, _, name) in enumerate(BANDS)]
    rows.append(("all", [[sum(band[i] for band in t) for i in range(3)] for _, t, _ in columns]))
    for name, cells in rows:
        text = []
        for (_, _, frames), (n, kept, used) in zip(columns, cells):
            text.append(f"{n / frames:.0f} ({kept / frames:.0f}), {100.0 * used / n:.0f}%" if n else "0")
        print(f"| {name} | " + " | ".join(text) + " |")

if __name__ == "__main__":
    try:
        main()
    except FigureError as e:
        fail(str(e))
