"""The `figures` command: the paper's figures from dynvo's own outputs, as PNG files (and PDF
beside each).

  fig_rpe_over_time.png    per-second RPE of paper mode and baseline over time (the paper's
                           Fig. 6), with the share of dynamic pixels below
  fig_trajectory_top.png   both trajectories aligned onto the groundtruth (ATE, Horn), seen
                           along the groundtruth axis with the least spread
  fig_mask_panels.png      the dynamic-mask stages of chosen frames (the paper's Fig. 1 and 3)

It runs `dynvo-cli run` with configs/paper.json (with --debug-frames) and
configs/baseline.json, then `rpe --pairs-out` and `ate --aligned-out` on both (reports in
RUN/rpe.json and RUN/ate.json), unless existing run folders are given with --paper-run /
--baseline-run. Without --dataset it generates a dynamic sequence first (dynvo-synth
--scenario two_crossing --camera-path xyz --frames 300 --seed 1), so it needs no download; a
real TUM folder works the same way.

  bash tools/figures.sh [--dataset DIR] [--out DIR] [--work DIR] [--frames-to-show 75,225]
                        [--paper-run RUN_DIR] [--baseline-run RUN_DIR]
                        [--trajectory FILE [--label NAME]]... [--force]

Other systems' trajectories of the same sequence (--trajectory, e.g. ORB-SLAM2's
CameraTrajectory.txt) are evaluated the same way and drawn beside dynvo's.

Needs numpy and matplotlib (Debian: python3-numpy python3-matplotlib, /usr/bin/python3); they
are imported only when the command runs.
"""
from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Sequence

from .common import ROOT, ToolError, bin_path, config_path, display_path, json_number, log, read_json, run_tool
from .evaluation import ATE, RPE_PER_SECOND, EvaluatedRun, Metric, RunRequest, evaluate_run, run_dynvo

if TYPE_CHECKING:
    import numpy
    from matplotlib.figure import SubFigure

