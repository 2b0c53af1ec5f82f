#!/usr/bin/env python3
"""The odometry's targets (issue 4) against the figures the benchmarks wrote to a results folder:
targets_table.py RESULTS_DIR > targets.md. One row per target, one column per dynamic config
(paper.json, the paper's method; occlusion.json, paper.json with our additions), each cell
**met** or **missed** with the figures behind it. A results file not there yet makes its cells
"not measured"; a file without a column the row needs is an error naming both (exit 1)."""
import csv
import os
import statistics
import sys

CONFIGS = ["paper", "occlusion"]
MAX_RATIO = 1.3      # dynamic sequence over its twin without people
MAX_WORSE = 0.10     # real static sequences, over the baseline
MAX_FR1 = 0.035      # m/s, fr1_rpy_head150
MAX_MS = 20.0        # median ms per frame
# The 20 ms were set where OpenCV's RgbdOdometry took about 31 ms; the host's speed drifts from
# run to run, so the ratio to that peer, timed in the same process, is what is held.
MAX_PEER_RATIO = MAX_MS / 31.0
MAX_MB = 300.0       # peak RSS, on a sequence of
MEMORY_FRAMES = 900  # frames


class NotMeasured(Exception):
    """A results file the row needs is not there yet."""


class BadResults(Exception):
    """A results file is there but lacks what the row needs."""


class Results:
    """The CSV files of one results folder, read once each."""

    def __init__(self, folder):
        self.folder = folder
        self.cache = {}

    def rows(self, name, script, columns=()):
        path = os.path.join(self.folder, name)
        if name not in self.cache:
            if not os.path.exists(path):
                raise NotMeasured("not measured: run `bash bench/%s`" % script)
            with open(path, newline="") as f:
                self.cache[name] = list(csv.DictReader(f))
        rows = self.cache[name]
        header = rows[0].keys() if rows else ()
        missing = [c for c in columns if c not in header]
        if not rows or missing:
            raise BadResults("%s: %s (rerun bash bench/%s)" % (
                path, "no rows" if not rows else "no column " + ", ".join(missing), script))
        return rows


def dynamic_sequences(results, c):
    rows = results.rows("accuracy.csv", "accuracy.sh",
                        ("sequence", "kind", c + "_rpe", "twin_%s_rpe" % c, "baseline_rpe"))
    return [r for r in rows if r["kind"] != "real static"]


def dynamic_cell(results, c):
    ratios = [float(r[c + "_rpe"]) / float(r["twin_%s_rpe" % c])
              for r in dynamic_sequences(results, c)]
    within = sum(x <= MAX_RATIO for x in ratios)
    return "%d of %d within, worst %.2fx" % (within, len(ratios), max(ratios)), within == len(ratios)


def baseline_cell(results, c):
    # The baseline over the twin of the config's run, on the sequences where the config holds.
    held = [r for r in dynamic_sequences(results, c)
            if float(r[c + "_rpe"]) <= MAX_RATIO * float(r["twin_%s_rpe" % c])]
    if not held:
        return "no sequence where the config holds", False
    ratios = [float(r["baseline_rpe"]) / float(r["twin_%s_rpe" % c]) for r in held]
    over = sum(x > MAX_RATIO for x in ratios)
    return ("baseline over %.1fx on %d of those %d, worst %.2fx"
            % (MAX_RATIO, over, len(ratios), max(ratios)), over > 0)


def static_cell(results, c):
    static = {r["sequence"] for r in results.rows("accuracy.csv", "accuracy.sh", ("kind",))
              if r["kind"] == "real static"}
    seeds = results.rows("accuracy_seeds.csv", "accuracy.sh",
                         ("sequence", c + "_rpe", "baseline_rpe"))
    parts, ok = [], True
    for name in dict.fromkeys(r["sequence"] for r in seeds if r["sequence"] in static):
        rows = [r for r in seeds if r["sequence"] == name]
        mine = [float(r[c + "_rpe"]) for r in rows]
        base = [float(r["baseline_rpe"]) for r in rows]
        median = statistics.median(mine) / statistics.median(base) - 1
        mean = statistics.mean(mine) / statistics.mean(base) - 1
        ok &= median <= MAX_WORSE
        parts.append("%s %+.1f%% (mean %+.1f%%)" % (name.split("_")[0], 100 * median, 100 * mean))
    if not parts:
        raise NotMeasured("not measured: no real static sequence in accuracy_seeds.csv (they need "
                          "../shared; run `bash bench/accuracy.sh`)")
    return ", ".join(parts), ok


def fr1_cell(results, c):
    mine = [float(r[c + "_rpe"]) for r in results.rows("accuracy_seeds.csv", "accuracy.sh",
                                                       ("sequence", c + "_rpe"))
            if r["sequence"] == "fr1_rpy_head150"]
    if not mine:
        raise NotMeasured("not measured: no fr1_rpy_head150 in accuracy_seeds.csv (it needs "
                          "../shared; run `bash bench/accuracy.sh`)")
    median = statistics.median(mine)
    return ("median %.4f, max %.4f m/s over %d seeds" % (median, max(mine), len(mine)),
            median <= MAX_FR1)


