"""The `suite-compare` command: two results CSVs of the benchmark suite (the same split, before
and after a change) row by row. Per config: each sequence's per-second RPE before and after and
their ratio, the mask's recall, precision and still-kept share before and after, and the
geometric mean of the RPE ratios over the rows both ran. How a change is judged (bench/README.md):
on dev to choose, on validation to report; over RANSAC seeds (`suite --seeds`) when rows are
chaotic.

  python3 -m dynvo_tools suite-compare BEFORE.csv AFTER.csv [--configs a,b]
  (or bash bench/suite.sh compare BEFORE.csv AFTER.csv)
"""
from __future__ import annotations

import argparse
import math
import os
from dataclasses import dataclass
from typing import Optional

from .common import ToolError, display_path
from .suite import comma_list, csv_number, csv_optional, read_results


@dataclass(frozen=True)
class RowChange:
    """One sequence in one config, before and after."""
    sequence: str
    rpe: tuple[float, float]
    recall: tuple[Optional[float], Optional[float]]
    precision: tuple[Optional[float], Optional[float]]
    still_kept: tuple[Optional[float], Optional[float]]

    @property
    def ratio(self) -> float:
        """After over before."""
        return self.rpe[1] / self.rpe[0]


def ok_rows(path: str) -> tuple[str, dict[tuple[str, str], dict[str, str]]]:
    """The split of a results CSV and its rows that ran, by (config, sequence)."""
    rows = read_results(path)
    return rows[0]["split"], {(r["config"], r["sequence"]): r for r in rows if r["status"] == "ok"}


def changes(before_path: str, after_path: str, configs: Optional[tuple[str, ...]]) -> dict[str, list[RowChange]]:
    """Per config (in the after CSV's order), the rows both CSVs ran with a positive RPE before."""
    split_before, before = ok_rows(before_path)
    split_after, after = ok_rows(after_path)
    if split_before != split_after:
        raise ToolError("%s is the %s split, %s the %s split" % (
            display_path(before_path), split_before, display_path(after_path), split_after))
    by_config: dict[str, list[RowChange]] = {}
    for key, new in after.items():
        old = before.get(key)
        if old is None or (configs and key[0] not in configs):
            continue
        rpe_before, rpe_after = csv_number(old, "rpe_m_s", before_path), csv_number(new, "rpe_m_s", after_path)
        if rpe_before is None or rpe_after is None or rpe_before <= 0:
            continue
        pairs = [(csv_optional(old, column, before_path), csv_optional(new, column, after_path))
                 for column in ("mask_recall", "mask_precision", "still_kept")]
        by_config.setdefault(key[0], []).append(RowChange(key[1], (rpe_before, rpe_after), *pairs))
    if not by_config:
        raise ToolError("%s and %s have no row in common%s" % (
            display_path(before_path), display_path(after_path), " for --configs" if configs else ""))
    return by_config


def geometric_mean(values: list[float]) -> float:
    """exp(mean(log v)) of positive values."""
    return math.exp(sum(math.log(v) for v in values) / len(values))


def before_after(values: tuple[Optional[float], Optional[float]]) -> str:
    """"0.90 -> 0.74"; "-" for a side without a value, and for both."""
    if values[0] is None and values[1] is None:
        return "-"
    return " -> ".join("-" if v is None else "%.2f" % v for v in values)


def markdown(by_config: dict[str, list[RowChange]], before_path: str, after_path: str) -> str:
    """One table per config, then its geometric mean of the RPE ratios."""
    text = ["Per-second RPE (m/s) and the mask, before (%s) -> after (%s)." % (
        os.path.basename(before_path), os.path.basename(after_path))]
    for config, rows in by_config.items():
        text += ["", "**%s**" % config, "",
                 "| sequence | RPE before | RPE after | after/before | mask recall | mask precision | still kept |",
                 "|---|---|---|---|---|---|---|"]
        text += ["| %s | %.4f | %.4f | %.2fx | %s | %s | %s |" % (
            r.sequence, r.rpe[0], r.rpe[1], r.ratio, before_after(r.recall), before_after(r.precision),
            before_after(r.still_kept)) for r in rows]
        text += ["", "%s: geometric mean of after/before %.3fx over %d rows." % (
            config, geometric_mean([r.ratio for r in rows]), len(rows))]
    return "\n".join(text) + "\n"


def run(args: argparse.Namespace) -> int:
    """Prints the comparison."""
    print(markdown(changes(args.before, args.after, args.configs), args.before, args.after), end="")
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `suite-compare` command."""
    parser = commands.add_parser("suite-compare", help="two suite results CSVs row by row",
                                 description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("before", metavar="BEFORE.csv", help="suite_<split>.csv before the change")
    parser.add_argument("after", metavar="AFTER.csv", help="suite_<split>.csv after it (the same split)")
    parser.add_argument("--configs", type=comma_list, default=None, metavar="A,B",
                        help="only these configs (default: all both ran)")
    parser.set_defaults(run=run)
