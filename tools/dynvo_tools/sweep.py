"""`sweep`: a parameter sweep of dynvo-cli over a JSON grid (tools/sweep.sh builds and runs it).

Every grid point (one value per listed config key) is run with `dynvo-cli run --config BASE
--set key=value ...` on every --dataset, evaluated with `rpe GT EST --json` (per-second RPE)
and the mask quality of run.json, and collected into OUT/sweep.csv, OUT/sweep_heatmap.png
and OUT/sweep.md (sweep_report.py).

  sweep.sh GRID.json --dataset SEQ [--dataset SEQ2 ...] --out DIR [--jobs N]   run, resume, collect
  sweep.sh GRID.json --dataset SEQ ... --out DIR --slurm FILE    write an sbatch job-array script
  sweep.sh GRID.json --dataset SEQ ... --out DIR --index I       run grid point I only (array task)
  sweep.sh GRID.json --dataset SEQ ... --out DIR --collect       CSV + heat map of what is finished

Grid file: {"base_config": "paper.json" (relative to the grid file; optional, default: the
built-in defaults), "parameters": {"dynamic_mask.erode_kernel_size": [2, 4, 6], ...},
"heatmap": {"x": KEY, "y": KEY, "facet": KEY} (optional; default x, y = the first two
parameters, no facet)}. Keys starting with "_" are comments. Grid points are numbered in
the order of itertools.product over the parameters as listed (the last one varies fastest).

Output layout: OUT/runs/<dataset folder name>/<point name>/ holds the dynvo-cli outputs
(trajectory.txt, timing.csv, run.json), rpe.json, and point.json, written last: a run is
finished when point.json matches the grid point, dataset, base config and dynvo-cli binary
(SHA-256), so a run that was interrupted (or made with another base config or build) is
redone and a finished one skipped.
Binaries come from $DYNVO_BIN_DIR (default: <repo>/build/bin).
"""
from __future__ import annotations

import argparse
import functools
import hashlib
import itertools
import json
import os
import re
import shlex
import subprocess
import tempfile
import threading
import time
from typing import Any, Callable, Optional, Sequence

from .common import (ROOT, ToolError, bin_path, display_path, json_number, log, read_json,
                     run_parallel, run_tool, write_atomically)
from .evaluation import RPE_PER_SECOND, RunRequest, run_and_evaluate

PROG = "sweep"
HEATMAP_KEYS = ("x", "y", "facet")
Value = Any  # a grid value: a number, a string or a boolean


def file_sha256(path: str) -> Optional[str]:
    """SHA-256 of a file, None when there is no such file."""
    if not os.path.isfile(path):
        return None
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def value_text(value: Value) -> str:
    """How a grid value is shown in names, CSV and tables: strings bare, the rest as JSON."""
    return value if isinstance(value, str) else json.dumps(value)


def flatten(config: dict, prefix: str = "") -> dict[str, Value]:
    """{"a": {"b": 1}, "_c": ...} -> {"a.b": 1}, as dynvo-cli reads config files."""
    flat: dict[str, Value] = {}
    for key, value in config.items():
        if key.startswith("_"):
            continue
        if isinstance(value, dict):
            flat.update(flatten(value, prefix + key + "."))
        else:
            flat[prefix + key] = value
    return flat


# ---------------------------------------------------------------- the grid

class Grid:
    """A checked grid file: its base config, its parameters and their points, in order."""

    def __init__(self, path: str, base_config: Optional[str], parameters: dict[str, list[Value]],
                 heatmap: dict[str, Optional[str]]) -> None:
        """The grid's points (itertools.product, the last key fastest), their folder names and
        the base config's SHA-256."""
        self.path = path
        self.base_config = base_config  # absolute path or None (built-in defaults)
        self.parameters = parameters    # ordered {key: [values]}
        self.keys = list(parameters)
        self.heatmap = heatmap          # {"x": key, "y": key or None, "facet": key or None}
        self.points = [dict(zip(self.keys, combo))
                       for combo in itertools.product(*parameters.values())]
        self.names = point_names(self.keys, self.points)
        if base_config:
            with open(base_config, "rb") as f:
                base_text = f.read()
        else:
            base_text = b"built-in defaults"
        self.base_sha256 = hashlib.sha256(base_text).hexdigest()

    def heatmap_axes(self) -> tuple[str, Optional[str], Optional[str]]:
        """The heat map's x key (always one), y key and facet key (None: not used)."""
        return self.heatmap["x"] or self.keys[0], self.heatmap["y"], self.heatmap["facet"]


