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


def test_a_lock_file_hard_linked_to_an_outside_file_is_neither_truncated_nor_written(tmp_path: Path) -> None:
    """A hard link is a regular file too, but its content is the outside file's: truncating it
    and writing the PID would destroy that file (found trying the door by hand)."""
    victim = _victim(tmp_path)
    data_dir = tmp_path / "data"
    data_dir.mkdir()
    os.link(victim, data_dir / ".lock")
    with pytest.raises(LockFileRefused) as refused:
        lock_data_dir(data_dir)
    assert ".lock" in str(refused.value) and "linked" in str(refused.value)
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


def _file_system(tmp_path: Path):
    from nck.storage import NcFileSystem

    fs = NcFileSystem(tmp_path / "nc")
    fs.save("MPF/AA.MPF", "G0 X1\n")
    return fs


def test_odd_entries_named_like_programs_are_skipped_and_named(tmp_path: Path) -> None:
    fs = _file_system(tmp_path)
    mpf = tmp_path / "nc" / "MPF"
    (mpf / "DANGLING.MPF").symlink_to(tmp_path / "nowhere")
    (mpf / "ZERO.MPF").symlink_to("/dev/zero")
    (mpf / "LINKED.MPF").symlink_to(mpf / "AA.MPF")
    os.mkfifo(mpf / "PIPE.MPF")
    (mpf / "FOLDER.MPF").mkdir()
    (tmp_path / "nc" / "WKS" / "FILE.WPD").write_text("")
    entries, odd = fs.scan_directory("MPF")
    assert [e.name for e in entries] == ["AA.MPF"]
    assert odd == ["DANGLING.MPF", "FOLDER.MPF", "LINKED.MPF", "PIPE.MPF", "ZERO.MPF"]
    assert fs.scan_directory("WKS") == ([], ["FILE.WPD"])
    assert [e.name for e in fs.all_programs()] == ["AA.MPF"]


def test_programs_are_never_read_through_a_link_or_fifo(tmp_path: Path) -> None:
    from nck.storage import StorageError

    fs = _file_system(tmp_path)
    victim = _victim(tmp_path)
    mpf = tmp_path / "nc" / "MPF"
    (mpf / "VICTIM.MPF").symlink_to(victim)
    (mpf / "ZERO.MPF").symlink_to("/dev/zero")
    os.mkfifo(mpf / "PIPE.MPF")
    for name in ("VICTIM.MPF", "ZERO.MPF", "PIPE.MPF"):
        with pytest.raises(StorageError, match="not a regular file"):
            fs.read(name)
        assert fs.read_program(name.removesuffix(".MPF")) is None  # a CALL finds nothing
    fs.save("VICTIM.MPF", "M30\n")  # replaces the link itself
    assert victim.read_text() == VICTIM_TEXT and fs.read("VICTIM.MPF") == "M30\n"
    fs.delete("ZERO.MPF")  # the link goes, nothing else
    assert not os.path.lexists(mpf / "ZERO.MPF")


def test_copying_a_workpiece_copies_regular_files_only(tmp_path: Path) -> None:
    fs = _file_system(tmp_path)
    fs.create_workpiece("SHAFT")
    folder = tmp_path / "nc" / "WKS" / "SHAFT.WPD"
    (folder / "ZERO.SPF").symlink_to("/dev/zero")
    os.mkfifo(folder / "PIPE.SPF")
    fs.copy("WKS/SHAFT.WPD", "WKS/COPY.WPD")
    assert sorted(p.name for p in (tmp_path / "nc" / "WKS" / "COPY.WPD").iterdir()) == ["SHAFT.MPF"]


def test_a_program_export_refuses_a_link_and_replaces_only_when_asked(tmp_path: Path) -> None:
    from nck.storage import StorageError

    fs = _file_system(tmp_path)
    victim = _victim(tmp_path)
    folder = tmp_path / "pc"
    folder.mkdir()
    (folder / "AA.MPF").symlink_to(victim)
    with pytest.raises(StorageError, match="not a regular file"):
        fs.export_file("AA.MPF", folder)
    assert victim.read_text() == VICTIM_TEXT
    (folder / "AA.MPF").unlink()
    (folder / "AA.MPF").write_text("older\n")
    with pytest.raises(FileExistsError):
        fs.export_file("AA.MPF", folder)
    assert (folder / "AA.MPF").read_text() == "older\n"
    assert fs.export_file("AA.MPF", folder, replace=True) == folder / "AA.MPF"
    assert (folder / "AA.MPF").read_text() == "G0 X1\n"


def test_a_retained_write_replaces_a_link_and_backs_up_nothing_through_it(tmp_path: Path) -> None:
    from nck.atomic import atomic_write_text, backup_path

    victim = _victim(tmp_path)
    target = tmp_path / "data" / "tools.json"
    target.parent.mkdir()
    target.symlink_to(victim)
    atomic_write_text(target, "new\n", backup=True)
    assert victim.read_text() == VICTIM_TEXT
    assert not target.is_symlink() and target.read_text() == "new\n"
    assert not os.path.lexists(backup_path(target))  # the outside content is not copied in
