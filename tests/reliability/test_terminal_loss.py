"""The HMI ends by itself when its terminal goes away or it is told to end (issue 19, nothing lost on quit).

A closed terminal window, a dropped SSH connection, ``tmux kill-session`` or a
classroom server stopping a session (issue 26): nobody is left to answer
"Quit the HMI?". The HMI keeps unsaved editor text in the journal, saves its NC
data, gives the data directory free and exits — within a bounded time and with
no thread left reading the dead terminal.

Each test runs ``hmi`` as a process on a pseudo terminal of its own, with a
private data directory, and types through the terminal as an operator would.
"""

from __future__ import annotations

import fcntl
import os
import select
import signal
import struct
import sys
import termios
import time
from pathlib import Path

import pytest

from hmi.journal import EditorJournal
from nck.cli import main as nck_main
from nck.datalock import lock_data_dir
from nck.persistence import Session

ROOT = Path(__file__).resolve().parents[2]
ROWS, COLUMNS = 48, 160
WAIT_S = 20.0
"""Bound on every wait for the HMI (start, screen, exit); a healthy run takes well under a second each."""

ALT_N, ALT_T, ALT_U, ALT_G, F3 = "\x1bn", "\x1bt", "\x1bu", "\x1bg", "\x1bOR"

pytestmark = pytest.mark.skipif(not hasattr(os, "pidfd_open"), reason="needs Linux pidfd_open")


class HmiOnTerminal:
    """``hmi`` running as a child process on a pseudo terminal; the test holds the terminal's side.

    ``controlling``: the terminal is the process's controlling terminal (as in a shell),
    so closing it sends SIGHUP; without, closing it only ends the process's input.
    """

    def __init__(self, data_dir: Path, *args: str, controlling: bool = True) -> None:
        self.output = bytearray()
        self.fd, terminal = os.openpty()
        fcntl.ioctl(terminal, termios.TIOCSWINSZ, struct.pack("HHHH", ROWS, COLUMNS, 0, 0))
        env = dict(os.environ, NCK_DATA_DIR=str(data_dir), TERM="xterm-256color")
        for name in ("COLUMNS", "LINES"):  # the size comes from the terminal, not from the test's environment
            env.pop(name, None)
        pid = os.fork()
        if pid == 0:  # the child: hmi in a session of its own, on the terminal
            try:
                os.setsid()
                for number in (0, 1, 2):
                    os.dup2(terminal, number)
                if controlling:
                    fcntl.ioctl(0, termios.TIOCSCTTY, 0)
                os.chdir(ROOT)
                os.execve(sys.executable, [sys.executable, "-m", "hmi", *args], env)
            finally:
                os._exit(127)
        os.close(terminal)
        self.pid = pid
        self.pidfd = os.pidfd_open(pid)

    def type(self, keys: str) -> None:
        """Send keys as a terminal does (UTF-8 bytes, escape sequences for special keys)."""
        os.write(self.fd, keys.encode())

    def wait_for(self, text: str) -> None:
        """Read the screen output until ``text`` has appeared in what came after this call."""
        start = len(self.output)
        deadline = time.monotonic() + WAIT_S
        while text.encode() not in self.output[start:]:
            ready, _, _ = select.select([self.fd], [], [], max(0.0, deadline - time.monotonic()))
            assert ready, f"{text!r} not shown within {WAIT_S} s; last output: {bytes(self.output[-400:])!r}"
            try:
                self.output += os.read(self.fd, 65536)
            except OSError:  # EIO: the HMI has ended and closed its side
                pytest.fail(f"hmi ended before {text!r} was shown; last output: {bytes(self.output[-400:])!r}")

    def close_terminal(self) -> None:
        """The terminal goes away (window closed, connection dropped)."""
        os.close(self.fd)
        self.fd = -1

    def wait_exit(self) -> int:
        """The exit status once the process has ended (failing after :data:`WAIT_S`), output read to the end."""
        deadline = time.monotonic() + WAIT_S
        while True:
            watched = [self.pidfd] + ([self.fd] if self.fd >= 0 else [])
            ready, _, _ = select.select(watched, [], [], max(0.0, deadline - time.monotonic()))
            if not ready:
                pytest.fail(f"hmi still running {WAIT_S} s after it was told to end")
            if self.fd in ready:
                try:
                    self.output += os.read(self.fd, 65536)
                except OSError:  # the child has closed its side of the terminal
                    self.close_terminal()
            if self.pidfd in ready:
                _, status = os.waitpid(self.pid, 0)
                return status

    def kill(self) -> None:
        """End the child by force if a test failed before it exited (it must never outlive the test)."""
        try:
            os.kill(self.pid, signal.SIGKILL)
            os.waitpid(self.pid, 0)
        except (ProcessLookupError, ChildProcessError):
            pass
        os.close(self.pidfd)
        if self.fd >= 0:
            os.close(self.fd)


