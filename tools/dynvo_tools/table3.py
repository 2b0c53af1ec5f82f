"""`table3`: the second paper's Table 3 (VO against SLAM) regenerated on generated loops.

Each split holds a few generated sequences (LOOPS below): loops (the camera turns once and a
fifth in the middle of the room, looking outward, and sees where it started again) with
people, a loop in a room papered with one panel over and over (false loop candidates
everywhere), and a sequence without a loop. Each is run with each config in slam mode
with the map (`dynvo-cli run --mode slam --map`): its trajectory_online.txt is the VO trajectory (the loop closer
never feeds back into tracking, so it equals a `--mode vo` run's trajectory.txt) and its
trajectory.txt the loop-corrected one. Per (sequence, config): ATE (SE(3)-aligned RMSE) and
per-second RPE of both, the loops accepted (loops.csv), and the false ones among them: an
accepted loop whose measured relative pose is more than 10 cm or 5 degrees from the ground
truth's (the frames' groundtruth.txt poses), and every loop accepted on the sequence without
a loop (the loop path stopped before it comes back); the map's points and the share of them on
people (bench/map_people: ground-truth masks).

Sequences are generated into OUT/seq (kept while their spec.json matches), runs go to
OUT/runs/SEQUENCE/CONFIG. Writes RESULTS/table3_<split>.csv and RESULTS/table3_<split>.md.

Normally run through tools/table3.sh, which builds the binaries first:
  python3 -m dynvo_tools table3 [--split dev|validation|all] [--configs a,b,c] [--frames N]
                                [--out DIR] [--results DIR] [--jobs N]
  (tools/ on PYTHONPATH; env: DYNVO_BIN_DIR, default $DYNVO_BUILD_DIR/bin or build/bin)
"""
from __future__ import annotations

import argparse
import csv
import functools
import math
import os
import time
from dataclasses import dataclass

from .common import ROOT, ToolError, bin_path, config_path, display_path, json_number, log, read_json, \
    run_parallel, run_tool, write_atomically
from .evaluation import ATE, RPE_PER_SECOND, RunRequest, evaluate_run, run_dynvo
from .suite import VALIDATION_NOTE, Sequence, comma_list, generate

COMMAND = "table3"
CONFIGS = ("baseline", "ipl", "dynvo")
SPLITS = ("dev", "validation")
LOOP, REPEATED, NO_LOOP = "loop", "repeated walls", "no loop"
FALSE_LOOP_M, FALSE_LOOP_DEG = 0.10, 5.0  # an accepted loop this far from the truth is false


@dataclass(frozen=True)
class LoopSource:
    """One generated sequence of a split."""
    split: str
    kind: str        # LOOP, REPEATED or NO_LOOP
    path: str        # --camera-path
    scenario: str    # --scenario
    seed: int

    def sequence(self, frames: int, seq_dir: str) -> Sequence:
        walls = ("--repeated-walls",) if self.kind == REPEATED else ()
        # A scene without people gets the people's Kinect sensor timing (tum_* always has it).
        sensor = ("--kinect-sensor",) if self.scenario == "none" else ()
        name = "synth_%s_%s%s_s%d" % (self.scenario, self.path, "_repeated" if walls else "", self.seed)
        command = ("dynvo-synth", "--scenario", self.scenario, "--camera-path", self.path, "--seed",
                   str(self.seed), "--frames", str(frames)) + walls + sensor
        return Sequence(name, os.path.join(seq_dir, name), command)


# The two splits. dev: may be tuned on; validation: reported only. 540 frames at 30 Hz: the
# loop path's turn takes 15 s, so the last 3 s see the start again. The sequence without a loop
# is the same path stopped at 11 s (330 of 540 frames, 264 degrees): it never sees its start
# again, so every loop it accepts is a false one.
#          split         kind      camera path  scenario      seed
LOOPS = (
    LoopSource("dev",        LOOP,     "loop",      "tum_walking", 7),
    LoopSource("dev",        REPEATED, "loop",      "none",        8),
    LoopSource("dev",        NO_LOOP,  "loop",      "tum_walking", 12),
    LoopSource("validation", LOOP,     "loop",      "tum_walking", 9),
    LoopSource("validation", LOOP,     "loop",      "tum_sitting", 10),
    LoopSource("validation", REPEATED, "loop",      "tum_away",    11),
    LoopSource("validation", NO_LOOP,  "loop",      "tum_walking", 13),
)
NO_LOOP_SHARE = 11.0 / 18.0  # of --frames

CSV_COLUMNS = ("split", "sequence", "kind", "config", "frames", "ate_vo_m", "ate_slam_m", "rpe_vo_m_s",
               "rpe_slam_m_s", "loops", "false_loops", "map_points", "map_on_people")


# ---------------------------------------------------------------- ground truth and loops


