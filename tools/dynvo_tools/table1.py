"""`table1`: Table 1 of Niu & Li (2019) regenerated on the sequence folders at hand.

Runs `dynvo-cli run` with configs/baseline.json (baseline: no dynamic handling) and
configs/paper.json (ours: the paper's method) on every sequence folder, evaluates each run
(evaluation.evaluate_run: per-second RPE, per-frame RPE and ATE, reports in RUN_DIR/rpe.json,
rpe_per_frame.json and ate.json), and writes OUT/table1.md and OUT/table1.csv: our two columns,
the paper's two published columns (ORB-SLAM2 VO and the paper), the improvement in %, and the
median ms per frame.

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
  python3 -m dynvo_tools table1 [SEQ_DIR...] [--root DIR]... [--out DIR] [--frames N] [--jobs N]
                                [--force] [--results DIR]
  (tools/ on PYTHONPATH; env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin;
   DYNVO_SHARED_DIR, default ../shared)
"""
from __future__ import annotations

import argparse
import csv
import functools
import io
import os
import re
import shlex
import subprocess
import sys
import time
from dataclasses import dataclass
from typing import Optional, Sequence, Union

from .common import (ROOT, ToolError, bin_dir, bin_path, config_path, display_path, json_number, log,
                     read_json, run_parallel, shared_dir, write_atomically)
from .evaluation import ATE, RPE_PER_FRAME, RPE_PER_SECOND, Metric, RunRequest, evaluate_run, run_dynvo

COMMAND = "table1"
Cell = Union[int, float, str]   # a number, or ABSENT / FAILED / "-"
Cells = dict[str, Cell]

# Published figures, not our output: Niu & Li (2019), "Visual odometry algorithm based on
# dynamic object feature point removal", Table 1, translational RPE RMSE in m (the paper does
# not say which RPE variant). Columns: ORB-SLAM2 (its visual odometry front end), the paper.
PUBLISHED_TABLE1 = (
    ("fr2_desk_person", 0.028470, 0.006524),
    ("fr3_sitting_halfsphere", 0.022873, 0.022707),
    ("fr3_sitting_rpy", 0.027072, 0.025064),
    ("fr3_sitting_static", 0.012438, 0.010573),
    ("fr3_sitting_xyz", 0.011698, 0.011544),
    ("fr3_walking_halfsphere", 0.447234, 0.299790),
    ("fr3_walking_rpy", 0.912968, 0.612395),
    ("fr3_walking_static", 0.463615, 0.056029),
    ("fr3_walking_xyz", 0.819595, 0.105852),
)
# Same source, section 3: mean time per frame (i7-7700HQ 2.8 GHz, CPU only).
PUBLISHED_MS_ORBSLAM2, PUBLISHED_MS_PAPER = 37.683, 56.746


@dataclass(frozen=True)
class Mode:
    """One column pair of the table: its label, its config and its run folder's name."""
    label: str     # in the table: baseline, ours
    config: str    # configs/CONFIG.json
    run_name: str  # OUT/runs/SEQUENCE/RUN_NAME


MODES = (Mode("baseline", "baseline", "baseline"), Mode("ours", "paper", "paper"))
# (key in the CSV columns, the evaluation)
METRICS: tuple[tuple[str, Metric], ...] = (
    ("rpe_per_second", RPE_PER_SECOND), ("rpe_per_frame", RPE_PER_FRAME), ("ate", ATE))
ABSENT, FAILED = "absent", "failed"
DEFAULT_FRAMES = 300
SEQUENCES_NOTE = (
    "Sequences here: made by `tools/make_sequences.sh`: synthetic ones (%d frames,"
    " seed 1, articulated photo people as TUM films them, camera path in the name:"
    " xyz hand-held translation, rpy rotation, halfsphere orbit; synth_none_* are the"
    " same without people) and people inserted into the real fr1_rpy_head150 with the"
    " TUM presets (when the project's data is present); and the real TUM folders found"
    " (NAME_headN: the first N frames of"
    " a TUM sequence).")


