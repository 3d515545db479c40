"""A minimal program source over plain directories (until the NC file system is wired in).

Implements the ``ProgramSource`` protocol of ``nck.interp.api`` and can list
what it holds, so the Machine area can offer a program selection.
"""

from __future__ import annotations

from pathlib import Path
from typing import Iterable

PROGRAM_SUFFIXES = (".MPF", ".SPF")


class DirectoryPrograms:
    """Part programs found in a list of folders (first folder wins on equal names)."""

    def __init__(self, folders: Iterable[Path]) -> None:
        self.folders = [Path(f) for f in folders if Path(f).is_dir()]

    def _files(self) -> dict[str, Path]:
        found: dict[str, Path] = {}
        for folder in self.folders:
            for path in sorted(folder.iterdir()):
                if path.suffix.upper() in PROGRAM_SUFFIXES and path.is_file():
                    found.setdefault(path.name.upper(), path)
        return found

    def list_programs(self) -> list[str]:
        """Names of the main programs (``.MPF``), sorted."""
        return sorted(name for name in self._files() if name.endswith(".MPF"))

    def read_program(self, name: str) -> tuple[str, str] | None:
        """Return ``(display_name, text)`` or None; without extension ``.SPF`` then ``.MPF``."""
        files = self._files()
        key = name.upper()
        candidates = [key] if Path(key).suffix else [key + ".SPF", key + ".MPF"]
        for candidate in candidates:
            path = files.get(candidate)
            if path is not None:
                try:
                    return path.name, path.read_text(encoding="utf-8", errors="replace")
                except OSError:
                    return None
        return None
