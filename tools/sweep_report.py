#!/usr/bin/env python3
"""The outputs of tools/sweep.py (not run by itself): the CSV, the heat map PNG and the
Markdown summary of a sweep, from the rows sweep.py collects.

Heat map: one panel per dataset and metric (per-second RPE RMSE; mask IoU where the
sequence has ground-truth masks), and per value of the grid's heatmap "facet" parameter.
Within a panel, the cell at (x, y) is the mean over the finished runs of all the other
parameters' values; a red outline marks the base config's values of x and y.
"""

import csv
import json
import os

# CSV metric columns, from rpe.json and run.json.
METRICS = ("rpe_trans_rmse_m", "rpe_rot_rmse_deg", "rpe_pairs", "mask_precision",
           "mask_recall", "mask_iou", "processing_median_ms")


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: "" if row.get(k) is None else row.get(k) for k in columns})


def short_name(key):
    return key.rsplit(".", 1)[-1]


def value_texts(grid, key):
    return [v if isinstance(v, str) else json.dumps(v) for v in grid.parameters[key]]


def mean(values):
    values = [v for v in values if v is not None]
    return sum(values) / len(values) if values else None


def dataset_names(rows):
    names = []
    for row in rows:
        if row["dataset"] not in names:
            names.append(row["dataset"])
    return names


def has_masks(rows, dataset):
    return any(r.get("mask_iou") is not None for r in rows if r["dataset"] == dataset)


def base_text(base_values, key):
    if base_values is None:
        return None
    v = base_values[key]
    return v if isinstance(v, str) else json.dumps(v)


def write_heatmap(path, grid, rows, base_values):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.patches as patches
    import numpy as np

    x_key, y_key, facet_key = grid.heatmap["x"], grid.heatmap["y"], grid.heatmap["facet"]
    xs = value_texts(grid, x_key)
    ys = value_texts(grid, y_key) if y_key else [""]
    facets = value_texts(grid, facet_key) if facet_key else [None]
    others = [short_name(k) for k in grid.keys if k not in (x_key, y_key, facet_key)]
    panels = []  # (dataset, metric, label, colormap, scale)
    for d in dataset_names(rows):
        panels.append((d, "rpe_trans_rmse_m", "RPE RMSE (mm/s)", "viridis_r", 1000.0))
        if has_masks(rows, d):
            panels.append((d, "mask_iou", "mask IoU", "viridis", 1.0))

    fig, axes = plt.subplots(len(panels), len(facets), squeeze=False, layout="constrained",
                             figsize=(1.0 + 0.9 * len(xs) * len(facets) + 1.2 * len(facets),
                                      0.8 + (0.6 * len(ys) + 1.0) * len(panels)))
    for row_index, (dataset, metric, label, cmap, scale) in enumerate(panels):
        grids = []
        for facet in facets:
            values = np.full((len(ys), len(xs)), np.nan)
            for yi, y in enumerate(ys):
                for xi, x in enumerate(xs):
                    m = mean([r.get(metric) for r in rows
                              if r["dataset"] == dataset and r["status"] == "finished"
                              and r[x_key] == x and (not y_key or r[y_key] == y)
                              and (not facet_key or r[facet_key] == facet)])
                    if m is not None:
                        values[yi, xi] = m * scale
            grids.append(values)
        finite = np.concatenate([g[np.isfinite(g)] for g in grids])
        vmin, vmax = (finite.min(), finite.max()) if finite.size else (0.0, 1.0)
        for col, (facet, values) in enumerate(zip(facets, grids)):
            ax = axes[row_index][col]
            image = ax.imshow(values, origin="lower", cmap=cmap, vmin=vmin, vmax=vmax, aspect="auto")
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
    note = "each cell: mean over " + ", ".join(others) if others else "each cell: one run"
    if base_values is not None:
        note += "\nred outline: the base config's values"
    fig.suptitle("Sweep %s\n%s" % (os.path.basename(grid.path), note), fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def fmt(v, pattern):
    return "-" if v is None else pattern % v


def write_summary(path, grid, rows, base_values):
    """A short Markdown summary: the best runs by RPE, the base config's point and the worst
    one; then the mean of each metric per value of each parameter."""
    short = [short_name(k) for k in grid.keys]
    datasets = dataset_names(rows)
    finished = [r for r in rows if r["status"] == "finished"]
    base = "dynvo-cli's built-in defaults"
    if grid.base_config:
        relative = os.path.relpath(grid.base_config)
        base = "the base config `%s`" % (grid.base_config if relative.startswith("..") else relative)
    lines = ["Sweep `%s`: %d grid points (%s) on %s, over %s. "
             "RPE: per-second translational RPE RMSE in m/s (`rpe GT EST`, TUM evaluate_rpe.py "
             "--fixed_delta --delta 1 --delta_unit s). Mask precision / recall / IoU: dynamic "
             "mask against the ground-truth masks, pixels pooled over all frames (run.json). "
             "ms: median processing time per frame in the run (concurrent runs share the cores)."
             % (grid.path, len(grid.points),
                " x ".join("%s %s" % (s, "/".join(value_texts(grid, k))) for s, k in zip(short, grid.keys)),
                ", ".join(datasets), base)]
    if len(finished) < len(rows):
        lines.append("")
        lines.append("%d of %d runs are missing (not finished yet)." % (len(rows) - len(finished), len(rows)))
    is_base = (lambda r: all(r[k] == base_text(base_values, k) for k in grid.keys)) \
        if base_values is not None else (lambda r: False)
    for d in datasets:
        done = sorted((r for r in finished if r["dataset"] == d), key=lambda r: r["rpe_trans_rmse_m"])
        if not done:
            continue
        if len(done) > 6:
            title = "the best 5 of %d runs by RPE, the base config and the worst" % len(done)
        else:
            title = "the %d runs by RPE" % len(done)
        lines += ["", "**%s**: %s:" % (d, title), ""]
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
        if len(grid.keys) < 2:
            continue
        masks = has_masks(rows, d)
        lines += ["", "Mean over the other parameters, per value:", ""]
        lines.append("| parameter | value | mean RPE (m/s) | best RPE (m/s) |" + (" mean IoU |" if masks else ""))
        lines.append("|---|---|---|---|" + ("---|" if masks else ""))
        for s, k in zip(short, grid.keys):
            for v in value_texts(grid, k):
                sel = [r for r in done if r[k] == v]
                rpes = [r["rpe_trans_rmse_m"] for r in sel]
                line = "| %s | %s | %s | %s |" % (s, v, fmt(mean(rpes), "%.5f"),
                                                 fmt(min(rpes) if rpes else None, "%.5f"))
                if masks:
                    line += " %s |" % fmt(mean([r["mask_iou"] for r in sel]), "%.3f")
                lines.append(line)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
