#!/usr/bin/env python3
"""Test of the `sweep` command (python3 -m dynvo_tools sweep, what tools/sweep.sh runs) on a
tiny generated sequence: the Slurm job-array script it writes (parsed, and one array index run
locally as sbatch would run it, through tools/sweep.sh), the RPE it records
(equal to what `rpe` prints), resuming (finished points skipped, a half-finished one
redone), the CSV and heat map, and bad grids (one clear error before any run).
Run by ctest (sweep_test) with DYNVO_BIN_DIR and DYNVO_SOURCE_DIR set:
  DYNVO_BIN_DIR=build/bin DYNVO_SOURCE_DIR=. /usr/bin/python3 tests/tools/sweep_test.py
"""
from __future__ import annotations

import csv
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import unittest

import command

BIN = os.environ.get("DYNVO_BIN_DIR", "")
SOURCE = os.environ.get("DYNVO_SOURCE_DIR", "")
SWEEP = os.path.join(SOURCE, "tools", "sweep.sh")

# 2 x 2 grid points, numbered as itertools.product: the last key varies fastest.
GRID = {
    "base_config": os.path.abspath(os.path.join(SOURCE, "configs", "paper.json")),  # the grid is elsewhere
    "parameters": {"dynamic_mask.erode_kernel_size": [2, 4],
                   "dynamic_mask.threshold": ["otsu", "fixed"]},
}
POINTS = [{"dynamic_mask.erode_kernel_size": e, "dynamic_mask.threshold": t}
          for e in (2, 4) for t in ("otsu", "fixed")]
INDEX = 2  # erode_kernel_size 4, otsu: the one array task run here


def env() -> dict[str, str]:
    e = dict(os.environ, PYTHON=sys.executable, DYNVO_BIN_DIR=BIN)
    e.pop("SLURM_ARRAY_TASK_ID", None)
    return e


def sweep(*args: str) -> subprocess.CompletedProcess[str]:
    return command.run_command("sweep", *args, env=env())


def read(path: str) -> str:
    with open(path) as f:
        return f.read()


def read_json(path: str) -> dict:
    return json.loads(read(path))


def read_csv(path: str) -> list[dict[str, str]]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def run_dirs(out: str, dataset: str = "seq") -> list[str]:
    folder = os.path.join(out, "runs", dataset)
    return sorted(os.listdir(folder)) if os.path.isdir(folder) else []


class SweepTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        if not BIN or not SOURCE:
            raise RuntimeError("DYNVO_BIN_DIR and DYNVO_SOURCE_DIR must be set (ctest sets them)")
        cls.tmp = tempfile.mkdtemp(prefix="dynvo-sweep-test-")
        cls.seq = os.path.join(cls.tmp, "seq")
        # 24 frames at 10 Hz: 2.3 s, long enough for per-second RPE; a person crosses.
        subprocess.run([os.path.join(BIN, "dynvo-synth"), "--scenario", "walking_across",
                        "--camera-path", "xyz", "--frames", "24", "--fps", "10", "--width", "320",
                        "--height", "240", "--seed", "1", "--out", cls.seq],
                       check=True, capture_output=True)
        cls.grid = os.path.join(cls.tmp, "grid.json")
        with open(cls.grid, "w") as f:
            json.dump(GRID, f)

    @classmethod
    def tearDownClass(cls) -> None:
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def write_grid(self, name: str, grid: dict) -> str:
        path = os.path.join(self.tmp, name)
        with open(path, "w") as f:
            json.dump(grid, f)
        return path

    def check_slurm_script(self, script: str, out: str) -> None:
        """The script: shebang, #SBATCH directives before the first command, an array of one
        task per grid point, and one command running the sweep for the task's index."""
        lines = read(script).splitlines()
        self.assertEqual(lines[0], "#!/bin/bash")
        first_command = next(i for i, l in enumerate(lines) if l.strip() and not l.startswith("#"))
        directives = [l for l in lines if l.startswith("#SBATCH")]
        self.assertTrue(all(lines.index(d) < first_command for d in directives))
        arrays = [l for l in directives if l.startswith("#SBATCH --array=")]
        self.assertEqual(arrays, ["#SBATCH --array=0-%d" % (len(POINTS) - 1)])
        commands = [l for l in lines if "$SLURM_ARRAY_TASK_ID" in l and not l.startswith("#")]
        self.assertEqual(len(commands), 1, lines)
        words = shlex.split(commands[0])
        if words[0] == "env":  # the --slurm-container prefix
            words = words[1:]
        same = lambda a, b: self.assertEqual(os.path.realpath(a), os.path.realpath(b))
        self.assertEqual(words[0], "bash")
        same(words[1], SWEEP)
        same(words[2], self.grid)
        same(words[words.index("--dataset") + 1], self.seq)
        same(words[words.index("--out") + 1], out)
        self.assertEqual(words[words.index("--index") + 1], "$SLURM_ARRAY_TASK_ID")

    def run_array_task(self, script: str, out: str) -> tuple[str, float]:
        """Runs one array task as sbatch would: exactly its grid point's outputs appear, and its
        RPE is what rpe prints on that trajectory. Returns the trajectory and the RPE RMSE."""
        r = subprocess.run(["bash", script], capture_output=True, text=True,
                           env=dict(env(), SLURM_ARRAY_TASK_ID=str(INDEX)))
        self.assertEqual(r.returncode, 0, r.stderr)
        names = run_dirs(out)
        self.assertEqual(len(names), 1, names)
        run = os.path.join(out, "runs", "seq", names[0])
        point = read_json(os.path.join(run, "point.json"))
        self.assertEqual(point["settings"], POINTS[INDEX])
        self.assertEqual(point["index"], INDEX)
        for name in ("trajectory.txt", "timing.csv", "run.json", "rpe.json"):
            self.assertTrue(os.path.isfile(os.path.join(run, name)), name)

        # Its RPE is what rpe prints on that trajectory.
        gt, est = os.path.join(self.seq, "groundtruth.txt"), os.path.join(run, "trajectory.txt")
        printed = subprocess.run([os.path.join(BIN, "rpe"), gt, est], check=True,
                                 capture_output=True, text=True).stdout
        printed_rmse = float(re.search(r"^translational_error\.rmse (\S+) m$", printed, re.M).group(1))
        rpe_json = json.loads(subprocess.run([os.path.join(BIN, "rpe"), gt, est, "--json"], check=True,
                                             capture_output=True, text=True).stdout)
        recorded = read_json(os.path.join(run, "rpe.json"))
        self.assertEqual(recorded, rpe_json)
        self.assertAlmostEqual(recorded["translational_error_m"]["rmse"], printed_rmse, places=6)
        return est, recorded["translational_error_m"]["rmse"]

    def test_slurm_array_index_collect_and_resume(self) -> None:
        out = os.path.join(self.tmp, "out")
        script = os.path.join(self.tmp, "sweep.sbatch")
        r = sweep(self.grid, "--dataset", self.seq, "--out", out, "--jobs", "2", "--slurm", script,
                  "--slurm-time", "00:30:00", "--slurm-mem", "3G", "--slurm-partition", "short",
                  "--slurm-setup", "echo setup ran >&2", "--slurm-container", "env")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(run_dirs(out), [], "--slurm must run nothing")
        for directive in ("#SBATCH --time=00:30:00", "#SBATCH --mem=3G", "#SBATCH --partition=short"):
            self.assertIn(directive + "\n", read(script))
        self.assertIn("\necho setup ran >&2\n", read(script))
        bad = sweep(self.grid, "--dataset", self.seq, "--out", out, "--slurm", script, "--slurm-mem", "3 G")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("an #SBATCH value is one word", bad.stderr)

        self.check_slurm_script(script, out)
        est, rmse = self.run_array_task(script, out)

        # Collecting now: the finished point has numbers, the others show as missing.
        r = sweep(self.grid, "--dataset", self.seq, "--out", out, "--collect")
        self.assertEqual(r.returncode, 1, "3 of 4 runs are missing: " + r.stderr)
        self.assertIn("3 of 4 runs are not finished", r.stderr)
        rows = read_csv(os.path.join(out, "sweep.csv"))
        self.assertEqual([row["status"] for row in rows], ["missing", "missing", "finished", "missing"])
        self.assertEqual(float(rows[INDEX]["rpe_trans_rmse_m"]), rmse)
        self.assertEqual(rows[0]["rpe_trans_rmse_m"], "")

        # The whole sweep skips the finished point and runs the other three.
        mtime = os.path.getmtime(est)
        r = sweep(self.grid, "--dataset", self.seq, "--out", out, "--jobs", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("4 runs: 1 finished earlier (skipped), 3 to run", r.stderr)
        self.assertEqual(os.path.getmtime(est), mtime)
        self.assertEqual(len(run_dirs(out)), 4)
        rows = read_csv(os.path.join(out, "sweep.csv"))
        self.assertEqual(len(rows), 4)
        for row, p in zip(rows, POINTS):
            self.assertEqual(row["status"], "finished")
            self.assertEqual(row["dynamic_mask.erode_kernel_size"], str(p["dynamic_mask.erode_kernel_size"]))
            self.assertEqual(row["dynamic_mask.threshold"], p["dynamic_mask.threshold"])
            self.assertGreater(float(row["rpe_trans_rmse_m"]), 0.0)
            self.assertGreater(float(row["mask_iou"]), 0.0)  # the sequence has ground-truth masks
        with open(os.path.join(out, "sweep_heatmap.png"), "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertIn("| rank |", read(os.path.join(out, "sweep.md")))

        # A half-finished run (no point.json, trajectory cut short) is redone; nothing else.
        half = os.path.join(out, "runs", "seq", run_dirs(out)[0])
        os.remove(os.path.join(half, "point.json"))
        with open(os.path.join(half, "trajectory.txt"), "w") as f:
            f.write("")
        r = sweep(self.grid, "--dataset", self.seq, "--out", out, "--jobs", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("4 runs: 3 finished earlier (skipped), 1 to run", r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(half, "point.json")))
        self.assertGreater(os.path.getsize(os.path.join(half, "trajectory.txt")), 0)
        self.assertEqual(os.path.getmtime(est), mtime)

        # A run recorded by another build of dynvo-cli is redone; point.json names the binary.
        with open(os.path.join(BIN, "dynvo-cli"), "rb") as f:
            binary = hashlib.sha256(f.read()).hexdigest()
        other = os.path.join(out, "runs", "seq", run_dirs(out)[1], "point.json")
        with open(other) as f:
            record = json.load(f)
        self.assertEqual(record["dynvo_cli_sha256"], binary)
        record["dynvo_cli_sha256"] = "0" * 64
        with open(other, "w") as f:
            json.dump(record, f)
        r = sweep(self.grid, "--dataset", self.seq, "--out", out, "--jobs", "2")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("4 runs: 3 finished earlier (skipped), 1 to run", r.stderr)
        with open(other) as f:
            self.assertEqual(json.load(f)["dynvo_cli_sha256"], binary)

    def check_rejected(self, grid: dict, *expected: str) -> None:
        path = self.write_grid("bad_grid.json", grid)
        out = os.path.join(self.tmp, "bad_out")
        r = sweep(path, "--dataset", self.seq, "--out", out)
        self.assertEqual(r.returncode, 1, r.stderr)
        message = r.stderr.strip()
        self.assertEqual(len(message.splitlines()), 1, message)
        self.assertTrue(message.startswith("sweep: error: %s: " % path), message)
        for text in expected:
            self.assertIn(text, message)
        self.assertFalse(os.path.exists(out), "nothing may run for a bad grid")

    def test_unknown_key_is_rejected_before_any_run(self) -> None:
        self.check_rejected({"parameters": {"dynamic_mask.erode_kernel_size": [2, 4],
                                            "dynamic_mask.erode_kernel_siz": [3]}},
                            "'dynamic_mask.erode_kernel_siz'", "unknown key")

    def test_empty_value_list_is_rejected(self) -> None:
        self.check_rejected({"parameters": {"dynamic_mask.erode_kernel_size": []}},
                            "'dynamic_mask.erode_kernel_size'", "expected a non-empty list of values")

    def test_value_out_of_range_is_rejected(self) -> None:
        self.check_rejected({"parameters": {"dynamic_mask.dilate_iterations": [1, -1]}},
                            "'dynamic_mask.dilate_iterations' = -1", "must be in")


if __name__ == "__main__":
    unittest.main(verbosity=2)
