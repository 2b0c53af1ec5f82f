"""What every command shares: where the repository and the binaries are, one error type,
running a tool with a clear message when it fails, reading its JSON, and tasks side by side."""
from __future__ import annotations

import concurrent.futures
import json
import math
import os
import shlex
import subprocess
import sys
from typing import Callable, Sequence, TypeVar

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
T = TypeVar("T")


class ToolError(Exception):
    """A failure a command reports as one line `COMMAND: error: ...` and exit code 1: which
    input or tool, which file, what happened."""


def bin_dir() -> str:
    """The dynvo binaries: $DYNVO_BIN_DIR, else $DYNVO_BUILD_DIR/bin, else build/bin."""
    return os.environ.get("DYNVO_BIN_DIR") or os.path.join(
        os.environ.get("DYNVO_BUILD_DIR") or os.path.join(ROOT, "build"), "bin")


def bin_path(name: str) -> str:
    """The path of the dynvo binary `name` (it may not exist: run_tool says so)."""
    return os.path.join(bin_dir(), name)


def shared_dir() -> str:
    """The project's shared data (real TUM frames): $DYNVO_SHARED_DIR, else ../shared."""
    return os.environ.get("DYNVO_SHARED_DIR") or os.path.join(ROOT, "..", "shared")


def config_path(name: str) -> str:
    """configs/NAME.json of the repository."""
    return os.path.join(ROOT, "configs", name + ".json")


def display_path(path: str) -> str:
    """Relative to the repository when inside it (no machine-specific prefix), else as given."""
    inside = os.path.relpath(os.path.abspath(path), ROOT)
    return path if inside.startswith("..") else inside


def log(command: str, message: str) -> None:
    """A progress line on stderr, prefixed by the command's name."""
    print("%s: %s" % (command, message), file=sys.stderr, flush=True)


def tail(text: str, lines: int = 8) -> str:
    """The last non-empty lines of a tool's stderr, indented."""
    kept = [line for line in text.splitlines() if line.strip()][-lines:]
    return "\n".join("  " + line for line in kept) if kept else "  (nothing on stderr)"


def run_tool(what: str, command: Sequence[str]) -> str:
    """Runs a binary and returns its stdout. A missing program or a non-zero exit is a
    ToolError naming what it was for, the program, and the end of its stderr."""
    program = command[0]
    if not os.access(program, os.X_OK):
        raise ToolError("%s: %s: not found or not executable (build it: the shell wrapper does, or"
                        " set DYNVO_BIN_DIR)" % (what, display_path(program)))
    done = subprocess.run(list(command), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise ToolError("%s: %s exited with code %d: %s\nthe end of its stderr:\n%s" % (
            what, os.path.basename(program), done.returncode, shlex.join(command), tail(done.stderr)))
    return done.stdout


def read_json(what: str, path: str) -> dict:
    """A JSON object from a file; a ToolError naming the file when unreadable or not an object."""
    try:
        with open(path) as f:
            data = json.load(f)
    except OSError as error:
        raise ToolError("%s: %s: cannot read: %s" % (what, display_path(path), error.strerror)) from None
    except ValueError as error:
        raise ToolError("%s: %s: not valid JSON (%s)" % (what, display_path(path), error)) from None
    if not isinstance(data, dict):
        raise ToolError("%s: %s: not a JSON object" % (what, display_path(path)))
    return data


def json_number(what: str, path: str, data: dict, key: str) -> float:
    """The finite number at a dotted key ("translational_error_m.rmse") of data read from path."""
    value: object = data
    for part in key.split("."):
        value = value.get(part) if isinstance(value, dict) else None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ToolError("%s: %s: no finite number at %s" % (what, display_path(path), key))
    return float(value)


def percentile(values: Sequence[float], q: float) -> float:
    """The q-th percentile, linear between the closest ranks (numpy's default)."""
    ordered = sorted(values)
    position = (len(ordered) - 1) * q / 100.0
    low = math.floor(position)
    high = min(low + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (position - low)


def write_atomically(path: str, text: str) -> None:
    """Writes a file whole or not at all (a reader never sees half of it)."""
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def run_parallel(tasks: Sequence[Callable[[], T]], jobs: int) -> list[T]:
    """The tasks' results in their order, up to `jobs` at a time. A failure cancels what has not
    started; once the running tasks are over, the first failure in task order is raised."""
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = [pool.submit(task) for task in tasks]
        concurrent.futures.wait(futures, return_when=concurrent.futures.FIRST_EXCEPTION)
        for future in futures:
            future.cancel()  # only those not started
        concurrent.futures.wait(futures)
        for future in futures:
            if not future.cancelled() and future.exception():
                raise future.exception()  # type: ignore[misc]
        return [future.result() for future in futures]
