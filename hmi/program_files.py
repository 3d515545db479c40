"""What the Program manager and the Program editor need from the NC file system.

Not a screen: a small adapter shared by ``screens/program_manager.py`` and
``screens/program.py`` (a screen never imports another area's module, so it lives in ``hmi``). The NC file
system itself is the kernel's :class:`nck.storage.NcFileSystem` (atomic writes,
name rules, the program-in-use rule); this module only finds it in the app,
formats its entries for the list, and carries the little state the two screens
share (the program the editor should open, the last program edited).

Programs are named by the storage's canonical paths: ``MPF/PART1.MPF``,
``SPF/CONTOUR.SPF``, ``WKS/SHAFT.WPD/SHAFT.MPF``.
"""

from __future__ import annotations

import datetime
import tempfile
from pathlib import Path
from typing import Any

from nck import queries
from nck import NcFileSystem, StorageError

from hmi.i18n import N_

DIRECTORIES: tuple[tuple[str, str], ...] = (
    ("MPF", N_("Part programs")),
    ("SPF", N_("Subprograms")),
    ("WKS", N_("Workpieces")),
)
"""The NC directories in the order of the manager's tree: path and title."""

ProgramFileError = StorageError
"""Every refusal of a file operation (its text is shown on the dialog line)."""


def decode_program(raw: bytes) -> tuple[str, bool]:
    """Decode a program file; return (text, binary).

    ``binary`` is True when the bytes are not UTF-8 text (or hold NUL bytes); the
    text is then a lossy rendering for a read-only view.
    """
    if b"\x00" in raw:
        return raw.decode("utf-8", errors="replace").replace("\x00", "\u2400"), True
    try:
        return raw.decode("utf-8"), False
    except UnicodeDecodeError:
        return raw.decode("utf-8", errors="replace"), True


def format_modified(modified_ns: int) -> str:
    """Modification time as the list shows it: ``2026-11-22 05:40`` (local time)."""
    return datetime.datetime.fromtimestamp(modified_ns / 1e9).strftime("%Y-%m-%d %H:%M")


def find_file_system(app: Any) -> NcFileSystem | None:
    """The NC file system of the app (its own, else the kernel's program source), if it has one."""
    bridge = getattr(app, "bridge", None)
    kernel_source = bridge.query(queries.ProgramSource()) if bridge is not None else None
    candidates = [getattr(app, attr, None) for attr in ("storage", "nc_files", "programs")] + [kernel_source]
    return next((candidate for candidate in candidates if isinstance(candidate, NcFileSystem)), None)


class ProgramFiles:
    """The NC file system plus the state the program screens share (one per app).

    Args:
        fs: the NC file system.
    """

    def __init__(self, fs: NcFileSystem) -> None:
        self.fs = fs
        self.scratch: tempfile.TemporaryDirectory[str] | None = None
        """The temporary folder of ``fs`` when the kernel has no file system (removed with this
        instance, when the app lets go of it, or at the latest when the process ends)."""
        self.last_program: str | None = None
        self.pending_open: str | None = None
        self.pending_at_end = False
        """The requested program opens with the cursor at its end (a new program: behind its header)."""

    @classmethod
    def of_app(cls, app: Any) -> ProgramFiles:
        """The instance of ``app``.

        A kernel without an NC file system (a test double) gets a temporary one,
        so the screens still work; nothing there outlives the process.
        """
        existing = getattr(app, "_program_files", None)
        if isinstance(existing, ProgramFiles):
            return existing
        fs = find_file_system(app)
        scratch = None
        if fs is None:
            scratch = tempfile.TemporaryDirectory(prefix="nc-data-")
            fs = NcFileSystem(Path(scratch.name) / "nc")
        files = cls(fs)
        files.scratch = scratch
        app._program_files = files
        return files

    @classmethod
    def forget(cls, app: Any) -> None:
        """Let go of ``app``'s instance: the kernel and its NC file system were replaced (an
        exercise started or ended), the next :meth:`of_app` finds the new one."""
        files = getattr(app, "_program_files", None)
        if isinstance(files, ProgramFiles) and files.scratch is not None:
            files.scratch.cleanup()
        if hasattr(app, "_program_files"):
            del app._program_files

    # -- names and shared state ------------------------------------------------------------------
    @property
    def journal_dir(self) -> Path:
        """Where the editor journal lives: ``<data dir>/hmi/journal``."""
        return self.fs.root.parent / "hmi" / "journal"

    def canonical(self, path: str) -> str:
        """The storage's canonical path of a program."""
        return self.fs.canonical(path)

    def request_open(self, path: str, *, at_end: bool = False) -> None:
        """Ask the editor to open ``path`` when it is shown next (Program manager → Open, New)."""
        self.pending_open = path
        self.pending_at_end = at_end

    def take_open_request(self) -> tuple[str, bool] | None:
        """The program the editor should open now and whether at its end (taken once), else None."""
        pending, self.pending_open = self.pending_open, None
        return None if pending is None else (pending, self.pending_at_end)

    def program_source(self, context: str | None = None) -> Any:
        """A ProgramSource for subprogram calls of ``context`` during checks and simulation."""
        return self.fs.program_source(context)

    def is_in_use(self, path: str) -> bool:
        """True when the storage considers the program in use (it cannot be changed)."""
        try:
            return self.fs.is_in_use(path)
        except StorageError:
            return False

    # -- operations the manager offers -------------------------------------------------------------
    def create(self, directory: str, name: str) -> str:
        """Create an empty program in ``directory`` (a workpiece in ``WKS``); return its path."""
        if directory == "WKS":
            return self.fs.create_workpiece(name).path
        file_name = name.strip().upper()
        if "." not in file_name:
            default = "SPF" if directory == "SPF" else "MPF"
            file_name = f"{file_name}.{default}"
        path = self.fs.canonical(f"{directory}/{file_name}")
        return self.fs.create(path, f"; {path.rpartition('/')[2]}\n").path

    def paste_copy(self, source: str, directory: str) -> str:
        """Copy ``source`` into ``directory``; a taken name gets ``_1``, ``_2`` … appended."""
        try:
            return self.fs.copy(source, directory).path
        except StorageError as exc:
            if exc.code != "exists":
                raise
        base = source.rpartition("/")[2]
        stem, _, kind = base.rpartition(".")
        for number in range(1, 1000):
            candidate = f"{stem[:20]}_{number}.{kind}"
            target = f"{directory}/{candidate}" if directory != "WKS" else f"WKS/{candidate}"
            try:
                return self.fs.copy(source, target).path
            except StorageError as exc:
                if exc.code != "exists":
                    raise
        raise StorageError("storage_no_free_copy_name", name=base)
