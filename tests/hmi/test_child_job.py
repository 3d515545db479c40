"""The editor's long computations in a forked child process (hmi/child_job.py): messages and the
result come back in order, a bug in the job reaches the parent as the same exception, a child
that dies or is cancelled leaves no process behind, and the child writes nothing to the panel's
terminal."""

from __future__ import annotations

import os
import signal
import sys
from typing import Any

import numpy as np
import pytest

from hmi.child_job import ChildJob, ChildJobFailed
from nck.errors import NcAlarmError


def _gone(pid: int) -> bool:
    """True when ``pid`` is no child of this process any more (it ended and was waited for)."""
    try:
        os.waitpid(pid, os.WNOHANG)
    except ChildProcessError:
        return True
    return False


def test_messages_come_in_order_then_the_result() -> None:
    def job(send: Any) -> Any:
        for k in range(5):
            send(k)
        return {"heights": np.arange(6.0).reshape(2, 3), "alarm": NcAlarmError(10720, "X", line=4)}

    run = ChildJob(job)
    assert list(run.messages(lambda: False)) == [0, 1, 2, 3, 4]
    assert run.result["heights"].tolist() == [[0.0, 1.0, 2.0], [3.0, 4.0, 5.0]]
    alarm = run.result["alarm"]
    assert (alarm.number, alarm.params, alarm.line) == (10720, ("X",), 4)  # an alarm pickles whole
    assert run.ended and _gone(run.pid)


def test_a_bug_in_the_job_is_raised_again_in_the_parent() -> None:
    def job(send: Any) -> Any:
        raise TypeError("a bug in the job")

    run = ChildJob(job)
    with pytest.raises(TypeError, match="a bug in the job") as raised:
        list(run.messages(lambda: False))
    assert "raised in the child process" in raised.value.__notes__[0]
    assert "a bug in the job" in raised.value.__notes__[0]  # the child's traceback
    assert _gone(run.pid)


class _Unpicklable(Exception):
    def __init__(self, first: str, second: str) -> None:
        super().__init__(f"{first} {second}")


def test_an_exception_that_does_not_pickle_comes_as_its_traceback() -> None:
    def job(send: Any) -> Any:
        raise _Unpicklable("lost", "type")

    run = ChildJob(job)
    with pytest.raises(ChildJobFailed, match="lost type"):
        list(run.messages(lambda: False))
    assert _gone(run.pid)


def test_a_child_that_dies_is_a_failure_and_is_waited_for() -> None:
    def job(send: Any) -> Any:
        send("started")
        os.kill(os.getpid(), signal.SIGKILL)

    run = ChildJob(job)
    messages = run.messages(lambda: False)
    assert next(messages) == "started"
    with pytest.raises(ChildJobFailed, match=f"signal {int(signal.SIGKILL)}"):
        next(messages)
    assert _gone(run.pid)


def test_cancelling_kills_the_child() -> None:
    def job(send: Any) -> Any:
        count = 0
        while True:  # runs until it is killed
            count += 1
            send(count)

    cancel: list[bool] = []
    run = ChildJob(job)
    received = []
    for message in run.messages(lambda: bool(cancel)):
        received.append(message)
        if message == 3:
            cancel.append(True)
    assert received[:3] == [1, 2, 3] and run.result is None
    assert run.ended and _gone(run.pid)


def test_leaving_the_loop_early_kills_the_child_too() -> None:
    def job(send: Any) -> Any:
        while True:
            send("tick")

    run = ChildJob(job)
    messages = run.messages(lambda: False)
    assert next(messages) == "tick"
    messages.close()  # the waiting thread stopped listening (its worker ended)
    assert run.ended and _gone(run.pid)


def test_the_child_writes_nothing_to_the_terminal(capfd: pytest.CaptureFixture[str]) -> None:
    def job(send: Any) -> Any:
        print("to stdout", flush=True)
        print("to stderr", file=sys.stderr, flush=True)
        return "done"

    run = ChildJob(job)
    assert list(run.messages(lambda: False)) == [] and run.result == "done"
    captured = capfd.readouterr()
    assert captured.out == "" and captured.err == ""