COMMAND = "figures"
FIGURES = ("fig_rpe_over_time.png", "fig_trajectory_top.png", "fig_mask_panels.png")
DEFAULT_SEQUENCE = "synth_two_crossing_xyz"
PAPER_COLOR, BASELINE_COLOR, GT_COLOR = "tab:blue", "tab:orange", "black"


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `figures` command: RPE over time, trajectory top view and mask panels as PNG."""
    parser = commands.add_parser(
        COMMAND, help="RPE over time, trajectory top view and mask panels (PNG)",
        description="RPE over time, trajectory top view and mask panels (PNG) of dynvo's "
                    "paper mode against its baseline on one TUM-layout sequence.")
    parser.add_argument("--dataset", help="TUM sequence folder with groundtruth.txt (default: "
                        "a generated two_crossing/xyz sequence, 300 frames, seed 1)")
    parser.add_argument("--out", help="folder for the PNGs (default: the --work folder)")
    parser.add_argument("--work", help="folder for runs and evaluation files (default: "
                        "out/figures/<sequence name>)")
    parser.add_argument("--frames-to-show", help="comma-separated frame indices of the mask "
                        "panels (default: at 1/4 and 3/4 of the sequence; with --paper-run, "
                        "the frames that have panels in RUN/debug)")
    parser.add_argument("--paper-run", help="reuse this dynvo-cli run folder (paper config) "
                        "instead of running it (its rpe.json and ate.json are rewritten)")
    parser.add_argument("--baseline-run", help="reuse this dynvo-cli run folder (baseline "
                        "config) instead of running it (its rpe.json and ate.json are rewritten)")
    parser.add_argument("--trajectory", action="append", default=[], metavar="FILE",
                        help="another system's trajectory of the same sequence (TUM format, e.g."
                             " ORB-SLAM2's CameraTrajectory.txt), drawn beside dynvo's (repeatable)")
    parser.add_argument("--label", action="append", default=[], metavar="NAME",
                        help="the legend name of each --trajectory, in order (default: its file name)")
    parser.add_argument("--force", action="store_true",
                        help="overwrite existing figures and runs of an earlier call")
    parser.set_defaults(run=_figures_command)


# ---------------------------------------------------------------- files


def read_lines(path: str) -> list[str]:
    """The lines of a text file; a ToolError naming the file when it cannot be read."""
    try:
        with open(path) as f:
            return f.read().splitlines()
    except OSError as error:
        raise ToolError("%s: cannot read: %s" % (path, error.strerror)) from None


def read_list(path: str) -> list[tuple[float, str]]:
    """TUM list file (rgb.txt, masks.txt): [(stamp, relative file)]; a ToolError naming the
    file and line for a line that is not 'timestamp filename'."""
    entries = []
    for number, line in enumerate(read_lines(path), 1):
        parts = line.split()
        if not parts or parts[0].startswith("#"):
            continue
        try:
            entries.append((float(parts[0]), parts[1]))
        except (ValueError, IndexError):
            raise ToolError("%s:%d: expected 'timestamp filename', got %r"
                            % (path, number, line.strip())) from None
    return entries


def read_positions(path: str) -> tuple[numpy.ndarray, numpy.ndarray]:
    """TUM trajectory file: (stamps, N x 3 positions)."""
    import numpy as np
    rows = [line.split() for line in read_lines(path) if line.strip() and not line.startswith("#")]
    try:
        data = np.array([[float(v) for v in row[:4]] for row in rows]).reshape(-1, 4)
    except ValueError:
        raise ToolError("%s: not a TUM trajectory (timestamp tx ty tz ...)" % path) from None
    return data[:, 0], data[:, 1:4]


def read_csv(path: str) -> list[dict[str, str]]:
    """The rows of a CSV file with a header line."""
    return list(csv.DictReader(read_lines(path)))


def lookup(entries: Sequence[tuple[float, str]], stamp: float, tolerance: float = 1e-4) -> Optional[str]:
    """The file of a list entry with this stamp, or None."""
    for entry_stamp, name in entries:
        if abs(entry_stamp - stamp) <= tolerance:
            return name
    return None


def parse_frames(text: str) -> list[int]:
    """--frames-to-show: sorted distinct non-negative frame indices (at least one)."""
    try:
        frames = sorted({int(item) for item in text.split(",") if item.strip()})
    except ValueError:
        raise ToolError("--frames-to-show: expected comma-separated frame indices, got '%s'"
                        % text) from None
    if not frames or frames[0] < 0:
        raise ToolError("--frames-to-show: expected non-negative frame indices, got '%s'" % text)
    return frames


# ---------------------------------------------------------------- runs


@dataclass(frozen=True)
class Evaluated:
    """One evaluated run: its reports, the RPE pairs and the aligned trajectory."""
    run: EvaluatedRun
    rpe: Metric
    ate: Metric
    pairs: str      # rpe --pairs-out: every compared pair as CSV
    aligned: str    # ate --aligned-out: the estimate aligned onto the groundtruth

    def timing(self) -> str:
        """RUN/timing.csv."""
        return os.path.join(self.run.run_dir, "timing.csv")

    def rmse(self, metric: Metric, field: str) -> float:
        """The RMSE of one object ("rotational_error_deg") of a metric's report."""
        return self.run.rmse(dataclasses.replace(metric, field=field))


def check_plotting(wrapper: str = "tools/figures.sh") -> None:
    """matplotlib (with the Agg backend) and numpy can be imported, else a ToolError that
    names the shell wrapper running Debian's python3."""
    try:
        import importlib
        import matplotlib
        matplotlib.use("Agg")
        importlib.import_module("numpy")
    except ImportError as error:
        raise ToolError("%s: run with Debian's python3 (apt install python3-matplotlib "
                        "python3-numpy), e.g. via bash %s" % (error, wrapper)) from None


def prepare_dataset(args: argparse.Namespace) -> str:
    """The dataset folder: --dataset, the reused paper run's, or the generated default."""
    if args.dataset:
        dataset = os.path.abspath(args.dataset)
        if not os.path.isdir(dataset):
            raise ToolError("--dataset %s: no such folder" % args.dataset)
    elif args.paper_run:
        run_json = os.path.join(args.paper_run, "run.json")
        folder = read_json("--paper-run %s" % args.paper_run, run_json).get("dataset", {})
        dataset = folder.get("folder") if isinstance(folder, dict) else None
        if not isinstance(dataset, str):
            raise ToolError("%s: cannot read the dataset folder (no dataset.folder); pass --dataset"
                            % run_json)
    else:
        dataset = os.path.join(ROOT, "out", "figures", "data", DEFAULT_SEQUENCE)
        if not os.path.isfile(os.path.join(dataset, "rgb.txt")):
            command = [bin_path("dynvo-synth"), "--scenario", "two_crossing", "--camera-path", "xyz",
                       "--frames", "300", "--seed", "1", "--out", dataset, "--force"]
            log(COMMAND, " ".join(command))
            run_tool("default sequence %s" % display_path(dataset), command)
    for name in ("rgb.txt", "groundtruth.txt"):
        if not os.path.isfile(os.path.join(dataset, name)):
            raise ToolError("%s: no %s (a TUM sequence folder with groundtruth is needed)"
                            % (dataset, name))
    return dataset


