#!/usr/bin/env python3
"""Tests of bench/feature_use_table.py on a hand-made run: one debug frame whose features lie at
known distances from a square ground-truth mask, so the table's bands, counts and inlier shares
are known; and the errors for a run without feature lists and a frame without a mask.
Run by ctest (test feature_use_table_test; env: DYNVO_SOURCE_DIR)."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np
from PIL import Image

SCRIPT = os.path.join(os.environ["DYNVO_SOURCE_DIR"], "bench", "feature_use_table.py")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


class FeatureUseTable(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        root = self.tmp.name
        # The mask sequence: one 320x240 mask, a person on the square [100, 199] x [100, 199].
        self.sequence = os.path.join(root, "seq")
        mask = np.zeros((240, 320), np.uint8)
        mask[100:200, 100:200] = 255
        os.makedirs(os.path.join(self.sequence, "masks"))
        Image.fromarray(mask).save(os.path.join(self.sequence, "masks", "1.png"))
        write(os.path.join(self.sequence, "masks.txt"), "# timestamp filename\n1.000000 masks/1.png\n")
        # The run: frame 1 at that stamp, four features.
        self.run_dir = os.path.join(root, "run")
        write(os.path.join(self.run_dir, "timing.csv"), "frame,stamp\n0,0.966667\n1,1.000000\n")
        write(os.path.join(self.run_dir, "debug", "frame_000001_features.csv"),
              "x,y,octave,depth_m,status,inlier\n"
              "150.0,150.0,0,2.0,removed,0\n"   # on the person
              "203.0,150.0,1,2.0,kept,1\n"      # 4 px from it
              "210.2,150.0,0,2.0,kept,0\n"      # 11 px
              "300.0,20.0,2,0.0,kept,1\n")      # 128.8 px (from the corner 199, 100)

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, *specs):
        return subprocess.run([sys.executable, SCRIPT] + list(specs), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)

    def test_bands_counts_and_inlier_shares(self):
        result = self.run_script("run:%s:%s" % (self.run_dir, self.sequence))
        self.assertEqual(result.returncode, 0, result.stderr)
        rows = {line.split("|")[1].strip(): line.split("|")[2].strip()
                for line in result.stdout.splitlines()[2:]}
        self.assertEqual(rows["on a person"], "1 (0), 0%")
        self.assertEqual(rows["0-5 px"], "1 (1), 100%")
        self.assertEqual(rows["5-15 px"], "1 (1), 0%")
        self.assertEqual(rows["15-30 px"], "0")
        self.assertEqual(rows["60-120 px"], "0")
        self.assertEqual(rows["over 120 px"], "1 (1), 100%")
        self.assertEqual(rows["all"], "4 (3), 50%")

    def test_a_run_without_feature_lists_is_one_error(self):
        os.remove(os.path.join(self.run_dir, "debug", "frame_000001_features.csv"))
        result = self.run_script("run:%s:%s" % (self.run_dir, self.sequence))
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("--debug-frames", result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_a_frame_without_a_mask_names_masks_txt(self):
        write(os.path.join(self.sequence, "masks.txt"), "5.000000 masks/1.png\n")
        result = self.run_script("run:%s:%s" % (self.run_dir, self.sequence))
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("masks.txt", result.stderr)
        self.assertIn("1.000000", result.stderr)


if __name__ == "__main__":
    unittest.main()
