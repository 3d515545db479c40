"""The terminal driver notices a terminal that has gone away and leaves no thread behind (issue 19).

The driver's parts are tested without a terminal set-up; the whole HMI on a
closed terminal is tested in ``tests/reliability/test_terminal_loss.py``.
"""

from __future__ import annotations

import errno
import os
import threading

from textual.drivers._writer_thread import MAX_QUEUED_WRITES, WriterThread

from hmi.messages import TerminalClosed
from hmi.terminal_driver import PanelTerminalDriver, TerminalOutput, read_terminal

JOIN_S = 5.0
"""Bound on waiting for a thread that must end by itself (it ends in milliseconds)."""


def bare_driver(fileno: int) -> tuple[PanelTerminalDriver, list]:
    """A driver reading ``fileno`` (no terminal set-up) and the messages it posts."""
    driver = PanelTerminalDriver.__new__(PanelTerminalDriver)
    driver.fileno, driver.exit_event = fileno, threading.Event()
    posted: list = []
    driver.process_message = posted.append
    return driver, posted


def run_until_it_ends(target) -> None:
    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(JOIN_S)
    assert not thread.is_alive(), f"still running after {JOIN_S} s: it must end by itself"


def test_input_thread_ends_at_end_of_input_and_says_so() -> None:
    """A hung-up terminal reads end of file: the keys before it are posted, then TerminalClosed, then the thread ends."""
    read_end, write_end = os.pipe()
    os.write(write_end, b"ab")
    os.close(write_end)
    driver, posted = bare_driver(read_end)
    try:
        run_until_it_ends(driver.run_input_thread)  # without the exit event being set
    finally:
        os.close(read_end)
    assert [getattr(m, "key", None) for m in posted] == ["a", "b", None]
    assert isinstance(posted[-1], TerminalClosed)


def test_read_error_of_a_hung_up_terminal_counts_as_its_end() -> None:
    """EIO (Linux: the other side of a pseudo terminal has closed) is the end of the terminal."""
    master, slave = os.openpty()
    os.close(slave)
    try:
        try:
            os.read(master, 1)
        except OSError as exc:
            assert exc.errno == errno.EIO  # what the driver meets
        assert read_terminal(master) == b""
    finally:
        os.close(master)


def test_sigcont_without_a_stop_of_its_own_starts_nothing() -> None:
    """The kernel sends SIGCONT with SIGHUP to a hung-up terminal's processes.

    Textual's driver started the application mode again on it — a second input thread
    that kept the process alive (two threads busy after ``tmux kill-session``).
    """
    driver, _ = bare_driver(-1)
    driver._stopped_by_operator = False
    resumed: list[bool] = []
    driver.resume_application_mode = lambda: resumed.append(True)
    driver._auto_restart = True
    driver._sigcont_application()
    assert resumed == []
    driver._stopped_by_operator = True  # after Ctrl+Z stopped the HMI, SIGCONT resumes it
    driver._sigcont_application()
    assert resumed == [True]


class GoneTerminal:
    """A terminal stream whose writes fail as those to a hung-up terminal do."""

    def __init__(self) -> None:
        self.attempts = 0

    def write(self, text: str) -> int:
        self.attempts += 1
        raise OSError(errno.EIO, "Input/output error")

    def flush(self) -> None:
        raise OSError(errno.EIO, "Input/output error")

    def fileno(self) -> int:
        return -1


def test_screen_output_to_a_gone_terminal_never_blocks_the_app() -> None:
    """Textual's writer thread ended at the first failed write; the app then waited forever for room in its queue."""
    terminal = GoneTerminal()
    writer = WriterThread(TerminalOutput(terminal))
    writer.start()

    def write_many_screens() -> None:
        for _ in range(MAX_QUEUED_WRITES * 3):
            writer.write("\x1b[1;1Hscreen")
        writer.stop()

    run_until_it_ends(write_many_screens)
    assert terminal.attempts == 1  # nothing more is sent to a terminal known to be gone
