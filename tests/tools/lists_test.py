"""Tests of `python3 -m dynvo_tools lists` (tools/dynvo_tools/lists.py), the README's path from a
folder of PNGs to a trajectory: a generated sequence stripped to its images (renamed like a
user's recording), listed, refused by dynvo-cli until its camera is given, then run; stamps
from names that are stamps; the errors of unequal counts, a missing folder and existing lists.

Run by ctest (lists_test) with Debian's python3 and DYNVO_BIN_DIR / DYNVO_SOURCE_DIR set; by hand:
  DYNVO_BIN_DIR=build/bin DYNVO_SOURCE_DIR=. /usr/bin/python3 tests/tools/lists_test.py
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
import unittest

import command

BIN_DIR = os.environ.get("DYNVO_BIN_DIR") or os.path.join(command.SOURCE_DIR, "build", "bin")
FRAMES = 12


def read_list(path: str) -> list[tuple[float, str]]:
    """The (stamp, file) lines of a TUM list, comments skipped."""
    with open(path) as f:
        return [(float(a), b) for a, b in (line.split() for line in f if not line.startswith("#"))]


class ListsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.tmp = tempfile.mkdtemp(prefix="lists_test_")
        cls.generated = os.path.join(cls.tmp, "generated")
        subprocess.run([os.path.join(BIN_DIR, "dynvo-synth"), "--scenario", "none", "--camera-path", "xyz",
                        "--frames", str(FRAMES), "--seed", "1", "--out", cls.generated], check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(cls.generated, "camera.json")) as f:
            cls.camera = json.load(f)

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def users_folder(self, name: str, rename: bool) -> str:
        """The generated images only, in NAME/rgb and NAME/depth; renamed frame_1.png.. when asked."""
        folder = os.path.join(self.tmp, name)
        for subdir, listing in (("rgb", "rgb.txt"), ("depth", "depth.txt")):
            os.makedirs(os.path.join(folder, subdir))
            for k, (_, path) in enumerate(read_list(os.path.join(self.generated, listing))):
                target = "frame_%d.png" % (k + 1) if rename else os.path.basename(path)
                shutil.copy(os.path.join(self.generated, path), os.path.join(folder, subdir, target))
        return folder

    def test_a_users_pngs_listed_then_run_once_the_camera_is_given(self) -> None:
        folder = self.users_folder("my_recording", rename=True)
        made = command.run_command("lists", folder, "--fps", "30")
        self.assertEqual(made.returncode, 0, made.stderr)
        self.assertIn("no camera.json", made.stdout)
        rgb = read_list(os.path.join(folder, "rgb.txt"))
        self.assertEqual(len(rgb), FRAMES)
        # frame_2 before frame_10: natural order, stamps k / fps.
        self.assertEqual([name for _, name in rgb[:3]], ["rgb/frame_1.png", "rgb/frame_2.png", "rgb/frame_3.png"])
        self.assertAlmostEqual(rgb[10][0], 10 / 30, places=6)
        self.assertEqual(read_list(os.path.join(folder, "depth.txt"))[10], (rgb[10][0], "depth/frame_11.png"))

        cli = os.path.join(BIN_DIR, "dynvo-cli")
        refused = subprocess.run([cli, "run", "--dataset", folder, "--config",
                                  os.path.join(command.SOURCE_DIR, "configs", "baseline.json"),
                                  "--out", os.path.join(self.tmp, "refused"), "--quiet"],
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(refused.returncode, 1)
        self.assertIn("cannot tell its camera", refused.stderr)
        self.assertEqual(len(refused.stderr.strip().splitlines()), 1, refused.stderr)

        out = os.path.join(self.tmp, "mine")
        given = ["--set", "camera.source=custom"] + [
            arg for key in ("fx", "fy", "cx", "cy") for arg in ("--set", "camera.%s=%r" % (key, self.camera[key]))]
        ran = subprocess.run([cli, "run", "--dataset", folder, "--config",
                              os.path.join(command.SOURCE_DIR, "configs", "baseline.json"), "--out", out, "--quiet",
                              *given], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(ran.returncode, 0, ran.stderr)
        with open(os.path.join(out, "trajectory.txt")) as f:
            self.assertEqual(len(f.read().splitlines()), FRAMES)
        with open(os.path.join(out, "run.json")) as f:
            dataset = json.load(f)["dataset"]
        self.assertEqual(dataset["camera_source"], 'config: camera.source "custom" and camera.*')
        self.assertEqual(dataset["camera"]["fx"], self.camera["fx"])

    def test_stamps_from_names_and_the_errors(self) -> None:
        folder = self.users_folder("stamped", rename=False)
        made = command.run_command("lists", folder)
        self.assertEqual(made.returncode, 0, made.stderr)
        self.assertEqual(read_list(os.path.join(folder, "rgb.txt")), read_list(os.path.join(self.generated, "rgb.txt")))
        self.assertEqual(read_list(os.path.join(folder, "depth.txt")),
                         read_list(os.path.join(self.generated, "depth.txt")))
        again = command.run_command("lists", folder)
        self.assertEqual(again.returncode, 1)
        self.assertIn("rgb.txt exists; pass --force", again.stderr)

        uneven = self.users_folder("uneven", rename=True)
        os.remove(os.path.join(uneven, "depth", "frame_3.png"))
        failed = command.run_command("lists", uneven)
        self.assertEqual(failed.returncode, 1)
        self.assertEqual(failed.stderr.strip(), "lists: error: %d colour and %d depth images, and their names are not"
                         " stamps: cannot pair them by order (name them by their stamps, or give as many of each)"
                         % (FRAMES, FRAMES - 1))
        missing = command.run_command("lists", os.path.join(self.tmp, "nowhere"))
        self.assertEqual(missing.returncode, 1)
        self.assertIn("nowhere/rgb: no such folder", missing.stderr)


if __name__ == "__main__":
    unittest.main()
