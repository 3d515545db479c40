"""Only regular files: never read or write through a link, a pipe or a device.

Everything the program keeps (lock, retained data, programs) or writes for the
operator (exports) is a regular file in its place. An entry of another kind
with such a name — a symbolic link pointing out of the data directory, a FIFO,
a device — is never opened through: a read would block on a FIFO or never end
on ``/dev/zero``, a write would land in a file somewhere else. The helpers here
check the entry itself (``lstat``, ``O_NOFOLLOW``) and raise
:class:`NotARegularFile` instead; reads are bounded in size
(:class:`FileTooLarge`). Both are ``OSError`` subclasses, so code that already
reports I/O failures reports these too.
"""

from __future__ import annotations

import errno
import io
import os
import shutil
import stat
from contextlib import contextmanager
from pathlib import Path
from typing import Callable, Iterator, TextIO

from nck.atomic import atomic_write_bytes, atomic_writer

_NO_FOLLOW = getattr(os, "O_NOFOLLOW", 0)
_NON_BLOCKING = getattr(os, "O_NONBLOCK", 0)
_CHUNK_BYTES = 1 << 20


class NotARegularFile(OSError):
    """The entry is a link, FIFO, device or directory where a regular file is expected."""

    def __init__(self, path: Path | str) -> None:
        super().__init__(errno.EINVAL, "not a regular file (a link, pipe or device)", str(path))

    def __str__(self) -> str:
        return f"{self.filename}: {self.strerror}"


class NotAFolder(OSError):
    """A file (or a link, pipe, device) where a path needs a folder: nothing can be written below it."""

    def __init__(self, path: Path | str) -> None:
        super().__init__(errno.ENOTDIR, "a file, not a folder", str(path))

    def __str__(self) -> str:
        return f"{self.filename}: {self.strerror}"


class FileTooLarge(OSError):
    """The file (or the files copied together) is larger than the reader accepts."""

    def __init__(self, path: Path | str, limit_bytes: int) -> None:
        self.limit_bytes = limit_bytes
        size = f"{limit_bytes >> 20} MB" if limit_bytes >= 1 << 20 else f"{limit_bytes} bytes"
        super().__init__(errno.EFBIG, f"larger than {size}", str(path))

    def __str__(self) -> str:
        return f"{self.filename}: {self.strerror}"


def is_regular_file(path: Path | str) -> bool:
    """True when ``path`` itself (not a link's target) is a regular file."""
    try:
        return stat.S_ISREG(os.lstat(path).st_mode)
    except OSError:
        return False


def is_plain_directory(path: Path | str) -> bool:
    """True when ``path`` itself (not a link's target) is a directory."""
    try:
        return stat.S_ISDIR(os.lstat(path).st_mode)
    except OSError:
        return False


def set_aside(path: Path) -> Path:
    """Rename the entry ``path`` (itself: a link is not followed) to ``<name>.bad-<n>``; return it.

    ``n`` is the first number free; what was there stays as it was, for the operator to look at.
    """
    n = 1
    while True:
        target = path.with_name(f"{path.name}.bad-{n}")
        if not os.path.lexists(target):
            path.rename(target)
            return target
        n += 1


def plain_directory(path: Path) -> Path | None:
    """Make ``path`` a directory of its own; return where an entry of another kind was kept.

    A folder the program fills and lists must not be a link (its writes would
    land elsewhere), a FIFO or a file: such an entry is set aside
    (:func:`set_aside`) and a new, empty directory takes its place. Returns
    None when ``path`` was a directory already or did not exist. The parent must
    be a plain directory itself (call this from the top down).
    """
    if is_plain_directory(path):
        return None
    kept = set_aside(path) if os.path.lexists(path) else None
    path.mkdir(parents=True, exist_ok=True)
    if not is_plain_directory(path):  # replaced again meanwhile
        raise NotARegularFile(path)
    return kept


def open_regular(path: Path | str, flags: int, mode: int = 0o644, *, follow_links: bool = False) -> int:
    """``os.open`` that refuses links, FIFOs and devices; return the descriptor.

    The file is opened without following a final symbolic link (unless
    ``follow_links``: for a file the operator names to be read) and without
    blocking on a FIFO; its kind is checked on the open descriptor, so a swap
    between check and use is impossible.
    """
    try:
        handle = os.open(path, flags | (0 if follow_links else _NO_FOLLOW) | _NON_BLOCKING, mode)
    except OSError as exc:
        if exc.errno == errno.ELOOP:  # the final component is a symbolic link
            raise NotARegularFile(path) from None
        raise
    try:
        if not stat.S_ISREG(os.fstat(handle).st_mode):
            raise NotARegularFile(path)
        if _NON_BLOCKING:
            os.set_blocking(handle, True)
    except BaseException:
        os.close(handle)
        raise
    return handle


