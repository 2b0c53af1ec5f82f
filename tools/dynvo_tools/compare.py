"""The `compare` command: several trajectories (dynvo's, ORB-SLAM2's CameraTrajectory.txt or
KeyFrameTrajectory.txt, any TUM-format file) against one groundtruth, in one table and one set
of plots (tools/compare.sh).

Every estimate is evaluated by the `rpe` and `ate` binaries (the TUM scripts' semantics): RPE
at the chosen fixed delta, ATE after the chosen alignment (se3: Horn, as evaluate_ate.py;
sim3: Umeyama with scale, as evo's --align --correct_scale; none), with the rotational ATE
beside it. Writes OUT/compare.md, compare.csv and compare.json (the variant of each metric in
every column header) and, with matplotlib, OUT/trajectories, rpe_over_time and
error_distribution as PNG and PDF."""
from __future__ import annotations

import argparse
import csv
import io
import json
import os
import tempfile
from dataclasses import dataclass

from .common import ToolError, bin_path, display_path, json_number, log, run_tool, write_atomically
from .figures import check_plotting

PROG = "compare"
OUTPUTS = ("compare.md", "compare.csv", "compare.json")


@dataclass
class Evaluated:
    """One estimate with its reports and per-pair errors."""
    label: str
    path: str
    rpe: dict
    ate: dict
    rpe_pairs: list[dict]      # rpe --pairs-out rows
    aligned: list[list[float]]  # ate --aligned-out: stamp x y z per pose
    ate_pairs: list[dict]      # ate --pairs-out rows


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `compare` command."""
    parser = commands.add_parser(PROG, help="several trajectories against one groundtruth: table and plots",
                                 description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("groundtruth", metavar="GT", help="groundtruth trajectory (TUM format)")
    parser.add_argument("estimates", nargs="+", metavar="EST", help="estimated trajectories (TUM format)")
    parser.add_argument("--label", action="append", default=[], metavar="NAME",
                        help="the name of each estimate, in order (the rest default to their folder"
                             " for a trajectory.txt, else their file name)")
    parser.add_argument("--align", choices=("se3", "sim3", "none"), default="se3",
                        help="ATE alignment (default se3, as evaluate_ate.py)")
    parser.add_argument("--delta", default="1", help="RPE fixed delta (default 1)")
    parser.add_argument("--delta-unit", choices=("s", "f", "m", "rad", "deg"), default="s",
                        help="RPE delta unit (default s: drift per second)")
    parser.add_argument("--title", default="", help="a title over the plots (default none)")
    parser.add_argument("--out", required=True, metavar="DIR", help="where the table and plots go")
    parser.add_argument("--force", action="store_true", help="replace an earlier comparison in DIR")
    parser.set_defaults(run=run)


def default_label(path: str) -> str:
    """out/mine/trajectory.txt -> mine; CameraTrajectory.txt -> CameraTrajectory."""
    name = os.path.basename(path)
    if name == "trajectory.txt":
        return os.path.basename(os.path.dirname(os.path.abspath(path))) or "trajectory"
    return os.path.splitext(name)[0]


def labels_of(args: argparse.Namespace) -> list[str]:
    """One distinct label per estimate; ToolError when they cannot be told apart."""
    if len(args.label) > len(args.estimates):
        raise ToolError("%d --label for %d estimates: at most one per estimate, in order"
                        % (len(args.label), len(args.estimates)))
    labels = args.label + [default_label(path) for path in args.estimates[len(args.label):]]
    repeated = sorted({label for label in labels if labels.count(label) > 1})
    if repeated:
        raise ToolError("the label %s names two estimates: give each its own with --label" % repeated[0])
    return labels


def read_csv(path: str) -> list[dict]:
    """The rows of a CSV the binaries wrote."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def evaluate(args: argparse.Namespace, label: str, path: str, work: str) -> Evaluated:
    """rpe and ate on one estimate, with their pairs and the aligned trajectory."""
    if not os.path.isfile(path):
        raise ToolError("%s: no such file" % display_path(path))
    stem = os.path.join(work, str(len(os.listdir(work))))
    rpe = json.loads(run_tool("RPE of %s" % label, [
        bin_path("rpe"), args.groundtruth, path, "--json", "--delta", args.delta, "--delta-unit", args.delta_unit,
        "--pairs-out", stem + "_rpe.csv"]))
    ate = json.loads(run_tool("ATE of %s" % label, [
        bin_path("ate"), args.groundtruth, path, "--json", "--align", args.align, "--pairs-out", stem + "_ate.csv",
        "--aligned-out", stem + "_aligned.txt"]))
    with open(stem + "_aligned.txt") as f:
        aligned = [[float(v) for v in line.split()[:4]] for line in f if line.strip()]
    return Evaluated(label, path, rpe, ate, read_csv(stem + "_rpe.csv"), aligned, read_csv(stem + "_ate.csv"))


