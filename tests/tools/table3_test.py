#!/usr/bin/env python3
"""Tests of the `table3` command (tools/dynvo_tools/table3.py): the false-loop judgement on a
hand-made loops.csv against a known ground truth (a true loop, one 30 cm off, one turned 10
degrees), and a real run of the dev split at 60 frames with the baseline: one row per
sequence, the CSV numbers what `ate` and `rpe` print on the same trajectories, and no loop
in 60 frames, so the online and corrected trajectories are the same.
Run by ctest (test table3_test; env: DYNVO_BIN_DIR, DYNVO_SOURCE_DIR)."""
from __future__ import annotations

import csv
import json
import math
import os
import subprocess
import tempfile
import unittest

import command
from dynvo_tools import table3

BIN_DIR = os.environ["DYNVO_BIN_DIR"]
HEADER = ("frame,candidate_frame,votes,consistent,verified,matches,inliers,cells,depth_agreement,"
          "correction_m,correction_deg,tx,ty,tz,qx,qy,qz,qw,accepted,reason\n")


def loop_row(frame: int, candidate: int, pose: table3.Pose, accepted: int = 1) -> str:
    (tx, ty, tz), (qx, qy, qz, qw) = pose
    return "%d,%d,50,2,1,100,80,10,0.9,0.05,2,%r,%r,%r,%r,%r,%r,%r,%d,\n" % (
        frame, candidate, tx, ty, tz, qx, qy, qz, qw, accepted)


class FalseLoops(unittest.TestCase):
    def test_loops_off_the_truth_are_counted_false(self):
        with tempfile.TemporaryDirectory() as d:
            # Three frames: the camera at x = 0, 1, 0, the last turned 90 degrees about z.
            s = math.sqrt(0.5)
            truth = [(0.0, ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))), (1.0, ((1.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))),
                     (2.0, ((0.0, 0.0, 0.0), (0.0, 0.0, s, s)))]
            with open(os.path.join(d, "groundtruth.txt"), "w") as f:
                f.writelines("%r %r %r %r %r %r %r %r\n" % ((t,) + p[0] + p[1]) for t, p in truth)
            with open(os.path.join(d, "rgb.txt"), "w") as f:
                f.writelines("%r rgb/%d.png\n" % (t, i) for i, (t, _) in enumerate(truth))
            # Frame 0 seen from frame 2: the true relative pose is a -90 degree turn.
            right = table3.relative(truth[2][1], truth[0][1])
            self.assertAlmostEqual(table3.pose_difference(right, ((0.0, 0.0, 0.0), (0.0, 0.0, -s, s)))[1], 0.0, 6)
            off = ((right[0][0] + 0.3, right[0][1], right[0][2]), right[1])
            turned = (right[0], table3.quaternion_multiply(right[1], (0.0, 0.0, math.sin(math.radians(5)),
                                                                      math.cos(math.radians(5)))))
            with open(os.path.join(d, "loops.csv"), "w") as f:
                f.write(HEADER + loop_row(2, 0, right) + loop_row(2, 0, off) + loop_row(2, 0, turned)
                        + loop_row(2, 0, off, accepted=0))
            self.assertEqual(table3.false_loops("t", d, d), (3, 2))
            self.assertEqual(table3.false_loops("t", d, d, no_loop=True), (3, 3))


class RealRun(unittest.TestCase):
    def test_dev_split_at_60_frames(self):
        with tempfile.TemporaryDirectory() as d:
            out, results = os.path.join(d, "out"), os.path.join(d, "results")
            done = command.run_command("table3", "--split", "dev", "--configs", "baseline", "--frames", "60",
                                       "--out", out, "--results", results, "--jobs", "2")
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(results, "table3_dev.csv")) as f:
                rows = list(csv.DictReader(f))
            self.assertEqual([r["kind"] for r in rows], [table3.LOOP, table3.REPEATED, table3.NO_LOOP])
            for r in rows:
                run_dir = os.path.join(out, "runs", r["sequence"], "baseline")
                gt = os.path.join(out, "seq", r["sequence"], "groundtruth.txt")
                for mode, trajectory in (("vo", "trajectory_online.txt"), ("slam", "trajectory.txt")):
                    ate = json.loads(subprocess.run([os.path.join(BIN_DIR, "ate"), gt, os.path.join(run_dir, trajectory),
                                                     "--json"], capture_output=True, text=True, check=True).stdout)
                    self.assertEqual(float(r["ate_%s_m" % mode]), ate["absolute_translational_error_m"]["rmse"])
                self.assertEqual((r["frames"], r["loops"], r["false_loops"]),
                                 ("37" if r["kind"] == table3.NO_LOOP else "60", "0", "0"))
                self.assertEqual(r["ate_vo_m"], r["ate_slam_m"])
                people = json.loads(subprocess.run([os.path.join(BIN_DIR, "map_people"), "--dataset",
                                                    os.path.dirname(gt), "--run", run_dir],
                                                   capture_output=True, text=True, check=True).stdout)
                self.assertEqual((int(r["map_points"]), float(r["map_on_people"])), (people["points"], people["share"]))
                self.assertGreater(people["points"], 1000)
            with open(os.path.join(results, "table3_dev.md")) as f:
                text = f.read()
            self.assertEqual(text.count("| baseline |"), 3)
            self.assertIn("Generated by `bash tools/table3.sh", text)


if __name__ == "__main__":
    unittest.main()