def grid_error(path: str, what: str) -> ToolError:
    """An error in the grid file `path`."""
    return ToolError("%s: %s" % (path, what))


def read_grid_json(path: str) -> dict:
    """The grid file's JSON object, with no key given twice."""
    def no_duplicates(pairs: list[tuple[str, Any]]) -> dict:
        """A JSON object's pairs as a dict; a key given twice is an error."""
        seen = set()
        for key, _ in pairs:
            if key in seen:
                raise grid_error(path, "key '%s' appears twice" % key)
            seen.add(key)
        return dict(pairs)

    try:
        with open(path) as f:
            grid = json.load(f, object_pairs_hook=no_duplicates)
    except FileNotFoundError:
        raise ToolError("%s: no such grid file" % path) from None
    except json.JSONDecodeError as e:
        raise ToolError("%s:%d: not valid JSON (%s)" % (path, e.lineno, e.msg)) from None
    if not isinstance(grid, dict):
        raise grid_error(path, "expected a JSON object with \"parameters\"")
    for key in grid:
        if not key.startswith("_") and key not in ("base_config", "parameters", "heatmap"):
            raise grid_error(path, "unknown key '%s' (expected base_config, parameters, heatmap)" % key)
    return grid


def grid_base_config(path: str, base: object) -> Optional[str]:
    """The absolute path of the grid's base_config (relative to the grid file), None if absent."""
    if base is None:
        return None
    if not isinstance(base, str) or not base:
        raise grid_error(path, "base_config: expected a config file path, got %s" % json.dumps(base))
    base = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(path)), base))
    if not os.path.isfile(base):
        raise grid_error(path, "base_config: %s: no such file (paths are relative to the grid file)" % base)
    return base


def grid_parameters(path: str, parameters: object) -> dict[str, list[Value]]:
    """The grid's parameters without comments: each a non-empty list of distinct scalars."""
    if not isinstance(parameters, dict) or not [k for k in parameters if not k.startswith("_")]:
        raise grid_error(path, "parameters: expected an object of config keys and lists of values, "
                               "e.g. {\"dynamic_mask.erode_kernel_size\": [2, 4, 6]}")
    parameters = {k: v for k, v in parameters.items() if not k.startswith("_")}
    for key, values in parameters.items():
        if not isinstance(values, list) or not values:
            raise grid_error(path, "parameters: '%s': expected a non-empty list of values, got %s"
                             % (key, json.dumps(values)))
        for v in values:
            if isinstance(v, (dict, list)) or v is None:
                raise grid_error(path, "parameters: '%s': expected numbers, strings or booleans, got %s"
                                 % (key, json.dumps(v)))
        texts = [json.dumps(v) for v in values]
        if len(set(texts)) != len(texts):
            raise grid_error(path, "parameters: '%s': a value is listed twice in %s"
                             % (key, json.dumps(values)))
    return parameters


def grid_heatmap(path: str, spec: object, keys: list[str]) -> dict[str, Optional[str]]:
    """The heat map's axes: x, y (default: the first two parameters) and facet (default none)."""
    if not isinstance(spec, dict):
        raise grid_error(path, "heatmap: expected {\"x\": KEY, \"y\": KEY, \"facet\": KEY}")
    heatmap: dict[str, Optional[str]] = {"x": keys[0], "y": keys[1] if len(keys) > 1 else None,
                                         "facet": None}
    for axis, key in spec.items():
        if axis.startswith("_"):
            continue
        if axis not in HEATMAP_KEYS:
            raise grid_error(path, "heatmap: unknown key '%s' (expected x, y, facet)" % axis)
        if key not in keys:
            raise grid_error(path, "heatmap: %s: '%s' is not one of the parameters (%s)"
                             % (axis, key, ", ".join(keys)))
        heatmap[axis] = key
    chosen = [k for k in heatmap.values() if k]
    if len(set(chosen)) != len(chosen):
        raise grid_error(path, "heatmap: x, y and facet must be different parameters")
    return heatmap


