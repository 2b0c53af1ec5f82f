"""The `suite-compare` command: two results CSVs of the benchmark suite (the same split, before
and after a change) row by row. Per config: each sequence's per-second RPE before and after and
their ratio, the mask's recall, precision and still-kept share before and after, and the
geometric mean of the RPE ratios over the rows both ran. Over RANSAC seeds (`suite --seeds`):
per row whether the seeds' RPE ranges before and after are apart, and, when both CSVs hold each
row's per-seed RPEs, the interval the geometric mean moves in when each row's seeds are drawn
again (a bootstrap): a change whose interval holds 1.0x is within the seeds' noise. How a change
is judged (bench/README.md): on dev to choose, on validation to report.

  python3 -m dynvo_tools suite-compare BEFORE.csv AFTER.csv [--configs a,b]
  (or bash bench/suite.sh compare BEFORE.csv AFTER.csv)
"""
from __future__ import annotations

import argparse
import math
import os
import random
import statistics
from dataclasses import dataclass
from typing import Optional

from .common import ToolError, display_path
from .suite import comma_list, csv_number, csv_optional, csv_seed_values, read_results

BOOTSTRAP_DRAWS = 2000  # resamples of the seeds behind the interval
BOOTSTRAP_SHARE = 0.90  # of them inside it


@dataclass(frozen=True)
class RowChange:
    """One sequence in one config, before and after."""
    sequence: str
    rpe: tuple[float, float]
    recall: tuple[Optional[float], Optional[float]]
    precision: tuple[Optional[float], Optional[float]]
    still_kept: tuple[Optional[float], Optional[float]]
    ranges: tuple[Optional[tuple[float, float]], Optional[tuple[float, float]]] = (None, None)  # seeds' min, max
    seeds: tuple[tuple[float, ...], tuple[float, ...]] = ((), ())  # the per-seed RPEs, before and after

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
        recall, precision, still_kept = [(csv_optional(old, column, before_path), csv_optional(new, column, after_path))
                                         for column in ("mask_recall", "mask_precision", "still_kept")]
        by_config.setdefault(key[0], []).append(RowChange(
            key[1], (rpe_before, rpe_after), recall, precision, still_kept,
            ranges=(seed_range(old, before_path), seed_range(new, after_path)),
            seeds=(csv_seed_values(old, before_path), csv_seed_values(new, after_path))))
    if not by_config:
        raise ToolError("%s and %s have no row in common%s" % (
            display_path(before_path), display_path(after_path), " for --configs" if configs else ""))
    return by_config


def seed_range(row: dict[str, str], path: str) -> Optional[tuple[float, float]]:
    """The row's RPE over its seeds, (min, max); None for a single run or an older CSV."""
    low, high = csv_optional(row, "rpe_min_m_s", path), csv_optional(row, "rpe_max_m_s", path)
    return None if low is None or high is None else (low, high)


def ranges_apart(change: RowChange) -> str:
    """"apart" when every seed after is below (or above) every seed before, "overlap" when not,
    "-" without the ranges."""
    before, after = change.ranges
    if before is None or after is None:
        return "-"
    return "apart" if after[1] < before[0] or after[0] > before[1] else "overlap"


def geometric_mean(values: list[float]) -> float:
    """exp(mean(log v)) of positive values."""
    return math.exp(sum(math.log(v) for v in values) / len(values))


def seed_interval(rows: list[RowChange]) -> Optional[tuple[float, float]]:
    """The central BOOTSTRAP_SHARE of the geometric means of the RPE ratios when each row's
    seeds, before and after, are drawn again with replacement (BOOTSTRAP_DRAWS times, a fixed
    RNG seed: the same CSVs give the same interval); None unless every row has two or more
    per-seed RPEs on both sides."""
    if any(len(side) < 2 for r in rows for side in r.seeds):
        return None
    rng = random.Random(1)

    def redrawn(values: tuple[float, ...]) -> float:
        return statistics.median(rng.choices(values, k=len(values)))

    means = sorted(geometric_mean([redrawn(r.seeds[1]) / redrawn(r.seeds[0]) for r in rows])
                   for _ in range(BOOTSTRAP_DRAWS))
    tail = int(round(BOOTSTRAP_DRAWS * (1.0 - BOOTSTRAP_SHARE) / 2))
    return means[tail], means[BOOTSTRAP_DRAWS - 1 - tail]


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
                 "| sequence | RPE before | RPE after | after/before | seeds | mask recall | mask precision |"
                 " still kept |",
                 "|---|---|---|---|---|---|---|---|"]
        text += ["| %s | %.4f | %.4f | %.2fx | %s | %s | %s | %s |" % (
            r.sequence, r.rpe[0], r.rpe[1], r.ratio, ranges_apart(r), before_after(r.recall),
            before_after(r.precision), before_after(r.still_kept)) for r in rows]
        text += ["", "%s: geometric mean of after/before %.3fx over %d rows." % (
            config, geometric_mean([r.ratio for r in rows]), len(rows))]
        interval = seed_interval(rows)
        text += ["%s: with the seeds of every row drawn again, %d%% of %d draws give %.3fx-%.3fx." % (
            config, round(100 * BOOTSTRAP_SHARE), BOOTSTRAP_DRAWS, *interval) if interval else
            "%s: no interval over the seeds (each row's per-seed RPEs are not in both CSVs)." % config]
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
