#!/usr/bin/env python3
"""The paper's figures from dynvo's own outputs, as PNG files.

  fig_rpe_over_time.png    per-second RPE of paper mode and baseline over time (the paper's
                           Fig. 6), with the share of dynamic pixels below
  fig_trajectory_top.png   both trajectories aligned onto the groundtruth (ATE, Horn), seen
                           along the groundtruth axis with the least spread
  fig_mask_panels.png      the dynamic-mask stages of chosen frames (the paper's Fig. 1 and 3)

It runs `dynvo-cli run` with configs/paper.json (with --debug-frames) and
configs/baseline.json, then `rpe --pairs-out` and `ate --aligned-out` on both, unless
existing run folders are given with --paper-run / --baseline-run. Without --dataset it
generates a dynamic sequence first (dynvo-synth --scenario two_crossing --camera-path xyz
--frames 300 --seed 1), so it needs no download; a real TUM folder works the same way.

  bash tools/figures.sh [--dataset DIR] [--out DIR] [--work DIR] [--frames-to-show 75,225]
                        [--paper-run RUN_DIR] [--baseline-run RUN_DIR] [--force]

Needs numpy and matplotlib (Debian: python3-numpy python3-matplotlib, /usr/bin/python3).
Binaries come from $DYNVO_BIN_DIR, else $DYNVO_BUILD_DIR/bin, else build/bin.
"""

import argparse
import csv
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURES = ("fig_rpe_over_time.png", "fig_trajectory_top.png", "fig_mask_panels.png")
DEFAULT_SEQUENCE = "synth_two_crossing_xyz"
PAPER_COLOR, BASELINE_COLOR, GT_COLOR = "tab:blue", "tab:orange", "black"


class FigureError(Exception):
    """An input or tool failure, printed as one line 'figures: error: ...'."""


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="figures",
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
                        "instead of running it")
    parser.add_argument("--baseline-run", help="reuse this dynvo-cli run folder (baseline "
                        "config) instead of running it")
    parser.add_argument("--force", action="store_true",
                        help="overwrite existing figures and runs of an earlier call")
    return parser.parse_args(argv)


# ---------------------------------------------------------------- tools and files


def bin_path(name):
    folder = os.environ.get("DYNVO_BIN_DIR") or os.path.join(
        os.environ.get("DYNVO_BUILD_DIR") or os.path.join(ROOT, "build"), "bin")
    path = os.path.join(folder, name)
    if not os.access(path, os.X_OK):
        raise FigureError("%s not found: build first (bash tools/figures.sh builds it) or set "
                          "DYNVO_BIN_DIR" % path)
    return path


def run_tool(args):
    """Runs a dynvo binary; its stderr goes to ours. Returns stdout."""
    print("figures: " + " ".join(args),
          file=sys.stderr)
    proc = subprocess.run(args, stdout=subprocess.PIPE, universal_newlines=True)
    if proc.returncode != 0:
        raise FigureError("%s failed with exit code %d (its message is above)"
                          % (os.path.basename(args[0]), proc.returncode))
    return proc.stdout


def read_list(path):
    """TUM list file (rgb.txt, masks.txt): [(stamp, relative file)]; FigureError naming the
    file and line for a line that is not 'timestamp filename'."""
    entries = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            parts = line.split()
            if not parts or parts[0].startswith("#"):
                continue
            try:
                entries.append((float(parts[0]), parts[1]))
            except (ValueError, IndexError):
                raise FigureError("%s:%d: expected 'timestamp filename', got %r"
                                  % (path, number, line.strip()))
    return entries


def read_positions(path):
    """TUM trajectory file: (stamps, N x 3 positions)."""
    import numpy as np
    rows = [line.split() for line in open(path) if line.strip() and not line.startswith("#")]
    data = np.array([[float(v) for v in row[:4]] for row in rows]).reshape(-1, 4)
    return data[:, 0], data[:, 1:4]


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def lookup(entries, stamp, tolerance=1e-4):
    """The file of a list entry with this stamp, or None."""
    for entry_stamp, name in entries:
        if abs(entry_stamp - stamp) <= tolerance:
            return name
    return None


