#!/usr/bin/env python3
"""Tests of bench/suite.py without real runs: the Markdown table made from a hand-made results
CSV (ratios, the median ratio per config, median/p90 ms, "-" where a config has no mask, the
validation caption), when a sequence is generated again (its spec.json), and the errors of a
failed run, a missing binary and an invalid JSON, with fake binaries (shell scripts).
Run by ctest (test suite_test; env: DYNVO_SOURCE_DIR)."""
import csv
import importlib.util
import json
import os
import stat
import subprocess
import sys
import tempfile
import unittest

SOURCE_DIR = os.environ["DYNVO_SOURCE_DIR"]
SCRIPT = os.path.join(SOURCE_DIR, "bench", "suite.py")
spec = importlib.util.spec_from_file_location("suite", SCRIPT)
suite = importlib.util.module_from_spec(spec)
sys.modules["suite"] = suite  # its dataclasses look their module up there
spec.loader.exec_module(suite)

COLUMNS = suite.CSV_COLUMNS


def row(sequence, config, kind="synthetic", twin="synth_none_xyz_s1", status="ok", frames="60",
        rpe="-", twin_rpe="-", ratio="-", ate="-", mask=("-", "-", "-"), ms=("-", "-"), split="dev"):
    return dict(zip(COLUMNS, [split, sequence, kind, twin, config, status, frames, rpe, twin_rpe,
                              ratio, ate, *mask, *ms]))


def write_results(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)


def table_rows(md_path):
    with open(md_path) as f:
        text = f.read()
    lines = [line for line in text.splitlines() if line.startswith("| ")]
    return text, [[c.strip() for c in line.strip("|").split("|")] for line in lines]


def hand_made_rows(split="dev"):
    """Two synthetic sequences and one not run. Ratios: baseline 2.0 and 3.0 (median 2.5),
    paper 1.0 and 1.5 (median 1.25). The baseline has no mask; paper has none on b."""
    rows = []
    for name, base, paper in (("a", ("0.02", "2.0"), ("0.01", "1.0")),
                              ("b", ("0.03", "3.0"), ("0.015", "1.5"))):
        rows.append(row(name, "baseline", rpe=base[0], twin_rpe="0.01", ratio=base[1],
                        ate="0.05", ms=("10.0", "12.5"), split=split))
        mask = ("0.6", "0.8", "0.5") if name == "a" else ("-", "-", "-")
        rows.append(row(name, "paper", rpe=paper[0], twin_rpe="0.01", ratio=paper[1],
                        ate="0.04", mask=mask, ms=("20.25", "31.0"), split=split))
    for config in ("baseline", "paper"):
        rows.append(row("fr2_desk_head50_p_s2", config, kind="inserted", twin="fr2_desk_head50",
                        status=suite.NOT_RUN, frames="-", split=split))
    return rows