def check_run(run: str, what: str) -> str:
    """The absolute path of a reused run folder whose run.json says 'completed'."""
    try:
        status = read_json("--%s %s" % (what, run), os.path.join(run, "run.json")).get("status")
    except ToolError as error:
        raise ToolError("%s (not a dynvo-cli run folder)" % error) from None
    if status != "completed":
        raise ToolError("--%s %s: run.json says '%s', not 'completed'" % (what, run, status))
    return os.path.abspath(run)


def run_odometry(dataset: str, config: str, out: str, debug_frames: Sequence[int] = ()) -> str:
    """Runs `dynvo-cli run` with configs/CONFIG.json into out (replacing an earlier run)."""
    options = ("--debug-frames", ",".join(str(f) for f in debug_frames)) if debug_frames else ()
    request = RunRequest(dataset, out, config_path(config), (), options)
    log(COMMAND, " ".join(request.command()))
    run_dynvo(request, display_path(out))
    return out


def evaluate(dataset: str, run: str, name: str, work: str, force: bool) -> Evaluated:
    """Per-second RPE and ATE of one run: RUN/rpe.json and RUN/ate.json, the pairs in
    WORK/rpe_pairs_NAME.csv and the aligned trajectory in WORK/ate_aligned_NAME.txt."""
    extra = ("--force",) if force else ()
    pairs = os.path.join(work, "rpe_pairs_%s.csv" % name)
    aligned = os.path.join(work, "ate_aligned_%s.txt" % name)
    rpe = dataclasses.replace(RPE_PER_SECOND, arguments=RPE_PER_SECOND.arguments + (
        "--delta", "1", "--delta-unit", "s", "--pairs-out", pairs) + extra)
    ate = dataclasses.replace(ATE, arguments=ATE.arguments + ("--aligned-out", aligned) + extra)
    log(COMMAND, "evaluating %s: rpe --pairs-out %s, ate --aligned-out %s" % (
        display_path(run), display_path(pairs), display_path(aligned)))
    try:
        evaluated = evaluate_run(dataset, run, (rpe, ate), display_path(run))
    except OSError as error:  # a report that cannot be written into the run folder
        raise ToolError("%s: cannot write its reports: %s: %s" % (
            display_path(run), error.filename, error.strerror)) from None
    return Evaluated(evaluated, rpe, ate, pairs, aligned)


@dataclass(frozen=True)
class Curve:
    """One trajectory as the figures draw it: legend, colour, RPE pairs, aligned poses, RMSEs."""
    label: str
    color: str
    pairs: str              # rpe --pairs-out CSV
    aligned: str            # ate --aligned-out trajectory
    rpe_trans_m: float      # per-second RPE RMSE
    rpe_rot_deg: float
    ate_m: float            # ATE RMSE (Horn)


def dynvo_curve(result: Evaluated, label: str, color: str) -> Curve:
    """A dynvo run's curve."""
    return Curve(label, color, result.pairs, result.aligned, result.rmse(result.rpe, "translational_error_m"),
                 result.rmse(result.rpe, "rotational_error_deg"),
                 result.rmse(result.ate, "absolute_translational_error_m"))