def quaternion_multiply(a: tuple[float, ...], b: tuple[float, ...]) -> tuple[float, ...]:
    """Hamilton product of (x, y, z, w) quaternions."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def rotate(q: tuple[float, ...], v: tuple[float, ...]) -> tuple[float, ...]:
    """v rotated by the unit quaternion q."""
    x, y, z, _ = quaternion_multiply(quaternion_multiply(q, (v[0], v[1], v[2], 0.0)), conjugate(q))
    return (x, y, z)


def conjugate(q: tuple[float, ...]) -> tuple[float, ...]:
    """The inverse rotation of a unit quaternion."""
    return (-q[0], -q[1], -q[2], q[3])


Pose = tuple[tuple[float, ...], tuple[float, ...]]  # translation, quaternion (x, y, z, w)


def relative(a: Pose, b: Pose) -> Pose:
    """a^-1 b: the pose of b in a's frame."""
    qa_inverse = conjugate(a[1])
    shift = tuple(b[0][i] - a[0][i] for i in range(3))
    return rotate(qa_inverse, shift), quaternion_multiply(qa_inverse, b[1])


def pose_difference(a: Pose, b: Pose) -> tuple[float, float]:
    """Translation (m) and rotation (degrees) of a^-1 b."""
    t, q = relative(a, b)
    angle = 2.0 * math.degrees(math.acos(min(1.0, abs(q[3]) / math.sqrt(sum(c * c for c in q)))))
    return math.sqrt(sum(c * c for c in t)), angle


def read_stamped_poses(what: str, path: str) -> list[tuple[float, Pose]]:
    """A TUM trajectory file's (stamp, pose) lines."""
    poses = []
    try:
        with open(path) as f:
            for number, line in enumerate(f, 1):
                if not line.strip() or line.startswith("#"):
                    continue
                v = [float(x) for x in line.split()]
                if len(v) != 8:
                    raise ValueError
                poses.append((v[0], (tuple(v[1:4]), tuple(v[4:8]))))
    except OSError as error:
        raise ToolError("%s: %s: cannot read: %s" % (what, display_path(path), error.strerror)) from None
    except ValueError:
        raise ToolError("%s: %s:%d: expected 'stamp tx ty tz qx qy qz qw'" % (what, display_path(path), number)) \
            from None
    return poses


def frame_stamps(dataset: str) -> list[float]:
    """The stamps of rgb.txt, in order: frame i's stamp (a generated sequence's list)."""
    with open(os.path.join(dataset, "rgb.txt")) as f:
        return [float(line.split()[0]) for line in f if line.strip() and not line.startswith("#")]


