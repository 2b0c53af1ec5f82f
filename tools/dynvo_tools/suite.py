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
made from the CSV alone (the command `suite-table` makes it again without running anything).
Tracking on real-looking frames is chaotic: another RANSAC seed can move a row's RPE severalfold. With
--seeds N every run is repeated with seeds 1..N and each figure is the median over them.

Normally run through bench/suite.sh, which builds the binaries first:
  python3 -m dynvo_tools suite [--split dev|validation|all] [--frames N] [--configs a,b,c]
                               [--out DIR] [--results DIR] [--jobs N] [--seeds N] [--update]
                               [--sequences NAME,NAME]
  python3 -m dynvo_tools suite-table --split dev|validation|all [--results DIR]
  (tools/ on PYTHONPATH; env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin;
   DYNVO_SHARED_DIR, default ../shared)
"""
from __future__ import annotations

import argparse
import csv
import functools
import json
import os
import statistics
import time
from dataclasses import dataclass
from typing import Optional

from .common import (ROOT, ToolError, bin_path, config_path, display_path, log, run_parallel,
                     run_tool, shared_dir)
from .evaluation import ATE, RPE_PER_SECOND, EvaluatedRun, RunRequest, run_and_evaluate, seed_overrides

# The people of each source: the TUM presets of dynvo-insert-people (articulated photo people in
# real frames) and the same scenarios of dynvo-synth (the same people in a synthetic room).
PRESETS = ("tum_walking", "tum_toward", "tum_away", "tum_sitting")
# The people of each split's real frames, from photos of a person 380-475 px tall: dev, the
# man on the left of opencv-doc's basketball1.png (cut by GrabCut); validation, the man
# standing on the right of the real TUM frame in SHARED/data/samples (cut by its depth;
# the frame ends at his shins). "{shared}" stands for the shared data folder.
DEV_PERSON = ("--person", "/usr/share/doc/opencv-doc/examples/data/basketball1.png", "--person-box", "31,86,135,380")
VALIDATION_PERSON = ("--person", "{shared}/data/samples/fr3_walking_xyz_rgb_1341846313.553992.png",
                     "--person-box", "470,5,170,475",
                     "--person-depth", "{shared}/data/samples/fr3_walking_xyz_depth_1341846313.592088.png")
CONFIGS = ("baseline", "paper", "dynvo")
SPLITS = ("dev", "validation")
INSERT, SYNTH = "inserted", "synthetic"
VALIDATION_NOTE = "Validation split: reported only, never used to choose a parameter or default."
NOT_RUN = "not run: shared data absent"
METRICS = (RPE_PER_SECOND, ATE)


@dataclass(frozen=True)
class Source:
    """Where some of a split's sequences come from: one sequence per preset."""
    split: str
    kind: str                      # INSERT: dynvo-insert-people; SYNTH: dynvo-synth
    where: str                     # INSERT: real folder in SHARED/data/tum; SYNTH: camera path
    seed: int                      # --seed of the generator
    person: tuple[str, ...] = ()   # INSERT only: --person, --person-box, --person-depth arguments
    plain: bool = False            # SYNTH only: the room in plain paint (--plain-room): low texture


# The two splits, every sequence of each.
#   dev:        parameters and defaults may be tuned on it.
#   validation: reported only, never used to choose a parameter or default.
# Each source gives one sequence per preset (PRESETS). Twins: INSERT: the real folder itself;
# SYNTH: dynvo-synth with the same camera path, seed and sensor and `--scenario none`.
#      split         kind    real folder (INSERT) or camera path (SYNTH)  seed  person
SOURCES = (
    Source("dev",        INSERT, "rgbd_dataset_freiburg1_rpy_head150",       1, DEV_PERSON),
    Source("dev",        SYNTH,  "xyz",                                      1),
    Source("dev",        SYNTH,  "rpy",                                      7),
    Source("dev",        SYNTH,  "rpy_fast",                                 4),
    Source("dev",        SYNTH,  "xyz",                                      5, plain=True),
    Source("dev",        SYNTH,  "halfsphere",                              16, plain=True),
    Source("validation", INSERT, "rgbd_dataset_freiburg2_desk_head50",       2, VALIDATION_PERSON),
    Source("validation", SYNTH,  "rpy",                                      2),
    Source("validation", SYNTH,  "halfsphere",                               3),
    Source("validation", SYNTH,  "halfsphere",                               6, plain=True),
)


