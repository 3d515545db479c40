"""Hostile editor-journal files: skipped or set aside, never a hang or a crash of the HMI.

The journal (``<data dir>/hmi/journal``) is read when the Program manager or
the editor opens. A FIFO would block that read forever, a link to
``/dev/zero`` would never end, deep nesting or bytes that are not UTF-8 would
raise; each must leave the other entries readable.
"""

from __future__ import annotations

import os
from pathlib import Path

from hmi.journal import EditorJournal


def test_odd_and_malformed_journal_files_leave_the_good_entry(tmp_path: Path) -> None:
    journal = EditorJournal(tmp_path)
    journal.write("/MPF/GOOD.MPF", "G0 X1\n")
    os.mkfifo(tmp_path / "fifo.json")
    (tmp_path / "zero.json").symlink_to("/dev/zero")
    (tmp_path / "deep.json").write_text("[" * 100_000 + "]" * 100_000)
    (tmp_path / "latin1.json").write_bytes(b'{"format_version": 1, "program": "\xe4"}')
    assert [e.program for e in journal.entries()] == ["/MPF/GOOD.MPF"]
    assert sorted(p.name for p in tmp_path.glob("*.bad")) == ["deep.json.bad", "latin1.json.bad"]
