"""The outputs of the `sweep` command (no command of its own): the CSV, the heat map PNG and
the Markdown summary of a sweep, from the rows sweep.py collects. Imported only when a sweep
is collected, so that runs on cluster nodes need no matplotlib.

Heat map: one panel per dataset and metric (per-second RPE RMSE; mask IoU where the
sequence has ground-truth masks), and per value of the grid's heatmap "facet" parameter.
Within a panel, the cell at (x, y) is the mean over the finished runs of all the other
parameters' values; a red outline marks the base config's values of x and y.
"""
from __future__ import annotations

import csv
import json
import os
from typing import TYPE_CHECKING, Any, Optional, Sequence

from .common import ToolError, display_path

if TYPE_CHECKING:
    from .sweep import Grid

Row = dict[str, Any]  # one CSV row: dataset, point, the grid values as text, status, METRICS

# CSV metric columns, from rpe.json and run.json.
METRICS = ("rpe_trans_rmse_m", "rpe_rot_rmse_deg", "rpe_pairs", "mask_precision",
           "mask_recall", "mask_iou", "processing_median_ms")


def write_csv(path: str, columns: Sequence[str], rows: Sequence[Row]) -> None:
    """The rows as CSV, with these columns; a missing value is an empty field."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: "" if row.get(k) is None else row.get(k) for k in columns})


def short_name(key: str) -> str:
    """The last part of a dotted config key."""
    return key.rsplit(".", 1)[-1]


def value_texts(grid: Grid, key: str) -> list[str]:
    """A parameter's values as the CSV shows them (strings bare, the rest as JSON)."""
    return [v if isinstance(v, str) else json.dumps(v) for v in grid.parameters[key]]


def mean(values: Sequence[Optional[float]]) -> Optional[float]:
    """The mean of the values that are not None; None when there is none."""
    present = [v for v in values if v is not None]
    return sum(present) / len(present) if present else None


def dataset_names(rows: Sequence[Row]) -> list[str]:
    """The datasets of the rows, in order of first appearance."""
    names: list[str] = []
    for row in rows:
        if row["dataset"] not in names:
            names.append(row["dataset"])
    return names


def has_masks(rows: Sequence[Row], dataset: str) -> bool:
    """Whether a run on the dataset has a mask IoU (ground-truth masks)."""
    return any(r.get("mask_iou") is not None for r in rows if r["dataset"] == dataset)


def base_text(base_values: Optional[dict[str, Any]], key: str) -> Optional[str]:
    """The base config's value of a key as text; None when unknown."""
    if base_values is None:
        return None
    v = base_values[key]
    return v if isinstance(v, str) else json.dumps(v)


def panel_values(grid: Grid, rows: Sequence[Row], dataset: str, metric: str, scale: float,
                 facet: Optional[str]) -> Any:
    """The (y, x) array of one heat map panel: each cell the mean of the metric (times scale)
    over the finished runs there, NaN where none is finished."""
    import numpy as np

    x_key, y_key, facet_key = grid.heatmap_axes()
    xs = value_texts(grid, x_key)
    ys = value_texts(grid, y_key) if y_key else [""]
    values = np.full((len(ys), len(xs)), np.nan)
    for yi, y in enumerate(ys):
        for xi, x in enumerate(xs):
            m = mean([r.get(metric) for r in rows
                      if r["dataset"] == dataset and r["status"] == "finished"
                      and r[x_key] == x and (not y_key or r[y_key] == y)
                      and (not facet_key or r[facet_key] == facet)])
            if m is not None:
                values[yi, xi] = m * scale
    return values


