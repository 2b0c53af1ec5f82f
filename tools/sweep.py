#!/usr/bin/env python3
"""Parameter sweep of dynvo-cli over a JSON grid: the core of tools/sweep.sh (run that).

Every grid point (one value per listed config key) is run with `dynvo-cli run --config BASE
--set key=value ...` on every --dataset, evaluated with `rpe GT EST --json` (per-second RPE)
and the mask quality of run.json, and collected into OUT/sweep.csv, OUT/sweep_heatmap.png
and OUT/sweep.md (tools/sweep_report.py).

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

import argparse
import concurrent.futures
import functools
import hashlib
import itertools
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
import threading
import time

PROG = "sweep"
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEATMAP_KEYS = ("x", "y", "facet")


class SweepError(Exception):
    """An input error: printed as one line 'sweep: error: ...', exit code 1."""


def bin_path(name):
    return os.path.join(os.environ.get("DYNVO_BIN_DIR") or os.path.join(ROOT, "build", "bin"), name)


@functools.lru_cache(maxsize=None)
def binary_sha256(name):
    """SHA-256 of a built tool, read once (None when it is not built)."""
    if not os.path.isfile(bin_path(name)):
        return None
    digest = hashlib.sha256()
    with open(bin_path(name), "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def value_text(value):
    """How a grid value is shown in names, CSV and tables: strings bare, the rest as JSON."""
    return value if isinstance(value, str) else json.dumps(value)


def flatten(config, prefix=""):
    """{"a": {"b": 1}, "_c": ...} -> {"a.b": 1}, as dynvo-cli reads config files."""
    flat = {}
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
    def __init__(self, path, base_config, parameters, heatmap):
        self.path = path
        self.base_config = base_config  # absolute path or None (built-in defaults)
        self.parameters = parameters    # ordered {key: [values]}
        self.keys = list(parameters)
        self.heatmap = heatmap          # {"x": key, "y": key or None, "facet": key or None}
        self.points = [dict(zip(self.keys, combo))
                       for combo in itertools.product(*parameters.values())]
        self.names = point_names(self.keys, self.points)
        base_text = open(base_config, "rb").read() if base_config else b"built-in defaults"
        self.base_sha256 = hashlib.sha256(base_text).hexdigest()


def load_grid(path):
    """Reads and checks the grid file; every problem is a SweepError naming the file."""
    def bad(what):
        return SweepError("%s: %s" % (path, what))

    def no_duplicates(pairs):
        seen = set()
        for key, _ in pairs:
            if key in seen:
                raise bad("key '%s' appears twice" % key)
            seen.add(key)
        return dict(pairs)

    try:
        with open(path) as f:
            grid = json.load(f, object_pairs_hook=no_duplicates)
    except FileNotFoundError:
        raise SweepError("%s: no such grid file" % path)
    except json.JSONDecodeError as e:
        raise SweepError("%s:%d: not valid JSON (%s)" % (path, e.lineno, e.msg))
    if not isinstance(grid, dict):
        raise bad("expected a JSON object with \"parameters\"")
    for key in grid:
        if not key.startswith("_") and key not in ("base_config", "parameters", "heatmap"):
            raise bad("unknown key '%s' (expected base_config, parameters, heatmap)" % key)

    base = grid.get("base_config")
    if base is not None:
        if not isinstance(base, str) or not base:
            raise bad("base_config: expected a config file path, got %s" % json.dumps(base))
        base = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(path)), base))
        if not os.path.isfile(base):
            raise bad("base_config: %s: no such file (paths are relative to the grid file)" % base)

    parameters = grid.get("parameters")
    if not isinstance(parameters, dict) or not [k for k in parameters if not k.startswith("_")]:
        raise bad("parameters: expected an object of config keys and lists of values, "
                  "e.g. {\"dynamic_mask.erode_kernel_size\": [2, 4, 6]}")
    parameters = {k: v for k, v in parameters.items() if not k.startswith("_")}
    for key, values in parameters.items():
        if not isinstance(values, list) or not values:
            raise bad("parameters: '%s': expected a non-empty list of values, got %s"
                      % (key, json.dumps(values)))
        for v in values:
            if isinstance(v, (dict, list)) or v is None:
                raise bad("parameters: '%s': expected numbers, strings or booleans, got %s"
                          % (key, json.dumps(v)))
        texts = [json.dumps(v) for v in values]
        if len(set(texts)) != len(texts):
            raise bad("parameters: '%s': a value is listed twice in %s" % (key, json.dumps(values)))

    spec = grid.get("heatmap", {})
    if not isinstance(spec, dict):
        raise bad("heatmap: expected {\"x\": KEY, \"y\": KEY, \"facet\": KEY}")
    keys = list(parameters)
    heatmap = {"x": keys[0], "y": keys[1] if len(keys) > 1 else None, "facet": None}
    for axis, key in spec.items():
        if axis.startswith("_"):
            continue
        if axis not in HEATMAP_KEYS:
            raise bad("heatmap: unknown key '%s' (expected x, y, facet)" % axis)
        if key not in parameters:
            raise bad("heatmap: %s: '%s' is not one of the parameters (%s)"
                      % (axis, key, ", ".join(keys)))
        heatmap[axis] = key
    chosen = [k for k in heatmap.values() if k]
    if len(set(chosen)) != len(chosen):
        raise bad("heatmap: x, y and facet must be different parameters")
    return Grid(path, base, parameters, heatmap)


def point_names(keys, points):
    """Folder names from the values, e.g. erode_kernel_size-4_threshold-otsu (last part of
    each key, the whole key where that is ambiguous); hashes when that is not usable."""
    last = [k.rsplit(".", 1)[-1] for k in keys]
    short = [l if last.count(l) == 1 else k for k, l in zip(keys, last)]
    names = []
    for p in points:
        name = "_".join("%s-%s" % (s, value_text(p[k])) for s, k in zip(short, keys))
        names.append(re.sub(r"[^A-Za-z0-9._+-]", "_", name))
    if len(set(names)) != len(names) or max(len(n) for n in names) > 200:
        names = ["point-" + hashlib.sha256(json.dumps(p, sort_keys=True).encode()).hexdigest()[:12]
                 for p in points]
    return names


def set_args(point):
    args = []
    for key, value in point.items():
        args += ["--set", "%s=%s" % (key, json.dumps(value))]
    return args


def check_with_dynvo_cli(grid, jobs):
    """Asks dynvo-cli whether it accepts the base config and every value of every key, before
    any run: a run with a dataset folder that does not exist fails on the config first, so a
    message about that folder means the config is fine."""
    with tempfile.TemporaryDirectory(prefix="dynvo-sweep-check-") as tmp:
        probe = os.path.join(tmp, "no_dataset")

        def rejection(extra):
            cmd = [bin_path("dynvo-cli"), "run", "--quiet", "--dataset", probe,
                   "--out", os.path.join(tmp, "out")]
            if grid.base_config:
                cmd += ["--config", grid.base_config]
            r = subprocess.run(cmd + extra, capture_output=True, text=True)
            message = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "exit code %d" % r.returncode
            return None if probe in message else message.replace("dynvo-cli: error: ", "")

        if not os.access(bin_path("dynvo-cli"), os.X_OK):
            raise SweepError("%s: not found or not executable (build it, or set DYNVO_BIN_DIR)"
                             % bin_path("dynvo-cli"))
        message = rejection([])
        if message:
            raise SweepError("%s: base_config is rejected by dynvo-cli: %s" % (grid.path, message))
        checks = [(k, v) for k in grid.keys for v in grid.parameters[k]]
        with concurrent.futures.ThreadPoolExecutor(max(1, jobs)) as pool:
            results = list(pool.map(lambda kv: rejection(set_args({kv[0]: kv[1]})), checks))
        for (key, value), message in zip(checks, results):
            if message:
                raise SweepError("%s: parameters: '%s' = %s is rejected by dynvo-cli: %s"
                                 % (grid.path, key, json.dumps(value), message))


# ---------------------------------------------------------------- datasets and runs

def dataset_list(paths):
    datasets = []
    for p in paths:
        folder = os.path.abspath(p)
        for needed in ("rgb.txt", "groundtruth.txt"):
            if not os.path.isfile(os.path.join(folder, needed)):
                raise SweepError("%s: no %s (expected a TUM sequence folder with groundtruth)"
                                 % (p, needed))
        datasets.append((os.path.basename(folder.rstrip("/")), folder))
    names = [n for n, _ in datasets]
    for n in names:
        if names.count(n) > 1:
            raise SweepError("two --dataset folders are both named '%s'; their runs would share "
                             "OUT/runs/%s" % (n, n))
    return datasets


class Run:
    """One grid point on one dataset."""

    def __init__(self, grid, out, index, dataset):
        self.grid = grid
        self.index = index
        self.point = grid.points[index]
        self.dataset_name, self.dataset = dataset
        self.dir = os.path.join(out, "runs", self.dataset_name, grid.names[index])
        self.expected = {"settings": self.point, "dataset": self.dataset,
                         "base_config": grid.base_config, "base_config_sha256": grid.base_sha256}
        # A run made by another build of dynvo-cli may differ: it is redone, not reused.
        binary = binary_sha256("dynvo-cli")
        if binary:
            self.expected["dynvo_cli_sha256"] = binary

    def finished(self):
        try:
            with open(os.path.join(self.dir, "point.json")) as f:
                recorded = json.load(f)
            if any(recorded.get(k) != v for k, v in self.expected.items()):
                return False
            with open(os.path.join(self.dir, "run.json")) as f:
                if json.load(f).get("status") != "completed":
                    return False
            with open(os.path.join(self.dir, "rpe.json")) as f:
                json.load(f)["translational_error_m"]["rmse"]
            return True
        except (OSError, ValueError, KeyError, TypeError):
            return False

    def execute(self):
        """Runs dynvo-cli and rpe; point.json is written last, so it marks a finished run."""
        os.makedirs(self.dir, exist_ok=True)
        for stale in ("point.json", "rpe.json"):
            if os.path.exists(os.path.join(self.dir, stale)):
                os.remove(os.path.join(self.dir, stale))
        cmd = [bin_path("dynvo-cli"), "run", "--quiet", "--force", "--dataset", self.dataset,
               "--out", self.dir]
        if self.grid.base_config:
            cmd += ["--config", self.grid.base_config]
        r = subprocess.run(cmd + set_args(self.point), capture_output=True, text=True)
        if r.returncode != 0:
            raise SweepError("%s: dynvo-cli failed: %s" % (self.dir, r.stderr.strip() or r.returncode))
        r = subprocess.run([bin_path("rpe"), os.path.join(self.dataset, "groundtruth.txt"),
                            os.path.join(self.dir, "trajectory.txt"), "--json"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise SweepError("%s: rpe failed: %s" % (self.dir, r.stderr.strip() or r.returncode))
        write_atomically(os.path.join(self.dir, "rpe.json"), r.stdout)
        record = dict(self.expected, index=self.index, grid=os.path.abspath(self.grid.path))
        write_atomically(os.path.join(self.dir, "point.json"), json.dumps(record, indent=2) + "\n")

    def metrics(self):
        """The CSV fields of a finished run."""
        with open(os.path.join(self.dir, "rpe.json")) as f:
            rpe = json.load(f)
        with open(os.path.join(self.dir, "run.json")) as f:
            run = json.load(f)
        mq = run.get("mask_quality") or {}
        processing = run["time"].get("processing_ms") or {}
        return {"rpe_trans_rmse_m": rpe["translational_error_m"]["rmse"],
                "rpe_rot_rmse_deg": rpe["rotational_error_deg"]["rmse"],
                "rpe_pairs": rpe["compared_pose_pairs"],
                "mask_precision": mq.get("precision"), "mask_recall": mq.get("recall"),
                "mask_iou": mq.get("iou"), "processing_median_ms": processing.get("median")}


def write_atomically(path, text):
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def run_all(runs, jobs):
    """Runs the unfinished runs, `jobs` at a time; returns the number of failures."""
    todo = [r for r in runs if not r.finished()]
    skipped = len(runs) - len(todo)
    print("%s: %d runs: %d finished earlier (skipped), %d to run, %d at a time"
          % (PROG, len(runs), skipped, len(todo), jobs), file=sys.stderr, flush=True)
    lock = threading.Lock()
    done = [0]

    def one(run):
        start = time.monotonic()
        try:
            run.execute()
            m = run.metrics()
            iou = "-" if m["mask_iou"] is None else "%.3f" % m["mask_iou"]
            note = "RPE %.4f m/s, mask IoU %s" % (m["rpe_trans_rmse_m"], iou)
            ok = True
        except SweepError as e:
            note, ok = "error: %s" % e, False
        with lock:
            done[0] += 1
            print("%s: [%d/%d] %s point %d (%s): %s (%.1f s)"
                  % (PROG, done[0], len(todo), run.dataset_name, run.index,
                     run.grid.names[run.index], note, time.monotonic() - start),
                  file=sys.stderr, flush=True)
        return ok

    with concurrent.futures.ThreadPoolExecutor(max(1, jobs)) as pool:
        results = list(pool.map(one, todo))
    return results.count(False)


# ---------------------------------------------------------------- CSV

def collect(grid, runs, out):
    """Writes OUT/sweep.csv (one row per grid point x dataset) and the report; returns the
    number of runs that are not finished."""
    import sweep_report  # here, so that runs on cluster nodes need no matplotlib
    rows, missing = [], 0
    for run in runs:
        row = {"dataset": run.dataset_name, "point": run.index}
        row.update({k: value_text(v) for k, v in run.point.items()})
        if run.finished():
            row["status"] = "finished"
            row.update(run.metrics())
        else:
            row["status"] = "missing"
            missing += 1
        rows.append(row)
    columns = (["dataset", "point"] + grid.keys + ["status"] + list(sweep_report.METRICS))
    sweep_report.write_csv(os.path.join(out, "sweep.csv"), columns, rows)
    base_values = base_point_values(grid)
    sweep_report.write_heatmap(os.path.join(out, "sweep_heatmap.png"), grid, rows, base_values)
    sweep_report.write_summary(os.path.join(out, "sweep.md"), grid, rows, base_values)
    print("%s: wrote %s, %s, %s (%d of %d runs finished)"
          % (PROG, os.path.join(out, "sweep.csv"), os.path.join(out, "sweep_heatmap.png"),
             os.path.join(out, "sweep.md"), len(runs) - missing, len(runs)), file=sys.stderr)
    return missing


def base_point_values(grid):
    """The base config's value of each grid key (from the file, else dynvo-cli's default);
    None when it cannot be told."""
    values = {}
    if grid.base_config:
        with open(grid.base_config) as f:
            values = flatten(json.load(f))
    try:
        listing = subprocess.run([bin_path("dynvo-cli"), "config-keys"], capture_output=True,
                                 text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        listing = ""
    defaults = {}
    for line in listing.splitlines():  # "key (type, default V): meaning"
        m = re.match(r"(\S+) \(.*default (.+?)\): ", line)
        if m:
            try:
                defaults[m.group(1)] = json.loads(m.group(2))
            except ValueError:
                pass
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

def write_slurm(grid, args, datasets, path):
    """An sbatch job-array script: array task I runs grid point I on every dataset."""
    out = os.path.abspath(args.out)
    logs = os.path.join(out, "slurm")
    os.makedirs(logs, exist_ok=True)
    common = ["bash", os.path.join(ROOT, "tools", "sweep.sh"), os.path.abspath(grid.path)]
    for _, folder in datasets:
        common += ["--dataset", folder]
    common += ["--out", out]
    quoted = " ".join(shlex.quote(a) for a in common)
    n = len(grid.points)
    text = """#!/bin/bash