# What the generators write, beyond their arguments: 2 = masks/ gives a person not moving 128;
# 3 = camera.json states the rolling shutter's readout.
GENERATED_FORMAT = 3


@dataclass(frozen=True)
class Sequence:
    """A sequence folder and what makes it: a generator and its arguments (without --out), or
    nothing for a real folder used as it is."""
    name: str
    folder: str
    command: tuple[str, ...] = ()

    def spec(self) -> dict:
        """What spec.json beside the generated sequence holds: a change means generate again."""
        return {"command": list(self.command), "format": GENERATED_FORMAT}


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
    mask: Optional[dict[str, Optional[float]]]  # precision, recall, iou, still_kept; None: no mask or no masks/
    ms_median: float
    ms_p90: float
    seeds: int = 1                  # runs (RANSAC seeds) the figures are the medians of
    rpe_range: Optional[tuple[float, float]] = None  # over the seeds: min, max
    rpe_seeds: tuple[float, ...] = ()  # per seed, in seed order (several seeds only)


def short_name(real_folder: str) -> str:
    """rgbd_dataset_freiburg1_rpy_head150 -> fr1_rpy_head150."""
    name = os.path.basename(os.path.normpath(real_folder))
    return name.replace("rgbd_dataset_freiburg", "fr", 1) if name.startswith("rgbd_dataset_") else name


# ---------------------------------------------------------------- sequences


def source_rows(source: Source, frames: int, seq_dir: str, shared: str) -> list[RowSpec]:
    """The rows of one source: one per preset, each with its twin."""
    seed = str(source.seed)
    if source.kind == INSERT:
        real = os.path.join(shared, "data", "tum", source.where)
        twin = Sequence(short_name(real), real)
        available = os.path.isdir(real)
        made = [(f"{twin.name}_{p}_s{seed}",
                 ("dynvo-insert-people", "--dataset", real, "--preset", p, "--seed", seed)
                 + tuple(arg.format(shared=shared) for arg in source.person)) for p in PRESETS]
    else:
        room = ("--plain-room",) if source.plain else ()
        path = source.where + ("_plain" if source.plain else "")

        def synth(scenario: str) -> tuple[str, ...]:
            return ("dynvo-synth", "--scenario", scenario, "--camera-path", source.where,
                    "--seed", seed, "--frames", str(frames)) + room
        twin_name = f"synth_none_{path}_s{seed}"
        # The twin has the people's sensor (the tum_* scenarios always have Kinect v1 timing).
        twin = Sequence(twin_name, os.path.join(seq_dir, twin_name), synth("none") + ("--kinect-sensor",))
        available = True
        made = [(f"synth_{p}_{path}_s{seed}", synth(p)) for p in PRESETS]
    return [RowSpec(source.split, source.kind, Sequence(name, os.path.join(seq_dir, name), command),
                    twin, available) for name, command in made]


def split_rows(split: str, frames: int, out_dir: str, shared: str) -> list[RowSpec]:
    """Every row of a split, its generated sequences in OUT/seq."""
    seq_dir = os.path.join(out_dir, "seq")
    return [row for source in SOURCES if source.split == split
            for row in source_rows(source, frames, seq_dir, shared)]


def needs_generation(sequence: Sequence) -> bool:
    """True when the folder has no rgb.txt, or no spec.json equal to the sequence's spec."""
    if not os.path.isfile(os.path.join(sequence.folder, "rgb.txt")):
        return True
    try:
        with open(os.path.join(sequence.folder, "spec.json")) as f:
            return json.load(f) != sequence.spec()
    except (OSError, ValueError):
        return True