def draw_panel(fig: Any, ax: Any, grid: Grid, values: Any, panel: tuple[str, str, str, str, float],
               facet: Optional[str], limits: tuple[float, float],
               base_values: Optional[dict[str, Any]]) -> None:
    """One panel: the cells with their numbers ("missing" where none), the base config's
    cell outlined in red, axis labels, title and colour bar."""
    import matplotlib.patches as patches
    import numpy as np

    dataset, _, label, cmap, scale = panel
    x_key, y_key, facet_key = grid.heatmap_axes()
    xs = value_texts(grid, x_key)
    ys = value_texts(grid, y_key) if y_key else [""]
    image = ax.imshow(values, origin="lower", cmap=cmap, vmin=limits[0], vmax=limits[1], aspect="auto")
    for yi in range(len(ys)):
        for xi in range(len(xs)):
            v = values[yi, xi]
            text = "missing" if not np.isfinite(v) else ("%.2f" % v if scale != 1.0 else "%.3f" % v)
            r, g, b, _ = image.cmap(image.norm(v)) if np.isfinite(v) else (1, 1, 1, 1)
            dark = 0.299 * r + 0.587 * g + 0.114 * b < 0.5
            ax.text(xi, yi, text, ha="center", va="center", fontsize=8,
                    color="white" if dark else "black")
    bx, by = base_text(base_values, x_key), base_text(base_values, y_key) if y_key else ""
    in_facet = not facet_key or base_text(base_values, facet_key) == facet
    if base_values is not None and bx in xs and by in ys and in_facet:
        ax.add_patch(patches.Rectangle((xs.index(bx) - 0.5, ys.index(by) - 0.5), 1, 1,
                                       fill=False, edgecolor="red", linewidth=2))
    ax.set_xticks(range(len(xs)), xs)
    ax.set_yticks(range(len(ys)), ys)
    ax.set_xlabel(short_name(x_key))
    if y_key:
        ax.set_ylabel(short_name(y_key))
    title = dataset + ": " + label
    if facet_key:
        title += "\n%s = %s" % (short_name(facet_key), facet)
    ax.set_title(title, fontsize=9)
    fig.colorbar(image, ax=ax, fraction=0.08)


def write_heatmap(path: str, grid: Grid, rows: Sequence[Row], base_values: Optional[dict[str, Any]]) -> None:
    """The heat map PNG: a row of panels per dataset and metric, a column per facet value,
    one colour scale per row."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy as np
    except ImportError as error:
        raise ToolError("%s: the heat map needs numpy and matplotlib (%s); set PYTHON to a python3"
                        " that has them" % (display_path(path), error)) from None

    x_key, y_key, facet_key = grid.heatmap_axes()
    xs = value_texts(grid, x_key)
    ys = value_texts(grid, y_key) if y_key else [""]
    facets: list[Optional[str]] = list(value_texts(grid, facet_key)) if facet_key else [None]
    others = [short_name(k) for k in grid.keys if k not in (x_key, y_key, facet_key)]
    panels = []  # (dataset, metric, label, colormap, scale)
    for d in dataset_names(rows):
        panels.append((d, "rpe_trans_rmse_m", "RPE RMSE (mm/s)", "viridis_r", 1000.0))
        if has_masks(rows, d):
            panels.append((d, "mask_iou", "mask IoU", "viridis", 1.0))

    fig, axes = plt.subplots(len(panels), len(facets), squeeze=False, layout="constrained",
                             figsize=(1.0 + 0.9 * len(xs) * len(facets) + 1.2 * len(facets),
                                      0.8 + (0.6 * len(ys) + 1.0) * len(panels)))
    for row_index, panel in enumerate(panels):
        dataset, metric, _, _, scale = panel
        grids = [panel_values(grid, rows, dataset, metric, scale, facet) for facet in facets]
        finite = np.concatenate([g[np.isfinite(g)] for g in grids])
        limits = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
        for col, (facet, values) in enumerate(zip(facets, grids)):
            draw_panel(fig, axes[row_index][col], grid, values, panel, facet, limits, base_values)
    note = "each cell: mean over " + ", ".join(others) if others else "each cell: one run"
    if base_values is not None:
        note += "\nred outline: the base config's values"
    fig.suptitle("Sweep %s\n%s" % (os.path.basename(grid.path), note), fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def fmt(v: Optional[float], pattern: str) -> str:
    """A number with the pattern, "-" for None."""
    return "-" if v is None else pattern % v


def summary_header(grid: Grid, rows: Sequence[Row]) -> list[str]:
    """The summary's opening paragraph: the grid, the datasets, the base config and what the
    numbers are; and how many runs are missing."""
    short = [short_name(k) for k in grid.keys]
    finished = [r for r in rows if r["status"] == "finished"]
    base = "dynvo-cli's built-in defaults"
    if grid.base_config:
        base = "the base config `%s`" % display_path(grid.base_config)
    lines = ["Sweep `%s`: %d grid points (%s) on %s, over %s. "
             "RPE: per-second translational RPE RMSE in m/s (`rpe GT EST`, TUM evaluate_rpe.py "
             "--fixed_delta --delta 1 --delta_unit s). Mask precision / recall / IoU: dynamic "
             "mask against the ground-truth masks, pixels pooled over all frames (run.json). "
             "ms: median processing time per frame in the run (concurrent runs share the cores)."
             % (grid.path, len(grid.points),
                " x ".join("%s %s" % (s, "/".join(value_texts(grid, k))) for s, k in zip(short, grid.keys)),
                ", ".join(dataset_names(rows)), base)]
    if len(finished) < len(rows):
        lines.append("")
        lines.append("%d of %d runs are missing (not finished yet)." % (len(rows) - len(finished), len(rows)))
    return lines


def ranking_table(grid: Grid, dataset: str, done: Sequence[Row],
                  base_values: Optional[dict[str, Any]]) -> list[str]:
    """The finished runs of a dataset by RPE: all of them up to 6, else the best 5, the base
    config's and the worst."""
    short = [short_name(k) for k in grid.keys]

    def is_base(r: Row) -> bool:
        """Whether the row is the base config's point."""
        return base_values is not None and all(r[k] == base_text(base_values, k) for k in grid.keys)

    if len(done) > 6:
        title = "the best 5 of %d runs by RPE, the base config and the worst" % len(done)
    else:
        title = "the %d runs by RPE" % len(done)
    lines = ["", "**%s**: %s:" % (dataset, title), ""]
    lines.append("| rank | " + " | ".join(short) + " | RPE (m/s) | precision | recall | IoU | ms |")
    lines.append("|---" * (len(short) + 6) + "|")
    shown = [(i, r) for i, r in enumerate(done) if i < 5 or is_base(r) or i == len(done) - 1]
    for i, r in shown:
        rank = str(i + 1)
        if is_base(r):
            rank += " (base)"
        elif i == len(done) - 1 and i >= 5:
            rank += " (worst)"
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            rank, " | ".join(r[k] for k in grid.keys), fmt(r["rpe_trans_rmse_m"], "%.5f"),
            fmt(r["mask_precision"], "%.3f"), fmt(r["mask_recall"], "%.3f"),
            fmt(r["mask_iou"], "%.3f"), fmt(r["processing_median_ms"], "%.1f")))
    return lines


