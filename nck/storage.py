"""The NC file system: part programs, subprograms and workpieces in the NC data directory.

Layout below the file-system root (``<data dir>/nc``)::

    MPF/PART1.MPF              part (main) programs
    SPF/L10.SPF                subprograms
    WKS/SHAFT.WPD/SHAFT.MPF    workpieces: a folder holding its own MPF/SPF

Programs are addressed by a path such as ``"MPF/PART1.MPF"``,
``"WKS/SHAFT.WPD/SHAFT.MPF"`` or simply ``"PART1.MPF"`` (the directory follows
from the extension). Names are not case-sensitive and are stored in capitals.
Every write is atomic (:mod:`nck.atomic`). Only regular files are programs
and only real directories workpieces (:mod:`nck.regular_files`): a link, FIFO
or device named like a program is never read or written through; the listing
skips it and names it (:meth:`NcFileSystem.scan_directory`). A program in use (selected for or
being executed) cannot be saved, renamed or deleted: the owner of the channel
reports which programs are in use through :attr:`NcFileSystem.in_use_check`.

:class:`NcFileSystem` implements the interpreter's ``ProgramSource``.
"""

from __future__ import annotations

import functools
import os
import re
import shutil
from dataclasses import dataclass
from pathlib import Path
from stat import S_ISDIR, S_ISREG
from typing import Any, Callable, Iterable, TypeVar, cast

from nck.atomic import atomic_write_bytes, remove_stale_temp_files
from nck.file_texts import FileTexts, FolderNames
from nck.os_refusals import os_refusal
from nck.refused import Refused
from nck.regular_files import (
    ExportTargetExists, NotAFolder,
    copy_regular_tree, is_plain_directory, is_regular_file, plain_directory, read_regular_bytes,
    write_export,
)

DIRECTORIES = ("MPF", "SPF", "WKS")
PROGRAM_TYPES = ("MPF", "SPF")
WORKPIECE_SUFFIX = "WPD"
NAME_MAX_CHARS = 24
MAX_IMPORT_BYTES = 50 * 1024 * 1024
SAMPLES_MARK = ".samples-installed"

# Two letters/underscores first, then letters, digits, underscores; or L followed by digits.
_NAME = re.compile(r"^(?:[A-Z_][A-Z_][A-Z0-9_]*|L[0-9]{1,7})$")


STORAGE_KEY_CODES = {
    "storage_name_needed": "invalid_name", "storage_name_too_long": "invalid_name",
    "storage_name_two_letters": "invalid_name", "storage_name_letters": "invalid_name",
    "storage_name_type": "invalid_name",
    "storage_not_nc_path": "bad_path", "storage_wrong_directory": "bad_path",
    "storage_wks_workpieces_only": "bad_path", "storage_workpiece_programs_only": "bad_path",
    "storage_too_many_levels": "bad_path", "storage_not_a_program": "bad_path",
    "storage_directory_not_deletable": "bad_path",
    "storage_exists": "exists", "storage_copy_onto_itself": "exists", "storage_no_free_copy_name": "exists",
    "storage_does_not_exist": "not_found", "storage_not_a_file": "not_found",
    "storage_in_use_changed": "in_use", "storage_in_use_overwritten": "in_use",
    "storage_in_use_renamed": "in_use", "storage_in_use_deleted": "in_use",
    "storage_not_utf8": "not_text", "storage_binary": "not_text",
    "storage_too_large": "io",
    "storage_not_nc_folder": "odd",
}
"""The kind (``StorageError.code``) of each refusal key of the NC file system; a key not
listed (an operating system's refusal, :mod:`nck.os_refusals`) is of kind ``io``."""


class StorageError(Refused):
    """A file operation was refused or failed: a keyed refusal (``data/refusals.toml``, ``str()``
    the English text) that a panel says in its own language.

    ``code`` is the kind: one of ``invalid_name``, ``bad_path``, ``exists``, ``not_found``,
    ``in_use``, ``not_text``, ``io``, ``odd`` (a folder that is a link, pipe or file).
    """

    def __init__(self, key: str, **fields: object) -> None:
        self.code = STORAGE_KEY_CODES.get(key, "io")
        super().__init__(key, **fields)

    @classmethod
    def from_os_error(cls, error: OSError, path: object, failed: str = "os_write_failed") -> "StorageError":
        """The operating system's refusal ``error`` of a file operation on ``path`` (:func:`os_refusal`)."""
        refusal = os_refusal(error, path=str(path), failed=failed)
        return cls(refusal.key, **dict(refusal.fields))