def row_name(folder: str) -> str:
    """Folder -> row name: rgbd_dataset_freiburg3_walking_xyz -> fr3_walking_xyz (as in Table 1)."""
    name = os.path.basename(os.path.normpath(folder))
    name = re.sub(r"^rgbd_dataset_freiburg(\d)_", r"fr\1_", name)
    return "fr2_desk_person" if name == "fr2_desk_with_person" else name


def checked_sequence(folder: str) -> str:
    """The folder, when it is a TUM-style sequence folder (with rgb.txt); else a ToolError."""
    if not os.path.isdir(folder):
        raise ToolError("%s: no such folder" % folder)
    if not os.path.isfile(os.path.join(folder, "rgb.txt")):
        raise ToolError("%s: no rgb.txt (not a TUM-style sequence folder)" % folder)
    return folder


def sequences_under(root: str) -> list[str]:
    """Every folder with rgb.txt under root (root included), sorted; not below such a folder."""
    if not os.path.isdir(root):
        raise ToolError("%s: no such folder" % root)
    found = []
    for folder, subfolders, files in os.walk(root):
        subfolders.sort()
        if "rgb.txt" in files:
            found.append(folder)
            subfolders[:] = []
    if not found:
        raise ToolError("%s: no sequence folder (with rgb.txt) under it" % root)
    return found


def sequences_here(out_dir: str, frames: int) -> list[str]:
    """The generated sequences (made now if missing, by tools/make_sequences.sh into
    OUT/sequences) and the real ones on this machine."""
    generator = os.path.join(ROOT, "tools", "make_sequences.sh")
    env = dict(os.environ, DYNVO_BIN_DIR=bin_dir(), DYNVO_SHARED_DIR=shared_dir())
    made = subprocess.run(["bash", generator, "--out", os.path.join(out_dir, "sequences"),
                           "--frames", str(frames)], env=env, stdout=subprocess.PIPE, text=True)
    if made.returncode != 0:
        raise ToolError("%s failed (exit code %d)" % (generator, made.returncode))
    folders = made.stdout.split()
    for real in (os.path.join(shared_dir(), "data", "tum"), os.path.join(ROOT, "data", "tum")):
        if os.path.isdir(real):
            folders += [os.path.join(real, name) for name in sorted(os.listdir(real))
                        if os.path.isfile(os.path.join(real, name, "rgb.txt"))]
    return folders


def run_is_finished(run_dir: str, sequence: str, config: str) -> bool:
    """True when run_dir holds a completed run of this sequence and config, newer than both and
    than the dynvo-cli binary (a rebuilt binary may give other results)."""
    try:
        info = read_json(run_dir, os.path.join(run_dir, "run.json"))
        return (info.get("status") == "completed"
                and os.path.realpath(info["dataset"]["folder"]) == os.path.realpath(sequence)
                and os.path.realpath(info["config_file"]) == os.path.realpath(config)
                and os.path.isfile(os.path.join(run_dir, "trajectory.txt"))
                and os.path.getmtime(os.path.join(run_dir, "run.json"))
                >= max(os.path.getmtime(os.path.join(sequence, "rgb.txt")), os.path.getmtime(config),
                       os.path.getmtime(bin_path("dynvo-cli"))))
    except (ToolError, OSError, ValueError, KeyError, TypeError):
        return False


def run_and_evaluate(name: str, sequence: str, mode: Mode, out_dir: str, force: bool) -> Cells:
    """One run of one config on one sequence, and its three evaluations.

    Returns {"frames", "ms", <metric key>...}: numbers; all FAILED when the run failed, and
    FAILED in a metric's cell when that evaluation failed (the reasons go to stderr)."""
    cells: Cells = {key: FAILED for key in ("frames", "ms", *(key for key, _ in METRICS))}
    try:
        run_dir = run_unless_finished(name, sequence, mode, out_dir, force)
        run = evaluate_run(sequence, run_dir, (), "run")  # run.json alone
        cells["frames"] = run.frames()
        cells["ms"] = json_number("run", os.path.join(run_dir, "run.json"), run.info, "time.processing_ms.median")
    except (ToolError, OSError) as error:  # OSError: an output that could not be read or written
        log(COMMAND, "%s %s: failed: %s" % (name, mode.label, error))
        return cells
    for key, metric in METRICS:
        try:
            cells[key] = evaluate_run(sequence, run_dir, (metric,), "evaluation").rmse(metric)
        except (ToolError, OSError) as error:
            log(COMMAND, "%s %s: %s failed: %s" % (name, mode.label, " ".join((metric.program,) + metric.arguments),
                                                  error))
    return cells


