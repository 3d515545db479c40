"""What the Program manager and the Program editor need from the NC file system.

Not a screen: a small adapter shared by ``screens/program_manager.py`` and
``screens/program.py`` (a screen never imports another screen). It turns the
kernel's NC file system (``nck.storage``) into the operations the two screens
offer, with NC names such as ``/MPF/PART1.MPF``, ``/SPF/CONTOUR.SPF`` and
``/WKS/SHAFT/SHAFT.MPF``.

Where the app has no NC file system (tests with a bare kernel), a directory
backend with the same layout below a data directory is used; every write goes
through :mod:`nck.atomic` (temp file, fsync, rename).
"""

from __future__ import annotations

import re
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from nck.atomic import atomic_write_bytes

DIRECTORIES: tuple[tuple[str, str], ...] = (
    ("MPF", "Part programs"),
    ("SPF", "Subprograms"),
    ("WKS", "Workpieces"),
)
"""The NC directories in the order of the manager's tree: id and title."""

KIND_OF_SUFFIX = {".MPF": "MPF", ".SPF": "SPF"}
_NAME = re.compile(r"^[A-Z_][A-Z0-9_]{0,23}$")


class ProgramFileError(Exception):
    """A file operation was refused; the message says why (shown on the dialog line)."""


@dataclass(frozen=True, slots=True)
class ProgramEntry:
    """One line of the manager's list.

    Attributes:
        path: NC name (``/MPF/PART1.MPF``; a workpiece folder is ``/WKS/SHAFT``).
        name: the file or folder name.
        kind: ``MPF``, ``SPF`` or ``WPD`` (workpiece folder).
        size: length in bytes (0 for folders).
        modified: modification time as text (``2026-11-22 05:40``), or "".
    """

    path: str
    name: str
    kind: str
    size: int
    modified: str


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


def validate_file_name(name: str, kinds: tuple[str, ...] = ("MPF", "SPF")) -> str:
    """Return the upper-case file name, or raise ProgramFileError saying what is wrong.

    A program name starts with a letter or underscore, holds letters, digits and
    underscores (at most 24), and ends in ``.MPF`` or ``.SPF``. Without a suffix
    ``.MPF`` is assumed.
    """
    candidate = name.strip().upper()
    if "." not in candidate:
        candidate += f".{kinds[0]}"
    stem, _, suffix = candidate.rpartition(".")
    if suffix not in kinds:
        raise ProgramFileError(f"'{name}': the type must be {' or '.join(kinds)}")
    if not _NAME.match(stem):
        raise ProgramFileError(
            f"'{name}': a name starts with a letter or _, has only letters, digits and _, at most 24"
        )
    return candidate


