#!/usr/bin/env python3
"""The benchmark suite: two splits of generated dynamic sequences, each run with several configs.

dev (parameters and defaults may be tuned on it) and validation (reported only, never used to
choose a parameter or default); the table SOURCES below says which sequences each holds. Each
sequence is run with each config and compared with its twin (the same frames or camera path
without people) run with the same config. Per (split, sequence, config): per-second RPE
(translational RMSE), the twin's, their ratio, ATE (SE(3)-aligned RMSE), mask precision, recall
and IoU against the generated masks, and the median and p90 of `processing_ms` per frame.

Sequences are generated into OUT/seq (kept while their spec.json matches what would be
generated), runs go to OUT/runs/SEQUENCE/CONFIG, up to --jobs at a time. Writes
RESULTS/suite_<split>.csv (one row per sequence and config) and RESULTS/suite_<split>.md, a table
made from the CSV alone (`suite.py table` makes it again without running anything).

Normally run through bench/suite.sh, which builds the binaries first:
  python3 bench/suite.py [--split dev|validation|all] [--frames N] [--configs a,b,c] [--out DIR]
                         [--results DIR] [--jobs N]
  python3 bench/suite.py table --split dev|validation|all [--results DIR]
  (env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin;
   DYNVO_SHARED_DIR, default ../shared)
"""
from __future__ import annotations

import argparse
import concurrent.futures
import csv
import functools
import json
import math
import os
import shlex
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass
from typing import Callable, Optional, TypeVar

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN_DIR = os.environ.get("DYNVO_BIN_DIR") or os.path.join(
    os.environ.get("DYNVO_BUILD_DIR") or os.path.join(ROOT, "build"), "bin")
SHARED_DIR = os.environ.get("DYNVO_SHARED_DIR") or os.path.join(ROOT, "..", "shared")

# The people of each source: the TUM presets of dynvo-insert-people (articulated photo people in
# real frames) and the same scenarios of dynvo-synth (the same people in a synthetic room).
PRESETS = ("tum_walking", "tum_toward", "tum_away", "tum_sitting")
# The people of each split's real frames: photos of Debian's opencv-doc and the boxes around them.
PHOTO = "/usr/share/doc/opencv-doc/opencv4/html/person_multi_det.jpg"
DEV_PERSON = ("--person", PHOTO, "--person-box", "343,170,40,178")
VALIDATION_PERSON = ("--person", PHOTO, "--person-box", "18,186,24,118")
CONFIGS = ("baseline", "paper", "dynvo")
SPLITS = ("dev", "validation")
INSERT, SYNTH = "inserted", "synthetic"
VALIDATION_NOTE = "Validation split: reported only, never used to choose a parameter or default."
NOT_RUN = "not run: shared data absent"


@dataclass(frozen=True)
class Source:
    """Where some of a split's sequences come from: one sequence per preset."""
    split: str
    kind: str                      # INSERT: dynvo-insert-people; SYNTH: dynvo-synth
    where: str                     # INSERT: real folder in SHARED/data/tum; SYNTH: camera path
    seed: int                      # --seed of the generator
    person: tuple[str, ...] = ()   # INSERT only: --person/--person-box arguments (none: drawn)


# The two splits, every sequence of each.
#   dev:        parameters and defaults may be tuned on it.
#   validation: reported only, never used to choose a parameter or default.
# Each source gives one sequence per preset (PRESETS). Twins: INSERT: the real folder itself;
# SYNTH: dynvo-synth with the same camera path and seed and `--scenario none`.
#      split         kind    real folder (INSERT) or camera path (SYNTH)  seed  person
SOURCES = (
    Source("dev",        INSERT, "rgbd_dataset_freiburg1_rpy_head150",       1, DEV_PERSON),
    Source("dev",        SYNTH,  "xyz",                                      1),
    Source("validation", INSERT, "rgbd_dataset_freiburg2_desk_head50",       2, VALIDATION_PERSON),
    Source("validation", SYNTH,  "rpy",                                      2),
    Source("validation", SYNTH,  "halfsphere",                               3),
)