def parse_frames(text):
    try:
        frames = sorted({int(item) for item in text.split(",") if item.strip()})
    except ValueError:
        raise FigureError("--frames-to-show: expected comma-separated frame indices, got '%s'"
                          % text)
    if not frames or frames[0] < 0:
        raise FigureError("--frames-to-show: expected non-negative frame indices, got '%s'" % text)
    return frames


# ---------------------------------------------------------------- runs


def prepare_dataset(args):
    """The dataset folder: --dataset, the reused paper run's, or the generated default."""
    if args.dataset:
        dataset = os.path.abspath(args.dataset)
        if not os.path.isdir(dataset):
            raise FigureError("--dataset %s: no such folder" % args.dataset)
    elif args.paper_run:
        run_json = os.path.join(args.paper_run, "run.json")
        try:
            dataset = json.load(open(run_json))["dataset"]["folder"]
        except (OSError, ValueError, KeyError) as e:
            raise FigureError("%s: cannot read the dataset folder (%s); pass --dataset"
                              % (run_json, e))
    else:
        dataset = os.path.join(ROOT, "out", "figures", "data", DEFAULT_SEQUENCE)
        if not os.path.isfile(os.path.join(dataset, "rgb.txt")):
            run_tool([bin_path("dynvo-synth"), "--scenario", "two_crossing", "--camera-path", "xyz",
                      "--frames", "300", "--seed", "1", "--out", dataset, "--force"])
    for name in ("rgb.txt", "groundtruth.txt"):
        if not os.path.isfile(os.path.join(dataset, name)):
            raise FigureError("%s: no %s (a TUM sequence folder with groundtruth is needed)"
                              % (dataset, name))
    return dataset


def check_run(run, what):
    run_json = os.path.join(run, "run.json")
    try:
        status = json.load(open(run_json)).get("status")
    except (OSError, ValueError) as e:
        raise FigureError("--%s %s: not a dynvo-cli run folder (%s)" % (what, run, e))
    if status != "completed":
        raise FigureError("--%s %s: run.json says '%s', not 'completed'" % (what, run, status))
    return os.path.abspath(run)


def run_odometry(dataset, config, out, force, debug_frames=None):
    args = [bin_path("dynvo-cli"), "run", "--dataset", dataset, "--config",
            os.path.join(ROOT, "configs", config), "--out", out, "--quiet"]
    if debug_frames:
        args += ["--debug-frames", ",".join(str(f) for f in debug_frames)]
    if force:
        args.append("--force")
    run_tool(args)
    return out


def evaluate(dataset, run, name, work, force):
    """rpe (per second) and ate of one run: pair and aligned files plus their JSON summaries."""
    gt = os.path.join(dataset, "groundtruth.txt")
    est = os.path.join(run, "trajectory.txt")
    extra = ["--force"] if force else []
    pairs = os.path.join(work, "rpe_pairs_%s.csv" % name)
    aligned = os.path.join(work, "ate_aligned_%s.txt" % name)
    rpe = json.loads(run_tool([bin_path("rpe"), gt, est, "--delta", "1", "--delta-unit", "s",
                               "--json", "--pairs-out", pairs] + extra))
    ate = json.loads(run_tool([bin_path("ate"), gt, est, "--json", "--aligned-out", aligned]
                              + extra))
    return {"rpe": rpe, "ate": ate, "pairs": pairs, "aligned": aligned,
            "timing": os.path.join(run, "timing.csv"), "run": run}


# ---------------------------------------------------------------- figures


def ground_truth_dynamic_share(dataset, stamps):
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