def load_grid(path: str) -> Grid:
    """Reads and checks the grid file; every problem is a ToolError naming the file."""
    grid = read_grid_json(path)
    base = grid_base_config(path, grid.get("base_config"))
    parameters = grid_parameters(path, grid.get("parameters"))
    heatmap = grid_heatmap(path, grid.get("heatmap", {}), list(parameters))
    return Grid(path, base, parameters, heatmap)


def point_names(keys: list[str], points: list[dict[str, Value]]) -> list[str]:
    """Folder names from the values, e.g. erode_kernel_size-4_threshold-otsu (last part of
    each key, the whole key where that is ambiguous); hashes when that is not usable."""
    last = [k.rsplit(".", 1)[-1] for k in keys]
    short = [part if last.count(part) == 1 else k for k, part in zip(keys, last)]
    names = []
    for p in points:
        name = "_".join("%s-%s" % (s, value_text(p[k])) for s, k in zip(short, keys))
        names.append(re.sub(r"[^A-Za-z0-9._+-]", "_", name))
    if len(set(names)) != len(names) or max(len(n) for n in names) > 200:
        names = ["point-" + hashlib.sha256(json.dumps(p, sort_keys=True).encode()).hexdigest()[:12]
                 for p in points]
    return names


def overrides(point: dict[str, Value]) -> tuple[str, ...]:
    """The point as dynvo-cli's `--set key=value` assignments (values as JSON)."""
    return tuple("%s=%s" % (key, json.dumps(value)) for key, value in point.items())


def check_with_dynvo_cli(grid: Grid, jobs: int) -> None:
    """Asks dynvo-cli whether it accepts the base config and every value of every key, before
    any run: a run with a dataset folder that does not exist fails on the config first, so a
    message about that folder means the config is fine. (Its own subprocess call: this run is
    meant to fail, and its message is the answer, which run_tool does not return.)"""
    with tempfile.TemporaryDirectory(prefix="dynvo-sweep-check-") as tmp:
        probe = os.path.join(tmp, "no_dataset")

        def rejection(assignments: tuple[str, ...]) -> Optional[str]:
            """dynvo-cli's message rejecting the base config with these overrides; None if accepted."""
            request = RunRequest(probe, os.path.join(tmp, "out"), grid.base_config, assignments)
            r = subprocess.run(request.command(), capture_output=True, text=True)
            message = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "exit code %d" % r.returncode
            return None if probe in message else message.replace("dynvo-cli: error: ", "")

        if not os.access(bin_path("dynvo-cli"), os.X_OK):
            raise ToolError("%s: not found or not executable (build it, or set DYNVO_BIN_DIR)"
                            % bin_path("dynvo-cli"))
        message = rejection(())
        if message:
            raise ToolError("%s: base_config is rejected by dynvo-cli: %s" % (grid.path, message))
        checks = [(k, v) for k in grid.keys for v in grid.parameters[k]]
        tasks: list[Callable[[], Optional[str]]] = [
            functools.partial(rejection, overrides({k: v})) for k, v in checks]
        for (key, value), message in zip(checks, run_parallel(tasks, jobs)):
            if message:
                raise ToolError("%s: parameters: '%s' = %s is rejected by dynvo-cli: %s"
                                % (grid.path, key, json.dumps(value), message))


# ---------------------------------------------------------------- datasets and runs

def dataset_list(paths: Sequence[str]) -> list[tuple[str, str]]:
    """(folder name, absolute folder) of each --dataset, checked: a TUM sequence with
    groundtruth, and no two with the same name."""
    datasets = []
    for p in paths:
        folder = os.path.abspath(p)
        for needed in ("rgb.txt", "groundtruth.txt"):
            if not os.path.isfile(os.path.join(folder, needed)):
                raise ToolError("%s: no %s (expected a TUM sequence folder with groundtruth)"
                                % (p, needed))
        datasets.append((os.path.basename(folder.rstrip("/")), folder))
    names = [n for n, _ in datasets]
    for n in names:
        if names.count(n) > 1:
            raise ToolError("two --dataset folders are both named '%s'; their runs would share "
                            "OUT/runs/%s" % (n, n))
    return datasets