def generate(sequence: Sequence) -> bool:
    """Generates the sequence (its generator from common.bin_dir()) unless it is there as
    specified; True when it generated it."""
    if not needs_generation(sequence):
        return False
    spec_path = os.path.join(sequence.folder, "spec.json")
    if os.path.exists(spec_path):
        os.remove(spec_path)  # no stale spec beside a half-made sequence
    log("suite", "generating %s" % sequence.name)
    program, *arguments = sequence.command
    run_tool("%s (generation)" % sequence.name,
             [bin_path(program)] + arguments + ["--out", sequence.folder, "--force"])
    with open(spec_path, "w") as f:
        json.dump(sequence.spec(), f, indent=2)
        f.write("\n")
    return True


# ---------------------------------------------------------------- runs


def run_result(run: EvaluatedRun) -> RunResult:
    """What the suite keeps of an evaluated run."""
    ms_median, ms_p90 = run.processing_ms()
    return RunResult(frames=run.frames(), rpe_m_s=run.rmse(RPE_PER_SECOND), ate_m=run.rmse(ATE),
                     mask=run.mask_quality(), ms_median=ms_median, ms_p90=ms_p90)


def run_sequence(sequence: Sequence, config: str, out_dir: str, overrides: tuple[str, ...],
                 seed: Optional[int] = None) -> RunResult:
    """Runs configs/CONFIG.json (then the overrides) on a sequence into OUT/runs/SEQUENCE/CONFIG
    and evaluates it (per-second RPE and ATE); with a RANSAC seed, into CONFIG_seedS with it."""
    name = config if seed is None else "%s_seed%d" % (config, seed)
    request = RunRequest(sequence.folder, os.path.join(out_dir, "runs", sequence.name, name), config_path(config),
                         overrides + (() if seed is None else seed_overrides(seed)))
    return run_result(run_and_evaluate(request, METRICS, "%s %s" % (sequence.name, name)))


def median_of(values: list[Optional[float]]) -> Optional[float]:
    """The median of the known values; None when none is known."""
    known = [v for v in values if v is not None]
    return statistics.median(known) if known else None


def combine_seeds(results: list[RunResult]) -> RunResult:
    """One run per RANSAC seed as one result: each figure the median over the seeds, the RPE's
    range beside it. A single run stays as it is."""
    if len(results) == 1:
        return results[0]
    masks = [r.mask for r in results if r.mask]
    mask = {key: median_of([m.get(key) for m in masks]) for key in masks[0]} if masks else None
    rpe = [r.rpe_m_s for r in results]
    return RunResult(frames=results[0].frames, rpe_m_s=statistics.median(rpe),
                     ate_m=statistics.median(r.ate_m for r in results), mask=mask,
                     ms_median=statistics.median(r.ms_median for r in results),
                     ms_p90=statistics.median(r.ms_p90 for r in results), seeds=len(results),
                     rpe_range=(min(rpe), max(rpe)), rpe_seeds=tuple(rpe))


# ---------------------------------------------------------------- results CSV

CSV_COLUMNS = ("split", "sequence", "kind", "twin", "config", "status", "frames", "rpe_m_s",
               "twin_rpe_m_s", "ratio", "ate_m", "mask_precision", "mask_recall", "mask_iou",
               "still_kept", "ms_median", "ms_p90", "overrides", "seeds", "rpe_min_m_s", "rpe_max_m_s",
               "rpe_seeds_m_s")
OPTIONAL_COLUMNS = ("overrides", "still_kept", "seeds", "rpe_min_m_s", "rpe_max_m_s",
                    "rpe_seeds_m_s")  # not in older CSVs
SEED_SEPARATOR = ";"  # between the per-seed RPEs of rpe_seeds_m_s
MASK_KEYS = ("precision", "recall", "iou")


def cell(value: object) -> str:
    """A CSV cell: floats as repr (all digits), None as "-"."""
    if value is None:
        return "-"
    return repr(value) if isinstance(value, float) else str(value)


