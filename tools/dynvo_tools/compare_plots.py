"""The plots of the `compare` command (compare.py): the aligned trajectories over the
groundtruth (top view), RPE over time and the error distributions, each as PNG and PDF. Titles
hold the user's --title only, never a command line; legends hold the labels."""
from __future__ import annotations

import os
import re
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from .compare import Evaluated


def read_positions(path: str) -> list[list[float]]:
    """stamp x y z of every pose line of a TUM trajectory (comments skipped)."""
    rows = []
    with open(path) as f:
        for line in f:
            fields = [v for v in re.split(r"[\s,]+", line.strip()) if v]
            if fields and not fields[0].startswith("#"):
                rows.append([float(v) for v in fields[:4]])
    return rows


def save(fig: Any, out: str, name: str) -> list[str]:
    """The figure as OUT/NAME.png and OUT/NAME.pdf."""
    paths = [os.path.join(out, name + suffix) for suffix in (".png", ".pdf")]
    for path in paths:
        fig.savefig(path, dpi=110)
    return paths


def plot_trajectories(plt: Any, evaluated: list[Evaluated], groundtruth: str, title: str, out: str) -> list[str]:
    """Top view on the groundtruth's two widest axes; every estimate as ate aligned it."""
    import numpy as np
    gt = np.array(read_positions(groundtruth))
    spans = gt[:, 1:4].max(axis=0) - gt[:, 1:4].min(axis=0)
    a, b = sorted(np.argsort(spans)[-2:])
    fig, ax = plt.subplots(figsize=(6.4, 5.2))
    ax.plot(gt[:, 1 + a], gt[:, 1 + b], "k--", linewidth=1.2, label="groundtruth")
    for e in evaluated:
        p = np.array(e.aligned)
        ax.plot(p[:, 1 + a], p[:, 1 + b], linewidth=1.0, label=e.label)
    ax.set_xlabel("%s (m)" % "xyz"[a])
    ax.set_ylabel("%s (m)" % "xyz"[b])
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    return save(fig, out, "trajectories")


def plot_rpe_over_time(plt: Any, evaluated: list[Evaluated], title: str, out: str) -> list[str]:
    """Each pair's translational RPE at the time of its first pose."""
    fig, ax = plt.subplots(figsize=(7.2, 3.6))
    start = min(float(e.rpe_pairs[0]["stamp_est_0"]) for e in evaluated if e.rpe_pairs)
    for e in evaluated:
        ax.plot([float(p["stamp_est_0"]) - start for p in e.rpe_pairs],
                [float(p["trans_error_m"]) for p in e.rpe_pairs], linewidth=0.9, label=e.label)
    variant = evaluated[0].rpe["variant"].split(":")[0]
    ax.set_xlabel("time (s)")
    ax.set_ylabel("RPE trans. error, %s (m)" % variant)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title)
    fig.tight_layout()
    return save(fig, out, "rpe_over_time")


def plot_error_distribution(plt: Any, evaluated: list[Evaluated], align: str, title: str, out: str) -> list[str]:
    """Box plots of the per-pair RPE and the per-pose ATE of every estimate."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(8.0, 3.8))
    labels = [e.label for e in evaluated]
    left.boxplot([[float(p["trans_error_m"]) for p in e.rpe_pairs] for e in evaluated], showfliers=False)
    left.set_xticks(range(1, len(labels) + 1), labels, rotation=20, fontsize=8)
    left.set_ylabel("RPE trans. error, %s (m)" % evaluated[0].rpe["variant"].split(":")[0])
    right.boxplot([[float(p["trans_error_m"]) for p in e.ate_pairs] for e in evaluated], showfliers=False)
    right.set_xticks(range(1, len(labels) + 1), labels, rotation=20, fontsize=8)
    right.set_ylabel("ATE trans. error, %s alignment (m)" % align)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    return save(fig, out, "error_distribution")


def plot_all(evaluated: list[Evaluated], groundtruth: str, title: str, out: str, align: str = "se3") -> list[str]:
    """The three plots, as PNG and PDF; the paths written."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    paths = plot_trajectories(plt, evaluated, groundtruth, title, out)
    paths += plot_rpe_over_time(plt, evaluated, title, out)
    paths += plot_error_distribution(plt, evaluated, align, title, out)
    plt.close("all")
    return paths
