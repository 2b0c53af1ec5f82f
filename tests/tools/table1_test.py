#!/usr/bin/env python3
"""Tests of tools/table1.py on a tiny generated sequence (45 frames at 320x240, named like
the TUM folder of fr3_walking_xyz so that it fills that Table 1 row). Checks that the other
Table 1 rows say absent, that the CSV numbers are what `rpe` and `ate` print on the same
trajectories, that finished runs are kept, that a missing folder is one error naming it, and
that a failed run is reported without losing the others.
Run by ctest (test table1_test; env: DYNVO_BIN_DIR, DYNVO_SOURCE_DIR)."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

BIN_DIR = os.environ["DYNVO_BIN_DIR"]
SOURCE_DIR = os.environ["DYNVO_SOURCE_DIR"]
TABLE1 = os.path.join(SOURCE_DIR, "tools", "table1.py")
TABLE1_ROWS = ["fr2_desk_person", "fr3_sitting_halfsphere", "fr3_sitting_rpy",
               "fr3_sitting_static", "fr3_sitting_xyz", "fr3_walking_halfsphere",
               "fr3_walking_rpy", "fr3_walking_static", "fr3_walking_xyz"]
MEASURED = ["folder", "frames", "baseline_ms_per_frame", "ours_ms_per_frame"] + [
    "%s_%s" % (label, metric) for metric in ("rpe_per_second", "rpe_per_frame", "ate")
    for label in ("baseline", "ours", "improvement")]


def run_table1(*args):
    return subprocess.run([sys.executable, TABLE1] + list(args), stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True)


def read_csv(out_dir):
    with open(os.path.join(out_dir, "table1.csv")) as f:
        return {row["sequence"]: row for row in csv.DictReader(f)}


def measured(row, name):
    """The CSV column of a measured value (metric columns end in _m or _pct)."""
    for suffix in ("", "_m", "_pct"):
        if name + suffix in row:
            return row[name + suffix]
    raise KeyError(name)


def printed_rmse(program, groundtruth, estimate, *options):
    """The RMSE line of the tool's text output (6 decimals) and the full value of its JSON."""
    text = subprocess.run([os.path.join(BIN_DIR, program), groundtruth, estimate] + list(options),
                          stdout=subprocess.PIPE, check=True, text=True).stdout
    line = [l for l in text.splitlines() if l.startswith(("translational_error.rmse",
                                                          "absolute_translational_error.rmse"))]
    report = json.loads(subprocess.run(
        [os.path.join(BIN_DIR, program), groundtruth, estimate, "--json"] + list(options),
        stdout=subprocess.PIPE, check=True, text=True).stdout)
    field = "translational_error_m" if program == "rpe" else "absolute_translational_error_m"
    return float(line[0].split()[1]), report[field]["rmse"]