def plot_rpe_over_time(path, sequence, dataset, paper, baseline):
    import matplotlib.pyplot as plt
    import numpy as np
    timing = read_csv(paper["timing"])
    t0 = float(timing[0]["stamp"])
    fig, axes = plt.subplots(3, 1, figsize=(10, 8.5), sharex=True,
                             gridspec_kw={"height_ratios": [3, 2, 1.4]})
    for result, label, color in ((baseline, "baseline (mask off)", BASELINE_COLOR),
                                 (paper, "paper mode", PAPER_COLOR)):
        pairs = read_csv(result["pairs"])
        t = np.array([float(p["stamp_est_0"]) for p in pairs]) - t0
        trans = np.array([float(p["trans_error_m"]) for p in pairs])
        rot = np.array([float(p["rot_error_deg"]) for p in pairs])
        axes[0].plot(t, trans, color=color, lw=1.3, label="%s, RMSE %.4f m" % (
            label, result["rpe"]["translational_error_m"]["rmse"]))
        axes[1].plot(t, rot, color=color, lw=1.3, label="%s, RMSE %.3f deg" % (
            label, result["rpe"]["rotational_error_deg"]["rmse"]))
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
    fig.suptitle("Per-second RPE over time on %s\n(rpe --delta 1 --delta-unit s: TUM "
                 "evaluate_rpe.py --fixed_delta semantics)" % sequence)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_trajectory_top(path, sequence, dataset, paper, baseline):
    import matplotlib.pyplot as plt
    import numpy as np
    est_stamps = []
    curves = []
    for result, label, color in ((baseline, "baseline (mask off)", BASELINE_COLOR),
                                 (paper, "paper mode", PAPER_COLOR)):
        stamps, xyz = read_positions(result["aligned"])
        est_stamps.append(stamps)
        curves.append((xyz, "%s, ATE RMSE %.4f m" % (
            label, result["ate"]["absolute_translational_error_m"]["rmse"]), color))
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
    for xyz, label, color in curves:
        ax.plot(xyz[:, a], xyz[:, b], color=color, lw=1.4, label=label)
    ax.plot(gt_xyz[0, a], gt_xyz[0, b], "o", color=GT_COLOR, ms=7, label="start")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("groundtruth %s (m)" % names[a])
    ax.set_ylabel("groundtruth %s (m)" % names[b])
    ax.grid(alpha=0.3)
    ax.legend(loc="best")
    ax.set_title("Trajectories on %s, aligned onto the groundtruth\n(ate: Horn rotation + "
                 "translation, no scale; the plane of the two axes with most motion)" % sequence)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_mask_panels(path, sequence, dataset, paper_run, frames):
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
    import numpy as np
    timing = {int(row["frame"]): row for row in read_csv(os.path.join(paper_run, "timing.csv"))}
    rgb = read_list(os.path.join(dataset, "rgb.txt"))
    masks_txt = os.path.join(dataset, "masks.txt")
    masks = read_list(masks_txt) if os.path.isfile(masks_txt) else None
    debug = os.path.join(paper_run, "debug")

    def panel(frame, name):
        file = os.path.join(debug, "frame_%06d_%s.png" % (frame, name))
        return mpimg.imread(file) if os.path.isfile(file) else None

    def rgb_of(frame):
        name = lookup(rgb, float(timing[frame]["stamp"])) if frame in timing else None
        return mpimg.imread(os.path.join(dataset, name)) if name else None

    cols = 4
    fig = plt.figure(figsize=(15, 6.4 * len(frames)), layout="constrained")
    blocks = fig.subfigures(len(frames), 1, squeeze=False)[:, 0]
    for block, frame in zip(blocks, frames):
        row = timing[frame]
        note = row["mask_note"] or "no mask"
        gt = None
        if masks is not None:
            name = lookup(masks, float(row["stamp"]))
            gt = mpimg.imread(os.path.join(dataset, name)) if name else None
        fused_title = "(g) fused mask = forward OR backward"
        if gt is not None:
            fused_title += "\ncyan: ground-truth outline"
            if row.get("mask_iou"):
                fused_title += " (IoU %.2f)" % float(row["mask_iou"])
        tiles = [
            ("(a) frame t-1 (RGB file)", rgb_of(frame - 1), None),
            ("(b) t-1 warped onto t by H", panel(frame, "compensated"), "gray"),
            ("(c) frame t (RGB file)", rgb_of(frame), None),
            ("(d) |t - warped t-1|, 0-255", panel(frame, "difference"), "gray"),
            ("(e) forward mask\n(Otsu, erode, dilate)", panel(frame, "forward_mask"), "gray"),
            ("(f) backward mask", panel(frame, "backward_mask"), "gray"),
            (fused_title, panel(frame, "fused_mask"), "gray"),
            ("(h) ORB features: kept green, removed\n(in mask) red, readmitted yellow", panel(frame, "features"), None),
        ]
        axes = block.subplots(2, cols)
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
            if image is not None and gt is not None and title.startswith("(g)"):
                ax.contour((gt > 0).astype(np.float32), levels=[0.5], colors="cyan",
                           linewidths=1.2)
        block.suptitle("%s, frame %d (t = %.2f s): %s of %s ORB features removed, %s of them "
                       "readmitted as static" % (
            sequence, frame, float(row["stamp"]) - float(timing[min(timing)]["stamp"]),
            row["features_removed"], row["features_total"], row["features_readmitted"]),
            fontsize=13)
    fig.savefig(path, dpi=80)
    # Photographic tiles compress poorly as true colour: a 256-colour palette keeps the
    # committed figure near 300 KB instead of 1.5 MB, with no visible loss at this size.
    from PIL import Image
    with Image.open(path) as image:
        palette = image.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)
    palette.save(path, optimize=True)
    plt.close(fig)