def result_row(row: RowSpec, config: str, result: Optional[RunResult],
               twin: Optional[RunResult], overrides: tuple[str, ...] = ()) -> dict[str, str]:
    """One CSV row; result None: the row was not run (its shared data is absent)."""
    values: dict[str, object] = {"split": row.split, "sequence": row.sequence.name,
                                 "kind": row.kind, "twin": row.twin.name, "config": config,
                                 "overrides": "; ".join(overrides) or None}
    if result is None or twin is None:
        values["status"] = NOT_RUN
        return {key: cell(values.get(key)) for key in CSV_COLUMNS}
    values.update(status="ok", frames=result.frames, rpe_m_s=result.rpe_m_s,
                  twin_rpe_m_s=twin.rpe_m_s, ate_m=result.ate_m, ms_median=result.ms_median,
                  ms_p90=result.ms_p90, seeds=result.seeds,
                  rpe_min_m_s=result.rpe_range[0] if result.rpe_range else None,
                  rpe_max_m_s=result.rpe_range[1] if result.rpe_range else None,
                  rpe_seeds_m_s=SEED_SEPARATOR.join(repr(v) for v in result.rpe_seeds) or None,
                  ratio=result.rpe_m_s / twin.rpe_m_s if twin.rpe_m_s > 0 else None)
    for key in MASK_KEYS:
        values["mask_" + key] = result.mask[key] if result.mask else None
    values["still_kept"] = result.mask["still_kept"] if result.mask else None
    return {key: cell(values.get(key)) for key in CSV_COLUMNS}


def write_csv(path: str, rows: list[dict[str, str]]) -> None:
    """The results CSV of one split, CSV_COLUMNS in order."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_COLUMNS, lineterminator="\n", restval="-")
        writer.writeheader()
        writer.writerows(rows)


def table_error(path: str, problem: str) -> ToolError:
    """A failure of making the table from the CSV at path."""
    return ToolError("%s: %s" % (display_path(path), problem))


def read_results(path: str) -> list[dict[str, str]]:
    """The rows of a results CSV; a ToolError when unreadable, without a column, or empty."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            missing = [c for c in CSV_COLUMNS
                       if c not in OPTIONAL_COLUMNS and c not in (reader.fieldnames or [])]
    except OSError as error:
        raise table_error(path, "cannot read (%s): run the suite first" % error.strerror) from None
    if missing:
        raise table_error(path, "no column %s" % ", ".join(missing))
    if not rows:
        raise table_error(path, "no rows")
    return rows


# ---------------------------------------------------------------- Markdown, from the CSV alone


def csv_number(row: dict[str, str], key: str, path: str) -> Optional[float]:
    """A number of the CSV; None for "-" or an empty cell."""
    if row[key] in ("-", ""):
        return None
    try:
        return float(row[key])
    except ValueError:
        raise table_error(path, "%s %s: %s is not a number: %r" % (
            row["sequence"], row["config"], key, row[key])) from None


def csv_optional(row: dict[str, str], key: str, path: str) -> Optional[float]:
    """csv_number of a column that older CSVs may lack (None then, as for "-")."""
    return csv_number(row, key, path) if key in row else None


def csv_seed_values(row: dict[str, str], path: str) -> tuple[float, ...]:
    """The per-seed RPEs of a row (rpe_seeds_m_s); () when the CSV or the row has none."""
    text = row.get("rpe_seeds_m_s") or "-"
    if text == "-":
        return ()
    try:
        return tuple(float(v) for v in text.split(SEED_SEPARATOR))
    except ValueError:
        raise table_error(path, "%s %s: rpe_seeds_m_s is not numbers separated by %r: %r" % (
            row["sequence"], row["config"], SEED_SEPARATOR, text)) from None


def seeds_of(rows: list[dict[str, str]]) -> int:
    """The RANSAC seeds the split's figures are medians over (1: single runs, older CSVs too)."""
    return max([int(r["seeds"]) for r in rows if r["status"] == "ok" and r.get("seeds", "-") not in ("-", "")]
               or [1])


