#!/usr/bin/env python3
"""Tests of the suite-compare command (tools/dynvo_tools/suite_compare.py) on hand-made results
CSVs: per-row ratios and their geometric mean, the mask's figures before and after, rows only one
side ran, --configs, and the errors of CSVs of two splits or without a row in common.
Run by ctest (test suite_compare_test; env: DYNVO_SOURCE_DIR)."""
import csv
import os
import tempfile
import unittest

import command  # puts tools/ on sys.path
from dynvo_tools import suite


def row(sequence, config, rpe, recall="-", precision="-", still="-", status="ok", split="dev"):
    values = {key: "-" for key in suite.CSV_COLUMNS}
    values.update(split=split, sequence=sequence, kind="synthetic", twin="t", config=config, status=status,
                  frames="60", rpe_m_s=rpe, mask_recall=recall, mask_precision=precision, still_kept=still)
    return values


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
        self.assertIn("| a | 0.0200 | 0.0100 | 0.50x | 0.90 -> 0.80 | 0.50 -> 0.70 | - |", out)
        self.assertIn("| b | 0.0400 | 0.0800 | 2.00x | - | - | 0.60 -> 0.90 |", out)
        self.assertNotIn("| c |", out)  # before only
        self.assertNotIn("| d |", out)  # after only
        self.assertNotIn("| n |", out)  # not run
        # sqrt(0.5 x 2.0) = 1: the halving and the doubling cancel.
        self.assertIn("dynvo: geometric mean of after/before 1.000x over 2 rows.", out)
        self.assertIn("paper: geometric mean of after/before 1.000x over 1 rows.", out)
        code, out, _ = self.compare(before, after, "--configs", "paper")
        self.assertEqual(code, 0)
        self.assertNotIn("dynvo", out)

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
