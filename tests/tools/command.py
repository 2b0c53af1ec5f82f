"""How the tool tests run a command of the dynvo_tools package: `python3 -m dynvo_tools COMMAND
ARGS...` with tools/ on PYTHONPATH (as the shell wrappers do), output captured as text."""
from __future__ import annotations

import os
import subprocess
import sys
from typing import Optional

SOURCE_DIR = os.environ["DYNVO_SOURCE_DIR"]
TOOLS_DIR = os.path.join(SOURCE_DIR, "tools")
if TOOLS_DIR not in sys.path:
    sys.path.insert(0, TOOLS_DIR)  # so that tests may also import dynvo_tools modules


def run_command(command: str, *args: str, env: Optional[dict[str, str]] = None) -> subprocess.CompletedProcess[str]:
    """Runs one dynvo_tools command in a child process; stdout and stderr captured."""
    environment = dict(os.environ if env is None else env)
    environment["PYTHONPATH"] = TOOLS_DIR + (os.pathsep + environment["PYTHONPATH"]
                                             if environment.get("PYTHONPATH") else "")
    return subprocess.run([sys.executable, "-m", "dynvo_tools", command, *args], env=environment,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