@dataclass(frozen=True)
class Sequence:
    """A sequence folder and what makes it: a generator and its arguments (without --out), or
    nothing for a real folder used as it is."""
    name: str
    folder: str
    command: tuple[str, ...] = ()

    def spec(self) -> dict:
        """What spec.json beside the generated sequence holds: a change means generate again."""
        return {"command": list(self.command)}


@dataclass(frozen=True)
class RowSpec:
    """One row of a split: a sequence with people and its twin without."""
    split: str
    kind: str
    sequence: Sequence
    twin: Sequence
    available: bool  # False: its real folder (the shared data) is absent


@dataclass(frozen=True)
class RunResult:
    """What one run of one config on one sequence measured."""
    frames: int
    rpe_m_s: float                  # per-second RPE, translational RMSE
    ate_m: float                    # ATE, SE(3)-aligned RMSE
    mask: Optional[dict[str, float]]  # precision, recall, iou; None: no mask or no masks/
    ms_median: float
    ms_p90: float


class SuiteError(Exception):
    """A failure that stops the suite: which sequence and config, which file, what happened."""

    def __init__(self, what: str, path: str, problem: str) -> None:
        super().__init__("%s: %s: %s" % (what, display_path(path), problem))


def log(message: str) -> None:
    print("suite: " + message, file=sys.stderr, flush=True)


def display_path(path: str) -> str:
    """Relative to the repository when inside it, else as given."""
    inside = os.path.relpath(os.path.abspath(path), ROOT)
    return path if inside.startswith("..") else inside


def short_name(real_folder: str) -> str:
    """rgbd_dataset_freiburg1_rpy_head150 -> fr1_rpy_head150."""
    name = os.path.basename(os.path.normpath(real_folder))
    return name.replace("rgbd_dataset_freiburg", "fr", 1) if name.startswith("rgbd_dataset_") else name


# ---------------------------------------------------------------- sequences


def source_rows(source: Source, frames: int, seq_dir: str, shared_dir: str) -> list[RowSpec]:
    """The rows of one source: one per preset, each with its twin."""
    seed = str(source.seed)
    if source.kind == INSERT:
        real = os.path.join(shared_dir, "data", "tum", source.where)
        twin = Sequence(short_name(real), real)
        available = os.path.isdir(real)
        made = [(f"{twin.name}_{p}_s{seed}",
                 ("dynvo-insert-people", "--dataset", real, "--preset", p, "--seed", seed)
                 + source.person) for p in PRESETS]
    else:
        def synth(scenario: str) -> tuple[str, ...]:
            return ("dynvo-synth", "--scenario", scenario, "--camera-path", source.where,
                    "--seed", seed, "--frames", str(frames))
        twin_name = f"synth_none_{source.where}_s{seed}"
        twin = Sequence(twin_name, os.path.join(seq_dir, twin_name), synth("none"))
        available = True
        made = [(f"synth_{p}_{source.where}_s{seed}", synth(p)) for p in PRESETS]
    return [RowSpec(source.split, source.kind, Sequence(name, os.path.join(seq_dir, name), command),
                    twin, available) for name, command in made]


def split_rows(split: str, frames: int, out_dir: str, shared_dir: str) -> list[RowSpec]:
    seq_dir = os.path.join(out_dir, "seq")
    return [row for source in SOURCES if source.split == split
            for row in source_rows(source, frames, seq_dir, shared_dir)]


def needs_generation(sequence: Sequence) -> bool:
    """True when the folder has no rgb.txt, or no spec.json equal to the sequence's spec."""
    if not os.path.isfile(os.path.join(sequence.folder, "rgb.txt")):
        return True
    try:
        with open(os.path.join(sequence.folder, "spec.json")) as f:
            return json.load(f) != sequence.spec()
    except (OSError, ValueError):
        return True


def generate(sequence: Sequence, bin_dir: str) -> bool:
    """Generates the sequence unless it is there as specified; True when it generated it."""
    if not needs_generation(sequence):
        return False
    spec_path = os.path.join(sequence.folder, "spec.json")
    if os.path.exists(spec_path):
        os.remove(spec_path)  # no stale spec beside a half-made sequence
    log("generating %s" % sequence.name)
    program, *arguments = sequence.command
    run_tool("%s (generation)" % sequence.name,
             [os.path.join(bin_dir, program)] + arguments + ["--out", sequence.folder, "--force"])
    with open(spec_path, "w") as f:
        json.dump(sequence.spec(), f, indent=2)
        f.write("\n")
    return True