def foreign_curves(dataset: str, paths: Sequence[str], labels: Sequence[str], work: str) -> list[Curve]:
    """Other systems' trajectories, evaluated like dynvo's (files WORK/other_K_*)."""
    if len(labels) > len(paths):
        raise ToolError("%d --label for %d --trajectory: at most one per trajectory" % (len(labels), len(paths)))
    groundtruth = os.path.join(dataset, "groundtruth.txt")
    colors = ("tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan")
    curves = []
    for k, path in enumerate(paths):
        if not os.path.isfile(path):
            raise ToolError("--trajectory %s: no such file" % path)
        label = labels[k] if k < len(labels) else os.path.splitext(os.path.basename(path))[0]
        pairs, aligned = (os.path.join(work, "other_%d_%s" % (k, name)) for name in ("rpe_pairs.csv", "aligned.txt"))
        rpe = json.loads(run_tool("RPE of " + label, [bin_path("rpe"), groundtruth, path, "--json", "--force",
                                                      "--pairs-out", pairs]))
        ate = json.loads(run_tool("ATE of " + label, [bin_path("ate"), groundtruth, path, "--json", "--force",
                                                      "--aligned-out", aligned]))
        curves.append(Curve(label, colors[k % len(colors)], pairs, aligned,
                            json_number(COMMAND, path, rpe, "translational_error_m.rmse"),
                            json_number(COMMAND, path, rpe, "rotational_error_deg.rmse"),
                            json_number(COMMAND, path, ate, "absolute_translational_error_m.rmse")))
    return curves


# ---------------------------------------------------------------- figures


def save_figure(fig: object, path: str, dpi: int) -> None:
    """The figure as PATH (PNG) and beside it as PDF, for papers."""
    fig.savefig(path, dpi=dpi)  # type: ignore[attr-defined]
    fig.savefig(os.path.splitext(path)[0] + ".pdf")  # type: ignore[attr-defined]


def ground_truth_dynamic_share(dataset: str, stamps: Sequence[float]) -> Optional[list[float]]:
    """Share of ground-truth dynamic pixels per frame stamp, or None without masks.txt."""
    import matplotlib.image as mpimg
    masks_txt = os.path.join(dataset, "masks.txt")
    if not os.path.isfile(masks_txt):
        return None
    entries = read_list(masks_txt)
    shares = []
    for stamp in stamps:
        name = lookup(entries, stamp)
        shares.append(float((mpimg.imread(os.path.join(dataset, name)) > 0).mean())
                      if name else float("nan"))
    return shares


def plot_rpe_over_time(path: str, sequence: str, dataset: str, paper: Evaluated, curves: Sequence[Curve]) -> None:
    """fig_rpe_over_time.png: translational and rotational per-second RPE of every curve over
    time, the share of dynamic pixels (detected, and ground truth when masks.txt exists) below."""
    import matplotlib.pyplot as plt
    import numpy as np
    timing = read_csv(paper.timing())
    t0 = float(timing[0]["stamp"])
    fig, axes = plt.subplots(3, 1, figsize=(10, 8.5), sharex=True,
                             gridspec_kw={"height_ratios": [3, 2, 1.4]})
    for curve in curves:
        pairs = read_csv(curve.pairs)
        t = np.array([float(p["stamp_est_0"]) for p in pairs]) - t0
        trans = np.array([float(p["trans_error_m"]) for p in pairs])
        rot = np.array([float(p["rot_error_deg"]) for p in pairs])
        axes[0].plot(t, trans, color=curve.color, lw=1.3, label="%s, RMSE %.4f m" % (curve.label, curve.rpe_trans_m))
        axes[1].plot(t, rot, color=curve.color, lw=1.3, label="%s, RMSE %.3f deg" % (curve.label, curve.rpe_rot_deg))
    axes[0].set_ylabel("translational RPE (m per 1 s)")
    axes[1].set_ylabel("rotational RPE (deg per 1 s)")
    for ax in axes[:2]:
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend(loc="best")

    stamps = [float(row["stamp"]) for row in timing]
    t_frames = np.array(stamps) - t0
    detected = [100.0 * float(row["dynamic_ratio"]) for row in timing]
    axes[2].plot(t_frames, detected, color=PAPER_COLOR, lw=1.2, label="detected (paper mode mask)")
    truth = ground_truth_dynamic_share(dataset, stamps)
    if truth is not None:
        axes[2].plot(t_frames, 100.0 * np.array(truth), color=GT_COLOR, lw=1.0, ls="--",
                     label="ground truth (masks.txt)")
    axes[2].set_ylabel("dynamic pixels (%)")
    axes[2].set_ylim(bottom=0)
    axes[2].set_xlabel("time since the first frame (s); RPE plotted at the start of each 1 s window")
    axes[2].grid(alpha=0.3)
    axes[2].legend(loc="best", fontsize="small")
    fig.suptitle("Per-second RPE over time on %s\n(TUM evaluate_rpe.py, fixed delta of 1 s)" % sequence)
    fig.tight_layout()
    save_figure(fig, path, 110)
    plt.close(fig)