class Table1Test(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="table1_test_")
        cls.sequence = os.path.join(cls.tmp, "rgbd_dataset_freiburg3_walking_xyz")
        subprocess.run([os.path.join(BIN_DIR, "dynvo-synth"), "--scenario", "walking_across",
                        "--camera-path", "xyz", "--frames", "45", "--seed", "1",
                        "--width", "320", "--height", "240", "--out", cls.sequence],
                       stdout=subprocess.DEVNULL, check=True)
        # The same frames under a name that is not in Table 1: an extra row.
        cls.extra = os.path.join(cls.tmp, "synth_walking")
        os.symlink(cls.sequence, cls.extra)
        cls.out = os.path.join(cls.tmp, "out")
        cls.result = run_table1(cls.sequence, cls.extra, "--out", cls.out, "--jobs", "2")
        cls.rows = read_csv(cls.out)
        with open(os.path.join(cls.out, "table1.md")) as f:
            cls.markdown = f.read()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def test_runs_and_writes_every_table1_row_then_the_extra_one(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)
        self.assertEqual(list(self.rows), TABLE1_ROWS + ["synth_walking"])
        self.assertEqual(self.rows["synth_walking"]["in_paper_table1"], "no")
        self.assertEqual(self.rows["synth_walking"]["published_paper_m"], "-")
        self.assertEqual(self.rows["fr3_walking_xyz"]["frames"], "45")

    def test_absent_sequences_say_absent_and_keep_the_published_numbers(self):
        for name in TABLE1_ROWS[:-1]:
            row = self.rows[name]
            for column in MEASURED:
                self.assertEqual(measured(row, column), "absent", (name, column))
            float(row["published_orbslam2_vo_m"])
            float(row["published_paper_m"])
            line = [l for l in self.markdown.splitlines() if l.startswith("| %s |" % name)][0]
            self.assertEqual(line.count("| absent "), 10, line)
        self.assertEqual(float(self.rows["fr3_walking_xyz"]["published_paper_m"]), 0.105852)

    def test_numbers_are_what_rpe_and_ate_print_on_the_same_trajectories(self):
        row = self.rows["fr3_walking_xyz"]
        groundtruth = os.path.join(self.sequence, "groundtruth.txt")
        for label, run_name in (("baseline", "baseline"), ("ours", "paper")):
            run_dir = os.path.join(self.out, "runs", "fr3_walking_xyz", run_name)
            estimate = os.path.join(run_dir, "trajectory.txt")
            for metric, program, options in (("rpe_per_second", "rpe", []),
                                             ("rpe_per_frame", "rpe", ["--delta-unit", "f"]),
                                             ("ate", "ate", [])):
                text, full = printed_rmse(program, groundtruth, estimate, *options)
                value = float(row["%s_%s_m" % (label, metric)])
                self.assertAlmostEqual(value, full, places=12, msg=(label, metric))
                self.assertEqual(round(value, 6), text, (label, metric))
                self.assertIn("| %.6f |" % text, self.markdown)
            with open(os.path.join(run_dir, "run.json")) as f:
                median_ms = json.load(f)["time"]["processing_ms"]["median"]
            self.assertAlmostEqual(float(row["%s_ms_per_frame" % label]), median_ms, places=9)
        baseline, ours = (float(row["%s_rpe_per_second_m" % l]) for l in ("baseline", "ours"))
        self.assertAlmostEqual(float(row["improvement_rpe_per_second_pct"]),
                               100 * (baseline - ours) / baseline, places=9)

    def test_markdown_states_the_variant_of_each_column(self):
        for evaluation in ("`rpe GT EST` (TUM `evaluate_rpe.py --fixed_delta --delta 1"
                           " --delta_unit s`)", "`rpe GT EST --delta-unit f`", "`ate GT EST`",
                           "The paper does not say which RPE variant"):
            self.assertIn(evaluation, self.markdown)

    def test_finished_runs_are_kept(self):
        run_json = os.path.join(self.out, "runs", "fr3_walking_xyz", "paper", "run.json")
        before = os.path.getmtime(run_json)
        again = run_table1(self.sequence, "--out", self.out)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertEqual(again.stderr.count("kept the finished run"), 2, again.stderr)
        self.assertEqual(os.path.getmtime(run_json), before)

    def test_a_missing_folder_is_one_error_naming_it(self):
        missing = os.path.join(self.tmp, "no_such_sequence")
        result = run_table1(self.sequence, missing, "--out", os.path.join(self.tmp, "missing"))
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(result.stderr, "table1: error: %s: no such folder\n" % missing)
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "missing")))

    def test_a_folder_without_rgb_txt_is_one_error_naming_it(self):
        empty = os.path.join(self.tmp, "empty_folder")
        os.makedirs(empty, exist_ok=True)
        result = run_table1(empty, "--out", os.path.join(self.tmp, "empty_out"))
        self.assertNotEqual(result.returncode, 0)
        self.assertEqual(result.stderr.splitlines(),
                         ["table1: error: %s: no rgb.txt (not a TUM-style sequence folder)"
                          % empty])

    def test_a_failed_run_is_reported_and_the_others_are_kept(self):
        # The lists of the sequence without its images: dynvo-cli stops at the first frame.
        broken = os.path.join(self.tmp, "rgbd_dataset_freiburg3_sitting_xyz")
        os.makedirs(broken, exist_ok=True)
        for name in ("rgb.txt", "depth.txt", "groundtruth.txt", "camera.json"):
            shutil.copy(os.path.join(self.sequence, name), broken)
        out = os.path.join(self.tmp, "with_failure")
        shutil.copytree(os.path.join(self.out, "runs"), os.path.join(out, "runs"))
        result = run_table1(self.sequence, broken, "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("fr3_sitting_xyz ours: failed: dynvo-cli run: dynvo-cli: error: %s"
                      % os.path.join(broken, "rgb"), result.stderr)
        rows = read_csv(out)
        for column in MEASURED[1:]:
            self.assertEqual(measured(rows["fr3_sitting_xyz"], column), "failed", column)
        self.assertEqual(rows["fr3_walking_xyz"]["ours_ate_m"],
                         self.rows["fr3_walking_xyz"]["ours_ate_m"])
        self.assertEqual(rows["fr3_sitting_static"]["ours_ate_m"], "absent")


if __name__ == "__main__":
    unittest.main()