# ---------------------------------------------------------------- runs


def tail(text: str, lines: int = 8) -> str:
    kept = [line for line in text.splitlines() if line.strip()][-lines:]
    return "\n".join("  " + line for line in kept) if kept else "  (nothing on stderr)"


def run_tool(what: str, command: list[str]) -> str:
    """Runs command and returns its stdout; a missing program or a non-zero exit is a SuiteError
    naming what it was for and the program, with the end of its stderr."""
    program = command[0]
    if not os.access(program, os.X_OK):
        raise SuiteError(what, program, "not found or not executable (bash bench/suite.sh builds it)")
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise SuiteError(what, program, "exited with code %d: %s\nthe end of its stderr:\n%s" % (
            done.returncode, shlex.join(command), tail(done.stderr)))
    return done.stdout


def read_json(what: str, path: str) -> dict:
    try:
        with open(path) as f:
            data = json.load(f)
    except OSError as error:
        raise SuiteError(what, path, "cannot read: %s" % error.strerror) from None
    except ValueError as error:
        raise SuiteError(what, path, "not valid JSON (%s)" % error) from None
    if not isinstance(data, dict):
        raise SuiteError(what, path, "not a JSON object")
    return data


def json_number(what: str, path: str, data: dict, key: str) -> float:
    """The number at a dotted key ("translational_error_m.rmse") of data read from path."""
    value = data
    for part in key.split("."):
        value = value.get(part) if isinstance(value, dict) else None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise SuiteError(what, path, "no finite number at %s" % key)
    return float(value)


def mask_quality(what: str, path: str, info: dict) -> Optional[dict[str, float]]:
    """run.json's mask_quality: None when missing or null (no mask, or no masks/ to compare)."""
    if info.get("mask_quality") is None:
        return None
    return {key: json_number(what, path, info, "mask_quality." + key)
            for key in ("precision", "recall", "iou")}


