"""Tests of `python3 -m dynvo_tools figures` (tools/dynvo_tools/figures.py) on a tiny generated sequence (30 frames at 10 Hz: 3 s, for 1 s RPE windows): the three PNGs are
written and are real images of a sensible size, earlier outputs are not overwritten without
--force, existing runs can be reused (not run again), and a missing dataset fails with one
clear line.

Run by ctest (figures_test) with Debian's python3 and DYNVO_BIN_DIR / DYNVO_SOURCE_DIR set;
by hand:
  DYNVO_BIN_DIR=build/bin DYNVO_SOURCE_DIR=. /usr/bin/python3 tests/tools/figures_test.py
"""
from __future__ import annotations

import os
import shutil
import struct
import subprocess
import tempfile
import unittest

import command

BIN_DIR = os.environ.get("DYNVO_BIN_DIR") or os.path.join(command.SOURCE_DIR, "build", "bin")
NAMES = ("fig_rpe_over_time.png", "fig_trajectory_top.png", "fig_mask_panels.png")


def run_figures(*args: str) -> subprocess.CompletedProcess[str]:
    """`python3 -m dynvo_tools figures ARGS...` with the binaries of BIN_DIR."""
    return command.run_command("figures", *args, env=dict(os.environ, DYNVO_BIN_DIR=BIN_DIR))


def png_size(path: str) -> tuple[int, int]:
    """(width, height) from the PNG header; fails the test when it is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise AssertionError("%s is not a PNG file" % path)
    return struct.unpack(">II", head[16:24])


class FiguresTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = tempfile.mkdtemp(prefix="figures_test_")
        cls.dataset = os.path.join(cls.tmp, "synth_two_crossing_30")
        subprocess.run([os.path.join(BIN_DIR, "dynvo-synth"), "--scenario", "two_crossing",
                        "--camera-path", "xyz", "--frames", "30", "--fps", "10", "--seed", "1", "--out",
                        cls.dataset], check=True, stdout=subprocess.DEVNULL)
        cls.work = os.path.join(cls.tmp, "work")
        cls.out = os.path.join(cls.tmp, "figures")
        cls.first = run_figures("--dataset", cls.dataset, "--work", cls.work, "--out", cls.out,
                                "--frames-to-show", "10,20")

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def assert_figures(self, folder: str, min_height: dict[str, int]) -> None:
        for name in NAMES:
            path = os.path.join(folder, name)
            self.assertTrue(os.path.isfile(path), path)
            width, height = png_size(path)
            self.assertGreaterEqual(width, 800, name)
            self.assertLessEqual(width, 4000, name)
            self.assertGreaterEqual(height, min_height.get(name, 600), name)
            self.assertLessEqual(height, 6000, name)
            self.assertGreater(os.path.getsize(path), 20000, name)  # not a blank canvas

    def test_writes_the_three_figures(self) -> None:
        self.assertEqual(self.first.returncode, 0, self.first.stderr)
        # Two frames of panels: two blocks of 2 x 4 tiles.
        self.assert_figures(self.out, {"fig_mask_panels.png": 1000})
        self.assertTrue(os.path.isfile(os.path.join(self.work, "paper", "debug",
                                                    "frame_000010_panels.png")))
        for name in ("rpe_pairs_paper.csv", "rpe_pairs_baseline.csv", "ate_aligned_paper.txt",
                     "ate_aligned_baseline.txt"):
            self.assertTrue(os.path.isfile(os.path.join(self.work, name)), name)
        for run in ("paper", "baseline"):  # the reports beside each run
            for name in ("rpe.json", "ate.json"):
                self.assertTrue(os.path.isfile(os.path.join(self.work, run, name)), (run, name))
        self.assertEqual(self.first.stdout.split(),
                         [os.path.join(self.out, name) for name in NAMES])

    def test_reuses_existing_runs(self) -> None:
        self.assertEqual(self.first.returncode, 0, self.first.stderr)
        self.assertIn("dynvo-cli run", self.first.stderr)  # runs are announced on stderr
        trajectories = [os.path.join(self.work, run, "trajectory.txt") for run in ("paper", "baseline")]
        stamps = [os.stat(path).st_mtime_ns for path in trajectories]
        out = os.path.join(self.tmp, "reused")
        result = run_figures("--paper-run", os.path.join(self.work, "paper"), "--baseline-run",
                             os.path.join(self.work, "baseline"), "--work", out, "--out", out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertNotIn("dynvo-cli", result.stderr)  # nothing was run again
        self.assertEqual([os.stat(path).st_mtime_ns for path in trajectories], stamps)
        self.assert_figures(out, {"fig_mask_panels.png": 1000})

    def test_draws_another_systems_trajectory_beside_dynvos(self) -> None:
        self.assertEqual(self.first.returncode, 0, self.first.stderr)
        # A foreign trajectory: the baseline's, in a file dynvo did not write into a run folder.
        other = os.path.join(self.tmp, "CameraTrajectory.txt")
        shutil.copy(os.path.join(self.work, "baseline", "trajectory.txt"), other)
        out = os.path.join(self.tmp, "foreign")
        result = run_figures("--paper-run", os.path.join(self.work, "paper"), "--baseline-run",
                             os.path.join(self.work, "baseline"), "--work", out, "--out", out,
                             "--trajectory", other, "--label", "ORB-SLAM2")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertTrue(os.path.isfile(os.path.join(out, "other_0_aligned.txt")))
        with open(os.path.join(out, "fig_trajectory_top.pdf"), "rb") as f:
            self.assertEqual(f.read(5), b"%PDF-")
        self.assert_figures(out, {"fig_mask_panels.png": 1000})
        missing = run_figures("--paper-run", os.path.join(self.work, "paper"), "--baseline-run",
                              os.path.join(self.work, "baseline"), "--work", out, "--out", out, "--force",
                              "--trajectory", os.path.join(self.tmp, "none.txt"))
        self.assertEqual(missing.returncode, 1)
        self.assertIn("none.txt: no such file", missing.stderr)

    def test_does_not_overwrite_without_force(self) -> None:
        self.assertEqual(self.first.returncode, 0, self.first.stderr)
        result = run_figures("--dataset", self.dataset, "--work", self.work, "--out", self.out)
        self.assertEqual(result.returncode, 1)
        self.assertIn("exists (pass --force to overwrite)", result.stderr)

    def test_missing_dataset_fails_clearly(self) -> None:
        missing = os.path.join(self.tmp, "no_such_sequence")
        out = os.path.join(self.tmp, "missing_out")
        result = run_figures("--dataset", missing, "--work", out, "--out", out)
        self.assertEqual(result.returncode, 1)
        self.assertEqual(result.stderr.strip().splitlines(),
                         ["figures: error: --dataset %s: no such folder" % missing])
        self.assertFalse(os.path.exists(out))

    def test_dataset_without_groundtruth_fails_clearly(self) -> None:
        folder = os.path.join(self.tmp, "no_groundtruth")
        os.makedirs(folder, exist_ok=True)
        open(os.path.join(folder, "rgb.txt"), "w").close()
        result = run_figures("--dataset", folder, "--work", folder)
        self.assertEqual(result.returncode, 1)
        self.assertIn("no groundtruth.txt", result.stderr)


if __name__ == "__main__":
    unittest.main()
