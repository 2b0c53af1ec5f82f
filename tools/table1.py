#!/usr/bin/env python3
"""Regenerates Table 1 of Niu & Li (2019) on the sequence folders at hand.

Runs `dynvo-cli run` with configs/baseline.json (baseline: no dynamic handling) and
configs/paper.json (ours: the paper's method) on every sequence folder, evaluates each run
with `rpe GT EST` (per second), `rpe GT EST --delta-unit f` (per frame) and `ate GT EST`,
and writes OUT/table1.md and OUT/table1.csv: our two columns, the paper's two published
columns (ORB-SLAM2 VO and the paper), the improvement in %, and the median ms per frame.

Sequences: the folders given, plus every TUM-style folder (one with rgb.txt) under each
--root. With neither, the sequences here: the generated ones (tools/make_sequences.sh:
synthetic scenes and, when the project's shared data is present, people inserted into
fr1_rpy_head150), the real folders in $DYNVO_SHARED_DIR/data/tum, and those in data/tum
(where tools/fetch_tum.sh puts the real Table 1 sequences).
Folders named like TUM's (rgbd_dataset_freiburg3_walking_xyz) fill the row of that sequence
(fr3_walking_xyz); a Table 1 sequence without a folder is "absent". Other folders become
extra rows. Finished runs are kept (OUT/runs/NAME/{baseline,paper}) unless --force.
A run that fails is "failed" in the table, its reason on stderr, and the exit code is 1.

Normally run through tools/table1.sh, which builds the binaries first:
  python3 tools/table1.py [SEQ_DIR...] [--root DIR]... [--out DIR] [--frames N] [--jobs N]
                          [--force] [--results DIR]
  (env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin;
   DYNVO_SHARED_DIR, default ../shared)
"""
import argparse
import concurrent.futures
import csv
import json
import os
import re
import shlex
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN_DIR = os.environ.get("DYNVO_BIN_DIR") or os.path.join(
    os.environ.get("DYNVO_BUILD_DIR") or os.path.join(ROOT, "build"), "bin")
SHARED_DIR = os.environ.get("DYNVO_SHARED_DIR") or os.path.join(ROOT, "..", "shared")

# Published figures, not our output: Niu & Li (2019), "Visual odometry algorithm based on
# dynamic object feature point removal", Table 1, translational RPE RMSE in m (the paper does
# not say which RPE variant). Columns: ORB-SLAM2 (its visual odometry front end), the paper.
PUBLISHED_TABLE1 = [
    ("fr2_desk_person", 0.028470, 0.006524),
    ("fr3_sitting_halfsphere", 0.022873, 0.022707),
    ("fr3_sitting_rpy", 0.027072, 0.025064),
    ("fr3_sitting_static", 0.012438, 0.010573),
    ("fr3_sitting_xyz", 0.011698, 0.011544),
    ("fr3_walking_halfsphere", 0.447234, 0.299790),
    ("fr3_walking_rpy", 0.912968, 0.612395),
    ("fr3_walking_static", 0.463615, 0.056029),
    ("fr3_walking_xyz", 0.819595, 0.105852),
]
# Same source, section 3: mean time per frame (i7-7700HQ 2.8 GHz, CPU only).
PUBLISHED_MS = {"ORB-SLAM2": 37.683, "paper": 56.746}

# (label in the table, config file, run folder name)
MODES = [("baseline", "configs/baseline.json", "baseline"),
         ("ours", "configs/paper.json", "paper")]
# (key, output file, command after `BIN/`, GT and EST; JSON field with the RMSE)
METRICS = [("rpe_per_second", "rpe_per_second.json", ["rpe"], "translational_error_m"),
           ("rpe_per_frame", "rpe_per_frame.json", ["rpe", "--delta-unit", "f"],
            "translational_error_m"),
           ("ate", "ate.json", ["ate"], "absolute_translational_error_m")]

ABSENT, FAILED = "absent", "failed"


class InputError(Exception):
    """A bad command-line input: reported as one line, exit code 1."""


def log(message):
    print("table1: " + message, file=sys.stderr, flush=True)


