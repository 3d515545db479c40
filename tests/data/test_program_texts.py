"""A called program's text is kept between calls and read again when its file changed.

The program sources (a directory, the NC file system, the cycle folder) keep each text with its
file's identity (nck.file_texts); these tests change the file between two look-ups — in place with
the same size and another time stamp, with another size, replaced by a new file, removed, replaced
by a link — and expect exactly what a fresh read gives. Time stamps are set with ``os.utime``
(no sleeps).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from nck.interp.interpreter import Interpreter
from nck.interp.sources import ChainSource, DirectorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from nck.storage import NcFileSystem

FIRST = "PROC SUB\nR1=1\nRET\n"
SAME_SIZE = "PROC SUB\nR1=2\nRET\n"
LONGER = "PROC SUB\nR1=33\nRET\n"


def _rewrite_in_place(path: Path, text: str) -> None:
    """Write ``text`` into the same file (same inode) and move its time stamps on by one second."""
    before = path.stat()
    with open(path, "r+", encoding="utf-8") as stream:
        stream.write(text)
        stream.truncate()
    later = before.st_mtime_ns + 1_000_000_000
    os.utime(path, ns=(later, later))


def _directory_source(tmp_path: Path) -> tuple[DirectorySource, Path]:
    (tmp_path / "SUB.SPF").write_text(FIRST)
    return DirectorySource(tmp_path), tmp_path / "SUB.SPF"


def _nc_file_system(tmp_path: Path) -> tuple[NcFileSystem, Path]:
    fs = NcFileSystem(tmp_path / "nc")  # creates its folders MPF, SPF, WKS
    path = tmp_path / "nc" / "SPF" / "SUB.SPF"  # changed behind the NC memory's back below
    path.write_text(FIRST)
    return fs, path


@pytest.fixture(params=["directory", "nc file system"])
def source(request, tmp_path):
    """(program source, the file of SUB on disk)."""
    return (_directory_source if request.param == "directory" else _nc_file_system)(tmp_path)


def test_the_same_size_rewritten_in_place_is_read_again(source):
    programs, path = source
    assert programs.read_program("SUB")[1] == FIRST
    _rewrite_in_place(path, SAME_SIZE)
    assert programs.read_program("SUB")[1] == SAME_SIZE


def test_a_longer_text_is_read_again(source):
    programs, path = source
    assert programs.read_program("SUB")[1] == FIRST
    with open(path, "a", encoding="utf-8") as stream:
        stream.write("M17\n")
    assert programs.read_program("SUB")[1] == FIRST + "M17\n"


def test_a_replaced_file_is_read_again(source):
    programs, path = source
    assert programs.read_program("SUB")[1] == FIRST
    replacement = path.with_name("NEW.TMP")
    replacement.write_text(LONGER)
    os.replace(replacement, path)
    assert programs.read_program("SUB")[1] == LONGER


def test_a_removed_file_is_not_found(source):
    programs, path = source
    assert programs.read_program("SUB") is not None
    path.unlink()
    assert programs.read_program("SUB") is None


def test_the_nc_memory_does_not_read_through_a_link_that_replaced_a_kept_program(tmp_path):
    fs, path = _nc_file_system(tmp_path)
    assert fs.read_program("SUB")[1] == FIRST
    elsewhere = tmp_path / "ELSEWHERE.SPF"
    elsewhere.write_text(SAME_SIZE)
    path.unlink()
    path.symlink_to(elsewhere)
    assert fs.read_program("SUB") is None


def test_a_subprogram_changed_between_two_calls_of_one_run_runs_its_new_text(tmp_path):
    """One interpreter, one run: the second call of SUB runs the text saved after the first."""
    programs, path = _directory_source(tmp_path)
    interp = Interpreter(load_machine(None), ChainSource(programs), NcData())
    interp.start_text("MAIN.MPF", "SUB\nR2=R1\nSUB\nM30\n")
    while (interp.current_source().file, interp.current_source().line) != ("MAIN.MPF", 2):
        interp.step()  # up to R2=R1, after the first call
    assert interp.r(1) == 1.0
    _rewrite_in_place(path, SAME_SIZE)
    while not interp.finished:
        interp.step()
    assert (interp.r(2), interp.r(1)) == (1.0, 2.0)


def _a_later_tick(folder: Path) -> None:
    """Move the folder's time stamps on by one second: what a change in a later time-stamp tick
    looks like (a change within the tick of the listing before it is the documented limit)."""
    later = folder.stat().st_mtime_ns + 1_000_000_000
    os.utime(folder, ns=(later, later))


def test_a_program_added_after_a_look_up_that_missed_it_is_found(source):
    programs, path = source
    assert programs.read_program("ADDED") is None
    path.with_name("ADDED.SPF").write_text(LONGER)
    _a_later_tick(path.parent)
    assert programs.read_program("ADDED") == ("ADDED.SPF", LONGER)


def test_a_renamed_program_is_found_under_its_new_name_only(source):
    programs, path = source
    assert programs.read_program("SUB") is not None
    path.rename(path.with_name("OTHER.SPF"))
    _a_later_tick(path.parent)
    assert programs.read_program("SUB") is None
    assert programs.read_program("OTHER") == ("OTHER.SPF", FIRST)


def test_a_file_named_in_lower_case_is_found(source):
    programs, path = source
    assert programs.read_program("LOWER") is None
    path.with_name("lower.spf").write_text(LONGER)
    _a_later_tick(path.parent)
    assert programs.read_program("LOWER")[1] == LONGER


@pytest.fixture
def coarse_time_stamps(monkeypatch):
    """A file system whose time stamps never tick and whose sizes and inodes repeat: every file
    and folder has the same signature, so only an explicit drop tells a kept entry is stale."""
    monkeypatch.setattr("nck.file_texts.signature", lambda stat: (0, 0, 0, 0, 0))


def test_the_nc_memorys_own_save_is_read_at_the_next_call(tmp_path, coarse_time_stamps):
    fs, _ = _nc_file_system(tmp_path)
    assert fs.read_program("SUB")[1] == FIRST
    fs.save("SPF/SUB.SPF", SAME_SIZE)
    assert fs.read_program("SUB")[1] == SAME_SIZE


def test_a_program_the_nc_memory_saves_after_a_missed_look_up_is_found(tmp_path, coarse_time_stamps):
    fs, _ = _nc_file_system(tmp_path)
    assert fs.read_program("ADDED") is None
    fs.save("SPF/ADDED.SPF", LONGER)
    assert fs.read_program("ADDED")[1] == LONGER
    fs.rename("SPF/ADDED.SPF", "OTHER")
    assert fs.read_program("ADDED") is None
    assert fs.read_program("OTHER")[1] == LONGER
    fs.delete("SPF/OTHER.SPF")
    assert fs.read_program("OTHER") is None


def test_a_long_text_is_read_on_every_call(tmp_path, coarse_time_stamps, monkeypatch):
    """Texts above the kept size are not held: with a frozen signature the rewrite still shows."""
    monkeypatch.setattr("nck.file_texts.TEXT_KEPT_MAX_CHARS", len(FIRST) - 1)
    programs, path = _directory_source(tmp_path)
    assert programs.read_program("SUB")[1] == FIRST
    path.write_text(SAME_SIZE)
    assert programs.read_program("SUB")[1] == SAME_SIZE