def run_unless_finished(name: str, sequence: str, mode: Mode, out_dir: str, force: bool) -> str:
    """The run folder of a mode on a sequence, run now unless a finished run is kept there (not
    with force); a ToolError when the run fails or there is nothing to evaluate against."""
    config = config_path(mode.config)
    run_dir = os.path.join(out_dir, "runs", name, mode.run_name)
    if not os.path.isfile(os.path.join(sequence, "groundtruth.txt")):  # not worth a run
        raise ToolError("%s: no groundtruth.txt to evaluate against" % display_path(sequence))
    if not force and run_is_finished(run_dir, sequence, config):
        log(COMMAND, "%s %s: kept the finished run in %s" % (name, mode.label, run_dir))
    else:
        log(COMMAND, "%s %s: running %s" % (name, mode.label, display_path(config)))
        start = time.monotonic()
        run_dynvo(RunRequest(sequence, run_dir, config), "dynvo-cli run")
        log(COMMAND, "%s %s: done in %.0f s" % (name, mode.label, time.monotonic() - start))
    return run_dir


def run_all(by_name: dict[str, str], out_dir: str, jobs: int, force: bool) -> dict[str, dict[str, Cells]]:
    """Every mode on every sequence, `jobs` at a time: row name -> mode label -> cells."""
    pairs = [(name, mode) for name in by_name for mode in MODES]
    tasks = [functools.partial(run_and_evaluate, name, by_name[name], mode, out_dir, force)
             for name, mode in pairs]
    results: dict[str, dict[str, Cells]] = {name: {} for name in by_name}
    for (name, mode), cells in zip(pairs, run_parallel(tasks, jobs)):
        results[name][mode.label] = cells
    return results


def gain_pct(reference: Cell, value: Cell) -> Cell:
    """(reference - value) / reference in %: positive when value is the lower error; the
    ABSENT / FAILED of either cell as it is."""
    for cell in (reference, value):
        if isinstance(cell, str):
            return cell
    return 100.0 * (reference - value) / reference  # type: ignore[operator]


def table_rows(matched: dict[str, str], extra: Sequence[tuple[str, str]],
               results: dict[str, dict[str, Cells]]) -> list[Cells]:
    """One dict per row: the 9 Table 1 rows in the paper's order, then the extra sequences."""
    rows = []
    for name, orbslam2, paper in PUBLISHED_TABLE1:
        row: Cells = {"sequence": name, "in_paper_table1": "yes",
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


def measured_cells(folder: Optional[str], by_mode: Optional[dict[str, Cells]]) -> Cells:
    """Our cells of one row: numbers, FAILED, or ABSENT everywhere when there is no folder."""
    keys = ["folder", "frames"] + ["%s_ms_per_frame" % mode.label for mode in MODES]
    for key, _ in METRICS:
        keys += ["baseline_%s_m" % key, "ours_%s_m" % key, "improvement_%s_pct" % key]
    if folder is None or by_mode is None:
        return {key: ABSENT for key in keys}
    ours, baseline = by_mode["ours"], by_mode["baseline"]
    cells: Cells = {"folder": display_path(folder),
                    "frames": ours["frames"] if ours["frames"] != FAILED else baseline["frames"],
                    "baseline_ms_per_frame": baseline["ms"], "ours_ms_per_frame": ours["ms"]}
    for key, _ in METRICS:
        cells["baseline_%s_m" % key], cells["ours_%s_m" % key] = baseline[key], ours[key]
        cells["improvement_%s_pct" % key] = gain_pct(baseline[key], ours[key])
    return cells


CSV_COLUMNS = (
    "sequence", "in_paper_table1", "folder", "frames",
    "baseline_rpe_per_second_m", "ours_rpe_per_second_m", "improvement_rpe_per_second_pct",
    "baseline_rpe_per_frame_m", "ours_rpe_per_frame_m", "improvement_rpe_per_frame_pct",
    "baseline_ate_m", "ours_ate_m", "improvement_ate_pct",
    "published_orbslam2_vo_m", "published_paper_m", "published_improvement_pct",
    "baseline_ms_per_frame", "ours_ms_per_frame")


def csv_text(rows: Sequence[Cells]) -> str:
    """table1.csv: CSV_COLUMNS, floats in full (repr)."""
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=CSV_COLUMNS)
    writer.writeheader()
    for row in rows:
        writer.writerow({key: repr(value) if isinstance(value, float) else value
                         for key, value in row.items()})
    return text.getvalue()