def per_value_table(grid: Grid, done: Sequence[Row], masks: bool) -> list[str]:
    """Per value of each parameter: the mean and best RPE over the other parameters (and the
    mean IoU when the dataset has masks)."""
    lines = ["", "Mean over the other parameters, per value:", ""]
    lines.append("| parameter | value | mean RPE (m/s) | best RPE (m/s) |" + (" mean IoU |" if masks else ""))
    lines.append("|---|---|---|---|" + ("---|" if masks else ""))
    for k in grid.keys:
        for v in value_texts(grid, k):
            sel = [r for r in done if r[k] == v]
            rpes = [r["rpe_trans_rmse_m"] for r in sel]
            line = "| %s | %s | %s | %s |" % (short_name(k), v, fmt(mean(rpes), "%.5f"),
                                             fmt(min(rpes) if rpes else None, "%.5f"))
            if masks:
                line += " %s |" % fmt(mean([r["mask_iou"] for r in sel]), "%.3f")
            lines.append(line)
    return lines


def write_summary(path: str, grid: Grid, rows: Sequence[Row], base_values: Optional[dict[str, Any]]) -> None:
    """A short Markdown summary: the best runs by RPE, the base config's point and the worst
    one; then the mean of each metric per value of each parameter."""
    lines = summary_header(grid, rows)
    finished = [r for r in rows if r["status"] == "finished"]
    for d in dataset_names(rows):
        done = sorted((r for r in finished if r["dataset"] == d), key=lambda r: r["rpe_trans_rmse_m"])
        if not done:
            continue
        lines += ranking_table(grid, d, done, base_values)
        if len(grid.keys) >= 2:
            lines += per_value_table(grid, done, has_masks(rows, d))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
