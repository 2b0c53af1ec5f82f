"""The one step every command shares: run a config on a sequence with `dynvo-cli run`, then
evaluate the trajectory with `rpe` / `ate GT EST --json`, each report kept beside the run."""
from __future__ import annotations

import argparse
import csv
import json
import os
import statistics
from dataclasses import dataclass, field
from typing import Optional, Sequence

from .common import (ToolError, bin_path, display_path, json_number, percentile, read_json, run_tool,
                     write_atomically)


@dataclass(frozen=True)
class Metric:
    """One evaluation of a run: `PROGRAM GT EST ARGUMENTS --json` into RUN_DIR/NAME.json."""
    name: str                          # the report's file stem
    program: str                       # "rpe" or "ate"
    arguments: tuple[str, ...] = ()    # options of the program
    field: str = "translational_error_m"  # the report's object whose "rmse" is the headline


# Per-second RPE (TUM evaluate_rpe.py --fixed_delta --delta 1 --delta_unit s), per-frame RPE,
# and ATE (evaluate_ate.py: Horn alignment, no scale).
RPE_PER_SECOND = Metric("rpe", "rpe")
RPE_PER_FRAME = Metric("rpe_per_frame", "rpe", ("--delta", "1", "--delta-unit", "f"))
ATE = Metric("ate", "ate", (), "absolute_translational_error_m")


def seed_overrides(seed: int) -> tuple[str, ...]:
    """The `--set` assignments that make a run use RANSAC seed SEED (homography and pose)."""
    return ("homography.seed=%d" % seed, "tracking.pose.seed=%d" % seed)


@dataclass(frozen=True)
class RunRequest:
    """One `dynvo-cli run`: a sequence folder, an output folder, a config and overrides."""
    dataset: str
    run_dir: str
    config: Optional[str] = None          # a config file; None: the built-in defaults
    overrides: tuple[str, ...] = ()       # `--set key=value` assignments, in order
    options: tuple[str, ...] = ()         # further options of `dynvo-cli run` (--debug-frames ...)

    def command(self) -> list[str]:
        """The `dynvo-cli run` command line (--quiet --force: the folder's earlier outputs go)."""
        command = [bin_path("dynvo-cli"), "run", "--quiet", "--force", "--dataset", self.dataset,
                   "--out", self.run_dir]
        if self.config:
            command += ["--config", self.config]
        for assignment in self.overrides:
            command += ["--set", assignment]
        return command + list(self.options)


@dataclass
class EvaluatedRun:
    """A finished run and its reports."""
    run_dir: str
    info: dict                                   # run.json
    reports: dict[str, dict] = field(default_factory=dict)  # metric name -> its JSON report
    suffix: str = ""                             # of the report files: "" for trajectory.txt

    def rmse(self, metric: Metric) -> float:
        """The headline RMSE of a metric's report."""
        return json_number(self.run_dir, os.path.join(self.run_dir, metric.name + self.suffix + ".json"),
                           self.reports[metric.name], metric.field + ".rmse")

    def frames(self) -> int:
        """The frames the run processed (run.json dataset.frames_to_process)."""
        return int(json_number(self.run_dir, os.path.join(self.run_dir, "run.json"), self.info,
                               "dataset.frames_to_process"))

    def mask_quality(self) -> Optional[dict[str, Optional[float]]]:
        """run.json's mask precision, recall and IoU, and "still_kept": the share of the features
        on people not moving that the mask left (None when none was detected on one); None
        without a mask or ground-truth masks."""
        if self.info.get("mask_quality") is None:
            return None
        path = os.path.join(self.run_dir, "run.json")
        quality: dict[str, Optional[float]] = {
            key: json_number(self.run_dir, path, self.info, "mask_quality." + key)
            for key in ("precision", "recall", "iou")}
        still = json_number(self.run_dir, path, self.info, "mask_quality.still_people.features")
        quality["still_kept"] = (json_number(self.run_dir, path, self.info, "mask_quality.still_people.kept_share")
                                 if still > 0 else None)
        return quality

    def processing_ms(self) -> tuple[float, float]:
        """Median and p90 of timing.csv's processing_ms (ms per frame)."""
        path = os.path.join(self.run_dir, "timing.csv")
        try:
            with open(path, newline="") as f:
                values = [float(row["processing_ms"]) for row in csv.DictReader(f)]
        except OSError as error:
            raise ToolError("%s: %s: cannot read: %s" % (self.run_dir, display_path(path), error.strerror)) from None
        except (KeyError, TypeError, ValueError):
            raise ToolError("%s: %s: no processing_ms column of numbers" % (self.run_dir, display_path(path))) from None
        if not values:
            raise ToolError("%s: %s: no frames" % (self.run_dir, display_path(path)))
        return statistics.median(values), percentile(values, 90)