def caption(split: str, rows: list[dict[str, str]], configs: list[str]) -> str:
    """The paragraphs above a split's table: what each column is, the frames, the split's note."""
    synthetic = sorted({r["frames"] for r in rows if r["status"] == "ok" and r["kind"] == SYNTH}, key=int)
    real: dict[str, set[str]] = {}
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
        " the same camera path, seed and Kinect sensor timing with `--scenario none"
        " --kinect-sensor`). **ATE**: SE(3)-aligned RMSE in m"
        " (`ate GT EST`, Horn alignment, no scale). **mask R/P/IoU**: recall, precision and IoU"
        " of the dynamic mask against the moving people of the generated masks (a person not"
        " moving counts as static), over all pixels of all frames (`-`: none); **still** after"
        " them, where people are not moving: the share of the features on them the mask left to"
        " the pose. **ms**: `processing_ms` per frame, median/p90, with runs in parallel.",
        "Frames: %s." % ("; ".join(frames) if frames else "none run"),
    ]
    seeds = seeds_of(rows)
    if seeds > 1:
        text.append("Every run over RANSAC seeds 1-%d (`--set homography.seed=S --set tracking.pose.seed=S`):"
                    " each figure is the median over the seeds, the RPE's [min, max] after it; the ratio is"
                    " the median over the twin's median." % seeds)
    overrides = sorted({r.get("overrides", "-") for r in rows} - {"-", ""})
    if overrides:
        text.append("Every run with %s." % ", ".join("`--set %s`" % o for group in overrides for o in group.split("; ")))
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
        row = by_config.get(config)
        return csv_optional(row, key, path) if row is not None else None

    def fmt(value: Optional[float], pattern: str) -> str:
        return "-" if value is None else pattern % value

    cells = []
    for c in configs:
        ratio, low, high = num(c, "ratio"), num(c, "rpe_min_m_s"), num(c, "rpe_max_m_s")
        cells.append(fmt(num(c, "rpe_m_s"), "%.4f") + ("" if low is None or high is None else " [%.4f, %.4f]" % (low, high))
                     + ("" if ratio is None else " (%.2fx)" % ratio))
    cells += [fmt(num(c, "ate_m"), "%.4f") for c in configs]
    for c in masked:
        values = [num(c, "mask_" + key) for key in ("recall", "precision", "iou")]
        known = [v for v in values if v is not None]
        still = num(c, "still_kept") if "still_kept" in by_config.get(c, {}) else None
        cells.append(("/".join("%.2f" % v for v in known) if len(known) == len(values) else "-")
                     + ("" if still is None else ", still %.2f" % still))
    cells += ["%s/%s" % (fmt(num(c, "ms_median"), "%.1f"), fmt(num(c, "ms_p90"), "%.1f"))
              for c in configs]
    return cells


def table_lines(rows: list[dict[str, str]], configs: list[str], path: str) -> list[str]:
    """The Markdown table of a split: one row per sequence, then the median ratio per config."""
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
    seeds = seeds_of(rows)
    text = [caption(split, rows, configs), ""] + table_lines(rows, configs, csv_path) + [
        "", "Generated by `bash bench/suite.sh --split %s%s`; the table alone again from %s by"
        " `bash bench/suite.sh table --split %s`." % (split, " --seeds %d" % seeds if seeds > 1 else "",
                                                      os.path.basename(csv_path), split)]
    with open(md_path, "w") as f:
        f.write("\n".join(text) + "\n")


# ---------------------------------------------------------------- commands


def splits_of(args: argparse.Namespace) -> tuple[str, ...]:
    """The splits --split names."""
    return SPLITS if args.split == "all" else (args.split,)


def selected_rows(rows: list[RowSpec], names: tuple[str, ...]) -> list[RowSpec]:
    """The rows whose sequence name contains one of `names` (all rows when `names` is empty)."""
    return [row for row in rows if not names or any(name in row.sequence.name for name in names)]