def row_name(folder):
    """Folder -> row name: rgbd_dataset_freiburg3_walking_xyz -> fr3_walking_xyz (as in Table 1)."""
    name = os.path.basename(os.path.normpath(folder))
    name = re.sub(r"^rgbd_dataset_freiburg(\d)_", r"fr\1_", name)
    return "fr2_desk_person" if name == "fr2_desk_with_person" else name


def checked_sequence(folder):
    if not os.path.isdir(folder):
        raise InputError("%s: no such folder" % folder)
    if not os.path.isfile(os.path.join(folder, "rgb.txt")):
        raise InputError("%s: no rgb.txt (not a TUM-style sequence folder)" % folder)
    return folder


def sequences_under(root):
    """Every folder with rgb.txt under root (root included), sorted; not below such a folder."""
    if not os.path.isdir(root):
        raise InputError("%s: no such folder" % root)
    found = []
    for folder, subfolders, files in os.walk(root):
        subfolders.sort()
        if "rgb.txt" in files:
            found.append(folder)
            subfolders[:] = []
    if not found:
        raise InputError("%s: no sequence folder (with rgb.txt) under it" % root)
    return found


def sequences_here(out_dir, frames):
    """The generated sequences (made now if missing) and the real ones on this machine."""
    generator = os.path.join(ROOT, "tools", "make_sequences.sh")
    env = dict(os.environ, DYNVO_BIN_DIR=BIN_DIR, DYNVO_SHARED_DIR=SHARED_DIR)
    made = subprocess.run(["bash", generator, "--out", os.path.join(out_dir, "sequences"),
                           "--frames", str(frames)], env=env, stdout=subprocess.PIPE, text=True)
    if made.returncode != 0:
        raise InputError("%s failed (exit code %d)" % (generator, made.returncode))
    folders = made.stdout.split()
    for real in (os.path.join(SHARED_DIR, "data", "tum"), os.path.join(ROOT, "data", "tum")):
        if os.path.isdir(real):
            folders += [os.path.join(real, name) for name in sorted(os.listdir(real))
                        if os.path.isfile(os.path.join(real, name, "rgb.txt"))]
    return folders


def run_is_finished(run_dir, sequence, config):
    """True when run_dir holds a completed run of this sequence and config, newer than both and
    than the dynvo-cli binary (a rebuilt binary may give other results)."""
    try:
        with open(os.path.join(run_dir, "run.json")) as f:
            info = json.load(f)
        return (info.get("status") == "completed"
                and os.path.realpath(info["dataset"]["folder"]) == os.path.realpath(sequence)
                and os.path.realpath(info["config_file"]) == os.path.realpath(config)
                and os.path.isfile(os.path.join(run_dir, "trajectory.txt"))
                and os.path.getmtime(os.path.join(run_dir, "run.json"))
                >= max(os.path.getmtime(os.path.join(sequence, "rgb.txt")), os.path.getmtime(config),
                       os.path.getmtime(os.path.join(BIN_DIR, "dynvo-cli"))))
    except (OSError, ValueError, KeyError, TypeError):
        return False


def last_line(text, fallback):
    lines = [line for line in text.splitlines() if line.strip()]
    return lines[-1] if lines else fallback


def run_and_evaluate(name, sequence, mode, out_dir, force):
    """One run of one config on one sequence, and its three evaluations.

    Returns {"frames", "ms", <metric key>...}, each a number or FAILED; reasons go to stderr."""
    failed = {key: FAILED for key in ["frames", "ms"] + [m[0] for m in METRICS]}
    try:
        return run_and_evaluate_or_raise(name, sequence, mode, out_dir, force, failed)
    except (OSError, ValueError, KeyError, TypeError) as error:  # unreadable outputs
        log("%s %s: failed: %s" % (name, mode[0], error))
        return failed


