"""Crash-safe file writes: the file on disk is always the old or the new content.

A write goes to a temporary file in the same directory, is flushed and
``fsync``-ed, and then renamed over the target with :func:`os.replace` (atomic
on POSIX and Windows); finally the directory itself is synced so that the
rename survives a power cut. A crash at any point leaves either the complete
old file or the complete new one, never a torn mixture.

With ``backup=True`` the previous content is kept as one backup generation,
``<name>.bak``, before the new content takes its place. The backup is created
atomically too (hard link to the old file, or a copy when the file system has
no hard links).
"""

from __future__ import annotations

import os
import shutil
import stat
from contextlib import contextmanager
from pathlib import Path
from typing import BinaryIO, Iterator

TEMP_MARK = ".tmp-"
BACKUP_SUFFIX = ".bak"


def backup_path(path: Path) -> Path:
    """Return the path of the backup generation of ``path`` (``<name>.bak``)."""
    return path.with_name(path.name + BACKUP_SUFFIX)


def _temp_path(path: Path) -> Path:
    """Return a fresh temporary name next to ``path`` (hidden, unique)."""
    return path.with_name(f".{path.name}{TEMP_MARK}{os.getpid()}-{os.urandom(4).hex()}")


def _is_regular_file(path: Path) -> bool:
    try:
        return stat.S_ISREG(os.lstat(path).st_mode)
    except OSError:
        return False


def fsync_directory(directory: Path) -> None:
    """Make a rename inside ``directory`` durable (no-op where directories cannot be opened)."""
    try:
        handle = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(handle)
    except OSError:
        pass
    finally:
        os.close(handle)


def _write_synced(path: Path, data: bytes, mode: int = 0o666) -> None:
    """Create ``path`` (permissions ``mode`` less the umask) with ``data`` and flush it to the disk."""
    with open(os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, mode), "wb") as handle:
        handle.write(data)
        handle.flush()
        os.fsync(handle.fileno())


def _make_backup(path: Path) -> None:
    """Keep the current content of ``path`` as ``<name>.bak`` (atomically)."""
    target = backup_path(path)
    temp = _temp_path(target)
    try:
        try:
            os.link(path, temp)
        except OSError:
            shutil.copyfile(path, temp)
            with open(temp, "rb+") as handle:
                os.fsync(handle.fileno())
        os.replace(temp, target)
    finally:
        if temp.exists():
            temp.unlink()


@contextmanager
def atomic_writer(path: Path | str) -> Iterator[BinaryIO]:
    """Stream the new content of ``path``; it replaces the old one when the block ends.

    For content too long to build in memory first (a run's segments). The
    stream writes a temporary file beside ``path``; at the end of the ``with``
    block it is synced and renamed over ``path`` — or removed when the block
    raised, leaving the old file as it was.
    """
    path = Path(path)
    temp = _temp_path(path)
    with _removed_on_failure(temp):
        with open(os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666), "wb") as handle:
            yield handle
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temp, path)
    fsync_directory(path.parent)


@contextmanager
def _removed_on_failure(temp: Path) -> Iterator[None]:
    """Remove ``temp`` when the block raises (anything, also KeyboardInterrupt), then re-raise."""
    try:
        yield
    except BaseException:
        try:
            temp.unlink()
        except OSError:
            pass
        raise


def atomic_write_bytes(path: Path | str, data: bytes, *, backup: bool = False,
                       private: bool = False) -> None:
    """Replace the content of ``path`` with ``data`` atomically.

    Args:
        path: the file to write; its directory is created when missing.
        data: the complete new content.
        backup: keep the previous content as ``<name>.bak`` first.
        private: readable and writable by the owner only (file and backup, mode 0600).

    On any failure the temporary file is removed and the old file is left
    untouched; the exception propagates (an ``OSError``).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    temp = _temp_path(path)
    with _removed_on_failure(temp):
        _write_synced(temp, data, 0o600 if private else 0o666)
        if backup and _is_regular_file(path):  # a link's target is never copied into the backup
            _make_backup(path)
            if private:
                os.chmod(backup_path(path), 0o600)
        os.replace(temp, path)
    fsync_directory(path.parent)


def atomic_write_text(
    path: Path | str, text: str, *, backup: bool = False, encoding: str = "utf-8", private: bool = False
) -> None:
    """Replace the content of ``path`` with ``text`` atomically (see :func:`atomic_write_bytes`)."""
    atomic_write_bytes(path, text.encode(encoding), backup=backup, private=private)


def remove_stale_temp_files(directory: Path | str) -> list[Path]:
    """Delete temporary files left behind by writers that crashed; return what was removed."""
    removed: list[Path] = []
    directory = Path(directory)
    if not directory.is_dir():
        return removed
    for candidate in directory.iterdir():
        if candidate.name.startswith(".") and TEMP_MARK in candidate.name and candidate.is_file():
            try:
                candidate.unlink()
                removed.append(candidate)
            except OSError:
                pass
    return removed
