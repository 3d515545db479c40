"""The program screens' adapter over the NC file system."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.storage import NcFileSystem, StorageError
from hmi.program_files import ProgramFiles, decode_program


def test_decode_program_flags_binary_and_non_utf8() -> None:
    """UTF-8 text decodes as is; NUL bytes or invalid UTF-8 mark the file binary (read-only)."""
    assert decode_program("G1 X1 ; Überlauf\n".encode()) == ("G1 X1 ; Überlauf\n", False)
    assert decode_program(b"G1\x00X1")[1] is True
    text, binary = decode_program(b"G1 X\xff")
    assert binary and text.startswith("G1 X")


def test_create_and_paste_copy(tmp_path: Path) -> None:
    """New programs get the directory's type; a pasted copy takes the next free _n name."""
    files = ProgramFiles(NcFileSystem(tmp_path / "nc"))
    assert files.create("MPF", "part1") == "MPF/PART1.MPF"
    assert files.create("SPF", "contour") == "SPF/CONTOUR.SPF"
    assert files.create("WKS", "shaft") == "WKS/SHAFT.WPD"
    assert files.paste_copy("MPF/PART1.MPF", "MPF") == "MPF/PART1_1.MPF"
    assert files.paste_copy("MPF/PART1.MPF", "MPF") == "MPF/PART1_2.MPF"
    assert files.paste_copy("MPF/PART1.MPF", "WKS/SHAFT.WPD") == "WKS/SHAFT.WPD/PART1.MPF"
    with pytest.raises(StorageError):
        files.create("MPF", "part1")


def test_open_request_is_taken_once(tmp_path: Path) -> None:
    """The manager's Open request reaches the editor exactly once."""
    files = ProgramFiles(NcFileSystem(tmp_path / "nc"))
    files.request_open("MPF/A_B.MPF")
    assert files.take_open_request() == ("MPF/A_B.MPF", False)
    assert files.take_open_request() is None


def test_journal_lives_beside_the_nc_file_system(tmp_path: Path) -> None:
    """The journal is in the data directory, not among the NC programs."""
    files = ProgramFiles(NcFileSystem(tmp_path / "data" / "nc"))
    assert files.journal_dir == tmp_path / "data" / "hmi" / "journal"