def run_and_evaluate_or_raise(name, sequence, mode, out_dir, force, failed):
    label, config_file, run_name = mode
    config = os.path.join(ROOT, config_file)
    run_dir = os.path.join(out_dir, "runs", name, run_name)
    groundtruth = os.path.join(sequence, "groundtruth.txt")
    if not os.path.isfile(groundtruth):
        log("%s %s: failed: %s: no groundtruth.txt to evaluate against" % (name, label, sequence))
        return failed
    if not force and run_is_finished(run_dir, sequence, config):
        log("%s %s: kept the finished run in %s" % (name, label, run_dir))
    else:
        log("%s %s: running %s" % (name, label, config_file))
        start = time.monotonic()
        run = subprocess.run([os.path.join(BIN_DIR, "dynvo-cli"), "run", "--quiet", "--force",
                              "--dataset", sequence, "--config", config, "--out", run_dir],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            log("%s %s: failed: dynvo-cli run: %s" % (name, label, last_line(
                run.stderr, "exit code %d" % run.returncode)))
            return failed
        log("%s %s: done in %.0f s" % (name, label, time.monotonic() - start))
    with open(os.path.join(run_dir, "run.json")) as f:
        info = json.load(f)
    result = {"frames": info["dataset"]["frames_to_process"],
              "ms": info["time"]["processing_ms"]["median"]}
    estimate = os.path.join(run_dir, "trajectory.txt")
    for key, output, command, field in METRICS:
        evaluation = subprocess.run(
            [os.path.join(BIN_DIR, command[0]), groundtruth, estimate] + command[1:] + ["--json"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if evaluation.returncode != 0:
            log("%s %s: %s failed: %s" % (name, label, " ".join(command), last_line(
                evaluation.stderr, "exit code %d" % evaluation.returncode)))
            result[key] = FAILED
            continue
        with open(os.path.join(run_dir, output), "w") as f:
            f.write(evaluation.stdout)
        result[key] = json.loads(evaluation.stdout)[field]["rmse"]
    return result


def gain_pct(reference, value):
    """(reference - value) / reference in %: positive when value is the lower error."""
    for cell in (reference, value):
        if isinstance(cell, str):
            return cell
    return 100.0 * (reference - value) / reference


def table_rows(matched, extra, results):
    """One dict per row: the 9 Table 1 rows in the paper's order, then the extra sequences."""
    rows = []
    for name, orbslam2, paper in PUBLISHED_TABLE1:
        row = {"sequence": name, "in_paper_table1": "yes",
               "published_orbslam2_vo_m": orbslam2, "published_paper_m": paper,
               "published_improvement_pct": gain_pct(orbslam2, paper)}
        row.update(measured_cells(matched.get(name), results.get(name)))
        rows.append(row)
    for name, folder in extra:
        row = {"sequence": name, "in_paper_table1": "no", "published_orbslam2_vo_m": "-",
               "published_paper_m": "-", "published_improvement_pct": "-"}
        row.update(measured_cells(folder, results[name]))
        rows.append(row)
    return rows


def measured_cells(folder, by_mode):
    """Our cells of one row: numbers, FAILED, or ABSENT everywhere when there is no folder."""
    keys = ["folder", "frames"] + ["%s_ms_per_frame" % label for label in ("baseline", "ours")]
    for key, _, _, _ in METRICS:
        keys += ["baseline_%s_m" % key, "ours_%s_m" % key, "improvement_%s_pct" % key]
    if folder is None:
        return {key: ABSENT for key in keys}
    ours, baseline = by_mode["ours"], by_mode["baseline"]
    cells = {"folder": display_path(folder),
             "frames": ours["frames"] if ours["frames"] != FAILED else baseline["frames"],
             "baseline_ms_per_frame": baseline["ms"], "ours_ms_per_frame": ours["ms"]}
    for key, _, _, _ in METRICS:
        cells["baseline_%s_m" % key], cells["ours_%s_m" % key] = baseline[key], ours[key]
        cells["improvement_%s_pct" % key] = gain_pct(baseline[key], ours[key])
    return cells


def display_path(folder):
    """Relative to the repository when inside it (no machine-specific prefix), else absolute."""
    absolute = os.path.realpath(folder)
    inside = os.path.relpath(absolute, ROOT)
    return absolute if inside.startswith("..") else inside


CSV_COLUMNS = [
    "sequence", "in_paper_table1", "folder", "frames",
    "baseline_rpe_per_second_m", "ours_rpe_per_second_m", "improvement_rpe_per_second_pct",
    "baseline_rpe_per_frame_m", "ours_rpe_per_frame_m", "improvement_rpe_per_frame_pct",
    "baseline_ate_m", "ours_ate_m", "improvement_ate_pct",
    "published_orbslam2_vo_m", "published_paper_m", "published_improvement_pct",
    "baseline_ms_per_frame", "ours_ms_per_frame"]


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_COLUMNS)
        writer.writeheader()
        for row in rows:
            writer.writerow({key: repr(value) if isinstance(value, float) else value
                             for key, value in row.items()})


def number(value, pattern):
    return value if isinstance(value, str) else pattern % value


# (header, CSV column, format) of the Markdown tables; published columns only in the first.
MEASURED_COLUMNS = [("baseline RPE/s", "baseline_rpe_per_second_m", "%.6f"),
                    ("ours RPE/s", "ours_rpe_per_second_m", "%.6f"),
                    ("gain RPE/s", "improvement_rpe_per_second_pct", "%+.1f%%")]
PUBLISHED_COLUMNS = [("ORB-SLAM2 VO, published", "published_orbslam2_vo_m", "%.6f"),
                     ("paper, published", "published_paper_m", "%.6f"),
                     ("gain, published", "published_improvement_pct", "%+.1f%%")]
MORE_COLUMNS = [("baseline RPE/frame", "baseline_rpe_per_frame_m", "%.6f"),
                ("ours RPE/frame", "ours_rpe_per_frame_m", "%.6f"),
                ("baseline ATE", "baseline_ate_m", "%.6f"),
                ("ours ATE", "ours_ate_m", "%.6f"),
                ("baseline ms/frame", "baseline_ms_per_frame", "%.1f"),
                ("ours ms/frame", "ours_ms_per_frame", "%.1f")]


def markdown_table(rows, columns):
    columns = [("sequence", "sequence", "%s"), ("frames", "frames", "%d")] + columns
    lines = ["| " + " | ".join(header for header, _, _ in columns) + " |",
             "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(number(row[key], pattern)
                                       for _, key, pattern in columns) + " |")
    return "\n".join(lines)


def markdown(rows, jobs, sequences_note, command):
    published_ms = "ORB-SLAM2 %.1f, the paper %.1f ms/frame" % (
        PUBLISHED_MS["ORB-SLAM2"], PUBLISHED_MS["paper"])
    text = [
        "Translational error RMSE of `dynvo-cli run` with `configs/baseline.json` (**baseline**:"
        " no dynamic handling) and `configs/paper.json` (**ours**: the paper's method), beside"
        " the two columns of Table 1 of Niu & Li (2019). What each column is:",
        "- **RPE/s**: per-second RPE in m/s, `rpe GT EST` (TUM `evaluate_rpe.py --fixed_delta"
        " --delta 1 --delta_unit s`).",
        "- **RPE/frame**: per-frame RPE in m, `rpe GT EST --delta-unit f` (the same with"
        " `--delta_unit f`).",
        "- **ATE**: absolute trajectory error in m, `ate GT EST` (TUM `evaluate_ate.py`, Horn"
        " alignment).",
        "- **published**: copied from the paper's Table 1, not measured here: translational RPE"
        " RMSE in m of ORB-SLAM2's visual odometry and of the paper's method. The paper does not"
        " say which RPE variant it used; per second is the likely reading, so compare with"
        " RPE/s. The paper's timing: %s (i7-7700HQ 2.8 GHz, CPU only)." % published_ms,
        "- **gain** = (baseline - ours) / baseline: positive when ours has the lower error;"
        " published: (ORB-SLAM2 - paper) / ORB-SLAM2.",
        "- **ms/frame**: median processing time per frame, image decoding excluded (run.json"
        " `time.processing_ms.median`), %d run%s at a time on %d cores." % (
            jobs, "" if jobs == 1 else "s", os.cpu_count()),
        "- **absent**: no folder of this sequence was given; **failed**: the run or its"
        " evaluation failed (the reason is on the command's stderr).",
        "",
        "The 9 sequences of Table 1:",
        "",
        markdown_table([r for r in rows if r["in_paper_table1"] == "yes"],
                       MEASURED_COLUMNS + PUBLISHED_COLUMNS + MORE_COLUMNS),
    ]
    extra = [r for r in rows if r["in_paper_table1"] == "no"]
    if extra:
        text += ["", "Other sequences:", "",
                 markdown_table(extra, MEASURED_COLUMNS + MORE_COLUMNS)]
    text += [""]
    if sequences_note:
        text += [sequences_note, ""]
    text += ["Generated by `%s`." % command]
    return "\n".join(text) + "\n"


def parse_args():
    parser = argparse.ArgumentParser(
        prog="table1", description="Table 1 of Niu & Li (2019), regenerated on sequence folders.")
    parser.add_argument("sequences", nargs="*", metavar="SEQ_DIR",
                        help="TUM-style sequence folder (with rgb.txt)")
    parser.add_argument("--root", action="append", default=[], metavar="DIR",
                        help="take every folder with rgb.txt under DIR (repeatable)")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "table1"), metavar="DIR",
                        help="runs, generated sequences, table1.md and table1.csv"
                             " (default: out/table1)")
    parser.add_argument("--frames", type=int, metavar="N",
                        help="length of the generated synthetic sequences (default 300); only"
                             " without SEQ_DIR and --root")
    parser.add_argument("--jobs", type=int, default=1, metavar="N",
                        help="runs at the same time (default 1; timings share the cores)")
    parser.add_argument("--force", action="store_true", help="redo finished runs")
    parser.add_argument("--results", metavar="DIR",
                        help="also write table1.md and table1.csv into DIR"
                             " (the copy docs/results.md shows: bench/results)")
    args = parser.parse_args()
    given = args.sequences or args.root
    if args.frames is not None and given:
        parser.error("--frames sets the length of the generated sequences: it applies only"
                     " without SEQ_DIR and --root")
    if args.frames is not None and args.frames < 2:
        parser.error("--frames must be at least 2")
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    return args