def run_dynvo(request: RunRequest, what: str) -> None:
    """Runs `dynvo-cli run` as requested (replacing the folder's earlier outputs)."""
    run_tool(what, request.command())


def evaluate_run(dataset: str, run_dir: str, metrics: Sequence[Metric], what: str,
                 trajectory: str = "trajectory.txt") -> EvaluatedRun:
    """Evaluates RUN_DIR/TRAJECTORY against DATASET/groundtruth.txt with each metric, each report
    written to RUN_DIR/<metric>.json (<metric>_<trajectory's stem>.json for another trajectory
    than trajectory.txt, e.g. slam mode's trajectory_online.txt) and read back, with run.json."""
    groundtruth = os.path.join(dataset, "groundtruth.txt")
    if not os.path.isfile(groundtruth):
        raise ToolError("%s: %s: no groundtruth.txt to evaluate against" % (what, display_path(dataset)))
    suffix = "" if trajectory == "trajectory.txt" else "_" + os.path.splitext(trajectory)[0]
    run = EvaluatedRun(run_dir, read_json(what, os.path.join(run_dir, "run.json")), suffix=suffix)
    for metric in metrics:
        text = run_tool(what, [bin_path(metric.program), groundtruth, os.path.join(run_dir, trajectory),
                               *metric.arguments, "--json"])
        path = os.path.join(run_dir, metric.name + suffix + ".json")
        write_atomically(path, text)
        run.reports[metric.name] = read_json(what, path)
        run.rmse(metric)  # a report without its number is an error here, not later
    return run


def run_and_evaluate(request: RunRequest, metrics: Sequence[Metric], what: str) -> EvaluatedRun:
    """The shared step: run a config on a sequence, then evaluate the run."""
    run_dynvo(request, what)
    return evaluate_run(request.dataset, request.run_dir, metrics, what)


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `evaluate` command: one config on one sequence, run and evaluated."""
    parser = commands.add_parser(
        "evaluate", help="run one config on one sequence and evaluate it",
        description="Runs `dynvo-cli run` on a sequence and evaluates the trajectory (per-second"
                    " RPE, per-frame RPE, ATE; reports in OUT/<metric>.json); prints the RMSEs as JSON.")
    parser.add_argument("--dataset", required=True, metavar="DIR", help="TUM-style sequence folder")
    parser.add_argument("--out", required=True, metavar="DIR", help="the run's folder")
    parser.add_argument("--config", metavar="FILE", help="config file (default: the built-in defaults)")
    parser.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                        help="config override (repeatable)")
    parser.set_defaults(run=_evaluate_command)


def _evaluate_command(args: argparse.Namespace) -> int:
    metrics = (RPE_PER_SECOND, RPE_PER_FRAME, ATE)
    request = RunRequest(os.path.abspath(args.dataset), os.path.abspath(args.out),
                         os.path.abspath(args.config) if args.config else None, tuple(args.overrides))
    run = run_and_evaluate(request, metrics, display_path(args.out))
    print(json.dumps({metric.name + "_rmse_m": run.rmse(metric) for metric in metrics}, indent=2))
    return 0