class Table(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.csv = os.path.join(self.tmp.name, "suite_dev.csv")
        self.md = os.path.join(self.tmp.name, "suite_dev.md")

    def tearDown(self):
        self.tmp.cleanup()

    def test_cells_ratios_and_the_median_ratio(self):
        write_results(self.csv, hand_made_rows())
        suite.write_markdown(self.csv, self.md)
        text, rows = table_rows(self.md)
        self.assertEqual(rows[0], ["sequence", "twin", "baseline RPE m/s (ratio)",
                                   "paper RPE m/s (ratio)", "baseline ATE m", "paper ATE m",
                                   "paper mask R/P/IoU", "baseline ms median/p90",
                                   "paper ms median/p90"])  # no mask column for the baseline
        self.assertEqual(rows[1], ["a", "synth_none_xyz_s1", "0.0200 (2.00x)", "0.0100 (1.00x)",
                                   "0.0500", "0.0400", "0.80/0.60/0.50", "10.0/12.5", "20.2/31.0"])
        self.assertEqual(rows[2][6], "-")  # paper without a mask quality on b
        self.assertEqual(rows[3][:3], ["fr2_desk_head50_p_s2", "fr2_desk_head50", suite.NOT_RUN])
        self.assertEqual(len(rows[3]), len(rows[0]))
        self.assertEqual(rows[4][:4], ["**median ratio**", "", "(2.50x)", "(1.25x)"])
        self.assertIn("per-second RPE, translational RMSE", text)
        self.assertIn("ATE**: SE(3)-aligned RMSE", text)
        self.assertIn("Frames: 60 per synthetic sequence.", text)
        self.assertNotIn(suite.VALIDATION_NOTE, text)

    def test_validation_caption(self):
        write_results(self.csv, hand_made_rows("validation"))
        suite.write_markdown(self.csv, self.md)
        text, _ = table_rows(self.md)
        self.assertIn("**validation** split", text)
        self.assertIn("Validation split: reported only, never used to choose a parameter or "
                      "default.", text)

    def test_table_command_from_the_csv_alone(self):
        write_results(os.path.join(self.tmp.name, "suite_validation.csv"),
                      hand_made_rows("validation"))
        result = subprocess.run([sys.executable, SCRIPT, "table", "--split", "validation",
                                 "--results", self.tmp.name], stderr=subprocess.PIPE, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertTrue(os.path.isfile(os.path.join(self.tmp.name, "suite_validation.md")))

    def test_a_bad_number_names_the_csv(self):
        rows = hand_made_rows()
        rows[0]["rpe_m_s"] = "fast"
        write_results(self.csv, rows)
        with self.assertRaisesRegex(suite.SuiteError, "suite_dev.csv: a baseline: rpe_m_s"):
            suite.write_markdown(self.csv, self.md)

    def test_result_rows_ratio_and_no_mask(self):
        spec_row = suite.RowSpec("dev", suite.SYNTH, suite.Sequence("a", "/a"),
                                 suite.Sequence("t", "/t"), True)
        people = suite.RunResult(60, 0.03, 0.1, None, 10.0, 12.0)
        twin = suite.RunResult(60, 0.02, 0.1, None, 9.0, 11.0)
        cells = suite.result_row(spec_row, "baseline", people, twin)
        self.assertEqual(float(cells["ratio"]), 1.5)
        self.assertEqual([cells["mask_" + k] for k in ("precision", "recall", "iou")], ["-"] * 3)
        self.assertEqual(suite.result_row(spec_row, "paper", None, None)["status"], suite.NOT_RUN)

    def test_median_and_p90_of_timing(self):
        path = os.path.join(self.tmp.name, "timing.csv")
        with open(path, "w") as f:
            f.write("frame,processing_ms\n" + "".join("%d,%d.0\n" % (i, 11 - i) for i in range(1, 11)))
        median, p90 = suite.timing_stats("x paper", path)
        self.assertAlmostEqual(median, 5.5)
        self.assertAlmostEqual(p90, 9.1)  # linear between the 9th and 10th of 1..10


FAKE_SYNTH = """#!/bin/sh
# Fake generator: a folder with rgb.txt and groundtruth.txt; each call logged.
while [ $# -gt 0 ]; do [ "$1" = "--out" ] && out="$2"; shift; done
mkdir -p "$out" && echo "# fake" > "$out/rgb.txt" && echo "0 0 0 0 0 0 0 1" > "$out/groundtruth.txt"
echo "$out" >> "$(dirname "$0")/calls.log"
"""
FAKE_CLI = """#!/bin/sh
# Fake dynvo-cli run: run.json (mask_quality null for the baseline), trajectory.txt, timing.csv.
while [ $# -gt 0 ]; do [ "$1" = "--out" ] && out="$2"; [ "$1" = "--config" ] && config="$2"; shift; done
mkdir -p "$out"
mask='{"precision": 0.8, "recall": 0.6, "iou": 0.5}'
case "$config" in *baseline.json) mask=null ;; esac
echo '{"dataset": {"frames_to_process": 3}, "mask_quality": '"$mask"'}' > "$out/run.json"
echo "0 0 0 0 0 0 0 1" > "$out/trajectory.txt"
printf 'frame,processing_ms\\n0,10\\n1,20\\n2,30\\n' > "$out/timing.csv"
"""
FAKE_RPE = """#!/bin/sh
case "$1" in *none*) r=0.01 ;; *) r=0.02 ;; esac
echo '{"translational_error_m": {"rmse": '$r'}}'
"""
FAKE_ATE = """#!/bin/sh
echo '{"absolute_translational_error_m": {"rmse": 0.05}}'
"""
FAILING = """#!/bin/sh
echo "loading frames" >&2
echo "error: frame 7: depth image unreadable" >&2
exit 1
"""


class WithFakeBinaries(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.bin = os.path.join(self.tmp.name, "bin")
        os.makedirs(self.bin)
        for name, text in (("dynvo-synth", FAKE_SYNTH), ("dynvo-cli", FAKE_CLI),
                           ("rpe", FAKE_RPE), ("ate", FAKE_ATE)):
            self.fake(name, text)

    def tearDown(self):
        self.tmp.cleanup()

    def fake(self, name, text):
        path = os.path.join(self.bin, name)
        with open(path, "w") as f:
            f.write(text)
        os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)

    def calls(self):
        try:
            with open(os.path.join(self.bin, "calls.log")) as f:
                return f.read().split()
        except FileNotFoundError:
            return []

    def run_suite(self, *args):
        env = dict(os.environ, DYNVO_BIN_DIR=self.bin,
                   DYNVO_SHARED_DIR=os.path.join(self.tmp.name, "no_shared"))
        return subprocess.run([sys.executable, SCRIPT, "--split", "dev",
                               "--configs", "baseline,paper", "--frames", "5", "--jobs", "2",
                               "--out", os.path.join(self.tmp.name, "out"),
                               "--results", os.path.join(self.tmp.name, "results")] + list(args),
                              env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)

    def test_generated_again_only_when_the_spec_changes(self):
        sequence = suite.Sequence("s", os.path.join(self.tmp.name, "s"),
                                  ("dynvo-synth", "--scenario", "x", "--frames", "5"))
        self.assertTrue(suite.needs_generation(sequence))
        self.assertTrue(suite.generate(sequence, self.bin))
        with open(os.path.join(sequence.folder, "spec.json")) as f:
            self.assertEqual(json.load(f), {"command": list(sequence.command)})
        self.assertFalse(suite.generate(sequence, self.bin))
        longer = suite.Sequence("s", sequence.folder, ("dynvo-synth", "--scenario", "x", "--frames", "6"))
        self.assertTrue(suite.needs_generation(longer))
        self.assertTrue(suite.generate(longer, self.bin))
        self.assertEqual(len(self.calls()), 2)
        os.remove(os.path.join(sequence.folder, "spec.json"))  # made by someone else: regenerate
        self.assertTrue(suite.needs_generation(longer))

    def test_whole_split_with_fakes(self):
        result = self.run_suite()
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(os.path.join(self.tmp.name, "results", "suite_dev.csv")) as f:
            rows = list(csv.DictReader(f))
        ok = [(r["sequence"], r["config"], r["ratio"], r["mask_iou"], r["ms_p90"])
              for r in rows if r["status"] == "ok"]
        scenarios = suite.PRESETS
        self.assertEqual(ok, [("synth_%s_xyz_s1" % s, c, "2.0", "-" if c == "baseline" else "0.5", "28.0")
                              for s in scenarios for c in ("baseline", "paper")])
        self.assertEqual([r["sequence"] for r in rows if r["status"] == suite.NOT_RUN],
                         ["fr1_rpy_head150_%s_s1" % p for p in suite.PRESETS for _ in range(2)])
        self.assertEqual(len(self.calls()), len(scenarios) + 1)  # the sequences and their twin
        self.assertEqual(self.run_suite().returncode, 0)
        self.assertEqual(len(self.calls()), len(scenarios) + 1)  # kept: same spec

    def test_a_failed_run_names_sequence_config_and_program(self):
        self.fake("dynvo-cli", FAILING)
        result = self.run_suite()
        self.assertEqual(result.returncode, 1)
        self.assertRegex(result.stderr, r"suite: error: synth_\w+ (baseline|paper): .*dynvo-cli: "
                                        r"exited with code 1")
        self.assertIn("error: frame 7: depth image unreadable", result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_a_missing_binary(self):
        os.remove(os.path.join(self.bin, "ate"))
        result = self.run_suite()
        self.assertEqual(result.returncode, 1)
        self.assertRegex(result.stderr, r"suite: error: synth_\w+ (baseline|paper): .*/ate: not found")

    def test_an_invalid_json(self):
        self.fake("rpe", "#!/bin/sh\necho 'RPE per second'\n")
        result = self.run_suite()
        self.assertEqual(result.returncode, 1)
        self.assertRegex(result.stderr, r"suite: error: synth_\w+ (baseline|paper): .*/runs/"
                                        r"synth_\w+/(baseline|paper)/rpe.json: not valid JSON")


if __name__ == "__main__":
    unittest.main()