def percentile(values: list[float], q: float) -> float:
    """The q-th percentile, linear between the closest ranks (numpy's default)."""
    ordered = sorted(values)
    position = (len(ordered) - 1) * q / 100.0
    low = math.floor(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def timing_stats(what: str, path: str) -> tuple[float, float]:
    """Median and p90 of the processing_ms column of a run's timing.csv."""
    try:
        with open(path, newline="") as f:
            values = [float(row["processing_ms"]) for row in csv.DictReader(f)]
    except OSError as error:
        raise SuiteError(what, path, "cannot read: %s" % error.strerror) from None
    except (KeyError, TypeError, ValueError):
        raise SuiteError(what, path, "no processing_ms column of numbers") from None
    if not values:
        raise SuiteError(what, path, "no frames")
    return statistics.median(values), percentile(values, 90)


def evaluate(what: str, bin_dir: str, metric: str, sequence: Sequence, run_dir: str) -> dict:
    """`rpe`/`ate GT TRAJ --json`, its output kept in RUN_DIR/<metric>.json and read back."""
    output = os.path.join(run_dir, metric + ".json")
    text = run_tool(what, [os.path.join(bin_dir, metric),
                           os.path.join(sequence.folder, "groundtruth.txt"),
                           os.path.join(run_dir, "trajectory.txt"), "--json"])
    with open(output, "w") as f:
        f.write(text)
    return read_json(what, output)


def run_and_evaluate(sequence: Sequence, config: str, out_dir: str, bin_dir: str) -> RunResult:
    """The one shared step: run a config on a sequence, then evaluate the run."""
    what = "%s %s" % (sequence.name, config)
    run_dir = os.path.join(out_dir, "runs", sequence.name, config)
    run_tool(what, [os.path.join(bin_dir, "dynvo-cli"), "run", "--quiet", "--force",
                    "--dataset", sequence.folder,
                    "--config", os.path.join(ROOT, "configs", config + ".json"), "--out", run_dir])
    rpe = evaluate(what, bin_dir, "rpe", sequence, run_dir)
    ate = evaluate(what, bin_dir, "ate", sequence, run_dir)
    run_json = os.path.join(run_dir, "run.json")
    info = read_json(what, run_json)
    ms_median, ms_p90 = timing_stats(what, os.path.join(run_dir, "timing.csv"))
    return RunResult(
        frames=int(json_number(what, run_json, info, "dataset.frames_to_process")),
        rpe_m_s=json_number(what, os.path.join(run_dir, "rpe.json"), rpe, "translational_error_m.rmse"),
        ate_m=json_number(what, os.path.join(run_dir, "ate.json"), ate,
                          "absolute_translational_error_m.rmse"),
        mask=mask_quality(what, run_json, info), ms_median=ms_median, ms_p90=ms_p90)


T = TypeVar("T")


def run_parallel(tasks: list[Callable[[], T]], jobs: int) -> list[T]:
    """The tasks' results in their order, up to jobs at a time. A failure cancels what has not
    started; once the running tasks are over, the first failure in task order is raised."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(task) for task in tasks]
        concurrent.futures.wait(futures, return_when=concurrent.futures.FIRST_EXCEPTION)
        for future in futures:
            future.cancel()  # only those not started
        concurrent.futures.wait(futures)
        for future in futures:
            if not future.cancelled() and future.exception():
                raise future.exception()
        return [future.result() for future in futures]


# ---------------------------------------------------------------- results CSV

CSV_COLUMNS = ["split", "sequence", "kind", "twin", "config", "status", "frames", "rpe_m_s",
               "twin_rpe_m_s", "ratio", "ate_m", "mask_precision", "mask_recall", "mask_iou",
               "ms_median", "ms_p90"]
MASK_KEYS = ("precision", "recall", "iou")


def cell(value: object) -> str:
    """A CSV cell: floats as repr (all digits), None as "-"."""
    if value is None:
        return "-"
    return repr(value) if isinstance(value, float) else str(value)


def result_row(row: RowSpec, config: str, result: Optional[RunResult],
               twin: Optional[RunResult]) -> dict[str, str]:
    """One CSV row; result None: the row was not run (its shared data is absent)."""
    values: dict[str, object] = {"split": row.split, "sequence": row.sequence.name,
                                 "kind": row.kind, "twin": row.twin.name, "config": config}
    if result is None or twin is None:
        values["status"] = NOT_RUN
        return {key: cell(values.get(key)) for key in CSV_COLUMNS}
    values.update(status="ok", frames=result.frames, rpe_m_s=result.rpe_m_s,
                  twin_rpe_m_s=twin.rpe_m_s, ate_m=result.ate_m, ms_median=result.ms_median,
                  ms_p90=result.ms_p90,
                  ratio=result.rpe_m_s / twin.rpe_m_s if twin.rpe_m_s > 0 else None)
    for key in MASK_KEYS:
        values["mask_" + key] = result.mask[key] if result.mask else None
    return {key: cell(values.get(key)) for key in CSV_COLUMNS}


def write_csv(path: str, rows: list[dict[str, str]]) -> None:
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def read_results(path: str) -> list[dict[str, str]]:
    what = "table"
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            missing = [c for c in CSV_COLUMNS if c not in (reader.fieldnames or [])]
    except OSError as error:
        raise SuiteError(what, path, "cannot read (%s): run the suite first" % error.strerror) from None
    if missing:
        raise SuiteError(what, path, "no column %s" % ", ".join(missing))
    if not rows:
        raise SuiteError(what, path, "no rows")
    return rows


# ---------------------------------------------------------------- Markdown, from the CSV alone


def csv_number(row: dict[str, str], key: str, path: str) -> Optional[float]:
    """A number of the CSV; None for "-" or an empty cell."""
    if row[key] in ("-", ""):
        return None
    try:
        return float(row[key])
    except ValueError:
        raise SuiteError("table", path, "%s %s: %s is not a number: %r" % (
            row["sequence"], row["config"], key, row[key])) from None


def caption(split: str, rows: list[dict[str, str]], configs: list[str]) -> str:
    synthetic = sorted({r["frames"] for r in rows if r["status"] == "ok" and r["kind"] == SYNTH}, key=int)
    real = {}
    for r in rows:
        if r["status"] == "ok" and r["kind"] == INSERT:
            real.setdefault(r["twin"], set()).add(r["frames"])
    frames = (["%s per synthetic sequence" % "/".join(synthetic)] if synthetic else []) + [
        "%s with people inserted into %s" % ("/".join(sorted(f, key=int)), twin)
        for twin, f in sorted(real.items())]
    text = [
        "Benchmark suite, **%s** split, configs %s (`configs/<name>.json`)." % (
            split, ", ".join(configs)),
        "**RPE**: per-second RPE, translational RMSE in m/s (`rpe GT EST`); in parentheses its"
        " ratio to the same config's RPE on the twin (the same real frames without people, or"
        " the same camera path and seed with `--scenario none`). **ATE**: SE(3)-aligned RMSE in m"
        " (`ate GT EST`, Horn alignment, no scale). **mask R/P/IoU**: recall, precision and IoU"
        " of the dynamic mask against the generated masks, over all pixels of all frames (`-`:"
        " none). **ms**: `processing_ms` per frame, median/p90, with runs in parallel.",
        "Frames: %s." % ("; ".join(frames) if frames else "none run"),
    ]
    if split == "validation":
        text.append(VALIDATION_NOTE)
    return " ".join(text[:2]) + "\n" + "\n".join(text[2:])


def masked_configs(rows: list[dict[str, str]], configs: list[str]) -> list[str]:
    """The configs with a mask quality somewhere in the split (the others have no mask)."""
    return [c for c in configs if any(r["config"] == c and r["mask_iou"] not in ("-", "")
                                      for r in rows)]


def sequence_cells(by_config: dict[str, dict[str, str]], configs: list[str], masked: list[str],
                   path: str) -> list[str]:
    """The cells of one sequence's row after its name and twin."""
    def num(config: str, key: str) -> Optional[float]:
        return csv_number(by_config[config], key, path) if config in by_config else None

    def fmt(value: Optional[float], pattern: str) -> str:
        return "-" if value is None else pattern % value

    cells = []
    for c in configs:
        ratio = num(c, "ratio")
        cells.append(fmt(num(c, "rpe_m_s"), "%.4f") + ("" if ratio is None else " (%.2fx)" % ratio))
    cells += [fmt(num(c, "ate_m"), "%.4f") for c in configs]
    for c in masked:
        values = [num(c, "mask_" + key) for key in ("recall", "precision", "iou")]
        cells.append("-" if None in values else "/".join("%.2f" % v for v in values))
    cells += ["%s/%s" % (fmt(num(c, "ms_median"), "%.1f"), fmt(num(c, "ms_p90"), "%.1f"))
              for c in configs]
    return cells


def table_lines(rows: list[dict[str, str]], configs: list[str], path: str) -> list[str]:
    masked = masked_configs(rows, configs)
    header = (["sequence", "twin"] + ["%s RPE m/s (ratio)" % c for c in configs]
              + ["%s ATE m" % c for c in configs] + ["%s mask R/P/IoU" % c for c in masked]
              + ["%s ms median/p90" % c for c in configs])
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    sequences: dict[str, dict[str, dict[str, str]]] = {}
    for r in rows:
        sequences.setdefault(r["sequence"], {})[r["config"]] = r
    for name, by_config in sequences.items():
        first = next(iter(by_config.values()))
        if first["status"] != "ok":
            cells = [first["status"]] + [""] * (len(header) - 3)
        else:
            cells = sequence_cells(by_config, configs, masked, path)
        lines.append("| " + " | ".join([name, first["twin"]] + cells) + " |")
    summary = []
    for c in configs:
        ratios = [v for r in rows if r["config"] == c and r["status"] == "ok"
                  for v in [csv_number(r, "ratio", path)] if v is not None]
        summary.append("(%.2fx)" % statistics.median(ratios) if ratios else "-")
    lines.append("| " + " | ".join(["**median ratio**", ""] + summary
                                   + [""] * (len(header) - 2 - len(configs))) + " |")
    return lines


def write_markdown(csv_path: str, md_path: str) -> None:
    """The Markdown table of one split, made from its results CSV alone."""
    rows = read_results(csv_path)
    split = rows[0]["split"]
    configs = list(dict.fromkeys(r["config"] for r in rows))
    text = [caption(split, rows, configs), ""] + table_lines(rows, configs, csv_path) + [
        "", "Generated by `bash bench/suite.sh --split %s`; the table alone again from %s by"
        " `python3 bench/suite.py table --split %s`." % (split, os.path.basename(csv_path), split)]
    with open(md_path, "w") as f:
        f.write("\n".join(text) + "\n")


# ---------------------------------------------------------------- command line


def comma_list(text: str) -> tuple[str, ...]:
    items = tuple(item.strip() for item in text.split(",") if item.strip())
    if not items:
        raise argparse.ArgumentTypeError("expected a comma-separated list, got %r" % text)
    return items


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="suite", description=__doc__.split("\n\n")[0])
    parser.add_argument("--split", choices=SPLITS + ("all",), default="all",
                        help="which split (default: all)")
    parser.add_argument("--results", default=os.path.join(ROOT, "bench", "results"), metavar="DIR",
                        help="where suite_<split>.csv and .md go (default: bench/results)")
    if argv[:1] == ["table"]:
        parser.prog = "suite table"
        parser.description = "Writes suite_<split>.md again from suite_<split>.csv alone."
        args = parser.parse_args(argv[1:])
        args.command = "table"
        return args
    parser.add_argument("--frames", type=int, default=300, metavar="N",
                        help="frames of each synthetic sequence (default 300; the sequences with"
                             " people inserted have all frames of their real folder)")
    parser.add_argument("--configs", type=comma_list, default=CONFIGS, metavar="A,B,C",
                        help="configs/<name>.json to run (default: %s)" % ",".join(CONFIGS))
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "suite"), metavar="DIR",
                        help="generated sequences and runs (default: out/bench/suite)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                        help="runs at the same time (default: the number of cores)")
    args = parser.parse_args(argv)
    args.command = "run"
    if args.frames < 2:
        parser.error("--frames must be at least 2")
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    for config in args.configs:
        if not os.path.isfile(os.path.join(ROOT, "configs", config + ".json")):
            parser.error("--configs: no configs/%s.json" % config)
    return args


