"""SIGUSR1 writes the stack of every thread of the HMI into a file: for diagnosing a hung HMI.

A stuck or busy ``hmi`` (a classroom server's session, an orphan after its
terminal went away) is examined with ``kill -USR1 <pid>``; the stacks are
appended to ``<data dir>/hmi/thread-stacks.txt``. They go to a file, not to
stderr: the terminal shows the panel, or is gone. The file is emptied at each
start and never written through a link (symbolic or hard).
"""

from __future__ import annotations

import errno
import faulthandler
import os
import signal
import stat
from pathlib import Path

STACK_DUMP_SIGNAL = getattr(signal, "SIGUSR1", None)
"""The signal that writes the stacks (None where the platform has no SIGUSR1)."""

STACK_FILE_NAME = "thread-stacks.txt"
"""The file in the HMI folder of the data directory that receives the stacks."""


def register_stack_dump(folder: Path) -> int | None:
    """Let :data:`STACK_DUMP_SIGNAL` write every thread's stack into ``folder``/:data:`STACK_FILE_NAME`.

    Returns the file descriptor the dumps go to (it stays open while the HMI runs),
    None where the platform has no such signal. Raises ``OSError`` when the file
    cannot be opened, or is a link, a FIFO or a device (never written through).
    """
    if STACK_DUMP_SIGNAL is None:
        return None
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / STACK_FILE_NAME
    # opened as nck.regular_files does (the HMI reaches the kernel's modules only through its façade)
    try:
        handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_APPEND | os.O_NOFOLLOW | os.O_NONBLOCK, 0o600)
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            raise OSError(errno.EINVAL, "not a regular file (a link)", str(path)) from None
        raise
    status = os.fstat(handle)
    if not stat.S_ISREG(status.st_mode) or status.st_nlink != 1:
        os.close(handle)
        kind = "a pipe or device" if not stat.S_ISREG(status.st_mode) else "a hard link of another file"
        raise OSError(errno.EINVAL, f"not a regular file of its own ({kind})", str(path))
    os.ftruncate(handle, 0)  # only after the check: a device is never truncated
    os.set_blocking(handle, True)
    faulthandler.register(STACK_DUMP_SIGNAL, file=handle, all_threads=True)
    return handle