def plot_trajectory_top(path: str, sequence: str, dataset: str, curves: Sequence[Curve]) -> None:
    """fig_trajectory_top.png: every aligned trajectory and the groundtruth in the plane of
    the two groundtruth axes with the most motion."""
    import matplotlib.pyplot as plt
    import numpy as np
    est_stamps = []
    drawn = []
    for curve in curves:
        stamps, xyz = read_positions(curve.aligned)
        est_stamps.append(stamps)
        drawn.append((xyz, "%s, ATE RMSE %.4f m" % (curve.label, curve.ate_m), curve.color))
    gt_stamps, gt_xyz = read_positions(os.path.join(dataset, "groundtruth.txt"))
    first = min(s[0] for s in est_stamps)
    last = max(s[-1] for s in est_stamps)
    inside = (gt_stamps >= first - 0.05) & (gt_stamps <= last + 0.05)
    gt_xyz = gt_xyz[inside] if inside.any() else gt_xyz
    # The two groundtruth axes along which the camera moved most: a top view for a camera
    # carried at constant height, the most informative plane otherwise.
    axes_shown = sorted(np.argsort(np.ptp(gt_xyz, axis=0))[-2:])
    a, b = axes_shown
    names = "xyz"
    fig, ax = plt.subplots(figsize=(8, 7.5))
    ax.plot(gt_xyz[:, a], gt_xyz[:, b], color=GT_COLOR, lw=2.2, ls="--", label="groundtruth")
    for xyz, label, color in drawn:
        ax.plot(xyz[:, a], xyz[:, b], color=color, lw=1.4, label=label)
    ax.plot(gt_xyz[0, a], gt_xyz[0, b], "o", color=GT_COLOR, ms=7, label="start")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("groundtruth %s (m)" % names[a])
    ax.set_ylabel("groundtruth %s (m)" % names[b])
    ax.grid(alpha=0.3)
    ax.legend(loc="best")
    ax.set_title("Trajectories on %s, aligned onto the groundtruth\n(Horn rotation + "
                 "translation, no scale; the plane of the two axes with most motion)" % sequence)
    fig.tight_layout()
    save_figure(fig, path, 110)
    plt.close(fig)


@dataclass(frozen=True)
class PanelSources:
    """Where the tiles of the mask panels come from: the sequence and the paper run."""
    dataset: str
    debug: str                                   # RUN/debug
    timing: dict[int, dict[str, str]]            # frame -> its row of RUN/timing.csv
    rgb: list[tuple[float, str]]                 # rgb.txt
    masks: Optional[list[tuple[float, str]]]     # masks.txt, None without it

    def panel(self, frame: int, name: str) -> Optional[numpy.ndarray]:
        """RUN/debug/frame_NNNNNN_NAME.png, or None when it was not written."""
        import matplotlib.image as mpimg
        file = os.path.join(self.debug, "frame_%06d_%s.png" % (frame, name))
        return mpimg.imread(file) if os.path.isfile(file) else None

    def rgb_of(self, frame: int) -> Optional[numpy.ndarray]:
        """The RGB file of a processed frame, or None."""
        import matplotlib.image as mpimg
        name = lookup(self.rgb, float(self.timing[frame]["stamp"])) if frame in self.timing else None
        return mpimg.imread(os.path.join(self.dataset, name)) if name else None

    def ground_truth(self, frame: int) -> Optional[numpy.ndarray]:
        """The ground-truth mask of a processed frame, or None without masks.txt or an entry."""
        import matplotlib.image as mpimg
        if self.masks is None:
            return None
        name = lookup(self.masks, float(self.timing[frame]["stamp"]))
        return mpimg.imread(os.path.join(self.dataset, name)) if name else None