def number(value: Cell, pattern: str) -> str:
    """A cell of the Markdown tables: a number formatted, a word as it is."""
    return value if isinstance(value, str) else pattern % value


# (header, CSV column, format) of the Markdown tables; published columns only in the first.
MEASURED_COLUMNS = (("baseline RPE/s", "baseline_rpe_per_second_m", "%.6f"),
                    ("ours RPE/s", "ours_rpe_per_second_m", "%.6f"),
                    ("gain RPE/s", "improvement_rpe_per_second_pct", "%+.1f%%"))
PUBLISHED_COLUMNS = (("ORB-SLAM2 VO, published", "published_orbslam2_vo_m", "%.6f"),
                     ("paper, published", "published_paper_m", "%.6f"),
                     ("gain, published", "published_improvement_pct", "%+.1f%%"))
MORE_COLUMNS = (("baseline RPE/frame", "baseline_rpe_per_frame_m", "%.6f"),
                ("ours RPE/frame", "ours_rpe_per_frame_m", "%.6f"),
                ("baseline ATE", "baseline_ate_m", "%.6f"),
                ("ours ATE", "ours_ate_m", "%.6f"),
                ("baseline ms/frame", "baseline_ms_per_frame", "%.1f"),
                ("ours ms/frame", "ours_ms_per_frame", "%.1f"))


def markdown_table(rows: Sequence[Cells], columns: Sequence[tuple[str, str, str]]) -> str:
    """A Markdown table of the rows: sequence, frames, then the columns given."""
    columns = [("sequence", "sequence", "%s"), ("frames", "frames", "%d"), *columns]
    lines = ["| " + " | ".join(header for header, _, _ in columns) + " |",
             "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(number(row[key], pattern)
                                       for _, key, pattern in columns) + " |")
    return "\n".join(lines)


def markdown(rows: Sequence[Cells], jobs: int, sequences_note: str, command: str) -> str:
    """table1.md: what each column is, the Table 1 rows, the other rows, how it was made."""
    published_ms = "ORB-SLAM2 %.1f, the paper %.1f ms/frame" % (PUBLISHED_MS_ORBSLAM2, PUBLISHED_MS_PAPER)
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
            jobs, "" if jobs == 1 else "s", os.cpu_count() or 1),
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
        text += ["", "Other sequences:", "", markdown_table(extra, MEASURED_COLUMNS + MORE_COLUMNS)]
    text += [""]
    if sequences_note:
        text += [sequences_note, ""]
    text += ["Generated by `%s`." % command]
    return "\n".join(text) + "\n"


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `table1` command."""
    parser = commands.add_parser(
        COMMAND, help="the paper's Table 1 on the sequences at hand",
        description="Table 1 of Niu & Li (2019), regenerated on sequence folders.")
    parser.add_argument("sequences", nargs="*", metavar="SEQ_DIR",
                        help="TUM-style sequence folder (with rgb.txt)")
    parser.add_argument("--root", action="append", default=[], metavar="DIR",
                        help="take every folder with rgb.txt under DIR (repeatable)")
    parser.add_argument("--out", metavar="DIR",
                        help="runs, generated sequences, table1.md and table1.csv"
                             " (default: out/table1)")
    parser.add_argument("--frames", type=int, metavar="N",
                        help="length of the generated synthetic sequences (default %d); only"
                             " without SEQ_DIR and --root" % DEFAULT_FRAMES)
    parser.add_argument("--jobs", type=int, default=1, metavar="N",
                        help="runs at the same time (default 1; timings share the cores)")
    parser.add_argument("--force", action="store_true", help="redo finished runs")
    parser.add_argument("--results", metavar="DIR",
                        help="also write table1.md and table1.csv into DIR"
                             " (the copy docs/results.md shows: bench/results)")
    parser.set_defaults(run=functools.partial(run_command, parser))


def check_arguments(parser: argparse.ArgumentParser, args: argparse.Namespace) -> None:
    """What argparse cannot check by itself; parser.error (exit code 2) when wrong."""
    if args.frames is not None and (args.sequences or args.root):
        parser.error("--frames sets the length of the generated sequences: it applies only"
                     " without SEQ_DIR and --root")
    if args.frames is not None and args.frames < 2:
        parser.error("--frames must be at least 2")
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")


def given_arguments(args: argparse.Namespace) -> list[str]:
    """The command's arguments as typed (those after `table1`)."""
    return list(args.argv[1:])