class _DirectoryBackend:
    """The NC directories as plain folders below ``root`` (``MPF/``, ``SPF/``, ``WKS/``)."""

    def __init__(self, root: Path) -> None:
        self.root = root
        for directory, _ in DIRECTORIES:
            (root / directory).mkdir(parents=True, exist_ok=True)

    def _path(self, nc_name: str) -> Path:
        parts = [p for p in nc_name.strip("/").split("/") if p]
        if not parts or parts[0] not in dict(DIRECTORIES) or any(p in (".", "..") for p in parts):
            raise ProgramFileError(f"{nc_name}: not a path of the NC file system")
        return self.root.joinpath(*parts)

    def list(self, directory: str) -> list[ProgramEntry]:
        import datetime

        folder = self._path(directory)
        entries = []
        if not folder.is_dir():
            return entries
        for child in sorted(folder.iterdir(), key=lambda p: p.name):
            if child.name.startswith("."):
                continue
            stat = child.stat()
            stamp = datetime.datetime.fromtimestamp(stat.st_mtime).strftime("%Y-%m-%d %H:%M")
            if child.is_dir():
                entries.append(ProgramEntry(f"{directory.rstrip('/')}/{child.name}", child.name, "WPD", 0, stamp))
            elif child.suffix.upper() in KIND_OF_SUFFIX:
                entries.append(ProgramEntry(f"{directory.rstrip('/')}/{child.name}", child.name,
                                            KIND_OF_SUFFIX[child.suffix.upper()], stat.st_size, stamp))
        return entries

    def read_bytes(self, nc_name: str) -> bytes:
        try:
            return self._path(nc_name).read_bytes()
        except FileNotFoundError:
            raise ProgramFileError(f"{nc_name} does not exist") from None

    def write_bytes(self, nc_name: str, data: bytes) -> None:
        atomic_write_bytes(self._path(nc_name), data)

    def exists(self, nc_name: str) -> bool:
        return self._path(nc_name).exists()

    def make_dir(self, nc_name: str) -> None:
        self._path(nc_name).mkdir(parents=True, exist_ok=False)

    def rename(self, nc_name: str, new_nc_name: str) -> None:
        self._path(nc_name).rename(self._path(new_nc_name))

    def delete(self, nc_name: str) -> None:
        path = self._path(nc_name)
        if path.is_dir():
            import shutil

            shutil.rmtree(path)
        else:
            path.unlink()

    def read_program(self, name: str) -> tuple[str, str] | None:
        key = name.upper().rsplit("/", 1)[-1]
        candidates = [key] if "." in key else [key + ".SPF", key + ".MPF"]
        for directory in ("SPF", "MPF"):
            for candidate in candidates:
                path = self.root / directory / candidate
                if path.is_file():
                    return candidate, decode_program(path.read_bytes())[0]
        for path in sorted((self.root / "WKS").glob("*/*")):
            if path.name.upper() in candidates and path.is_file():
                return path.name, decode_program(path.read_bytes())[0]
        return None