def validate_name(name: str) -> str:
    """Return a program or workpiece name (without extension) in capitals, or raise.

    Rules: 1..24 characters; letters, digits and underscores; the first two
    characters letters or underscores — except subprogram names ``L<digits>``.
    """
    upper = name.strip().upper()
    if not upper:
        raise StorageError("storage_name_needed")
    if len(upper) > NAME_MAX_CHARS:
        raise StorageError("storage_name_too_long", name=upper, max=NAME_MAX_CHARS)
    if len(upper) == 1 and re.fullmatch(r"[A-Z_]", upper):
        raise StorageError("storage_name_two_letters", name=upper)
    if not _NAME.match(upper):
        raise StorageError("storage_name_letters", name=upper)
    return upper


def split_file_name(file_name: str) -> tuple[str, str]:
    """Split ``PART1.MPF`` into (``PART1``, ``MPF``), validating both parts."""
    stem, dot, ext = file_name.strip().upper().rpartition(".")
    if not dot or ext not in PROGRAM_TYPES + (WORKPIECE_SUFFIX,):
        raise StorageError("storage_name_type", name=file_name)
    return validate_name(stem), ext


@dataclass(frozen=True, slots=True)
class ProgramEntry:
    """One program or workpiece as the program manager lists it."""

    path: str  # canonical path, e.g. "WKS/SHAFT.WPD/SHAFT.MPF"
    name: str  # file name, e.g. "SHAFT.MPF"
    kind: str  # "MPF", "SPF" or "WPD"
    size_bytes: int
    modified_ns: int

    @property
    def directory(self) -> str:
        """The containing directory path (``MPF``, ``WKS/SHAFT.WPD`` …)."""
        return self.path.rpartition("/")[0]


@dataclass(frozen=True, slots=True)
class OpenedProgram:
    """A program opened for the editor: its text and whether it may be edited."""

    path: str
    text: str
    read_only: bool
    message: str = ""


def check_program_size(name: str, data: bytes) -> None:
    """Raise StorageError ``io`` for content larger than a program the NC memory takes
    (:data:`MAX_IMPORT_BYTES`: what is read back; a larger program could never be opened)."""
    if len(data) > MAX_IMPORT_BYTES:
        raise StorageError("storage_too_large", name=name)


Method = TypeVar("Method", bound=Callable[..., Any])


def changes_files(method: Method) -> Method:
    """Mark a method of :class:`NcFileSystem` that writes, renames or removes files: afterwards
    (also when it fails half-way) the kept program texts and folder listings are dropped, so the
    next call sees the change whatever the file system's time-stamp granularity."""

    @functools.wraps(method)
    def changing(self: "NcFileSystem", *args: Any, **kwargs: Any) -> Any:
        try:
            return method(self, *args, **kwargs)
        finally:
            self.forget_kept_files()

    return cast(Method, changing)


