"""The editor journal on disk."""

from __future__ import annotations

from pathlib import Path

from hmi.journal import EditorJournal, text_hash


def test_write_read_discard(tmp_path: Path) -> None:
    """An entry survives a new journal object on the same directory and is gone after discard."""
    EditorJournal(tmp_path).write("/MPF/PART1.MPF", "G0 X1\n", text_hash("G0 X0\n"))
    entries = EditorJournal(tmp_path).entries()
    assert [(e.program, e.text, e.base_sha256) for e in entries] == [
        ("/MPF/PART1.MPF", "G0 X1\n", text_hash("G0 X0\n"))
    ]
    EditorJournal(tmp_path).discard("/MPF/PART1.MPF")
    assert EditorJournal(tmp_path).entries() == []


def test_garbage_entry_is_put_aside(tmp_path: Path) -> None:
    """A torn journal file is ignored and renamed ``.bad``; good entries still load."""
    journal = EditorJournal(tmp_path)
    journal.write("/MPF/GOOD.MPF", "M30")
    (tmp_path / "BAD.MPF.json").write_text('{"format_version": 1, "program": "/MPF/BA')
    assert [e.program for e in journal.entries()] == ["/MPF/GOOD.MPF"]
    assert (tmp_path / "BAD.MPF.json.bad").exists()


def test_no_directory_means_no_entries(tmp_path: Path) -> None:
    """A journal directory that does not exist yet is simply empty."""
    assert EditorJournal(tmp_path / "missing").entries() == []
