"""Links, pipes and devices in the data directory: the program never reads or writes through them.

A symbolic link named like a file the program keeps (the lock, a retained
section, a program) or writes for the operator (an export) could send a write
to a file outside the data directory; a FIFO would block a read forever. Each
test plants such an entry and checks that the outside file is untouched and
the user gets a clear message (or the entry is skipped and reported).
"""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest

from hmi.app import main as hmi_main
from nck.cli import main as nck_main
from nck.cli_md import run as md_run
from nck.datalock import LockFileRefused, lock_data_dir

VICTIM_TEXT = "precious outside file\n"


def _victim(tmp_path: Path) -> Path:
    victim = tmp_path / "outside" / "victim.txt"
    victim.parent.mkdir()
    victim.write_text(VICTIM_TEXT)
    return victim


def test_a_lock_file_linked_outside_is_neither_truncated_nor_written(tmp_path: Path) -> None:
    victim = _victim(tmp_path)
    data_dir = tmp_path / "data"
    data_dir.mkdir()
    (data_dir / ".lock").symlink_to(victim)
    with pytest.raises(LockFileRefused) as refused:
        lock_data_dir(data_dir)
    assert ".lock" in str(refused.value) and "not a regular file" in str(refused.value)
    assert victim.read_text() == VICTIM_TEXT


def test_a_dangling_lock_link_creates_nothing_outside(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    data_dir.mkdir()
    target = tmp_path / "created-through-link"
    (data_dir / ".lock").symlink_to(target)
    with pytest.raises(LockFileRefused):
        lock_data_dir(data_dir)
    assert not target.exists()


def test_a_fifo_lock_is_refused_without_blocking(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / ".lock")
    with pytest.raises(LockFileRefused):
        lock_data_dir(tmp_path)


def test_every_door_refuses_a_linked_lock_with_a_message(tmp_path: Path, capsys) -> None:
    victim = _victim(tmp_path)
    data_dir = tmp_path / "data"
    data_dir.mkdir()
    (data_dir / ".lock").symlink_to(victim)
    program = tmp_path / "P.MPF"
    program.write_text("R1=1\nM30\n")

    err = io.StringIO()
    assert md_run(["--data-dir", str(data_dir), "MD28050"], io.StringIO(), err) == 2
    assert "not a regular file" in err.getvalue()
    assert nck_main(["run", "--data-dir", str(data_dir), str(program)]) == 2
    assert nck_main(["check", "--data-dir", str(data_dir), str(program)]) == 2
    assert hmi_main(["--data-dir", str(data_dir)]) == 2
    messages = capsys.readouterr().err
    assert messages.count("not a regular file") == 3 and "Traceback" not in messages
    assert victim.read_text() == VICTIM_TEXT