class Run:
    """One grid point on one dataset."""

    def __init__(self, grid: Grid, out: str, index: int, dataset: tuple[str, str],
                 dynvo_cli_sha256: Optional[str]) -> None:
        """The run's folder and what its point.json must record (dynvo-cli's SHA-256 if built)."""
        self.grid = grid
        self.index = index
        self.point = grid.points[index]
        self.dataset_name, self.dataset = dataset
        self.dir = os.path.join(out, "runs", self.dataset_name, grid.names[index])
        self.expected: dict[str, Any] = {
            "settings": self.point, "dataset": self.dataset,
            "base_config": grid.base_config, "base_config_sha256": grid.base_sha256}
        # A run made by another build of dynvo-cli may differ: it is redone, not reused.
        if dynvo_cli_sha256:
            self.expected["dynvo_cli_sha256"] = dynvo_cli_sha256

    def finished(self) -> bool:
        """Whether point.json records this very run and its run.json and rpe.json are complete."""
        try:
            recorded = read_json(self.dir, os.path.join(self.dir, "point.json"))
            if any(recorded.get(k) != v for k, v in self.expected.items()):
                return False
            if read_json(self.dir, os.path.join(self.dir, "run.json")).get("status") != "completed":
                return False
            path = os.path.join(self.dir, RPE_PER_SECOND.name + ".json")
            json_number(self.dir, path, read_json(self.dir, path), "translational_error_m.rmse")
            return True
        except ToolError:
            return False

    def execute(self) -> None:
        """Runs dynvo-cli and rpe; point.json is written last, so it marks a finished run."""
        os.makedirs(self.dir, exist_ok=True)
        for stale in ("point.json", RPE_PER_SECOND.name + ".json"):
            if os.path.exists(os.path.join(self.dir, stale)):
                os.remove(os.path.join(self.dir, stale))
        request = RunRequest(self.dataset, self.dir, self.grid.base_config, overrides(self.point))
        run_and_evaluate(request, (RPE_PER_SECOND,), display_path(self.dir))
        record = dict(self.expected, index=self.index, grid=os.path.abspath(self.grid.path))
        write_atomically(os.path.join(self.dir, "point.json"), json.dumps(record, indent=2) + "\n")

    def metrics(self) -> dict[str, Any]:
        """The CSV fields of a finished run (sweep_report.METRICS)."""
        rpe = read_json(self.dir, os.path.join(self.dir, RPE_PER_SECOND.name + ".json"))
        run = read_json(self.dir, os.path.join(self.dir, "run.json"))
        mq = run.get("mask_quality") or {}
        processing = (run.get("time") or {}).get("processing_ms") or {}
        try:
            return {"rpe_trans_rmse_m": rpe["translational_error_m"]["rmse"],
                    "rpe_rot_rmse_deg": rpe["rotational_error_deg"]["rmse"],
                    "rpe_pairs": rpe["compared_pose_pairs"],
                    "mask_precision": mq.get("precision"), "mask_recall": mq.get("recall"),
                    "mask_iou": mq.get("iou"), "processing_median_ms": processing.get("median")}
        except (KeyError, TypeError):
            raise ToolError("%s: rpe.json lacks translational_error_m, rotational_error_deg or"
                            " compared_pose_pairs" % self.dir) from None


def run_all(runs: list[Run], jobs: int) -> int:
    """Runs the unfinished runs, `jobs` at a time; returns the number of failures."""
    todo = [r for r in runs if not r.finished()]
    skipped = len(runs) - len(todo)
    log(PROG, "%d runs: %d finished earlier (skipped), %d to run, %d at a time"
        % (len(runs), skipped, len(todo), jobs))
    lock = threading.Lock()
    done = [0]

    def one(run: Run) -> bool:
        """Runs one, logs its RPE and IoU or its error; whether it succeeded."""
        start = time.monotonic()
        try:
            run.execute()
            m = run.metrics()
            iou = "-" if m["mask_iou"] is None else "%.3f" % m["mask_iou"]
            note = "RPE %.4f m/s, mask IoU %s" % (m["rpe_trans_rmse_m"], iou)
            ok = True
        except ToolError as e:
            note, ok = "error: %s" % e, False
        with lock:
            done[0] += 1
            log(PROG, "[%d/%d] %s point %d (%s): %s (%.1f s)"
                % (done[0], len(todo), run.dataset_name, run.index, run.grid.names[run.index],
                   note, time.monotonic() - start))
        return ok

    tasks: list[Callable[[], bool]] = [functools.partial(one, run) for run in todo]
    return run_parallel(tasks, jobs).count(False)


# ---------------------------------------------------------------- CSV