def run_suite(args: argparse.Namespace, splits: tuple[str, ...]) -> None:
    start = time.monotonic()
    out_dir = os.path.abspath(args.out)
    rows = {s: split_rows(s, args.frames, out_dir, SHARED_DIR) for s in splits}
    ready = [row for split in splits for row in rows[split] if row.available]
    if len(ready) < sum(len(r) for r in rows.values()):
        log("%s: absent: the rows with people inserted into real frames are not run"
            % os.path.join(SHARED_DIR, "data", "tum"))
    to_make = list(dict.fromkeys(s for row in ready for s in (row.sequence, row.twin) if s.command))
    made = run_parallel([functools.partial(generate, s, BIN_DIR) for s in to_make], args.jobs)
    log("%d sequences generated, %d kept" % (sum(made), len(made) - sum(made)))
    runs = list(dict.fromkeys((s, c) for row in ready for s in (row.sequence, row.twin)
                              for c in args.configs))
    log("%d runs, %d at a time" % (len(runs), args.jobs))
    results = dict(zip(runs, run_parallel(
        [functools.partial(run_and_evaluate, s, c, out_dir, BIN_DIR) for s, c in runs], args.jobs)))
    os.makedirs(args.results, exist_ok=True)
    for split in splits:
        csv_path = os.path.join(args.results, "suite_%s.csv" % split)
        write_csv(csv_path, [result_row(row, c, results.get((row.sequence, c)),
                                        results.get((row.twin, c)))
                             for row in rows[split] for c in args.configs])
        write_markdown(csv_path, csv_path[:-4] + ".md")
        log("wrote %s and .md" % display_path(csv_path))
    log("done in %.0f s" % (time.monotonic() - start))


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    splits = SPLITS if args.split == "all" else (args.split,)
    try:
        if args.command == "table":
            for split in splits:
                csv_path = os.path.join(args.results, "suite_%s.csv" % split)
                write_markdown(csv_path, csv_path[:-4] + ".md")
                log("wrote %s" % display_path(csv_path[:-4] + ".md"))
        else:
            run_suite(args, splits)
    except SuiteError as error:
        print("suite: error: %s" % error, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