class NcFileSystem:
    """The NC file system below ``root``; creates its directories when missing.

    ``root`` and its directories MPF, SPF and WKS are never links: an entry of
    another kind in their place is set aside as ``<name>.bad-<n>`` and a new
    empty folder used (:func:`nck.regular_files.plain_directory`);
    :attr:`folders_set_aside` lists ``(folder, where it was kept)`` for the report.
    """

    def __init__(self, root: Path | str) -> None:
        self.root = Path(root)
        self._root_text = str(self.root)  # the root for look-ups on plain strings (_disk_listed)
        self.folders_set_aside: list[tuple[Path, Path]] = []
        for folder in (self.root, *(self.root / d for d in DIRECTORIES)):
            kept = plain_directory(folder)
            if kept is not None:
                self.folders_set_aside.append((folder, kept))
        for directory in DIRECTORIES:
            remove_stale_temp_files(self.root / directory)
        self._in_use: set[str] = set()
        self._texts = FileTexts()  # program texts for the interpreter's calls, kept while unchanged
        self._folders = FolderNames()  # and the folders' names for their look-ups
        #: Returns the paths or file names of the programs in use (selected/running).
        self.in_use_check: Callable[[], Iterable[str]] = lambda: self._in_use

    def forget_kept_files(self) -> None:
        """Drop the program texts and folder listings kept for the interpreter's look-ups."""
        self._texts.clear()
        self._folders.clear()

    # ------------------------------------------------------------------ paths
    def canonical(self, path: str) -> str:
        """Return the canonical form of a program/directory path, or raise bad_path."""
        parts = [p for p in path.strip().replace("\\", "/").upper().split("/") if p]
        if len(parts) == 1 and parts[0] not in DIRECTORIES:
            _, ext = split_file_name(parts[0])
            if ext == WORKPIECE_SUFFIX:
                parts = ["WKS", parts[0]]
            else:
                parts = [ext, parts[0]]
        if not parts or parts[0] not in DIRECTORIES:
            raise StorageError("storage_not_nc_path", path=path)
        if len(parts) == 1:
            return parts[0]
        stem, ext = split_file_name(parts[1])
        if parts[0] in PROGRAM_TYPES:
            if len(parts) != 2 or ext != parts[0]:
                raise StorageError("storage_wrong_directory", path=path, ext=ext, directory=parts[0])
        else:
            if ext != WORKPIECE_SUFFIX:
                raise StorageError("storage_wks_workpieces_only", path=path)
            if len(parts) == 3:
                _, inner = split_file_name(parts[2])
                if inner not in PROGRAM_TYPES:
                    raise StorageError("storage_workpiece_programs_only", path=path)
            elif len(parts) > 3:
                raise StorageError("storage_too_many_levels", path=path)
        return "/".join(parts)

    def _disk(self, canonical: str) -> Path:
        """The file on disk for a canonical path (matching names case-insensitively).

        Raises StorageError ``odd`` when a folder on the way is not a folder of its
        own (a link to one, a pipe, a file): nothing is read or written through it.
        """
        current = self.root
        for part in canonical.split("/"):
            if current != self.root and os.path.lexists(current) and not is_plain_directory(current):
                raise StorageError("storage_not_nc_folder", path=current.name)
            candidate = current / part
            if not candidate.exists() and current.is_dir():
                for existing in current.iterdir():
                    if existing.name.upper() == part:
                        candidate = existing
                        break
            current = candidate
        return current

    def _disk_listed(self, canonical: str) -> str:
        """:meth:`_disk` for look-ups, on plain strings: a folder's names come from its kept
        listing (:class:`nck.file_texts.FolderNames`; OSError when a folder on the way is none)."""
        root = self._root_text
        current = root
        for part in canonical.split("/"):
            if current != root:
                try:
                    status = os.lstat(current)
                except (OSError, ValueError):
                    pass  # not there: the listing below raises
                else:
                    if not S_ISDIR(status.st_mode):
                        raise StorageError("storage_not_nc_folder", path=os.path.basename(current))
            candidate = os.path.join(current, part)
            same = self._folders.named(current).get(part, ())
            if same and candidate not in same:
                candidate = same[0]
            current = candidate
        return current

    def _entry(self, canonical: str) -> ProgramEntry:
        disk = self._disk(canonical)
        stat = disk.lstat()
        name = canonical.rpartition("/")[2]
        kind = name.rpartition(".")[2]
        size = stat.st_size if kind != WORKPIECE_SUFFIX else sum(
            p.lstat().st_size for p in disk.iterdir() if is_regular_file(p)
        )
        return ProgramEntry(canonical, name, kind, size, stat.st_mtime_ns)

    # ----------------------------------------------------------------- in use
    def set_in_use(self, paths: Iterable[str]) -> None:
        """Declare the programs in use (for a simple owner; see :attr:`in_use_check`)."""
        self._in_use = {p.upper() for p in paths}

    def is_in_use(self, path: str) -> bool:
        """True when the program (or, for a workpiece, any program in it) is in use."""
        canonical = self.canonical(path)
        name = canonical.rpartition("/")[2]
        for used in self.in_use_check():
            used_upper = used.strip().replace("\\", "/").upper()
            if used_upper in (canonical, name):
                return True
            if canonical.endswith("." + WORKPIECE_SUFFIX) and used_upper.startswith(canonical + "/"):
                return True
        return False

    def _refuse_in_use(self, path: str, key: str) -> None:
        if self.is_in_use(path):
            raise StorageError(key, path=path)

    # ---------------------------------------------------------------- listing
    def exists(self, path: str) -> bool:
        """True when the program or directory exists."""
        return self._disk(self.canonical(path)).exists()

    def list_directory(self, directory: str = "MPF") -> list[ProgramEntry]:
        """The programs (or, for ``WKS``, the workpieces) of one directory, sorted by name."""
        return self.scan_directory(directory)[0]

    def scan_directory(self, directory: str = "MPF") -> tuple[list[ProgramEntry], list[str]]:
        """The entries of one directory sorted by name, and the odd ones skipped.

        An odd entry has the name of a program or workpiece but is of the wrong
        kind: a link (even to a program), a FIFO, a device, a file named like a
        workpiece or a folder named like a program. It is left out of the list
        and never opened; its file name is returned so that it can be reported.
        Files with other names (temporary files, foreign files) are ignored.
        """
        canonical = self.canonical(directory)
        disk = self._disk(canonical)
        if not is_plain_directory(disk):
            if os.path.lexists(disk):
                raise StorageError("storage_not_nc_folder", path=canonical)
            raise StorageError("storage_does_not_exist", path=directory)
        entries, odd = [], []
        for item in disk.iterdir():
            try:
                child = self.canonical(f"{canonical}/{item.name}")
            except StorageError:
                continue  # not an NC file (temp files, foreign files)
            wanted = is_plain_directory if child.endswith("." + WORKPIECE_SUFFIX) else is_regular_file
            try:
                if not wanted(item):
                    raise FileNotFoundError(item)
                entries.append(self._entry(child))
            except OSError:  # of the wrong kind, or gone meanwhile
                odd.append(item.name)
        return sorted(entries, key=lambda e: e.name), sorted(odd)

    def all_programs(self) -> list[ProgramEntry]:
        """Every MPF and SPF file, workpieces included."""
        entries = self.list_directory("MPF") + self.list_directory("SPF")
        for workpiece in self.list_directory("WKS"):
            entries += self.list_directory(workpiece.path)
        return entries

    # ---------------------------------------------------------- read / write
    def read_bytes(self, path: str) -> bytes:
        """The raw content of a program (a regular file of at most MAX_IMPORT_BYTES)."""
        disk = self._disk(self.canonical(path))
        if not os.path.lexists(disk):
            raise StorageError("storage_does_not_exist", path=path)
        try:
            return read_regular_bytes(disk, MAX_IMPORT_BYTES)
        except OSError as exc:
            raise StorageError.from_os_error(exc, path, failed="os_read_failed") from exc

    def program_text(self, canonical: str) -> str | None:
        """The text of the program at a canonical path for the interpreter (undecodable bytes
        replaced), None when no regular file is there; read again only when the file changed
        (:class:`nck.file_texts.FileTexts`). Raises StorageError (odd folder) or OSError."""
        disk = self._disk_listed(canonical)
        try:
            status = os.lstat(disk)
        except FileNotFoundError:
            return None
        if not S_ISREG(status.st_mode):
            return None  # a link, folder or pipe is never read
        return self._texts.text(disk, status, lambda: read_regular_bytes(disk, MAX_IMPORT_BYTES).decode(
            "utf-8", errors="replace"))

    def read(self, path: str) -> str:
        """The text of a program (raise not_text when it is binary or not UTF-8)."""
        data = self.read_bytes(path)
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise StorageError("storage_not_utf8", path=path) from exc
        if "\x00" in text:
            raise StorageError("storage_binary", path=path)
        return text

    def open_program(self, path: str) -> OpenedProgram:
        """Open a program for the editor.

        Binary or non-UTF-8 files open read-only (undecodable bytes replaced), with a
        message; so does a program in use.
        """
        canonical = self.canonical(path)
        try:
            text = self.read(canonical)
        except StorageError as exc:
            if exc.code != "not_text":
                raise
            shown = self.read_bytes(canonical).decode("utf-8", errors="replace").replace("\x00", "?")
            return OpenedProgram(canonical, shown, True, f"{exc} — opened read-only")
        if self.is_in_use(canonical):
            return OpenedProgram(canonical, text, True, f"{canonical} is in use — opened read-only")
        return OpenedProgram(canonical, text, False)

    def save(self, path: str, text: str) -> ProgramEntry:
        """Write a program (new or existing) atomically; refused while it is in use."""
        return self.save_bytes(path, text.encode("utf-8"))

    @changes_files
    def save_bytes(self, path: str, data: bytes) -> ProgramEntry:
        """:meth:`save` of raw content (a program kept as it came, e.g. from an archive)."""
        canonical = self.canonical(path)
        check_program_size(canonical, data)
        if "/" not in canonical or canonical.endswith("." + WORKPIECE_SUFFIX):
            raise StorageError("storage_not_a_program", path=path)
        self._refuse_in_use(canonical, "storage_in_use_changed")
        self._require_parent(canonical)
        try:
            atomic_write_bytes(self._disk(canonical), data)
        except OSError as exc:
            raise StorageError.from_os_error(exc, canonical) from exc
        return self._entry(canonical)

    def create(self, path: str, text: str = "") -> ProgramEntry:
        """Create a new program (refused when the name exists)."""
        canonical = self.canonical(path)
        if self.exists(canonical):
            raise StorageError("storage_exists", path=canonical)
        return self.save(canonical, text)

    @changes_files
    def create_workpiece(self, name: str, with_program: bool = True) -> ProgramEntry:
        """Create ``WKS/<NAME>.WPD`` (and its main program ``<NAME>.MPF``)."""
        stem = validate_name(name.upper().removesuffix("." + WORKPIECE_SUFFIX))
        canonical = f"WKS/{stem}.{WORKPIECE_SUFFIX}"
        if self.exists(canonical):
            raise StorageError("storage_exists", path=canonical)
        try:
            self._disk(canonical).mkdir(parents=True)
        except OSError as exc:
            raise StorageError.from_os_error(exc, canonical) from exc
        if with_program:
            self.save(f"{canonical}/{stem}.MPF", "")
        return self._entry(canonical)

    def _require_parent(self, canonical: str) -> None:
        parent = canonical.rpartition("/")[0]
        if not self._disk(parent).is_dir():
            raise StorageError("storage_does_not_exist", path=parent)

    # ------------------------------------------------- copy / rename / delete
    def _target(self, source: str, target: str) -> str:
        """The canonical target path; a directory target keeps the source's file name."""
        target_canonical = self.canonical(target)
        name = source.rpartition("/")[2]
        if target_canonical in DIRECTORIES or (
            target_canonical.endswith("." + WORKPIECE_SUFFIX) and not source.endswith("." + WORKPIECE_SUFFIX)
        ):
            target_canonical = self.canonical(f"{target_canonical}/{name}")
        return target_canonical

    @changes_files
    def copy(self, source: str, target: str, overwrite: bool = False) -> ProgramEntry:
        """Copy a program (or workpiece) to a new path or into a directory."""
        src = self.canonical(source)
        if not self.exists(src):
            raise StorageError("storage_does_not_exist", path=src)
        dst = self._target(src, target)
        if dst == src:
            raise StorageError("storage_copy_onto_itself", path=src)
        if self.exists(dst):
            if not overwrite:
                raise StorageError("storage_exists", path=dst)
            self._refuse_in_use(dst, "storage_in_use_overwritten")
        if src.endswith("." + WORKPIECE_SUFFIX):
            if self.exists(dst):
                raise StorageError("storage_exists", path=dst)
            try:
                copy_regular_tree(self._disk(src), self._disk(dst), MAX_IMPORT_BYTES)
            except OSError as exc:
                shutil.rmtree(self._disk(dst), ignore_errors=True)
                raise StorageError.from_os_error(exc, dst) from exc
            return self._entry(dst)
        self._require_parent(dst)
        try:
            atomic_write_bytes(self._disk(dst), self.read_bytes(src))
        except OSError as exc:
            raise StorageError.from_os_error(exc, dst) from exc
        return self._entry(dst)

    @changes_files
    def rename(self, source: str, new_name: str) -> ProgramEntry:
        """Rename a program or workpiece within its directory (refused while in use)."""
        src = self.canonical(source)
        if not self.exists(src):
            raise StorageError("storage_does_not_exist", path=src)
        self._refuse_in_use(src, "storage_in_use_renamed")
        parent, _, old_name = src.rpartition("/")
        new_file = new_name.strip().upper()
        if "." not in new_file:
            new_file = f"{new_file}.{old_name.rpartition('.')[2]}"
        dst = self.canonical(f"{parent}/{new_file}")
        if dst != src and self.exists(dst):
            raise StorageError("storage_exists", path=dst)
        try:
            os.replace(self._disk(src), self._disk(parent) / dst.rpartition("/")[2])
        except OSError as exc:
            raise StorageError.from_os_error(exc, src) from exc
        return self._entry(dst)

    @changes_files
    def delete(self, path: str) -> None:
        """Delete a program or a whole workpiece (refused while in use)."""
        canonical = self.canonical(path)
        if canonical in DIRECTORIES:
            raise StorageError("storage_directory_not_deletable", path=canonical)
        disk = self._disk(canonical)
        if not os.path.lexists(disk):
            raise StorageError("storage_does_not_exist", path=canonical)
        self._refuse_in_use(canonical, "storage_in_use_deleted")
        try:
            if is_plain_directory(disk):
                shutil.rmtree(disk)
            else:
                disk.unlink()  # a file, or a link itself (never what it points to)
        except OSError as exc:
            raise StorageError.from_os_error(exc, canonical) from exc

    # ------------------------------------------------------- import / export
    @changes_files
    def import_file(self, local_path: Path | str, directory: str = "MPF",
                    name: str | None = None, overwrite: bool = False) -> ProgramEntry:
        """Copy a file from the local file system into ``directory``.

        Without ``name`` the local file name is used (its extension, or the
        directory's type when it has none of MPF/SPF).
        """
        local = Path(local_path)
        if not local.is_file():
            raise StorageError("storage_not_a_file", path=local)
        if local.stat().st_size > MAX_IMPORT_BYTES:
            raise StorageError("storage_too_large", name=local)
        target = self.import_target(local, directory, name)
        if self.exists(target):
            if not overwrite:
                raise StorageError("storage_exists", path=target)
            self._refuse_in_use(target, "storage_in_use_overwritten")
        try:
            atomic_write_bytes(self._disk(target), local.read_bytes())
        except OSError as exc:
            raise StorageError.from_os_error(exc, target) from exc
        return self._entry(target)

    def import_target(self, local_path: Path | str, directory: str = "MPF", name: str | None = None) -> str:
        """The canonical path :meth:`import_file` writes a local file to."""
        folder = self.canonical(directory)
        file_name = (name or Path(local_path).name).strip().upper()
        stem, dot, ext = file_name.rpartition(".")
        if not dot or ext not in PROGRAM_TYPES:
            default_ext = folder if folder in PROGRAM_TYPES else "MPF"
            file_name = f"{file_name if not dot else stem}.{default_ext}"
        if folder in PROGRAM_TYPES:
            file_name = f"{file_name.rpartition('.')[0]}.{folder}"
        return self.canonical(f"{folder}/{file_name}")

    def keep_backup(self, path: str) -> ProgramEntry:
        """Copy a program to the first free ``<name>_OLD<n>`` beside it (before it is replaced)."""
        canonical = self.canonical(path)
        folder, _, file_name = canonical.rpartition("/")
        stem, _, ext = file_name.rpartition(".")
        number = 1
        while True:
            suffix = f"_OLD{number}"
            backup = f"{folder}/{stem[:NAME_MAX_CHARS - len(suffix)]}{suffix}.{ext}"
            if not self.exists(backup):
                return self.copy(canonical, backup)
            number += 1

    def export_file(self, path: str, local_path: Path | str, replace: bool = False) -> Path:
        """Copy a program to the local file system (atomically); return the file written.

        ``local_path`` may be a directory, or a text ending in a slash (a folder, made if
        missing): the program's file name is used there. An existing file is replaced only with
        ``replace`` (else ``ExportTargetExists`` is raised: ask first); a link or pipe there is
        refused, never written through.
        """
        canonical = self.canonical(path)
        local = Path(local_path)
        if local.is_dir() or str(local_path).endswith(("/", os.sep)):
            local = local / canonical.rpartition("/")[2]
        try:
            write_export(local, self.read_bytes(canonical), replace=replace)
        except ExportTargetExists:
            raise
        except NotAFolder as exc:  # the file in the way, not the export, is named
            raise StorageError.from_os_error(exc, exc.filename) from exc
        except OSError as exc:
            raise StorageError.from_os_error(exc, local) from exc
        return local

    # ---------------------------------------------------------- ProgramSource
    def read_program(self, name: str) -> tuple[str, str] | None:
        """``ProgramSource``: the text of a program by name, or None when absent.

        A name with an extension is looked up in its directory; without one as
        ``.SPF`` first, then ``.MPF``. A full path (``WKS/X.WPD/X.MPF``) is read as is.
        """
        return self.program_source().read_program(name)

    def program_source(self, context: str | None = None) -> "ScopedProgramSource":
        """A ``ProgramSource`` that searches the workpiece of ``context`` first."""
        return ScopedProgramSource(self, context)

    # --------------------------------------------------------------- samples
    @changes_files
    def install_samples(self, source: Path | str, force: bool = False,
                        wanted: Callable[[str], bool] | None = None) -> list[str]:
        """Copy the training programs of ``source`` into an NC file system once.

        ``*.MPF``/``*.SPF`` files go to MPF/SPF (from any sub-folder), ``*.WPD``
        folders to WKS. Existing programs are never overwritten, and after the
        first installation (a mark file in the root) nothing is installed again
        unless ``force``. ``wanted`` (given the upper-case file name) leaves out
        programs of another machine. Returns the paths installed.
        """
        mark = self.root / SAMPLES_MARK
        if mark.exists() and not force:
            return []
        installed: list[str] = []
        source = Path(source)
        if source.is_dir():
            for item in sorted(source.rglob("*")):
                upper = item.name.upper()
                try:
                    if item.is_dir() and upper.endswith("." + WORKPIECE_SUFFIX):
                        target = self.canonical(f"WKS/{upper}")
                        if not self.exists(target):
                            self._disk(target).mkdir(parents=True)
                            installed.append(target)
                    elif (item.is_file() and upper.rpartition(".")[2] in PROGRAM_TYPES
                          and (wanted is None or wanted(upper))):
                        parent = item.parent.name.upper()
                        folder = f"WKS/{parent}" if parent.endswith("." + WORKPIECE_SUFFIX) else ""
                        target = self.canonical(f"{folder}/{upper}" if folder else upper)
                        if not self.exists(target):
                            atomic_write_bytes(self._disk(target), item.read_bytes())
                            installed.append(target)
                except StorageError:
                    continue  # a sample with a name the control cannot hold
        atomic_write_bytes(mark, "\n".join(installed).encode("utf-8"))
        return installed