def sequence_rows(args: argparse.Namespace, out_dir: str) -> tuple[dict[str, str], str]:
    """Row name -> absolute sequence folder, and the note on the sequences here (empty when the
    folders were given). A ToolError for a bad folder or two folders of one row."""
    if args.sequences or args.root:
        folders = [checked_sequence(folder) for folder in args.sequences]
        for root in args.root:
            folders += sequences_under(root)
        note = ""
    else:
        frames = args.frames or DEFAULT_FRAMES
        folders = sequences_here(out_dir, frames)
        note = SEQUENCES_NOTE % frames
    by_name: dict[str, str] = {}
    for folder in folders:
        name = row_name(folder)
        if name in by_name and os.path.realpath(by_name[name]) != os.path.realpath(folder):
            raise ToolError("two folders give the row %s: %s and %s" % (name, by_name[name], folder))
        by_name[name] = os.path.abspath(folder)
    return by_name, note


def run_command(parser: argparse.ArgumentParser, args: argparse.Namespace) -> int:
    """Runs and evaluates every sequence, writes table1.md and table1.csv (in OUT and in
    --results) and prints the Markdown; exit code 1 when a run or evaluation failed."""
    check_arguments(parser, args)
    out_dir = os.path.abspath(args.out or os.path.join(ROOT, "out", "table1"))
    for program in ("dynvo-cli", "rpe", "ate"):
        if not os.access(bin_path(program), os.X_OK):
            raise ToolError("%s not found: build it first (tools/table1.sh does)" % bin_path(program))
    by_name, sequences_note = sequence_rows(args, out_dir)
    table1_names = {name for name, _, _ in PUBLISHED_TABLE1}
    matched = {name: folder for name, folder in by_name.items() if name in table1_names}
    extra = [(name, folder) for name, folder in by_name.items() if name not in table1_names]

    results = run_all(by_name, out_dir, args.jobs, args.force)
    rows = table_rows(matched, extra, results)
    command = " ".join(["bash tools/table1.sh"] + [shlex.quote(a) for a in given_arguments(args)])
    text = markdown(rows, args.jobs, sequences_note, command)
    sys.stdout.write(text)
    for directory in [out_dir] + ([args.results] if args.results else []):
        os.makedirs(directory, exist_ok=True)
        write_atomically(os.path.join(directory, "table1.csv"), csv_text(rows))
        write_atomically(os.path.join(directory, "table1.md"), text)
        log(COMMAND, "wrote %s and table1.csv" % os.path.join(directory, "table1.md"))

    failures = sum(FAILED in cells.values() for by_mode in results.values() for cells in by_mode.values())
    if failures:
        log(COMMAND, "%d of %d runs failed or could not be evaluated: see the reasons above"
            % (failures, len(by_name) * len(MODES)))
        return 1
    return 0