def collect(grid: Grid, runs: list[Run], out: str) -> int:
    """Writes OUT/sweep.csv (one row per grid point x dataset) and the report; returns the
    number of runs that are not finished."""
    from . import sweep_report  # here, so that runs on cluster nodes need no matplotlib
    rows, missing = [], 0
    for run in runs:
        row: dict[str, Any] = {"dataset": run.dataset_name, "point": run.index}
        row.update({k: value_text(v) for k, v in run.point.items()})
        if run.finished():
            row["status"] = "finished"
            row.update(run.metrics())
        else:
            row["status"] = "missing"
            missing += 1
        rows.append(row)
    os.makedirs(out, exist_ok=True)
    columns = ["dataset", "point"] + grid.keys + ["status"] + list(sweep_report.METRICS)
    sweep_report.write_csv(os.path.join(out, "sweep.csv"), columns, rows)
    base_values = base_point_values(grid)
    sweep_report.write_heatmap(os.path.join(out, "sweep_heatmap.png"), grid, rows, base_values)
    sweep_report.write_summary(os.path.join(out, "sweep.md"), grid, rows, base_values)
    log(PROG, "wrote %s, %s, %s (%d of %d runs finished)"
        % (os.path.join(out, "sweep.csv"), os.path.join(out, "sweep_heatmap.png"),
           os.path.join(out, "sweep.md"), len(runs) - missing, len(runs)))
    return missing


def config_defaults() -> dict[str, Value]:
    """dynvo-cli's default of each config key (`dynvo-cli config-keys`); empty when it fails."""
    try:
        listing = run_tool("config defaults", [bin_path("dynvo-cli"), "config-keys"])
    except ToolError:
        return {}
    defaults = {}
    for line in listing.splitlines():  # "key (type, default V): meaning"
        m = re.match(r"(\S+) \(.*default (.+?)\): ", line)
        if m:
            try:
                defaults[m.group(1)] = json.loads(m.group(2))
            except ValueError:
                pass
    return defaults


def base_point_values(grid: Grid) -> Optional[dict[str, Value]]:
    """The base config's value of each grid key (from the file, else dynvo-cli's default);
    None when it cannot be told."""
    values = flatten(read_json(grid.path, grid.base_config)) if grid.base_config else {}
    defaults = config_defaults()
    base = {}
    for key in grid.keys:
        if key in values:
            base[key] = values[key]
        elif key in defaults:
            base[key] = defaults[key]
        else:
            return None
    return base


# ---------------------------------------------------------------- Slurm

SLURM_SCRIPT = """#!/bin/bash
# dynvo parameter sweep as a Slurm job array, written by tools/sweep.sh --slurm.
# Grid %(grid)s: %(n)d points; array task I runs grid point I on %(nd)d dataset(s).
# Submit:  sbatch %(path)s
# Collect: %(quoted)s --collect
# (Or rerun the sweep without --slurm: finished points are skipped.)
# Add your site's other options (account, QOS) as more #SBATCH lines.
#SBATCH --job-name=dynvo-sweep
#SBATCH --array=0-%(last)d
#SBATCH --cpus-per-task=2
#SBATCH --time=%(time)s
#SBATCH --mem=%(mem)s
%(partition)s#SBATCH --output=%(logs)s/%%A_%%a.log
set -euo pipefail
# Site setup (--slurm-setup): module loads, environments.
%(setup)sexport DYNVO_BIN_DIR=%(bin)s
%(container)s%(quoted)s --index "$SLURM_ARRAY_TASK_ID"
"""


def write_slurm(grid: Grid, out: str, datasets: list[tuple[str, str]], path: str, args: argparse.Namespace) -> None:
    """An sbatch job-array script: array task I runs grid point I on every dataset, with the
    time, memory and partition of --slurm-*, the --slurm-setup lines before it and the
    --slurm-container prefix (e.g. `apptainer exec dynvo.sif`) in front of it."""
    out = os.path.abspath(out)
    logs = os.path.join(out, "slurm")
    os.makedirs(logs, exist_ok=True)
    command = ["bash", os.path.join(ROOT, "tools", "sweep.sh"), os.path.abspath(grid.path)]
    for _, folder in datasets:
        command += ["--dataset", folder]
    command += ["--out", out]
    quoted = shlex.join(command)
    n = len(grid.points)
    text = SLURM_SCRIPT % {
        "grid": os.path.abspath(grid.path), "n": n, "nd": len(datasets),
        "path": shlex.quote(os.path.abspath(path)), "quoted": quoted, "last": n - 1,
        "logs": shlex.quote(logs), "bin": shlex.quote(os.path.dirname(os.path.abspath(bin_path("rpe")))),
        "time": args.slurm_time, "mem": args.slurm_mem,
        "partition": "#SBATCH --partition=%s\n" % args.slurm_partition if args.slurm_partition else "",
        "setup": "".join(line + "\n" for line in args.slurm_setup),
        "container": args.slurm_container + " " if args.slurm_container else ""}
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, 0o755)
    log(PROG, "wrote %s: a job array of %d tasks (one grid point each); submit it with sbatch, "
        "then collect with the --collect line in its header" % (path, n))


