"""The terminal the HMI runs on: Textual's Linux driver with the panel's key reader, and its end.

:class:`PanelTerminalDriver` reads the keyboard through :class:`hmi.key_input.TerminalReader`
and notices when the terminal goes away — a closed window, a dropped SSH
connection, ``tmux kill-session``: the terminal is hung up, its input reads end
of file (or fails with EIO) and every write to it fails. Textual's own driver
does not end on that:

- its input thread reads the end of file again and again, a thread busy for
  nothing (here the thread posts :class:`hmi.messages.TerminalClosed` and ends);
- the kernel sends SIGCONT along with SIGHUP to the hung-up terminal's
  processes, and Textual answers every SIGCONT by starting the application mode
  again — a second input thread, which keeps the process alive after the app
  has ended (here only a SIGCONT after the HMI's own Ctrl+Z stop resumes);
- its writer thread dies at the first failed write, after which the app blocks
  for good on the writer's full queue (here output to a lost terminal is dropped).
"""

from __future__ import annotations

import errno
import os
import selectors
from typing import IO, Any

from textual.drivers.linux_driver import LinuxDriver

from hmi.key_input import TerminalReader
from hmi.messages import TerminalClosed

READ_POLL_S = 0.1
"""How long the input thread waits for bytes before it lets the parser check its escape delay."""

READ_SIZE = 4096
"""Bytes taken from the terminal per read."""

TERMINAL_GONE_ERRNOS = frozenset({errno.EIO, errno.ENXIO})
"""Read errors of a terminal that has been hung up (besides end of file)."""


def read_terminal(fileno: int) -> bytes:
    """Bytes the terminal has ready; ``b""`` once it has gone away (end of file, or EIO)."""
    try:
        return os.read(fileno, READ_SIZE)
    except OSError as exc:
        if exc.errno in TERMINAL_GONE_ERRNOS:
            return b""
        raise


class TerminalOutput:
    """The stream Textual's writer thread writes the screen to; after a failed write, output is dropped.

    A write to a terminal that is gone fails (EIO). Textual's writer thread would end
    on that error, and the app, writing on, would wait forever for room in its queue.
    """

    def __init__(self, stream: IO[str]) -> None:
        self.stream = stream
        self.lost = False
        """Whether a write has failed: the terminal is gone and nothing more is written to it."""

    def write(self, text: str) -> None:
        """Write ``text`` to the terminal, unless it is gone."""
        self._attempt(self.stream.write, text)

    def flush(self) -> None:
        """Flush the stream, unless the terminal is gone."""
        self._attempt(self.stream.flush)

    def fileno(self) -> int:
        """The terminal's file descriptor."""
        return self.stream.fileno()

    def _attempt(self, operation: Any, *args: Any) -> None:
        if self.lost:
            return
        try:
            operation(*args)
        except OSError:
            self.lost = True


class PanelTerminalDriver(LinuxDriver):
    """The Linux terminal driver with the panel's key reader, ending cleanly when the terminal goes."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._file = TerminalOutput(self._file)
        self._stopped_by_operator = False

    def run_input_thread(self) -> None:
        """Read the terminal until the app exits or the terminal is gone; post what the parser makes of it."""
        reader = TerminalReader()
        with selectors.DefaultSelector() as selector:
            selector.register(self.fileno, selectors.EVENT_READ)
            while not self.exit_event.is_set():
                for _ in selector.select(READ_POLL_S):
                    data = read_terminal(self.fileno)
                    if not data:
                        self.process_message(TerminalClosed())
                        return
                    for message in reader.feed(data):
                        self.process_message(message)
                for message in reader.tick():
                    self.process_message(message)

    def _sigtstp_application(self, *args: Any) -> None:
        """Ctrl+Z (SIGTSTP): stop as Textual does, remembering that the next SIGCONT resumes."""
        self._stopped_by_operator = self._auto_restart
        super()._sigtstp_application(*args)

    def _sigcont_application(self, *args: Any) -> None:
        """SIGCONT: resume the application mode only after a stop of the HMI's own.

        A hung-up terminal's processes get SIGCONT with SIGHUP; starting the
        application mode again then would start a second input thread.
        """
        if self._stopped_by_operator:
            self._stopped_by_operator = False
            super()._sigcont_application(*args)