def speed_cell(results, c):
    rows = [r for r in results.rows("speed.csv", "speed.sh",
                                    ("sequence", "config", "overrides", "dynvo_median_ms",
                                     "rgbd_odometry_median_ms", "ratio_to_rgbd_odometry"))
            if r["config"] == c and not r["overrides"]]
    if not rows:
        raise NotMeasured("not measured: no %s run in speed.csv (run `bash bench/speed.sh`)" % c)
    ratios = [float(r["ratio_to_rgbd_odometry"]) for r in rows]
    text = ", ".join("%s %.2f ms = %.2fx (peer %.2f ms)" % (
        "fr1" if r["sequence"].startswith("rgbd_dataset_freiburg1") else r["sequence"],
        float(r["dynvo_median_ms"]), float(r["ratio_to_rgbd_odometry"]),
        float(r["rgbd_odometry_median_ms"])) for r in rows)
    ok = max(ratios) <= MAX_PEER_RATIO
    if ok and max(float(r["dynvo_median_ms"]) for r in rows) > MAX_MS:
        text += "; over %.0f ms, within by the ratio" % MAX_MS
    return text, ok


def memory_cell(results, c):
    rows = [r for r in results.rows("memory.csv", "memory.sh", ("config", "frames", "peak_rss_mb"))
            if r["config"] == c]
    if not rows:
        raise NotMeasured("not measured: no %s run in memory.csv (run `bash bench/memory.sh`)" % c)
    longest = max(rows, key=lambda r: int(r["frames"]))
    if int(longest["frames"]) < MEMORY_FRAMES:
        raise NotMeasured("not measured at %d frames (%s at most): run `bash bench/memory.sh`"
                          % (MEMORY_FRAMES, longest["frames"]))
    rss = float(longest["peak_rss_mb"])
    return "%.1f MB at %s frames" % (rss, longest["frames"]), rss < MAX_MB


def spread_cell(results, c):
    name = "ratio_spread.csv" if c == "paper" else "ratio_spread_%s.csv" % c
    people, twins = {}, {}
    for r in results.rows(name, "ratio_spread.sh",
                          ("sequence", "scene_seed", "rpe_m", "twin_rpe_m")):
        key = (r["sequence"], r["scene_seed"])
        people.setdefault(key, []).append(float(r["rpe_m"]))
        twins.setdefault(key, []).append(float(r["twin_rpe_m"]))
    always = sum(all(p <= MAX_RATIO * t for p, t in zip(people[k], twins[k])) for k in people)
    medians = sum(statistics.median(people[k]) <= MAX_RATIO * statistics.median(twins[k])
                  for k in people)
    return ("%d of %d pairs at every budget, %d of %d by the ratio of the medians"
            % (always, len(people), medians, len(people)), always == len(people))


TARGETS = [
    ("Generated dynamic sequences (synthetic and inserted people, scene seed 1): per-second RPE "
     "within %.1fx of the twin without people" % MAX_RATIO, "accuracy.csv", dynamic_cell),
    ("... while the baseline degrades visibly (over %.1fx, where the config holds)" % MAX_RATIO,
     "accuracy.csv", baseline_cell),
    ("Real static sequences: no worse than the baseline by more than %d%% (median over RANSAC "
     "seeds)" % round(100 * MAX_WORSE), "accuracy_seeds.csv", static_cell),
    ("fr1_rpy_head150: per-second RPE at most %.3f m/s (median over RANSAC seeds)" % MAX_FR1,
     "accuracy_seeds.csv", fr1_cell),
    ("Median per-frame time at most %.0f ms at 640x480, held as at most %.3fx of RgbdOdometry "
     "in the same process" % (MAX_MS, MAX_PEER_RATIO), "speed.csv", speed_cell),
    ("Peak RSS under %.0f MB on a %d-frame sequence" % (MAX_MB, MEMORY_FRAMES), "memory.csv",
     memory_cell),
    ("Stricter than the targets (ours): the first one on the generated scenes of seeds 1-3 at "
     "990, 1000 and 1010 ORB features, every budget", "ratio_spread*.csv", spread_cell),
]


def cell_text(results, source, cell, c):
    try:
        value, ok = cell(results, c)
    except NotMeasured as e:
        return str(e)
    except (ValueError, ZeroDivisionError) as e:
        raise BadResults("%s: a figure of the %s column(s) is not a positive number (%s)"
                         % (os.path.join(results.folder, source), c, e))
    return "%s: %s" % ("**met**" if ok else "**missed**", value)


def main(argv):
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        sys.exit("usage: targets_table.py RESULTS_DIR (a folder of benchmark results)")
    results = Results(argv[1])
    try:
        rows = [(text, source, [cell_text(results, source, cell, c) for c in CONFIGS])
                for text, source, cell in TARGETS]
    except BadResults as e:
        sys.exit("targets_table: %s" % e)
    print("The targets of the odometry (issue 4) against the figures in `bench/results`, per "
          "config: `configs/paper.json` is the paper's method, `configs/occlusion.json` adds ours "
          "(Config). Generated by `bash bench/targets.sh` from the files named in each row.\n")
    print("| target | from | " + " | ".join(CONFIGS) + " |")
    print("|---|---|" + "---|" * len(CONFIGS))
    for text, source, cells in rows:
        print("| %s | `%s` | %s |" % (text, source, " | ".join(cells)))


if __name__ == "__main__":
    main(sys.argv)
