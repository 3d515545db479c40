"""The bridge: the only code of the HMI that calls the kernel.

It advances the simulated NCK from a Textual interval timer (no threads),
posts :class:`~hmi.messages.NckStatusChanged` only when the snapshot's ``seq``
changed, forwards operator commands and reports rejections. Screens read what
the snapshot does not carry with :meth:`NckBridge.query` (the questions of
:mod:`nck.queries`); they never hold the kernel. The bridge times every advance
of the kernel for the system utilisation view (:mod:`hmi.utilisation`).

For tests the timer is not started (``realtime=False``): the test advances the
kernel explicitly with :meth:`NckBridge.advance` or :meth:`NckBridge.step` and
then lets the app process the posted messages (``await pilot.pause()``).
"""

from __future__ import annotations

import math
import time
from typing import Any, Callable, Protocol

from textual.message_pump import MessagePump

from nck import queries, refuse
from nck.commands import Accepted, EnterPassword, Rejected, SubmitResult
from nck.status import NckStatus

from hmi.alarm_times import AlarmTimes
from hmi.messages import CommandRejected, NckStatusChanged
from hmi.utilisation import UtilisationMeter

REFRESH_PERIOD_S = 0.05
"""Timer period: the kernel is advanced and the screen refreshed at most 20 times a second."""

SHOWN_AT_LEAST_EVERY_S = 1.0
"""An unchanged snapshot is still handed to the screens once a second of control time: an idle
machine's snapshot does not change, but some views show figures it does not carry (System
utilisation's IPO cycles since power on)."""

MAX_CATCH_UP_S = 0.25
"""After a stall (debugger, suspended terminal) the kernel catches up at most this much time."""


class NckLike(Protocol):
    """What the bridge needs from the kernel facade (``nck.kernel.Nck``)."""

    def submit(self, command: Any) -> SubmitResult:
        """Take or refuse an operator command."""

    def tick(self, dt_s: float) -> None:
        """Advance simulated time."""

    def status(self) -> NckStatus:
        """Return the current snapshot."""


