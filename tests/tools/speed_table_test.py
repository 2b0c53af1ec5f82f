#!/usr/bin/env python3
"""Tests of the `speed-table` command (tools/dynvo_tools/speed_table.py) on real `odometry_speed`
runs of a tiny generated sequence (30 frames at 320x240): one back to back with the OpenCV peers,
one fed at a live camera's rate (`--rate`). Checks that the live run's JSON holds the rate and
its latency figures in order, that it goes to its own table and not into the CSV or the
back-to-back tables, and that a folder without runs is one error naming it.
Run by ctest (test speed_table_test; env: DYNVO_BIN_DIR, DYNVO_SOURCE_DIR)."""
from __future__ import annotations

import csv
import json
import os
import shutil
import subprocess
import tempfile
import time
import unittest

import command

BIN_DIR = os.environ["DYNVO_BIN_DIR"]
CONFIG = os.path.join(command.SOURCE_DIR, "configs", "baseline.json")


class SpeedTableTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = tempfile.mkdtemp(prefix="speed_table_test_")
        cls.sequence = os.path.join(cls.tmp, "seq")
        subprocess.run([os.path.join(BIN_DIR, "dynvo-synth"), "--scenario", "none", "--camera-path", "xyz",
                        "--frames", "30", "--width", "320", "--height", "240", "--seed", "1", "--out",
                        cls.sequence], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        cls.work = os.path.join(cls.tmp, "work")
        os.makedirs(cls.work)
        cls.speed(["--runs", "1"], "a_back_to_back.json")
        start = time.monotonic()
        cls.speed(["--runs", "1", "--rate", "30", "--no-peers"], "b_live.json")
        cls.live_seconds = time.monotonic() - start

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    @classmethod
    def speed(cls, args: list[str], name: str) -> None:
        subprocess.run([os.path.join(BIN_DIR, "odometry_speed"), "--dataset", cls.sequence, "--config", CONFIG,
                        "--threads", "2", "--json", os.path.join(cls.work, name), *args], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def test_live_run_reports_its_rate_and_latency(self) -> None:
        with open(os.path.join(self.work, "b_live.json")) as f:
            live = json.load(f)
        self.assertEqual(live["rate"], 30)
        self.assertEqual(live["frames"], 30)
        ours = live["methods"]["dynvo"]
        self.assertGreater(ours["median_ms"], 0.0)
        self.assertLessEqual(ours["median_ms"], ours["max_ms"])
        self.assertLessEqual(ours["p90_ms"], ours["max_ms"])
        self.assertNotIn("opencv_rgbd_odometry", live["methods"])
        # Fed at 30 frames/s, 30 frames take at least 29 frame periods.
        self.assertGreaterEqual(self.live_seconds, 29 / 30)

    def test_live_runs_get_their_own_table(self) -> None:
        csv_path = os.path.join(self.tmp, "speed.csv")
        result = command.run_command("speed-table", self.work, "--csv", csv_path)
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(csv_path) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), 1)  # the back-to-back run only
        self.assertEqual(rows[0]["sequence"], "seq")
        lines = result.stdout.splitlines()
        live_header = lines.index("| sequence | config | camera frames/s | median ms | p90 ms | max ms |")
        live_rows = [line for line in lines[live_header + 2:] if line.startswith("| seq |")]
        self.assertEqual(len(live_rows), 1)
        with open(os.path.join(self.work, "b_live.json")) as f:
            ours = json.load(f)["methods"]["dynvo"]
        self.assertEqual(live_rows[0], "| seq | baseline | 30 | %.1f | %.1f | %.1f |" % (
            ours["median_ms"], ours["p90_ms"], ours["max_ms"]))
        # Above the live table: one row in each back-to-back table.
        self.assertEqual(sum(1 for line in lines[:live_header] if line.startswith("| seq |")), 2)

    def test_folder_without_runs_is_one_error(self) -> None:
        empty = os.path.join(self.tmp, "empty")
        os.makedirs(empty, exist_ok=True)
        result = command.run_command("speed-table", empty, "--csv", os.path.join(self.tmp, "x.csv"))
        self.assertNotEqual(result.returncode, 0)
        self.assertIn(empty, result.stderr)
        self.assertIn("no odometry_speed --json files", result.stderr)


if __name__ == "__main__":
    unittest.main()