def draw_panel_block(block: SubFigure, sources: PanelSources, sequence: str, frame: int) -> None:
    """One frame's 2 x 4 tiles (RGB, warped, difference, masks, features) and its title."""
    import numpy as np
    row = sources.timing[frame]
    note = row["mask_note"] or "no mask"
    gt = sources.ground_truth(frame)
    fused_title = "(g) fused mask = forward OR backward"
    if gt is not None:
        fused_title += "\ncyan: ground-truth outline"
        if row.get("mask_iou"):
            fused_title += " (IoU %.2f)" % float(row["mask_iou"])
    tiles = [
        ("(a) frame t-1 (RGB file)", sources.rgb_of(frame - 1), None),
        ("(b) t-1 warped onto t by H", sources.panel(frame, "compensated"), "gray"),
        ("(c) frame t (RGB file)", sources.rgb_of(frame), None),
        ("(d) |t - warped t-1|, 0-255", sources.panel(frame, "difference"), "gray"),
        ("(e) forward mask\n(Otsu, erode, dilate)", sources.panel(frame, "forward_mask"), "gray"),
        ("(f) backward mask", sources.panel(frame, "backward_mask"), "gray"),
        (fused_title, sources.panel(frame, "fused_mask"), "gray"),
        ("(h) ORB features: kept green, removed\n(in mask) red, readmitted yellow",
         sources.panel(frame, "features"), None),
    ]
    axes = block.subplots(2, 4)
    for ax, (title, image, cmap) in zip(axes.ravel(), tiles):
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(title, fontsize=11)
        if image is None:
            ax.set_facecolor("0.85")
            ax.text(0.5, 0.5, "not available" if title.startswith("(a)") else note,
                    ha="center", va="center", wrap=True, transform=ax.transAxes, fontsize=9)
            continue
        ax.imshow(image, cmap=cmap, vmin=0, vmax=1 if cmap else None)
        if gt is not None and title.startswith("(g)"):
            ax.contour((gt > 0).astype(np.float32), levels=[0.5], colors="cyan", linewidths=1.2)
    block.suptitle("%s, frame %d (t = %.2f s): %s of %s ORB features removed, %s of them "
                   "readmitted as static" % (
                       sequence, frame,
                       float(row["stamp"]) - float(sources.timing[min(sources.timing)]["stamp"]),
                       row["features_removed"], row["features_total"], row["features_readmitted"]),
                   fontsize=13)


def plot_mask_panels(path: str, sequence: str, dataset: str, paper_run: str,
                     frames: Sequence[int]) -> None:
    """fig_mask_panels.png: one block of mask-stage tiles per frame, as a 256-colour PNG."""
    import matplotlib.pyplot as plt
    masks_txt = os.path.join(dataset, "masks.txt")
    timing = {int(row["frame"]): row for row in read_csv(os.path.join(paper_run, "timing.csv"))}
    missing = [frame for frame in frames if frame not in timing]
    if missing:
        raise ToolError("%s: no frame(s) %s in timing.csv" % (
            display_path(paper_run), ",".join(map(str, missing))))
    sources = PanelSources(dataset, os.path.join(paper_run, "debug"), timing,
                           read_list(os.path.join(dataset, "rgb.txt")),
                           read_list(masks_txt) if os.path.isfile(masks_txt) else None)
    fig = plt.figure(figsize=(15, 6.4 * len(frames)), layout="constrained")
    blocks = fig.subfigures(len(frames), 1, squeeze=False)[:, 0]
    for block, frame in zip(blocks, frames):
        draw_panel_block(block, sources, sequence, frame)
    save_figure(fig, path, 80)
    plt.close(fig)
    # Photographic tiles compress poorly as true colour: a 256-colour palette keeps the
    # committed figure near 300 KB instead of 1.5 MB, with no visible loss at this size.
    from PIL import Image
    with Image.open(path) as image:
        palette = image.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)  # type: ignore[arg-type]
    palette.save(path, optimize=True)


# ---------------------------------------------------------------- the command


@dataclass(frozen=True)
class Plan:
    """What one call works on and where it writes."""
    dataset: str
    sequence: str                  # the name in the figures' titles
    work: str                      # runs and evaluation files
    out: str                       # the PNGs
    frames: list[int]              # frames of the mask panels (none: no panel figure)
    paper_run: Optional[str]       # a reused run folder, else None (run into WORK/paper)
    baseline_run: Optional[str]    # a reused run folder, else None (run into WORK/baseline)


