"""``hmi`` without a terminal (``hmi </dev/null``, output into a pipe): one line saying what it
needs and exit status 2, no traceback of the terminal driver, and nothing left behind (the
ephemeral copy removed, the data directory's lock given back)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from nck.paths import EPHEMERAL_PREFIX

ROOT = Path(__file__).resolve().parents[2]


def test_hmi_without_a_terminal_says_so_and_leaves_nothing(tmp_path: Path) -> None:
    temp = tmp_path / "temp"
    temp.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "TEXTUAL_DRIVER"}
    env.update(TMPDIR=str(temp), NCK_DATA_DIR=str(tmp_path / "data"))
    ended = subprocess.run([sys.executable, "-m", "hmi", "--ephemeral"], cwd=ROOT, env=env,
                           stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)
    assert ended.returncode == 2
    assert "needs a terminal" in ended.stderr
    assert "Traceback" not in ended.stderr + ended.stdout
    assert [p.name for p in temp.iterdir() if p.name.startswith(EPHEMERAL_PREFIX)] == []
    # the lock is free again: a second start gets the same answer, not "in use"
    again = subprocess.run([sys.executable, "-m", "hmi"], cwd=ROOT, env=env,
                           stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)
    assert again.returncode == 2 and "needs a terminal" in again.stderr