# ---------------------------------------------------------------- main


def default_frames(dataset):
    count = len(read_list(os.path.join(dataset, "rgb.txt")))
    return sorted({max(1, count // 4), max(1, (3 * count) // 4)})


def debug_frames_of(run):
    debug = os.path.join(run, "debug")
    if not os.path.isdir(debug):
        return []
    return sorted({int(name[6:12]) for name in os.listdir(debug)
                   if name.startswith("frame_") and name.endswith("_panels.png")})


def main(argv):
    args = parse_args(argv)
    try:
        import importlib
        import matplotlib
        matplotlib.use("Agg")
        importlib.import_module("numpy")
    except ImportError as e:
        raise FigureError("%s: run with Debian's python3 (apt install python3-matplotlib "
                          "python3-numpy), e.g. via bash tools/figures.sh" % e)
    paper_run = check_run(args.paper_run, "paper-run") if args.paper_run else None
    baseline_run = check_run(args.baseline_run, "baseline-run") if args.baseline_run else None
    dataset = prepare_dataset(args)
    name = os.path.basename(dataset.rstrip("/"))
    generated = not args.dataset and not args.paper_run
    sequence = name + " (generated)" if generated else name
    work = os.path.abspath(args.work or os.path.join(ROOT, "out", "figures", name))
    out = os.path.abspath(args.out or work)

    if args.frames_to_show:
        frames = parse_frames(args.frames_to_show)
    elif paper_run:
        frames = debug_frames_of(paper_run)
    else:
        frames = default_frames(dataset)
    if paper_run and args.frames_to_show:
        missing = [f for f in frames if f not in debug_frames_of(paper_run)]
        if missing:
            raise FigureError("--paper-run %s has no panels of frame(s) %s in debug/: rerun "
                              "dynvo-cli run with --debug-frames %s" % (
                                  args.paper_run, ",".join(map(str, missing)),
                                  ",".join(map(str, frames))))

    written = [os.path.join(out, name) for name in FIGURES]
    outputs = list(written)
    outputs += [os.path.join(work, name) for name in (
        "rpe_pairs_paper.csv", "rpe_pairs_baseline.csv", "ate_aligned_paper.txt",
        "ate_aligned_baseline.txt")]
    if not paper_run:
        outputs.append(os.path.join(work, "paper"))
    if not baseline_run:
        outputs.append(os.path.join(work, "baseline"))
    existing = [p for p in outputs if os.path.exists(p)]
    if existing and not args.force:
        raise FigureError("%s exists (pass --force to overwrite)" % existing[0])
    os.makedirs(work, exist_ok=True)
    os.makedirs(out, exist_ok=True)

    if not paper_run:
        paper_run = run_odometry(dataset, "paper.json", os.path.join(work, "paper"), args.force,
                                 frames)
    if not baseline_run:
        baseline_run = run_odometry(dataset, "baseline.json", os.path.join(work, "baseline"),
                                    args.force)
    paper = evaluate(dataset, paper_run, "paper", work, args.force)
    baseline = evaluate(dataset, baseline_run, "baseline", work, args.force)

    plot_rpe_over_time(written[0], sequence, dataset, paper, baseline)
    plot_trajectory_top(written[1], sequence, dataset, paper, baseline)
    if frames:
        plot_mask_panels(written[2], sequence, dataset, paper_run, frames)
    else:
        written.pop()
        print("figures: no mask panels: %s/debug has none (dynvo-cli run --debug-frames)"
              % paper_run, file=sys.stderr)
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except FigureError as e:
        print("figures: error: %s" % e, file=sys.stderr)
        sys.exit(1)