def main():
    args = parse_args()
    out_dir = os.path.abspath(args.out)
    try:
        for program in ("dynvo-cli", "rpe", "ate"):
            if not os.access(os.path.join(BIN_DIR, program), os.X_OK):
                raise InputError("%s/%s not found: build it first (tools/table1.sh does)"
                                 % (BIN_DIR, program))
        if args.sequences or args.root:
            folders = [checked_sequence(folder) for folder in args.sequences]
            for root in args.root:
                folders += sequences_under(root)
            sequences_note = ""
        else:
            frames = args.frames or 300
            folders = sequences_here(out_dir, frames)
            sequences_note = (
                "Sequences here: made by `tools/make_sequences.sh`: synthetic ones (%d frames,"
                " seed 1, articulated photo people as TUM films them, camera path in the name:"
                " xyz hand-held translation, rpy rotation, halfsphere orbit; synth_none_* are the"
                " same without people) and people inserted into the real fr1_rpy_head150 with the"
                " TUM presets (when the project's data is present); and the real TUM folders found"
                " (NAME_headN: the first N frames of"
                " a TUM sequence)." % frames)
        by_name = {}
        for folder in folders:
            name = row_name(folder)
            if name in by_name and os.path.realpath(by_name[name]) != os.path.realpath(folder):
                raise InputError("two folders give the row %s: %s and %s"
                                 % (name, by_name[name], folder))
            by_name[name] = os.path.abspath(folder)
    except InputError as error:
        print("table1: error: %s" % error, file=sys.stderr)
        return 1

    table1_names = {name for name, _, _ in PUBLISHED_TABLE1}
    matched = {name: folder for name, folder in by_name.items() if name in table1_names}
    extra = [(name, folder) for name, folder in by_name.items() if name not in table1_names]

    results = {name: {} for name in by_name}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(run_and_evaluate, name, folder, mode, out_dir, args.force):
                   (name, mode[0]) for name, folder in by_name.items() for mode in MODES}
        for future in concurrent.futures.as_completed(futures):
            name, label = futures[future]
            results[name][label] = future.result()

    rows = table_rows(matched, extra, results)
    command = " ".join(["bash tools/table1.sh"] + [shlex.quote(a) for a in sys.argv[1:]])
    text = markdown(rows, args.jobs, sequences_note, command)
    sys.stdout.write(text)
    for directory in [out_dir] + ([args.results] if args.results else []):
        os.makedirs(directory, exist_ok=True)
        write_csv(os.path.join(directory, "table1.csv"), rows)
        with open(os.path.join(directory, "table1.md"), "w") as f:
            f.write(text)
        log("wrote %s and table1.csv" % os.path.join(directory, "table1.md"))

    failures = sum(FAILED in result.values() for by_mode in results.values()
                   for result in by_mode.values())
    if failures:
        log("%d of %d runs failed or could not be evaluated: see the reasons above"
            % (failures, len(futures)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
