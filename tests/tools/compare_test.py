"""Tests of `python3 -m dynvo_tools compare` (tools/dynvo_tools/compare.py): a groundtruth and two
estimates (one a scaled copy, as a monocular system would give) compared in one table whose
numbers are what `rpe` and `ate` print, the plots written as PNG and PDF, the Sim(3) alignment
recovering the scale, and the errors of labels, missing files and an earlier comparison.

Run by ctest (compare_test) with Debian's python3 and DYNVO_BIN_DIR / DYNVO_SOURCE_DIR set; by hand:
  DYNVO_BIN_DIR=build/bin DYNVO_SOURCE_DIR=. /usr/bin/python3 tests/tools/compare_test.py
"""
from __future__ import annotations

import csv
import json
import math
import os
import shutil
import subprocess
import tempfile
import unittest

import command

BIN_DIR = os.environ.get("DYNVO_BIN_DIR") or os.path.join(command.SOURCE_DIR, "build", "bin")


def write_trajectory(path: str, scale: float, wobble: float) -> None:
    """A 20 s loop at 30 Hz; `scale` shrinks the positions, `wobble` adds a known error."""
    with open(path, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for k in range(600):
            t = k / 30.0
            x, y, z = math.cos(0.3 * t) + wobble * math.sin(5 * t), math.sin(0.3 * t), 0.1 * t
            half = 0.15 * t / 2
            f.write("%.6f %.7f %.7f %.7f 0 0 %.7f %.7f\n" % (1000 + t, scale * x, scale * y, scale * z,
                                                             math.sin(half), math.cos(half)))


def compare(*args: str) -> subprocess.CompletedProcess[str]:
    return command.run_command("compare", *args, env=dict(os.environ, DYNVO_BIN_DIR=BIN_DIR))


class CompareTest(unittest.TestCase):
    def setUp(self) -> None:
        self.tmp = tempfile.mkdtemp(prefix="compare_test_")
        self.gt, self.good, self.mono = (os.path.join(self.tmp, n) for n in ("gt.txt", "good.txt", "mono.txt"))
        write_trajectory(self.gt, 1.0, 0.0)
        write_trajectory(self.good, 1.0, 0.01)
        os.makedirs(os.path.join(self.tmp, "orb"))
        self.mono = os.path.join(self.tmp, "orb", "CameraTrajectory.txt")
        write_trajectory(self.mono, 0.5, 0.01)

    def tearDown(self) -> None:
        shutil.rmtree(self.tmp, ignore_errors=True)

    def binary(self, *args: str) -> dict:
        return json.loads(subprocess.run([os.path.join(BIN_DIR, args[0]), *args[1:], "--json"], check=True,
                                         capture_output=True, text=True).stdout)

    def test_one_table_with_the_binaries_numbers_and_plots(self) -> None:
        out = os.path.join(self.tmp, "out")
        done = compare(self.gt, self.good, self.mono, "--label", "dynvo", "--align", "sim3", "--out", out)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(out, "compare.csv")) as f:
            rows = list(csv.reader(f))
        header = rows[0]
        self.assertIn("RPE trans. RMSE, per second (m)", header)
        self.assertIn("ATE trans. RMSE, sim3 alignment (m)", header)
        self.assertEqual([r[0] for r in rows[1:]], ["dynvo", "CameraTrajectory"])  # default label: the file
        for r, path in zip(rows[1:], (self.good, self.mono)):
            rpe = self.binary("rpe", self.gt, path)
            ate = self.binary("ate", self.gt, path, "--align", "sim3")
            cell = dict(zip(header, r))
            self.assertAlmostEqual(float(cell["RPE trans. RMSE, per second (m)"]), rpe["translational_error_m"]["rmse"])
            self.assertAlmostEqual(float(cell["ATE trans. RMSE, sim3 alignment (m)"]),
                                   ate["absolute_translational_error_m"]["rmse"])
        # The scaled estimate: Sim(3) finds the factor 2, and its ATE is the unscaled one's.
        self.assertAlmostEqual(float(rows[2][header.index("ATE scale, sim3 alignment")]), 2.0, places=3)
        ate_column = header.index("ATE trans. RMSE, sim3 alignment (m)")
        self.assertAlmostEqual(float(rows[2][ate_column]), float(rows[1][ate_column]), places=4)
        report = json.load(open(os.path.join(out, "compare.json")))
        self.assertEqual([e["label"] for e in report["estimates"]], ["dynvo", "CameraTrajectory"])
        for name in ("trajectories", "rpe_over_time", "error_distribution"):
            with open(os.path.join(out, name + ".png"), "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
            with open(os.path.join(out, name + ".pdf"), "rb") as f:
                self.assertEqual(f.read(5), b"%PDF-")
        again = compare(self.gt, self.good, "--out", out)
        self.assertEqual(again.returncode, 1)
        self.assertIn("compare.md exists from an earlier comparison; pass --force", again.stderr)

    def test_bad_labels_and_files(self) -> None:
        out = os.path.join(self.tmp, "bad")
        cases = [((self.gt, self.good, "--label", "a", "--label", "b"), "2 --label for 1 estimates"),
                 ((self.gt, self.good, self.good), "the label good names two estimates"),
                 ((self.gt, os.path.join(self.tmp, "none.txt")), "none.txt: no such file")]
        for args, message in cases:
            done = compare(*args, "--out", out)
            self.assertEqual(done.returncode, 1, args)
            self.assertIn(message, done.stderr)
            self.assertEqual(len(done.stderr.strip().splitlines()), 1, done.stderr)


if __name__ == "__main__":
    unittest.main()