class ScopedProgramSource:
    """Looks programs up in one workpiece first, then in SPF and MPF."""

    def __init__(self, fs: NcFileSystem, context: str | None = None) -> None:
        self.fs = fs
        self.workpiece: str | None = None
        if context:
            try:
                canonical = fs.canonical(context)
            except StorageError:
                canonical = ""
            if canonical.startswith("WKS/"):
                self.workpiece = "/".join(canonical.split("/")[:2])

    def read_program(self, name: str) -> tuple[str, str] | None:
        """``ProgramSource.read_program`` (see :meth:`NcFileSystem.read_program`)."""
        upper = name.strip().replace("\\", "/").upper()
        if "/" in upper:
            candidates = [upper]
        else:
            stem, dot, ext = upper.rpartition(".")
            names = [upper] if dot and ext in PROGRAM_TYPES else [f"{upper}.SPF", f"{upper}.MPF"]
            candidates = []
            for file_name in names:
                if self.workpiece:
                    candidates.append(f"{self.workpiece}/{file_name}")
                candidates.append(file_name)
        for candidate in candidates:
            try:
                canonical = self.fs.canonical(candidate)
                text = self.fs.program_text(canonical)
            except (StorageError, OSError):
                continue
            if text is not None:
                return canonical.rpartition("/")[2], text
        return None