def false_loops(what: str, dataset: str, run_dir: str, no_loop: bool = False) -> tuple[int, int]:
    """Accepted loops in RUN_DIR/loops.csv, and those whose measured pose is off the truth (all
    of them on a sequence without a loop)."""
    truth = read_stamped_poses(what, os.path.join(dataset, "groundtruth.txt"))
    stamps = frame_stamps(dataset)

    def truth_at(frame: int) -> Pose:
        return min(truth, key=lambda entry: abs(entry[0] - stamps[frame]))[1]

    accepted = wrong = 0
    with open(os.path.join(run_dir, "loops.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["accepted"] != "1":
                continue
            accepted += 1
            measured: Pose = (tuple(float(row[k]) for k in ("tx", "ty", "tz")),
                              tuple(float(row[k]) for k in ("qx", "qy", "qz", "qw")))
            expected = relative(truth_at(int(row["frame"])), truth_at(int(row["candidate_frame"])))
            metres, degrees = pose_difference(expected, measured)
            wrong += metres > FALSE_LOOP_M or degrees > FALSE_LOOP_DEG or no_loop
    return accepted, wrong


# ---------------------------------------------------------------- runs


def run_row(split: str, source: LoopSource, sequence: Sequence, config: str, out_dir: str) -> dict[str, str]:
    """Runs one config in slam mode on one sequence and measures it: a CSV row."""
    what = "%s %s" % (sequence.name, config)
    run_dir = os.path.join(out_dir, "runs", sequence.name, config)
    run_dynvo(RunRequest(sequence.folder, run_dir, config_path(config), (), ("--mode", "slam", "--map")), what)
    loops, wrong = false_loops(what, sequence.folder, run_dir, source.kind == NO_LOOP)
    text = run_tool(what, [bin_path("map_people"), "--dataset", sequence.folder, "--run", run_dir])
    path = os.path.join(run_dir, "map_people.json")
    write_atomically(path, text)
    people = read_json(what, path)
    values = {"split": split, "sequence": sequence.name, "kind": source.kind, "config": config,
              "loops": loops, "false_loops": wrong,
              "map_points": int(json_number(what, path, people, "points")),
              "map_on_people": json_number(what, path, people, "share")}
    for mode, trajectory in (("vo", "trajectory_online.txt"), ("slam", "trajectory.txt")):
        run = evaluate_run(sequence.folder, run_dir, (RPE_PER_SECOND, ATE), what, trajectory)
        values.update({"frames": run.frames(), "ate_%s_m" % mode: run.rmse(ATE), "rpe_%s_m_s" % mode: run.rmse(RPE_PER_SECOND)})
    return {key: repr(v) if isinstance(v, float) else str(v) for key, v in values.items()}


# ---------------------------------------------------------------- tables


def markdown(split: str, rows: list[dict[str, str]]) -> str:
    """The split's table from its CSV rows."""
    lines = [
        "VO against SLAM (`dynvo-cli run --mode slam --map`), **%s** split. **ATE**: SE(3)-aligned RMSE in m"
        " (`ate GT EST`); **RPE**: per-second RPE, translational RMSE in m/s (`rpe GT EST`). **vo**:"
        " trajectory_online.txt (the poses as tracked, = `--mode vo`), **slam**: trajectory.txt (loops"
        " closed); ratio = vo / slam. **loops**: accepted (loops.csv); **false**: of those, the ones more"
        " than %g cm or %g degrees from the ground truth's relative pose, and every one on a sequence without a"
        " loop. **map**: the points of `--map`'s map.ply, and the share of them on people (`bench/map_people`:"
        " in every third frame, seen inside a person's true mask at the depth measured there, within 3 cm, and"
        " never away from the people at the depth measured there)." % (
            split, FALSE_LOOP_M * 100, FALSE_LOOP_DEG),
        "",
        "| sequence | kind | config | frames | ATE vo | ATE slam | ratio | RPE vo | RPE slam | loops | false | map points"
        " | map on people |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        ate_vo, ate_slam = float(r["ate_vo_m"]), float(r["ate_slam_m"])
        lines.append("| %s | %s | %s | %s | %.4f | %.4f | %.2fx | %.4f | %.4f | %s | %s | %s | %.2f%% |" % (
            r["sequence"], r["kind"], r["config"], r["frames"], ate_vo, ate_slam,
            ate_vo / ate_slam if ate_slam > 0 else float("nan"), float(r["rpe_vo_m_s"]),
            float(r["rpe_slam_m_s"]), r["loops"], r["false_loops"], r["map_points"], 100 * float(r["map_on_people"])))
    if split == "validation":
        lines += ["", VALIDATION_NOTE]
    lines += ["", "Generated by `bash tools/table3.sh --split %s`." % split]
    return "\n".join(lines) + "\n"


def run_table3(args: argparse.Namespace) -> int:
    start = time.time()
    splits = SPLITS if args.split == "all" else (args.split,)
    seq_dir = os.path.join(args.out, "seq")
    sources = [s for s in LOOPS if s.split in splits]
    sequences = {s: s.sequence(round(args.frames * NO_LOOP_SHARE) if s.kind == NO_LOOP else args.frames, seq_dir)
                 for s in sources}
    run_parallel([functools.partial(generate, q) for q in sequences.values()], args.jobs)
    tasks = [(s, c) for s in sources for c in args.configs]
    rows = run_parallel([functools.partial(run_row, s.split, s, sequences[s], c, args.out) for s, c in tasks],
                        args.jobs)
    os.makedirs(args.results, exist_ok=True)
    for split in splits:
        split_rows = [r for r in rows if r["split"] == split]
        csv_path = os.path.join(args.results, "table3_%s.csv" % split)
        with open(csv_path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=CSV_COLUMNS, lineterminator="\n")
            writer.writeheader()
            writer.writerows(split_rows)
        write_atomically(os.path.join(args.results, "table3_%s.md" % split),
                         markdown(split, split_rows))
        log(COMMAND, "wrote %s and .md" % display_path(csv_path))
    log(COMMAND, "done in %.0f s" % (time.time() - start))
    return 0


def add_parser(commands: argparse._SubParsersAction) -> None:
    """The `table3` command."""
    parser = commands.add_parser(COMMAND, help="VO against SLAM on generated loops (the second paper's Table 3)",
                                 description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--split", choices=SPLITS + ("all",), default="all", help="which split (default: all)")
    parser.add_argument("--configs", type=comma_list, default=CONFIGS, metavar="A,B,C",
                        help="configs/<name>.json to run (default: %s)" % ",".join(CONFIGS))
    parser.add_argument("--frames", type=int, default=540, metavar="N",
                        help="frames of each loop (default 540; the sequence without a loop: 11/18 of them)")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "bench", "table3"), metavar="DIR",
                        help="sequences and runs (default: out/bench/table3)")
    parser.add_argument("--results", default=os.path.join(ROOT, "bench", "results"), metavar="DIR",
                        help="where table3_<split>.csv and .md go (default: bench/results)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, metavar="N",
                        help="runs at a time (default: the cores)")
    parser.set_defaults(run=checked_run)


def checked_run(args: argparse.Namespace) -> int:
    if args.frames < 10:
        raise ToolError("--frames must be >= 10, got %d" % args.frames)
    if args.jobs < 1:
        raise ToolError("--jobs must be >= 1, got %d" % args.jobs)
    return run_table3(args)