def kept_rows(path: str, rows: list[RowSpec], run: list[RowSpec], args: argparse.Namespace) -> list[dict[str, str]]:
    """With --update: the rows of the results CSV at path that this run does not replace (the
    configs not run now, and every config of the split's rows not in `run`), checked before any
    run: no sequence the split does not have, every one it has either there or in `run` with
    every config the CSV holds, and the same seeds. A ToolError otherwise."""
    old = read_results(path)
    running = {row.sequence.name for row in run}
    there = {r["sequence"] for r in old}
    missing = {row.sequence.name for row in rows} - there
    if there - {row.sequence.name for row in rows} or not missing <= running:
        raise table_error(path, "--update: holds other sequences than this split has now: run every config")
    others = sorted({r["config"] for r in old} - set(args.configs))
    if missing and others:
        raise table_error(path, "--update: has no rows of %s: run them with its configs %s too" % (
            ",".join(sorted(missing)), ",".join(others)))
    kept = [r for r in old if r["config"] not in args.configs or r["sequence"] not in running]
    if kept and seeds_of(kept) != args.seeds:
        raise table_error(path, "--update: made with --seeds %d, not %d" % (seeds_of(kept), args.seeds))
    return kept


def merged_rows(path: str, kept: list[dict[str, str]], new: list[dict[str, str]],
                sequences: list[str]) -> list[dict[str, str]]:
    """The kept rows and the new rows, sequence by sequence in the order of `sequences`, the kept
    configs first; a ToolError when a sequence's frames differ between them (another --frames)."""
    frames = {r["sequence"]: r["frames"] for r in new if r["status"] == "ok"}
    for r in kept:
        if r["status"] == "ok" and frames.get(r["sequence"], r["frames"]) != r["frames"]:
            raise table_error(path, "--update: %s has %s frames there and %s now: run every config" % (
                r["sequence"], r["frames"], frames[r["sequence"]]))
    configs = list(dict.fromkeys([r["config"] for r in kept] + [r["config"] for r in new]))
    by_key = {(r["sequence"], r["config"]): r for r in kept + new}
    return [by_key[(sequence, config)] for sequence in sequences for config in configs if (sequence, config) in by_key]


def run_suite(args: argparse.Namespace) -> int:
    """Generates the splits' sequences, runs and evaluates every config on each, and writes
    RESULTS/suite_<split>.csv and .md."""
    start = time.monotonic()
    splits = splits_of(args)
    out_dir = os.path.abspath(args.out)
    shared = shared_dir()
    every = {s: split_rows(s, args.frames, out_dir, shared) for s in splits}
    rows = {s: selected_rows(every[s], args.sequences) for s in splits}
    splits = tuple(s for s in splits if rows[s])  # a split none of --sequences names is left as it is
    if not splits:
        raise ToolError("--sequences: no sequence of %s matches %s" % (args.split, ",".join(args.sequences)))
    kept = {s: kept_rows(os.path.join(args.results, "suite_%s.csv" % s), every[s], rows[s], args) for s in splits} \
        if args.update else {}
    ready = [row for split in splits for row in rows[split] if row.available]
    if len(ready) < sum(len(r) for r in rows.values()):
        log("suite", "%s: absent: the rows with people inserted into real frames are not run"
            % os.path.join(shared, "data", "tum"))
    to_make = list(dict.fromkeys(s for row in ready for s in (row.sequence, row.twin) if s.command))
    made = run_parallel([functools.partial(generate, s) for s in to_make], args.jobs)
    log("suite", "%d sequences generated, %d kept" % (sum(made), len(made) - sum(made)))
    runs = list(dict.fromkeys((s, c) for row in ready for s in (row.sequence, row.twin)
                              for c in args.configs))
    seeds: list[Optional[int]] = list(range(1, args.seeds + 1)) if args.seeds > 1 else [None]
    log("suite", "%d runs, %d at a time" % (len(runs) * len(seeds), args.jobs))
    each = run_parallel([functools.partial(run_sequence, s, c, out_dir, tuple(args.overrides), seed)
                         for s, c in runs for seed in seeds], args.jobs)
    results = {run: combine_seeds(each[k * len(seeds):(k + 1) * len(seeds)]) for k, run in enumerate(runs)}
    os.makedirs(args.results, exist_ok=True)
    for split in splits:
        csv_path = os.path.join(args.results, "suite_%s.csv" % split)
        new_rows = [result_row(row, c, results.get((row.sequence, c)), results.get((row.twin, c)),
                               tuple(args.overrides)) for row in rows[split] for c in args.configs]
        order = [row.sequence.name for row in every[split]]
        write_csv(csv_path, merged_rows(csv_path, kept[split], new_rows, order) if args.update else new_rows)
        write_markdown(csv_path, csv_path[:-4] + ".md")
        log("suite", "wrote %s and .md" % display_path(csv_path))
    log("suite", "done in %.0f s" % (time.monotonic() - start))
    return 0


