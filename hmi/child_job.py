"""A long computation of the panel run in a child process, its messages streamed back.

The editor's simulation runs a whole program through the kernel and sweeps the blank: seconds
to a minute of pure Python. In a worker thread it shares the interpreter lock with the screen:
every key waits for it, and it waits for every frame (figures in bench/analysis.md, "Editor
computations in a child process"). :class:`ChildJob` runs such a job in a child process forked
from the panel instead:
the child starts at once with everything the job needs already in memory (the program text,
the copy of the NC data, the subprogram source), the job runs on the other core at full speed,
and the screen thread only waits on a pipe.

The job is a function of one argument, ``send``: each value it passes to ``send`` comes back
to the parent as a message (progress); its return value is the result (pickled, so it must be
plain data: :class:`nck.simulation.run.Simulation` is). An exception in the job is a bug: the
parent raises the same exception, the child's traceback added as a note (or
:class:`ChildJobFailed` with that traceback when the exception cannot be pickled). Cancelling
kills the child.

The child never touches the screen, the terminal or the asyncio loop it inherited: it resets
the signal handlers the panel installed, sends its output nowhere, and leaves by ``os._exit``
(no atexit handlers, no flushing of the parent's buffers). At each message it sends it checks
that the panel is still there and ends itself when the panel is gone.

Choice (the manuals are silent on how a trainer computes): ``fork`` rather than ``spawn``,
because a spawned child would have to import the kernel and numpy first (about half a second
for even a three-line program) and be handed the subprogram source, which holds the panel's
file system. Nothing in ``nck/`` takes a lock or starts a thread, so the forked child cannot
wait for a lock another thread of the panel held at the fork. (Python 3.12 warns about any fork
of a process with threads; the project runs on 3.11, and the reasoning above is why that warning
may be silenced here when it moves.)
"""

from __future__ import annotations

import os
import pickle
import signal
import sys
import traceback
from collections.abc import Callable, Iterator
from multiprocessing import Pipe
from multiprocessing.connection import Connection
from typing import Any

POLL_S = 0.05
"""How often the waiting thread looks whether it was cancelled."""

_RESULT, _MESSAGE, _FAILED = "result", "message", "failed"


class ChildJobFailed(RuntimeError):
    """The job raised in the child (a bug), or the child ended without a result."""


class ChildJob:
    """One job run in a forked child process (see the module's docstring).

    Started by the constructor; :meth:`messages` yields what the job sends and then sets
    :attr:`result`. Use from one thread (a worker thread of the screen).
    """

    def __init__(self, job: Callable[[Callable[[Any], None]], Any]) -> None:
        self.result: Any = None
        self._receiver, sender = Pipe(duplex=False)
        parent = os.getpid()
        self.pid = os.fork()
        """The child's process id."""
        if self.pid == 0:  # the child: never returns
            self._receiver.close()
            _run_child(job, sender, parent)
        sender.close()
        self.ended = False
        """True once the child has ended and was waited for (no process is left behind)."""

    def messages(self, cancelled: Callable[[], bool]) -> Iterator[Any]:
        """Each message the job sends, as it comes; when the job has returned, :attr:`result`
        holds what it returned. ``cancelled()`` true: the child is killed and nothing more comes."""
        try:
            while True:
                if cancelled():
                    self.cancel()
                    return
                if not self._receiver.poll(POLL_S):
                    continue
                try:
                    kind, payload = self._receiver.recv()
                except EOFError:
                    status = self._reap()
                    raise ChildJobFailed(f"the child process ended without a result ({_ended_how(status)})") from None
                if kind == _MESSAGE:
                    yield payload
                elif kind == _RESULT:
                    self.result = payload
                    self._reap()
                    return
                else:
                    self._reap()
                    error, trace = payload
                    if error is None:
                        raise ChildJobFailed(f"the child process failed:\n{trace}")
                    error.add_note(f"raised in the child process:\n{trace}")
                    raise error
        finally:
            if not self.ended:
                self.cancel()

    def cancel(self) -> None:
        """Kill the child (if still running) and wait for its end."""
        if self.ended:
            return
        try:
            os.kill(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        self._reap()

    def _reap(self) -> int:
        self._receiver.close()
        _, status = os.waitpid(self.pid, 0)
        self.ended = True
        return status


def _ended_how(status: int) -> str:
    if os.WIFSIGNALED(status):
        return f"signal {os.WTERMSIG(status)}"
    return f"exit status {os.waitstatus_to_exitcode(status)}"


def _picklable(error: BaseException) -> BaseException | None:
    """``error`` when it survives pickling (the parent raises it again), else None."""
    try:
        pickle.loads(pickle.dumps(error))
    except Exception:  # noqa: BLE001 - any exception that does not pickle is sent as text
        return None
    return error


def _run_child(job: Callable[[Callable[[Any], None]], Any], sender: Connection, parent: int) -> None:
    """The forked child: run ``job``, send its messages and its result, leave by ``os._exit``."""
    code = 0
    try:
        signal.set_wakeup_fd(-1)  # the panel's event loop is woken by this fd: not from here
        for number in (signal.SIGINT, signal.SIGTERM, signal.SIGWINCH, signal.SIGTSTP, signal.SIGCONT,
                       signal.SIGHUP):
            signal.signal(number, signal.SIG_DFL)
        quiet = open(os.devnull, "w", encoding="utf-8")  # noqa: SIM115 - the child leaves by os._exit
        sys.stdout = sys.stderr = quiet

        def send(message: Any) -> None:
            if os.getppid() != parent:  # the panel is gone: nobody waits for this
                os._exit(0)
            sender.send((_MESSAGE, message))

        result = job(send)
        sender.send((_RESULT, result))
    except BaseException as error:  # noqa: BLE001 - everything goes to the parent; the child has no terminal
        code = 1
        try:
            sender.send((_FAILED, (_picklable(error), traceback.format_exc())))
        except BaseException:  # noqa: BLE001 - the parent is gone or the pipe broke: nothing to tell
            pass
    finally:
        os._exit(code)