class NckBridge:
    """Drives one kernel for one app.

    Args:
        nck: the kernel facade.
        realtime: start a timer that advances the kernel with the wall clock.
        ipo_cycle_s: the kernel's IPO cycle; :meth:`step` advances whole cycles.
        clock: monotonic clock in seconds (replaceable for tests).
        alarm_times: where the log entries read are stamped with the wall clock
            (a fresh :class:`AlarmTimes` when None).
    """

    def __init__(
        self,
        nck: NckLike,
        *,
        realtime: bool = True,
        ipo_cycle_s: float | None = None,
        clock: Callable[[], float] = time.monotonic,
        alarm_times: AlarmTimes | None = None,
    ) -> None:
        self.nck = nck
        """The kernel. Only the bridge calls it (screens ask :meth:`query`; tests may read it)."""
        _record_cuts(nck)
        self.alarm_times = alarm_times if alarm_times is not None else AlarmTimes()
        """Date and time of day of the alarms and messages read from the kernel's log."""
        self.realtime = realtime
        self.ipo_cycle_s = ipo_cycle_s or float(getattr(nck, "ipo_cycle_s", 0.002) or 0.002)
        self.clock = clock
        self._target: MessagePump | None = None
        self._last_wall: float | None = None
        self._last_seq: int | None = None
        self._posted_at_s = 0.0  # control time of the last snapshot posted
        self._last_log_seq = 0
        self._status: NckStatus = nck.status()
        self.refresh_count = 0
        self.utilisation = UtilisationMeter()
        """The kernel's compute time per IPO cycle, measured over the last advances."""
        # wrong passwords: the kernel counts them, the panel waits before it takes the next one
        self._password_open_at_s = self.clock() + self._password_delay_s()

    # -- wiring -----------------------------------------------------------------------
    def attach(self, target: MessagePump) -> None:
        """Post messages to ``target`` (the app) and, if realtime, start the timer."""
        self._target = target
        self._last_wall = self.clock()
        if self.realtime:
            target.set_interval(REFRESH_PERIOD_S, self._on_timer, name="nck-bridge")
        self.poll(force=True)

    def start_realtime(self) -> None:
        """Start advancing the kernel with the wall clock now (after a test set the scene)."""
        if self._target is None or self.realtime:
            return
        self.realtime = True
        self._last_wall = self.clock()
        self._target.set_interval(REFRESH_PERIOD_S, self._on_timer, name="nck-bridge")

    def _on_timer(self) -> None:
        now = self.clock()
        last = self._last_wall if self._last_wall is not None else now
        self._last_wall = now
        dt = min(max(now - last, 0.0), MAX_CATCH_UP_S)
        if dt > 0:
            try:
                self.advance(dt)
            except Exception as exc:  # the kernel promises never to raise; stay alive if it does
                report = getattr(self._target, "report_internal_error", None)
                if report is None:
                    raise
                report(exc)

    def replace_kernel(self, nck: NckLike) -> NckLike:
        """Drive a new kernel (after "Reset (po)", an exercise): its snapshots and log start
        afresh; return the kernel driven so far (an exercise gives it back at its end)."""
        previous, self.nck = self.nck, nck
        _record_cuts(nck)
        self.ipo_cycle_s = float(getattr(nck, "ipo_cycle_s", self.ipo_cycle_s) or self.ipo_cycle_s)
        self._last_seq = None
        self._posted_at_s = 0.0
        self._last_log_seq = 0
        self._status = nck.status()
        return previous

    # -- kernel access ------------------------------------------------------------------
    @property
    def status(self) -> NckStatus:
        """The latest snapshot read from the kernel."""
        return self._status

    def advance(self, dt_s: float) -> NckStatus:
        """Advance the kernel by ``dt_s`` seconds of simulated time, then poll."""
        self._timed(self.nck.tick, dt_s)
        return self.poll()

    def step(self, n_ipo_cycles: int = 1) -> NckStatus:
        """Advance the kernel by whole IPO cycles (tests), then poll."""
        stepper = getattr(self.nck, "step", None)
        if callable(stepper):
            self._timed(stepper, n_ipo_cycles)
        else:
            self._timed(self.nck.tick, n_ipo_cycles * self.ipo_cycle_s)
        return self.poll()

    def run_until(self, predicate: Callable[[NckStatus], bool], *, max_s: float = 60.0,
                  dt_s: float = 0.01) -> NckStatus:
        """Advance in steps of ``dt_s`` until ``predicate(status)`` holds or ``max_s`` passed."""
        elapsed = 0.0
        status = self.poll()
        while not predicate(status) and elapsed < max_s:
            self._timed(self.nck.tick, dt_s)
            elapsed += dt_s
            status = self.nck.status()
        return self.poll()

    def _timed(self, advance: Callable[[Any], None], amount: Any) -> None:
        """Advance the kernel with ``advance(amount)``, timed for the utilisation view."""
        self.utilisation.measure(lambda: advance(amount), self._counters)

    def _counters(self) -> tuple[int, int]:
        return int(getattr(self.nck, "cycles_done", 0)), int(getattr(self.nck, "blocks_interpreted", 0))

    def query(self, question: object) -> Any:
        """Answer a read-only question about the kernel (a class of :mod:`nck.queries`)."""
        return queries.answer(self.nck, question)

    @property
    def traceable(self) -> bool:
        """True when the kernel can be sampled every IPO cycle (a trace can be started)."""
        return hasattr(self.nck, "cycle_listeners")

    def attach_trace(self, recorder: Any) -> None:
        """Let ``recorder`` (``nck.trace.TraceRecorder``) sample the kernel at every IPO cycle."""
        recorder.attach(self.nck)

    def poll(self, force: bool = False) -> NckStatus:
        """Read the snapshot; post it when ``seq`` changed (or :data:`SHOWN_AT_LEAST_EVERY_S`
        passed), and stamp new log entries with the wall clock (:attr:`alarm_times`)."""
        status = self.nck.status()
        self._status = status
        if force or status.seq != self._last_seq or status.time_s - self._posted_at_s >= SHOWN_AT_LEAST_EVERY_S:
            self._last_seq = status.seq
            self._posted_at_s = status.time_s
            self.refresh_count += 1
            self._post(NckStatusChanged(status))
        self._stamp_new_log_entries()
        return status

    def _stamp_new_log_entries(self) -> None:
        reader = getattr(self.nck, "alarm_log_since", None)
        if not callable(reader):
            return
        for entry in reader(self._last_log_seq):
            self._last_log_seq = max(self._last_log_seq, entry.seq)
            self.alarm_times.record(entry)
        self.alarm_times.record_logbook(len(getattr(self.nck, "logbook", ()) or ()))

    def _password_delay_s(self) -> float:
        """The wait the kernel's count of wrong passwords asks for (0 without access control)."""
        access = getattr(self.nck, "access_state", None)
        if access is None:
            return 0.0
        return float(getattr(self.nck.access, "retry_delay_s", 0.0))

    def submit(self, command: Any) -> SubmitResult:
        """Forward an operator command; a refusal is posted as :class:`CommandRejected`.

        After a wrong password the next one is taken only when the growing delay has passed
        (a password entered earlier is refused without being checked).
        """
        if isinstance(command, EnterPassword):
            wait_s = self._password_open_at_s - self.clock()
            if wait_s > 0:
                result: SubmitResult = refuse("password_wait", seconds=math.ceil(wait_s))
                self._post(CommandRejected(command, result))
                return result
        result = self.nck.submit(command)
        if isinstance(command, EnterPassword):
            self._password_open_at_s = self.clock() + self._password_delay_s()
        if isinstance(result, Rejected):
            self._post(CommandRejected(command, result))
        self.poll()
        return result if isinstance(result, (Accepted, Rejected)) else Accepted()

    def _post(self, message: Any) -> None:
        if self._target is not None:
            self._target.post_message(message)


def _record_cuts(nck: Any) -> None:
    """Simultaneous recording on for a kernel that offers it (the Machine area's view)."""
    if hasattr(nck, "run_recorder_factory"):
        queries.record_cuts(nck)