@pytest.fixture
def terminals():
    """Every HMI started by the test; those still alive at the end are killed."""
    started: list[HmiOnTerminal] = []
    yield started
    for hmi in started:
        hmi.kill()


def start_hmi(terminals: list[HmiOnTerminal], data_dir: Path, *args: str,
              controlling: bool = True) -> HmiOnTerminal:
    hmi = HmiOnTerminal(data_dir, *args, controlling=controlling)
    terminals.append(hmi)
    hmi.wait_for("JOG")
    return hmi


def journal_texts(data_dir: Path) -> dict[str, str]:
    journal = EditorJournal(data_dir / "hmi" / "journal")  # where the editor keeps it
    return {entry.program: entry.text for entry in journal.entries()}


def assert_lock_free(data_dir: Path) -> None:
    lock_data_dir(data_dir).release()  # DataDirInUse if the HMI still held it


@pytest.mark.parametrize("controlling", [True, False], ids=["hang-up", "input-ends"])
def test_closed_terminal_keeps_the_text_and_ends(tmp_path: Path, terminals, controlling: bool) -> None:
    """Text typed, then the terminal closes: no question, the text is in the journal, the process ends.

    Closing a controlling terminal hangs it up: the HMI gets SIGHUP (and SIGCONT)
    and its input reads end of file. A terminal that is not the controlling one
    (a terminal server's pipe) only ends the input: that alone ends the HMI too.
    """
    data_dir = tmp_path / "data"
    Session.open(data_dir).files.save("MPF/AA.MPF", "G0 X1\nM30\n")  # first in the list
    hmi = start_hmi(terminals, data_dir, controlling=controlling)
    hmi.type(ALT_T * 3)  # keyswitch 3: level 4, programs may be edited
    hmi.wait_for("Keyswitch 3")
    hmi.type(ALT_N + F3)
    hmi.wait_for("MPF/AA.MPF")
    hmi.type("HANGUP")
    hmi.wait_for("col 7")  # the HMI has every character
    hmi.close_terminal()
    status = hmi.wait_exit()
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 128 + signal.SIGHUP
    assert journal_texts(data_dir) == {"MPF/AA.MPF": "HANGUPG0 X1\nM30\n"}
    assert (data_dir / "nc" / "MPF" / "AA.MPF").read_text() == "G0 X1\nM30\n"  # kept aside, not saved
    assert_lock_free(data_dir)


def test_sigterm_with_a_running_program_ends_without_asking(tmp_path: Path, terminals) -> None:
    """SIGTERM (a service manager, the classroom server) while a program runs: saved, ended."""
    data_dir = tmp_path / "data"
    # NC START without referencing the axes first (MD20700 REFP_NC_START_LOCK = 0)
    assert nck_main(["md", "--data-dir", str(data_dir), "--password", "EVENING", "MD20700=0"]) == 0
    program = tmp_path / "LOOP.MPF"
    program.write_text("LOOP\nR1=R1+1\nENDLOOP\nM30\n")
    hmi = start_hmi(terminals, data_dir, "--program", str(program))
    hmi.type(ALT_U + ALT_G)
    hmi.wait_for("Channel active")
    os.kill(hmi.pid, signal.SIGTERM)
    status = hmi.wait_exit()
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 128 + signal.SIGTERM
    assert b"Quit the HMI?" not in hmi.output and b"Traceback" not in hmi.output
    assert_lock_free(data_dir)


def test_sigusr1_writes_the_thread_stacks_and_the_hmi_goes_on(tmp_path: Path, terminals) -> None:
    """``kill -USR1``: the stacks of a running (or hung) HMI land in ``<data dir>/hmi/thread-stacks.txt``."""
    data_dir = tmp_path / "data"
    hmi = start_hmi(terminals, data_dir)
    os.kill(hmi.pid, signal.SIGUSR1)
    # The dump reads the other threads' frames without a lock: a thread busy meanwhile (the key
    # reader parsing a key typed at once) can show a cut stack. So the key comes once the dump,
    # which ends with the main thread's stack, is in the file.
    stacks_file = data_dir / "hmi" / "thread-stacks.txt"
    deadline = time.monotonic() + WAIT_S
    while "_run_module_as_main" not in stacks_file.read_text():
        assert time.monotonic() < deadline, f"no stacks within {WAIT_S} s: {stacks_file.read_text()!r}"
        time.sleep(0.01)  # polling the file: the dump gives no other sign that it is complete
    hmi.type(ALT_N)
    hmi.wait_for("PROGRAM MANAGER")
    stacks = stacks_file.read_text()
    assert "run_input_thread" in stacks and "Current thread" in stacks, stacks
    hmi.close_terminal()
    assert os.WEXITSTATUS(hmi.wait_exit()) == 128 + signal.SIGHUP
