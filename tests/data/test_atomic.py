"""Atomic writes: the file is always the complete old or the complete new content."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from nck import atomic
from nck.atomic import atomic_write_text, backup_path, remove_stale_temp_files

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.durability  # the writes here flush to the disk for real


def test_write_creates_file_and_directory(tmp_path: Path) -> None:
    target = tmp_path / "sub" / "data.json"
    atomic_write_text(target, "hello")
    assert target.read_text() == "hello"
    assert [p.name for p in target.parent.iterdir()] == ["data.json"]


def test_backup_keeps_previous_generation(tmp_path: Path) -> None:
    target = tmp_path / "data.json"
    atomic_write_text(target, "one", backup=True)
    assert not backup_path(target).exists()
    atomic_write_text(target, "two", backup=True)
    atomic_write_text(target, "three", backup=True)
    assert target.read_text() == "three"
    assert backup_path(target).read_text() == "two"


def test_backup_survives_later_write_of_main(tmp_path: Path) -> None:
    # the backup is a separate file, not an alias that changes with the main file
    target = tmp_path / "data.json"
    atomic_write_text(target, "one")
    atomic_write_text(target, "two", backup=True)
    atomic_write_text(target, "three")
    assert backup_path(target).read_text() == "one"


def test_failure_between_write_and_rename_keeps_old_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "PART1.MPF"
    atomic_write_text(target, "N10 G0 X0\n")

    def broken_replace(src: object, dst: object) -> None:
        raise OSError("simulated crash before rename")

    monkeypatch.setattr(atomic.os, "replace", broken_replace)
    with pytest.raises(OSError):
        atomic_write_text(target, "N10 G1 X100 F100\n")
    assert target.read_text() == "N10 G0 X0\n"
    assert [p.name for p in tmp_path.iterdir()] == ["PART1.MPF"]  # no temp left behind


def test_failure_during_write_keeps_old_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "data.json"
    atomic_write_text(target, "old")

    def broken_fsync(fd: int) -> None:
        raise OSError("disk full")

    monkeypatch.setattr(atomic.os, "fsync", broken_fsync)
    with pytest.raises(OSError):
        atomic_write_text(target, "new")
    assert target.read_text() == "old"
    assert len(list(tmp_path.iterdir())) == 1


def test_stale_temp_files_are_removed(tmp_path: Path) -> None:
    (tmp_path / ".data.json.tmp-123-abcd").write_text("half")
    (tmp_path / "data.json").write_text("whole")
    removed = remove_stale_temp_files(tmp_path)
    assert [p.name for p in removed] == [".data.json.tmp-123-abcd"]
    assert [p.name for p in tmp_path.iterdir()] == ["data.json"]


WRITER = """
import sys
from nck.atomic import atomic_write_text
path = sys.argv[1]
size = int(sys.argv[2])
i = 0
print("ready", flush=True)
while True:
    letter = "AB"[i % 2]
    atomic_write_text(path, letter * size, backup=True)
    i += 1
"""


def test_sigkilled_writer_never_leaves_a_torn_file(tmp_path: Path) -> None:
    target = tmp_path / "retained.json"
    size = 400_000
    atomic_write_text(target, "A" * size)
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    for round_no in range(12):
        proc = subprocess.Popen(
            [sys.executable, "-c", WRITER, str(target), str(size)],
            stdout=subprocess.PIPE,
            env=env,
        )
        assert proc.stdout is not None
        assert proc.stdout.readline().strip() == b"ready"
        # let it write for a varying number of rounds, then kill it without warning
        try:
            proc.wait(timeout=0.01 + 0.007 * round_no)
        except subprocess.TimeoutExpired:
            pass
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        for path in (target, backup_path(target)):
            if path.exists():
                content = path.read_text()
                assert len(content) == size, f"torn file after kill in round {round_no}"
                assert content in ("A" * size, "B" * size)
        remove_stale_temp_files(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["retained.json", "retained.json.bak"]
