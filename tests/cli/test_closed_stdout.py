"""A reader that stops early (``nck run … | head``) ends the command quietly.

Unix tools end without a message when the reader of their standard output goes
away; the shell reports such a command with 141 (128 + SIGPIPE). ``nck`` does
the same: no "Internal error" alarm, exit code 141 (README, "exit codes").
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

STDOUT_CLOSED_EXIT = 141


def _long_output_program(tmp_path: Path) -> Path:
    program = tmp_path / "LONG.MPF"  # 3000 segments: far more than a pipe buffers (64 KB)
    program.write_text("G1 F1000\nR1=0\nAA: X=R1 Y=0\nR1=R1+1\nIF R1<3000 GOTOB AA\nM30\n")
    return program


def _first_line_then_close(args: list[str], tmp_path: Path) -> tuple[int, str]:
    env = dict(os.environ, NCK_DATA_DIR=str(tmp_path / "data"))
    with subprocess.Popen([sys.executable, "-m", "nck", *args], stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, env=env) as process:
        assert process.stdout is not None and process.stderr is not None
        assert process.stdout.readline()  # like `head -1`: read a line, then go away
        process.stdout.close()
        errors = process.stderr.read().decode()
        return process.wait(timeout=60), errors


def test_run_with_segments_to_a_reader_that_went_away_ends_quietly(tmp_path: Path) -> None:
    code, errors = _first_line_then_close(["run", "--segments", "-", str(_long_output_program(tmp_path))],
                                          tmp_path)
    assert errors == ""
    assert code == STDOUT_CLOSED_EXIT