# dynvo parameter sweep as a Slurm job array, written by tools/sweep.sh --slurm.
# Grid %(grid)s: %(n)d points; array task I runs grid point I on %(nd)d dataset(s).
# Submit:  sbatch %(path)s
# Collect: %(quoted)s --collect
# (Or rerun the sweep without --slurm: finished points are skipped.)
# Add your site's options (partition, account, time limit) as more #SBATCH lines.
#SBATCH --job-name=dynvo-sweep
#SBATCH --array=0-%(last)d
#SBATCH --cpus-per-task=2
#SBATCH --output=%(logs)s/%%A_%%a.log
set -euo pipefail
export DYNVO_BIN_DIR=%(bin)s
%(quoted)s --index "$SLURM_ARRAY_TASK_ID"
""" % {"grid": os.path.abspath(grid.path), "n": n, "nd": len(datasets),
       "path": shlex.quote(os.path.abspath(path)), "quoted": quoted, "last": n - 1,
       "logs": shlex.quote(logs), "bin": shlex.quote(os.path.dirname(os.path.abspath(bin_path("rpe"))))}
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, 0o755)
    print("%s: wrote %s: a job array of %d tasks (one grid point each); submit it with sbatch, "
          "then collect with the --collect line in its header" % (PROG, path, n), file=sys.stderr)


# ---------------------------------------------------------------- main

def main(argv):
    parser = argparse.ArgumentParser(
        prog="sweep.sh", description="dynvo-cli parameter sweep over a JSON grid (see tools/sweep.py)")
    parser.add_argument("grid", help="grid JSON file")
    parser.add_argument("--dataset", action="append", required=True,
                        help="TUM sequence folder with groundtruth.txt (repeatable)")
    parser.add_argument("--out", required=True, help="output folder (runs/, sweep.csv, ...)")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time (default 1)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--slurm", metavar="FILE", help="write an sbatch job-array script instead of running")
    mode.add_argument("--index", type=int, help="run grid point INDEX only (what an array task does)")
    mode.add_argument("--collect", action="store_true",
                      help="run nothing: write the CSV, heat map and summary of the finished runs")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")

    try:
        grid = load_grid(args.grid)
        datasets = dataset_list(args.dataset)
        if args.index is not None and not 0 <= args.index < len(grid.points):
            raise SweepError("--index %d: the grid has points 0 to %d"
                             % (args.index, len(grid.points) - 1))
        if not args.collect:
            check_with_dynvo_cli(grid, args.jobs)
        indices = [args.index] if args.index is not None else range(len(grid.points))
        runs = [Run(grid, args.out, i, d) for i in indices for d in datasets]
        if args.slurm:
            write_slurm(grid, args, datasets, args.slurm)
            return 0
        failures = 0 if args.collect else run_all(runs, args.jobs)
        if args.index is not None:
            return 1 if failures else 0
        missing = collect(grid, runs, args.out)
        if failures or missing:
            print("%s: %d of %d runs are not finished%s" % (
                PROG, missing, len(runs), " (%d failed, see above)" % failures if failures else ""),
                file=sys.stderr)
            return 1
        return 0
    except SweepError as e:
        print("%s: error: %s" % (PROG, e), file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