def read_regular_bytes(path: Path | str, limit_bytes: int, *, follow_links: bool = False) -> bytes:
    """The content of the regular file ``path``, at most ``limit_bytes`` long.

    Raises :class:`NotARegularFile`, :class:`FileTooLarge` or another ``OSError``.
    ``follow_links`` reads through a link to a regular file (see :func:`open_regular`).
    """
    handle = open_regular(path, os.O_RDONLY, follow_links=follow_links)
    with os.fdopen(handle, "rb") as stream:
        data = stream.read(limit_bytes + 1)
    if len(data) > limit_bytes:
        raise FileTooLarge(path, limit_bytes)
    return data


def copy_regular_tree(source: Path, target: Path, limit_bytes: int,
                      skip_name: Callable[[str], bool] | None = None) -> list[Path]:
    """Copy the directories and regular files below ``source`` to ``target`` (created).

    ``source`` itself must be a directory, not a link to one (else
    :class:`NotARegularFile`). Links, FIFOs, sockets and devices below it are
    not copied (never followed); neither
    is anything past ``limit_bytes`` in total (:class:`FileTooLarge` is raised,
    the caller removes ``target``). ``skip_name`` leaves out entries by name
    (e.g. temporary files). Returns the entries left out because of their kind.
    """
    if not is_plain_directory(source):
        raise NotARegularFile(source)
    skipped: list[Path] = []
    copied_bytes = 0
    target.mkdir(parents=True)
    pending = [(source, target)]
    while pending:
        folder, copy = pending.pop()
        for entry in sorted(folder.iterdir()):
            if skip_name is not None and skip_name(entry.name):
                continue
            if is_plain_directory(entry):
                (copy / entry.name).mkdir()
                pending.append((entry, copy / entry.name))
                continue
            try:
                handle = open_regular(entry, os.O_RDONLY)
            except NotARegularFile:
                skipped.append(entry)
                continue
            with os.fdopen(handle, "rb") as stream, open(copy / entry.name, "xb") as out:
                while chunk := stream.read(_CHUNK_BYTES):
                    copied_bytes += len(chunk)
                    if copied_bytes > limit_bytes:
                        raise FileTooLarge(source, limit_bytes)
                    out.write(chunk)
            shutil.copystat(entry, copy / entry.name, follow_symlinks=False)
    return skipped


class ExportTargetExists(FileExistsError):
    """The export's file is already there: ask the operator before replacing it. Its own class,
    because any other ``FileExistsError`` (a file where a folder of the path should be) is a
    failure to report, not a question."""


def check_export_target(path: Path | str, *, replace: bool = False) -> None:
    """Raise unless ``path`` may take an export: free, or a regular file (replaced only with ``replace``).

    A link, FIFO or device there is refused (:class:`NotARegularFile`) — the
    write would land elsewhere or block; an existing file without ``replace``
    raises :class:`ExportTargetExists` (ask the operator first); a file where a folder of the
    path belongs raises :class:`NotAFolder` naming it (the missing folders are made when written).
    """
    for folder in Path(path).parents:  # the nearest one that is there must be a folder
        if os.path.lexists(folder):
            if not os.path.isdir(folder):
                raise NotAFolder(folder)
            break
    if os.path.lexists(path):
        if not is_regular_file(path):
            raise NotARegularFile(path)
        if not replace:
            raise ExportTargetExists(errno.EEXIST, "already exists", str(path))


def write_export(path: Path | str, data: bytes, *, replace: bool = False) -> None:
    """Write a file for the operator (an export) atomically, never through a link.

    ``path`` is checked by :func:`check_export_target`. The new file replaces
    the entry itself, so a link planted in between is replaced, not written through.
    """
    check_export_target(path, replace=replace)
    atomic_write_bytes(path, data)


@contextmanager
def export_text_stream(path: Path | str, *, replace: bool = False) -> Iterator[TextIO]:
    """A text stream (UTF-8) for an export too long to build in memory first.

    Checked like :func:`write_export` before anything is written; the file
    appears as a whole when the ``with`` block ends (:func:`nck.atomic.atomic_writer`)
    and not at all when it raised.
    """
    check_export_target(path, replace=replace)
    with atomic_writer(path) as raw:
        text = io.TextIOWrapper(raw, encoding="utf-8", newline="\n")
        yield text
        text.flush()
        text.detach()  # the binary stream stays open for the writer's sync