def headers(first: Evaluated, align: str) -> list[str]:
    """The table's columns, each with its metric's variant."""
    rpe_variant = first.rpe["variant"].split(":")[0]  # e.g. "per second"
    ate_variant = {"se3": "se3 alignment", "sim3": "sim3 alignment", "none": "no alignment"}[align]
    return ["estimate", "RPE trans. RMSE, %s (m)" % rpe_variant, "RPE rot. RMSE, %s (deg)" % rpe_variant,
            "ATE trans. RMSE, %s (m)" % ate_variant, "ATE rot. RMSE, %s (deg)" % ate_variant,
            "ATE scale, %s" % ate_variant, "RPE pairs", "ATE poses"]


def row(e: Evaluated) -> list[object]:
    """One estimate's cells, in the order of headers()."""
    number = lambda report, key: json_number(PROG, e.path, report, key)  # noqa: E731
    return [e.label, number(e.rpe, "translational_error_m.rmse"), number(e.rpe, "rotational_error_deg.rmse"),
            number(e.ate, "absolute_translational_error_m.rmse"), number(e.ate, "absolute_rotational_error_deg.rmse"),
            number(e.ate, "alignment_scale"), int(number(e.rpe, "compared_pose_pairs")),
            int(number(e.ate, "compared_pose_pairs"))]


def tables(evaluated: list[Evaluated], args: argparse.Namespace) -> dict[str, str]:
    """compare.md, compare.csv and compare.json."""
    names = headers(evaluated[0], args.align)
    rows = [row(e) for e in evaluated]
    fmt = lambda v: v if isinstance(v, str) else ("%d" % v if isinstance(v, int) else "%.4f" % v)  # noqa: E731
    md = ["Trajectories against %s (`rpe` and `ate`, TUM benchmark semantics). Generated by"
          " `bash tools/compare.sh`." % os.path.basename(args.groundtruth), "",
          "| " + " | ".join(names) + " |", "|" + "---|" * len(names)]
    md += ["| " + " | ".join(fmt(v) for v in r) + " |" for r in rows]
    text = io.StringIO()
    writer = csv.writer(text)
    writer.writerow(names)
    writer.writerows(rows)
    records = [{"label": e.label, "path": os.path.abspath(e.path), "rpe": e.rpe, "ate": e.ate} for e in evaluated]
    return {"compare.md": "\n".join(md) + "\n", "compare.csv": text.getvalue(),
            "compare.json": json.dumps({"groundtruth": os.path.abspath(args.groundtruth), "columns": names,
                                        "estimates": records}, indent=2) + "\n"}


def run(args: argparse.Namespace) -> int:
    """Evaluates every estimate, writes the tables and plots, prints the Markdown table."""
    check_plotting("tools/compare.sh")
    labels = labels_of(args)
    if not os.path.isfile(args.groundtruth):
        raise ToolError("%s: no such file" % display_path(args.groundtruth))
    existing = [name for name in OUTPUTS if os.path.exists(os.path.join(args.out, name))]
    if existing and not args.force:
        raise ToolError("%s exists from an earlier comparison; pass --force to replace it"
                        % display_path(os.path.join(args.out, existing[0])))
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as work:
        evaluated = [evaluate(args, label, path, work) for label, path in zip(labels, args.estimates)]
    for name, text in tables(evaluated, args).items():
        write_atomically(os.path.join(args.out, name), text)
    from .compare_plots import plot_all  # matplotlib only when it gets this far
    for path in plot_all(evaluated, args.groundtruth, args.title, args.out, args.align):
        log(PROG, "wrote %s" % display_path(path))
    with open(os.path.join(args.out, "compare.md")) as f:
        print(f.read(), end="")
    return 0