def run_table(args: argparse.Namespace) -> int:
    """Writes RESULTS/suite_<split>.md again from RESULTS/suite_<split>.csv alone."""
    for split in splits_of(args):
        csv_path = os.path.join(args.results, "suite_%s.csv" % split)
        write_markdown(csv_path, csv_path[:-4] + ".md")
        log("suite-table", "wrote %s" % display_path(csv_path[:-4] + ".md"))
    return 0


def checked_run(parser: argparse.ArgumentParser, args: argparse.Namespace) -> int:
    """The `suite` command after the checks of its options (argparse errors of parser)."""
    if args.frames < 2:
        parser.error("--frames must be at least 2")
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    if args.seeds < 1:
        parser.error("--seeds must be at least 1")
    for config in args.configs:
        if not os.path.isfile(config_path(config)):
            parser.error("--configs: no configs/%s.json" % config)
    return run_suite(args)


def comma_list(text: str) -> tuple[str, ...]:
    """The items of a comma-separated list (argparse type)."""
    items = tuple(item.strip() for item in text.split(",") if item.strip())
    if not items:
        raise argparse.ArgumentTypeError("expected a comma-separated list, got %r" % text)
    return items


def add_split_options(parser: argparse.ArgumentParser) -> None:
    """--split and --results, shared by `suite` and `suite-table`."""
    parser.add_argument("--split", choices=SPLITS + ("all",), default="all",
                        help="which split (default: all)")
    parser.add_argument("--results", default=os.path.join(ROOT, "bench", "results"), metavar="DIR",
                        help="where suite_<split>.csv and .md go (default: bench/results)")


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `suite` command (the runs) and `suite-table` (the Markdown again from the CSV)."""
    parser = commands.add_parser("suite", help="run the benchmark suite's splits",
                                 description=(__doc__ or "").split("\n\n")[0])
    add_split_options(parser)
    parser.add_argument("--frames", type=int, default=300, metavar="N",
                        help="frames of each synthetic sequence (default 300; the sequences with"
                             " people inserted have all frames of their real folder)")
    parser.add_argument("--configs", type=comma_list, default=CONFIGS, metavar="A,B,C",
                        help="configs/<name>.json to run (default: %s)" % ",".join(CONFIGS))
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "suite"), metavar="DIR",
                        help="generated sequences and runs (default: out/bench/suite)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                        help="runs at the same time (default: the number of cores)")
    parser.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                        help="config override for every run, e.g. detector.model=PATH (repeatable)")
    parser.add_argument("--seeds", type=int, default=1, metavar="N",
                        help="run each config on each sequence with RANSAC seeds 1..N and report the medians"
                             " (default 1: one run with the config's own seeds)")
    parser.add_argument("--update", action="store_true",
                        help="keep the rows of the configs not in --configs from the split's CSV in --results"
                             " (same sequences and --seeds, checked first; same frames); the configs run replace"
                             " theirs there or join them: one config's figures after it changed")
    parser.add_argument("--sequences", type=comma_list, default=(), metavar="NAME,NAME",
                        help="run only the rows whose sequence name contains one of these (and their twins);"
                             " with --update the table keeps every other row: a new source's rows, or a"
                             " row regenerated")
    parser.set_defaults(run=functools.partial(checked_run, parser))
    table = commands.add_parser(
        "suite-table", help="the benchmark suite's Markdown tables again from their CSVs",
        description="Writes suite_<split>.md again from suite_<split>.csv alone.")
    add_split_options(table)
    table.set_defaults(run=run_table)
