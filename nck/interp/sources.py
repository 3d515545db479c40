"""Program sources for the interpreter: a directory on disk and an in-memory table.

Both implement :class:`nck.interp.api.ProgramSource`. Names are matched without
regard to case; a name without extension is looked up as ``.SPF`` then ``.MPF``
(then as written).
"""

from __future__ import annotations

import os
from pathlib import Path
from stat import S_ISREG

from nck.file_texts import FileTexts, FolderNames
from nck.regular_files import read_regular_bytes

EXTENSIONS = (".SPF", ".MPF")


PROGRAM_FILE_LIMIT_BYTES = 50 * 1024 * 1024
"""Largest program file read (as large as the NC memory takes one, ``nck.storage.MAX_IMPORT_BYTES``)."""


def program_file_key(name: str) -> str:
    """A program file's name as compared: without folders, upper case."""
    return name.replace("\\", "/").rsplit("/", 1)[-1].upper()


def read_text_file(path: Path) -> str:
    """Read a program file as text; undecodable bytes never fail (latin-1 fallback).

    Only a regular file (a link to one is followed) of at most
    :data:`PROGRAM_FILE_LIMIT_BYTES` is read; else an ``OSError`` says why.
    """
    raw = read_regular_bytes(path, PROGRAM_FILE_LIMIT_BYTES, follow_links=True)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return raw.decode("latin-1")


class DirectorySource:
    """Programs in one or more directories (searched in order).

    A directory is listed again only when it changed (:class:`FolderNames`), a found program's
    text read again only when its file changed (:class:`FileTexts`).
    """

    def __init__(self, *directories: Path | str) -> None:
        self.directories = [Path(d) for d in directories]
        self.texts = FileTexts()
        self.folders = FolderNames()

    def _candidates(self, name: str) -> list[str]:
        upper = name.upper()
        if Path(upper).suffix in EXTENSIONS:
            return [upper]
        return [upper + ext for ext in EXTENSIONS] + [upper]

    def read_program(self, name: str) -> tuple[str, str] | None:
        """Return ``(display_name, text)`` or None."""
        wanted = self._candidates(name)
        for directory in self.directories:
            try:
                found = self._files(directory, wanted)
            except OSError:  # not a directory (any more)
                continue
            for candidate in wanted:
                if candidate in found:
                    path, status = found[candidate]
                    try:
                        return path.name, self.texts.text(str(path), status, lambda: read_text_file(path))
                    except OSError:
                        return None
        return None

    def _files(self, directory: Path, wanted: list[str]) -> dict[str, tuple[Path, os.stat_result]]:
        """The regular files (or links to one) of ``directory`` named as one of ``wanted`` (in
        capitals), with their ``stat``; of several names that differ only in case the last
        listed. Only the wanted names are tested (one stat each, not one per entry)."""
        named = self.folders.named(str(directory))
        found: dict[str, tuple[Path, os.stat_result]] = {}
        for upper in wanted:
            for path in named.get(upper, ()):
                try:
                    status = os.stat(path)  # through a link, as read_text_file reads
                except OSError:
                    continue
                if S_ISREG(status.st_mode):
                    found[upper] = (Path(path), status)
        return found


class MemorySource:
    """Programs held in a dictionary name → text (tests, MDA)."""

    def __init__(self, programs: dict[str, str] | None = None) -> None:
        self.programs = {k.upper(): (k, v) for k, v in (programs or {}).items()}

    def add(self, name: str, text: str) -> None:
        """Add or replace a program."""
        self.programs[name.upper()] = (name, text)

    def read_program(self, name: str) -> tuple[str, str] | None:
        """Return ``(display_name, text)`` or None."""
        upper = name.upper()
        if Path(upper).suffix in EXTENSIONS:
            return self.programs.get(upper)
        for ext in EXTENSIONS:
            if upper + ext in self.programs:
                return self.programs[upper + ext]
        return self.programs.get(upper)


class ChainSource:
    """Several program sources searched in order (program directory, then NC file system)."""

    def __init__(self, *sources: object) -> None:
        self.sources = [s for s in sources if s is not None]

    def read_program(self, name: str) -> tuple[str, str] | None:
        """Return the first source's ``(display_name, text)``, or None."""
        for source in self.sources:
            found = source.read_program(name)  # type: ignore[attr-defined]
            if found is not None:
                return found
        return None
