"""Termination signals end the program like a normal exit, so that its clean-up runs.

SIGTERM (``kill``, a service manager, a server stopping a classroom session)
and SIGHUP (the terminal was closed) end a Python process at once by default:
``finally`` blocks and ``atexit`` functions are skipped, so a temporary copy of
the data directory (``--ephemeral``) would stay behind. Inside
:func:`exit_on_termination` such a signal raises ``SystemExit`` instead, with
the exit code a shell shows for a process ended by that signal (128 + number).
Ctrl+C raises ``KeyboardInterrupt`` on its own; a command that catches it at its
entry point ends with :data:`INTERRUPTED_EXIT` after its clean-up ran.
"""

from __future__ import annotations

import signal
from contextlib import contextmanager
from typing import Iterator

INTERRUPTED_EXIT = 128 + int(signal.SIGINT)
"""Exit code of a command ended by Ctrl+C (``KeyboardInterrupt``), as a shell shows it."""

TERMINATION_SIGNALS = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))


def _exit(signum: int, _frame: object) -> None:
    raise SystemExit(128 + signum)


@contextmanager
def exit_on_termination() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise ``SystemExit``; the old handlers come back after."""
    previous = {}
    try:
        for number in TERMINATION_SIGNALS:
            previous[number] = signal.signal(number, _exit)
    except ValueError:  # not the main thread: leave the handlers alone
        pass
    try:
        yield
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