class ProgramFiles:
    """NC file operations for the program screens (one instance per app).

    Args:
        backend: the NC file system (``nck.storage``) or a directory backend.
        root: the NC data directory (the journal lives below it).
    """

    def __init__(self, backend: Any, root: Path) -> None:
        self.backend = backend
        self.root = root
        self.last_program: str | None = None
        self.pending_open: str | None = None

    @classmethod
    def of_app(cls, app: Any) -> ProgramFiles:
        """The instance of ``app`` (created on first use from its kernel's file system)."""
        existing = getattr(app, "_program_files", None)
        if isinstance(existing, ProgramFiles):
            return existing
        storage = None
        for owner in (app, getattr(getattr(app, "bridge", None), "nck", None)):
            for attr in ("storage", "nc_files", "programs"):
                candidate = getattr(owner, attr, None)
                if candidate is not None and hasattr(candidate, "list") and hasattr(candidate, "write_bytes"):
                    storage = candidate
                    break
            if storage is not None:
                break
        root = Path(getattr(storage, "root", "") or getattr(app, "data_dir", "") or "")
        if storage is None:
            if not str(root) or str(root) == ".":
                root = Path(tempfile.mkdtemp(prefix="nc-data-"))
            storage = _DirectoryBackend(root)
        files = cls(storage, root)
        app._program_files = files
        return files

    # -- names ---------------------------------------------------------------------------------
    @property
    def journal_dir(self) -> Path:
        """Where the editor journal lives."""
        return self.root / "hmi-journal"

    def display_name(self, nc_name: str) -> str:
        """The NC name as the screens show it (``/MPF/PART1.MPF``)."""
        return "/" + nc_name.strip("/")

    def select_name(self, nc_name: str) -> str:
        """The name the kernel's program selection takes (the file name)."""
        return nc_name.rsplit("/", 1)[-1]

    def remember_last(self, nc_name: str) -> None:
        """Note the program last opened in the editor (Alt+P opens it again)."""
        self.last_program = nc_name

    def request_open(self, nc_name: str) -> None:
        """Ask the editor to open ``nc_name`` when it is shown next (Program manager → Open)."""
        self.pending_open = nc_name

    def take_open_request(self) -> str | None:
        """The program the editor should open now (a request is taken once), else None."""
        pending, self.pending_open = self.pending_open, None
        return pending

    def program_source(self) -> Any:
        """A ProgramSource for subprogram calls during checks and simulation."""
        return self.backend if hasattr(self.backend, "read_program") else None

    # -- reading -------------------------------------------------------------------------------
    def list(self, directory: str) -> list[ProgramEntry]:
        """The entries of an NC directory (``/MPF``, ``/SPF``, ``/WKS``, ``/WKS/SHAFT``)."""
        return self.backend.list(directory)

    def read_bytes(self, nc_name: str) -> bytes:
        """The raw content of a program."""
        return self.backend.read_bytes(nc_name)

    def exists(self, nc_name: str) -> bool:
        """True when the file or folder exists."""
        return self.backend.exists(nc_name)

    # -- writing -------------------------------------------------------------------------------
    def write_text(self, nc_name: str, text: str) -> None:
        """Save a program atomically."""
        self.backend.write_bytes(nc_name, text.encode("utf-8"))

    def create(self, directory: str, name: str) -> str:
        """Create an empty program (or workpiece folder) in ``directory``; return its NC name."""
        if directory == "/WKS":
            folder = validate_file_name(name + ".MPF").rsplit(".", 1)[0] if "." not in name else None
            if folder is None:
                raise ProgramFileError("a workpiece is a folder: give a name without a type")
            target = f"/WKS/{folder}"
            self._must_not_exist(target)
            self.backend.make_dir(target)
            return target
        kinds = ("SPF", "MPF") if directory == "/SPF" else ("MPF", "SPF")
        target = f"{directory}/{validate_file_name(name, kinds)}"
        self._must_not_exist(target)
        self.backend.write_bytes(target, f"; {target.rsplit('/', 1)[-1]}\n".encode())
        return target

    def _must_not_exist(self, nc_name: str) -> None:
        if self.exists(nc_name):
            raise ProgramFileError(f"{nc_name} already exists")

    def copy(self, nc_name: str, directory: str) -> str:
        """Paste a copy of ``nc_name`` into ``directory`` (``_1`` … appended when taken)."""
        data = self.read_bytes(nc_name)
        base = nc_name.rsplit("/", 1)[-1]
        stem, _, suffix = base.rpartition(".")
        target = f"{directory}/{base}"
        number = 1
        while self.exists(target):
            target = f"{directory}/{stem[:20]}_{number}.{suffix}"
            number += 1
        self.backend.write_bytes(target, data)
        return target

    def rename(self, nc_name: str, new_name: str, in_use: set[str]) -> str:
        """Rename a program; refused for the program in execution or an existing name."""
        self._not_in_use(nc_name, in_use, "renamed")
        directory, _, base = nc_name.rpartition("/")
        kind = base.rpartition(".")[2]
        target = f"{directory}/{validate_file_name(new_name, (kind,))}"
        if target.upper() == nc_name.upper():
            return nc_name
        self._must_not_exist(target)
        self.backend.rename(nc_name, target)
        return target

    def delete(self, nc_name: str, in_use: set[str]) -> None:
        """Delete a program or workpiece; refused for the program in execution."""
        self._not_in_use(nc_name, in_use, "deleted")
        self.backend.delete(nc_name)

    @staticmethod
    def _not_in_use(nc_name: str, in_use: set[str], verb: str) -> None:
        names = {n.upper().rsplit("/", 1)[-1] for n in in_use}
        if nc_name.upper().rsplit("/", 1)[-1] in names:
            raise ProgramFileError(f"{nc_name} is being executed and cannot be {verb}")

    def import_file(self, local_path: str, directory: str) -> str:
        """Copy a file of the PC into an NC directory; return its NC name."""
        source = Path(local_path).expanduser()
        if not source.is_file():
            raise ProgramFileError(f"{local_path}: no such file")
        kinds = ("SPF", "MPF") if directory == "/SPF" else ("MPF", "SPF")
        target = f"{directory}/{validate_file_name(source.name, kinds)}"
        self._must_not_exist(target)
        self.backend.write_bytes(target, source.read_bytes())
        return target

    def export_file(self, nc_name: str, local_path: str) -> Path:
        """Write a copy of a program to a path of the PC (a folder takes the file name)."""
        target = Path(local_path).expanduser()
        if target.is_dir():
            target = target / nc_name.rsplit("/", 1)[-1]
        atomic_write_bytes(target, self.read_bytes(nc_name))
        return target