def default_frames(dataset: str) -> list[int]:
    """Frames at 1/4 and 3/4 of the sequence (at least frame 1)."""
    count = len(read_list(os.path.join(dataset, "rgb.txt")))
    return sorted({max(1, count // 4), max(1, (3 * count) // 4)})


def debug_frames_of(run: str) -> list[int]:
    """The frames that have panels in RUN/debug."""
    debug = os.path.join(run, "debug")
    if not os.path.isdir(debug):
        return []
    return sorted({int(name[6:12]) for name in os.listdir(debug)
                   if name.startswith("frame_") and name.endswith("_panels.png")})


def make_plan(args: argparse.Namespace) -> Plan:
    """Checks the reused runs, prepares the dataset and chooses the frames of the panels."""
    paper_run = check_run(args.paper_run, "paper-run") if args.paper_run else None
    baseline_run = check_run(args.baseline_run, "baseline-run") if args.baseline_run else None
    dataset = prepare_dataset(args)
    name = os.path.basename(dataset.rstrip("/"))
    generated = not args.dataset and not args.paper_run
    work = os.path.abspath(args.work or os.path.join(ROOT, "out", "figures", name))
    if args.frames_to_show:
        frames = parse_frames(args.frames_to_show)
    elif paper_run:
        frames = debug_frames_of(paper_run)
    else:
        frames = default_frames(dataset)
    if paper_run and args.frames_to_show:
        missing = [f for f in frames if f not in debug_frames_of(paper_run)]
        if missing:
            raise ToolError("--paper-run %s has no panels of frame(s) %s in debug/: rerun "
                            "dynvo-cli run with --debug-frames %s" % (
                                args.paper_run, ",".join(map(str, missing)),
                                ",".join(map(str, frames))))
    return Plan(dataset, name + " (generated)" if generated else name, work,
                os.path.abspath(args.out or work), frames, paper_run, baseline_run)


def check_outputs(plan: Plan, force: bool) -> None:
    """Without --force, none of the call's outputs may exist yet; then makes the folders."""
    outputs = [os.path.join(plan.out, name) for name in FIGURES]
    outputs += [os.path.join(plan.work, name) for name in (
        "rpe_pairs_paper.csv", "rpe_pairs_baseline.csv", "ate_aligned_paper.txt",
        "ate_aligned_baseline.txt")]
    if not plan.paper_run:
        outputs.append(os.path.join(plan.work, "paper"))
    if not plan.baseline_run:
        outputs.append(os.path.join(plan.work, "baseline"))
    existing = [p for p in outputs if os.path.exists(p)]
    if existing and not force:
        raise ToolError("%s exists (pass --force to overwrite)" % existing[0])
    os.makedirs(plan.work, exist_ok=True)
    os.makedirs(plan.out, exist_ok=True)


def _figures_command(args: argparse.Namespace) -> int:
    check_plotting()
    plan = make_plan(args)
    check_outputs(plan, args.force)
    paper_run = plan.paper_run or run_odometry(plan.dataset, "paper", os.path.join(plan.work, "paper"),
                                               plan.frames)
    baseline_run = plan.baseline_run or run_odometry(plan.dataset, "baseline",
                                                     os.path.join(plan.work, "baseline"))
    paper = evaluate(plan.dataset, paper_run, "paper", plan.work, args.force)
    baseline = evaluate(plan.dataset, baseline_run, "baseline", plan.work, args.force)

    curves = [dynvo_curve(baseline, "baseline (mask off)", BASELINE_COLOR),
              dynvo_curve(paper, "paper mode", PAPER_COLOR)]
    curves += foreign_curves(plan.dataset, args.trajectory, args.label, plan.work)
    written = [os.path.join(plan.out, name) for name in FIGURES]
    plot_rpe_over_time(written[0], plan.sequence, plan.dataset, paper, curves)
    plot_trajectory_top(written[1], plan.sequence, plan.dataset, curves)
    if plan.frames:
        plot_mask_panels(written[2], plan.sequence, plan.dataset, paper_run, plan.frames)
    else:
        written.pop()
        log(COMMAND, "no mask panels: %s/debug has none (dynvo-cli run --debug-frames)" % paper_run)
    for path in written:
        print(path)
    return 0
