"""The editor journal: unsaved editor text kept on disk so that a crash loses nothing.

While a program is open with unsaved changes, the editor writes its whole text
every few seconds into ``<journal dir>/<key>.json`` (atomically: temp file,
fsync, rename). Saving or discarding the changes deletes the entry. When the
HMI starts after a crash or a kill, the entries still on disk are the texts
that were never saved, and the editor offers to restore them.

File format (JSON, ``format_version`` 1)::

    {"format_version": 1, "program": "/MPF/PART1.MPF",
     "base_sha256": "<hash of the saved file the edit started from>",
     "text": "<editor text>"}

A file that cannot be read (torn, garbage, other version) is moved aside as
``<name>.bad`` and ignored, never a reason to fail.
"""

from __future__ import annotations

import hashlib
import json
import re
from dataclasses import dataclass
from pathlib import Path

from nck import MAX_IMPORT_BYTES, atomic_write_text, read_regular_bytes

FORMAT_VERSION = 1
AUTOSAVE_PERIOD_S = 3.0
"""How often the editor writes its unsaved text into the journal."""
JOURNAL_LIMIT_BYTES = 8 * MAX_IMPORT_BYTES
"""Largest journal file read: the biggest program, escaped as JSON text."""


def text_hash(text: str) -> str:
    """SHA-256 of a text (UTF-8), to tell whether a file changed since the edit began."""
    return hashlib.sha256(text.encode("utf-8", "surrogateescape")).hexdigest()


@dataclass(frozen=True, slots=True)
class JournalEntry:
    """Unsaved text of one program.

    Attributes:
        program: the program's NC path (``/MPF/PART1.MPF``) as the storage names it.
        text: the unsaved editor text.
        base_sha256: hash of the saved file when the edit started.
        path: the journal file.
    """

    program: str
    text: str
    base_sha256: str
    path: Path


class EditorJournal:
    """The journal directory: one entry per program with unsaved changes."""

    def __init__(self, directory: Path | str) -> None:
        self.directory = Path(directory)

    def _file(self, program: str) -> Path:
        safe = re.sub(r"[^A-Za-z0-9_.-]+", "_", program.strip("/")) or "program"
        return self.directory / f"{safe}.json"

    def write(self, program: str, text: str, base_sha256: str = "") -> None:
        """Store the unsaved ``text`` of ``program`` (atomic; replaces the previous entry)."""
        record = {
            "format_version": FORMAT_VERSION,
            "program": program,
            "base_sha256": base_sha256,
            "text": text,
        }
        atomic_write_text(self._file(program), json.dumps(record, ensure_ascii=False))

    def discard(self, program: str) -> None:
        """Forget the entry of ``program`` (after save or when the operator discards it)."""
        try:
            self._file(program).unlink()
        except FileNotFoundError:
            pass

    def entry(self, program: str) -> JournalEntry | None:
        """The entry of ``program``, or None."""
        return self._read(self._file(program))

    def entries(self) -> list[JournalEntry]:
        """Every readable entry, sorted by program name."""
        if not self.directory.is_dir():
            return []
        found = [self._read(path) for path in sorted(self.directory.glob("*.json"))]
        return sorted((e for e in found if e is not None), key=lambda e: e.program)

    def _read(self, path: Path) -> JournalEntry | None:
        try:  # a regular file only: a FIFO would block, a link to /dev/zero never end
            raw = read_regular_bytes(path, JOURNAL_LIMIT_BYTES)
        except OSError:
            return None
        try:
            record = json.loads(raw.decode("utf-8"))
            if record.get("format_version") != FORMAT_VERSION:
                raise ValueError("unknown journal format")
            return JournalEntry(
                program=str(record["program"]),
                text=str(record["text"]),
                base_sha256=str(record.get("base_sha256", "")),
                path=path,
            )
        except (ValueError, KeyError, TypeError, AttributeError, RecursionError):
            try:
                path.replace(path.with_name(path.name + ".bad"))
            except OSError:
                pass
            return None
