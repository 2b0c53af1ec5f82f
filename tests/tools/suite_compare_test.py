#!/usr/bin/env python3
"""Tests of the suite-compare command (tools/dynvo_tools/suite_compare.py) on hand-made results
CSVs: per-row ratios and their geometric mean, the mask's figures before and after, rows only one
side ran, --configs, and the errors of CSVs of two splits or without a row in common.
Run by ctest (test suite_compare_test; env: DYNVO_SOURCE_DIR)."""
import csv
import os
import re
import statistics
import tempfile
import unittest

import command  # puts tools/ on sys.path
from dynvo_tools import suite


def row(sequence, config, rpe, recall="-", precision="-", still="-", status="ok", split="dev"):
    values = {key: "-" for key in suite.CSV_COLUMNS}
    values.update(split=split, sequence=sequence, kind="synthetic", twin="t", config=config, status=status,
                  frames="60", rpe_m_s=rpe, mask_recall=recall, mask_precision=precision, still_kept=still)
    return values


def seeded_row(sequence, seeds):
    """A dynvo row over RANSAC seeds with these per-seed RPEs."""
    values = row(sequence, "dynvo", repr(statistics.median(seeds)))
    values.update(seeds=str(len(seeds)), rpe_min_m_s=repr(min(seeds)), rpe_max_m_s=repr(max(seeds)),
                  rpe_seeds_m_s=";".join(repr(v) for v in seeds))
    return values


def interval(out):
    """The (low, high) of suite-compare's interval over the seeds."""
    found = re.search(r"give ([0-9.]+)x-([0-9.]+)x\.", out)
    return float(found.group(1)), float(found.group(2))


class SuiteCompare(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, rows):
        path = os.path.join(self.tmp.name, name)
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=suite.CSV_COLUMNS)
            writer.writeheader()
            writer.writerows(rows)
        return path

    def compare(self, *args):
        result = command.run_command("suite-compare", *args)
        return result.returncode, result.stdout, result.stderr

    def test_ratios_their_geometric_mean_and_the_mask(self):
        before = self.write("before.csv", [
            row("a", "dynvo", "0.02", "0.90", "0.50"), row("b", "dynvo", "0.04", still="0.60"),
            row("c", "dynvo", "0.01"), row("a", "paper", "0.03"),
            row("n", "dynvo", "-", status=suite.NOT_RUN)])
        after = self.write("after.csv", [
            row("a", "dynvo", "0.01", "0.80", "0.70"), row("b", "dynvo", "0.08", still="0.90"),
            row("d", "dynvo", "0.05"), row("a", "paper", "0.03"), row("n", "dynvo", "-", status=suite.NOT_RUN)])
        code, out, err = self.compare(before, after)
        self.assertEqual(code, 0, err)
        self.assertIn("| a | 0.0200 | 0.0100 | 0.50x | - | 0.90 -> 0.80 | 0.50 -> 0.70 | - |", out)
        self.assertIn("| b | 0.0400 | 0.0800 | 2.00x | - | - | - | 0.60 -> 0.90 |", out)
        self.assertNotIn("| c |", out)  # before only
        self.assertNotIn("| d |", out)  # after only
        self.assertNotIn("| n |", out)  # not run
        # sqrt(0.5 x 2.0) = 1: the halving and the doubling cancel.
        self.assertIn("dynvo: geometric mean of after/before 1.000x over 2 rows.", out)
        self.assertIn("paper: geometric mean of after/before 1.000x over 1 rows.", out)
        code, out, _ = self.compare(before, after, "--configs", "paper")
        self.assertEqual(code, 0)
        self.assertNotIn("dynvo", out)

    def test_seed_ranges_apart_and_the_interval_over_the_seeds(self):
        before = self.write("before.csv", [seeded_row("a", [0.020, 0.022, 0.021]),
                                           seeded_row("b", [0.010, 0.030, 0.020])])
        # a: every seed after below every seed before; b: the same seeds again.
        after = self.write("after.csv", [seeded_row("a", [0.011, 0.010, 0.012]),
                                         seeded_row("b", [0.020, 0.010, 0.030])])
        code, out, err = self.compare(before, after)
        self.assertEqual(code, 0, err)
        self.assertIn("| a | 0.0210 | 0.0110 | 0.52x | apart |", out)
        self.assertIn("| b | 0.0200 | 0.0200 | 1.00x | overlap |", out)
        low, high = interval(out)
        # Any redraw: a's ratio within [0.010 / 0.022, 0.012 / 0.020], b's within [1/3, 3].
        self.assertGreaterEqual(low, (0.010 / 0.022 / 3) ** 0.5)
        self.assertLessEqual(high, (0.012 / 0.020 * 3) ** 0.5)
        self.assertLess(low, (0.011 / 0.021) ** 0.5)  # the medians' own mean lies inside
        self.assertGreater(high, (0.011 / 0.021) ** 0.5)
        self.assertEqual(self.compare(before, after)[1], out)  # the same CSVs, the same interval
        # The same seeds on both sides: a change within the seeds' noise, the interval holds 1.0x.
        code, out, _ = self.compare(before, before)
        low, high = interval(out)
        self.assertLess(low, 1.0)
        self.assertGreater(high, 1.0)
        # Without the per-seed RPEs (single runs, older CSVs) there is no interval, and no error.
        plain = self.write("plain.csv", [row("a", "dynvo", "0.02"), row("b", "dynvo", "0.02")])
        code, out, err = self.compare(plain, after)
        self.assertEqual(code, 0, err)
        self.assertIn("dynvo: no interval over the seeds", out)

    def test_a_bad_per_seed_value_names_the_csv_and_row(self):
        good = self.write("good.csv", [seeded_row("a", [0.02, 0.03])])
        bad_row = seeded_row("a", [0.02, 0.03])
        bad_row["rpe_seeds_m_s"] = "0.02;x"
        bad = self.write("bad.csv", [bad_row])
        code, _, err = self.compare(good, bad)
        self.assertEqual(code, 1)
        self.assertIn("bad.csv: a dynvo: rpe_seeds_m_s is not numbers separated by ';': '0.02;x'", err)
        self.assertNotIn("Traceback", err)

    def test_two_splits_or_nothing_in_common_is_an_error(self):
        dev = self.write("dev.csv", [row("a", "dynvo", "0.02")])
        validation = self.write("validation.csv", [row("a", "dynvo", "0.02", split="validation")])
        code, _, err = self.compare(dev, validation)
        self.assertEqual(code, 1)
        self.assertIn("suite-compare: error: ", err)
        self.assertIn("dev.csv is the dev split, ", err)
        self.assertIn("validation.csv the validation split", err)
        other = self.write("other.csv", [row("b", "dynvo", "0.02")])
        code, _, err = self.compare(dev, other)
        self.assertEqual(code, 1)
        self.assertIn("have no row in common", err)
        code, _, err = self.compare(dev, os.path.join(self.tmp.name, "missing.csv"))
        self.assertEqual(code, 1)
        self.assertIn("missing.csv: cannot read", err)
        self.assertNotIn("Traceback", err)


if __name__ == "__main__":
    unittest.main()