# ---------------------------------------------------------------- the command

def slurm_value(text: str) -> str:
    """An #SBATCH value: one word, no line break."""
    if not text or any(c.isspace() for c in text):
        raise argparse.ArgumentTypeError("an #SBATCH value is one word, got %r" % text)
    return text


def positive_int(text: str) -> int:
    """--jobs: an integer of at least 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("invalid int value: '%s'" % text) from None
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `sweep` command."""
    parser = commands.add_parser(
        "sweep", help="a parameter sweep over a JSON grid, locally or as a Slurm array",
        description="dynvo-cli parameter sweep over a JSON grid (grid format and output layout:"
                    " tools/dynvo_tools/sweep.py)")
    parser.add_argument("grid", help="grid JSON file")
    parser.add_argument("--dataset", action="append", required=True,
                        help="TUM sequence folder with groundtruth.txt (repeatable)")
    parser.add_argument("--out", required=True, help="output folder (runs/, sweep.csv, ...)")
    parser.add_argument("--jobs", type=positive_int, default=1, help="runs at a time (default 1)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--slurm", metavar="FILE", help="write an sbatch job-array script instead of running")
    mode.add_argument("--index", type=int, help="run grid point INDEX only (what an array task does)")
    slurm = parser.add_argument_group("the Slurm script (with --slurm)")
    slurm.add_argument("--slurm-time", default="01:00:00", type=slurm_value,
                       help="time limit of one array task, [D-]HH:MM:SS (default 01:00:00: a grid point on a"
                            " few 900-frame sequences takes minutes)")
    slurm.add_argument("--slurm-mem", default="2G", type=slurm_value,
                       help="memory of one array task (default 2G; a run peaks near 300 MB)")
    slurm.add_argument("--slurm-partition", type=slurm_value, help="the partition to submit to")
    slurm.add_argument("--slurm-setup", action="append", default=[], metavar="LINE",
                       help="a shell line run before the task, e.g. 'module load opencv' (repeatable)")
    slurm.add_argument("--slurm-container", metavar="PREFIX",
                       help="a command prefix the task runs under, e.g. 'apptainer exec dynvo.sif'")
    mode.add_argument("--collect", action="store_true",
                      help="run nothing: write the CSV, heat map and summary of the finished runs")
    parser.set_defaults(run=run_sweep)


def run_sweep(args: argparse.Namespace) -> int:
    """Checks the grid and datasets, then writes the Slurm script, or runs (all points or
    --index) and collects; exit code 1 when a run failed or is missing."""
    grid = load_grid(args.grid)
    datasets = dataset_list(args.dataset)
    if args.index is not None and not 0 <= args.index < len(grid.points):
        raise ToolError("--index %d: the grid has points 0 to %d" % (args.index, len(grid.points) - 1))
    if not args.collect:
        check_with_dynvo_cli(grid, args.jobs)
    if args.slurm:
        write_slurm(grid, args.out, datasets, args.slurm, args)
        return 0
    binary = file_sha256(bin_path("dynvo-cli"))
    indices = [args.index] if args.index is not None else range(len(grid.points))
    runs = [Run(grid, args.out, i, d, binary) for i in indices for d in datasets]
    failures = 0 if args.collect else run_all(runs, args.jobs)
    if args.index is not None:
        return 1 if failures else 0
    missing = collect(grid, runs, args.out)
    if failures or missing:
        log(PROG, "%d of %d runs are not finished%s" % (
            missing, len(runs), " (%d failed, see above)" % failures if failures else ""))
        return 1
    return 0
