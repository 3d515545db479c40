"""The HMI's exit code survives a terminal that went away (issue 19, nothing lost on quit).

Python flushes stdout and stderr as it ends; on a hung-up terminal that flush
fails and Python then ends with 120 instead of the HMI's ``128 + SIGHUP``. Seen
in the terminal-loss tests under load, when screen output was still buffered.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

CHILD = """
import os, sys
from hmi.app import detach_lost_terminal
read_end, write_end = os.pipe()
os.close(read_end)  # nobody reads: the next flush fails (EPIPE), as on a hung-up terminal (EIO)
sys.stdout = open(write_end, "w", buffering=65536)
sys.stdout.write("screen output still in the buffer")
detach_lost_terminal()
sys.exit(129)
"""


def test_a_failed_final_flush_keeps_the_exit_code() -> None:
    done = subprocess.run([sys.executable, "-c", CHILD], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert done.returncode == 129, done.stderr


def test_without_the_detach_python_ends_with_120() -> None:
    """The failure the detach prevents (test the test)."""
    child = CHILD.replace("detach_lost_terminal()", "pass")
    done = subprocess.run([sys.executable, "-c", child], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert done.returncode == 120, done.stderr
