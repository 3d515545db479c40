"""A lock on the NC data directory: one HMI (or writing CLI command) at a time.

Two programs saving the retained data of one directory would overwrite each
other's changes, so the process that opens a data directory for writing holds
an exclusive lock on ``<data dir>/.lock`` for as long as it works there. A
second one gets :class:`DataDirInUse`, whose message names the directory and
the process holding it. The operating system drops the lock when the holder
ends, even when it is killed (SIGKILL), so a crash never leaves a stale lock
behind; the PID written into the file is only information for the message.

On platforms without ``fcntl`` the lock is a no-op (documented limitation).
"""

from __future__ import annotations

import os
from pathlib import Path

from nck.regular_files import NotARegularFile, open_regular, read_regular_bytes

try:  # POSIX advisory locks; released by the kernel when the process dies
    import fcntl
except ImportError:  # pragma: no cover - Windows: no lock
    fcntl = None  # type: ignore[assignment]

LOCK_NAME = ".lock"
"""File name of the lock inside the NC data directory."""


class DataDirLockError(Exception):
    """The NC data directory cannot be locked; ``str()`` says why."""


class LockFileRefused(DataDirLockError):
    """``.lock`` is not a regular file of its own (a link, pipe or device, or a file with
    further hard links): it is never truncated or written."""

    def __init__(self, path: Path, kind: str = "not a regular file (a link, pipe or device)") -> None:
        self.path = path
        super().__init__(f"{path} is {kind}; the lock is never taken through it — remove it and start again")


class DataDirInUse(DataDirLockError):
    """The NC data directory is locked by another running process."""

    def __init__(self, directory: Path, holder_pid: int | None) -> None:
        self.directory = directory
        self.holder_pid = holder_pid
        holder = f"process {holder_pid}" if holder_pid else "another process"
        super().__init__(
            f"NC data directory {directory} is in use by {holder} (another HMI or nck command); "
            "close it first, or start with --ephemeral to work on a copy")


class DataDirLock:
    """An exclusive lock on one NC data directory; use :func:`lock_data_dir` to take it.

    Usable as a context manager; :meth:`release` may be called more than once.
    """

    def __init__(self, directory: Path, handle: int | None) -> None:
        self.directory = directory
        self._handle = handle

    @property
    def held(self) -> bool:
        """True until :meth:`release`."""
        return self._handle is not None

    def release(self) -> None:
        """Give the directory free (closing the file drops the lock)."""
        handle, self._handle = self._handle, None
        if handle is None:
            return
        try:
            if fcntl is not None:
                fcntl.flock(handle, fcntl.LOCK_UN)
        finally:
            os.close(handle)

    def __del__(self) -> None:  # an abandoned session (tests) must not keep the directory locked
        try:
            self.release()
        except OSError:
            pass

    def __enter__(self) -> "DataDirLock":
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()


def _holder_pid(path: Path) -> int | None:
    try:
        text = read_regular_bytes(path, 32).decode("ascii", errors="replace").strip()
    except OSError:
        return None
    return int(text) if text.isdigit() else None


def lock_data_dir(directory: str | Path) -> DataDirLock:
    """Take the lock of ``directory`` (created if missing).

    Raises :class:`DataDirInUse` while another process holds it and
    :class:`LockFileRefused` when ``.lock`` is a link, pipe or device, or a
    hard link of another file (the file it points to is never truncated or written).
    """
    root = Path(directory)
    root.mkdir(parents=True, exist_ok=True)
    path = root / LOCK_NAME
    if fcntl is None:  # pragma: no cover
        return DataDirLock(root, None)
    try:
        handle = open_regular(path, os.O_RDWR | os.O_CREAT, 0o644)
    except NotARegularFile:
        raise LockFileRefused(path) from None
    if os.fstat(handle).st_nlink != 1:  # a hard link shares its content with a file elsewhere
        os.close(handle)
        raise LockFileRefused(path, "linked to another file (a hard link)")
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(handle)
        raise DataDirInUse(root, _holder_pid(path)) from None
    os.ftruncate(handle, 0)
    os.write(handle, f"{os.getpid()}\n".encode("ascii"))
    return DataDirLock(root, handle)
