"""The interpolator of :class:`nck.motion.system.PlannedMotion`: setpoints per IPO cycle.

:class:`PathInterpolator` is a mixin of the planned motion system. It fills
rows of path setpoints (one per IPO cycle) from the running profile, finishes
a segment and starts the next one inside a cycle (the rest of the cycle goes
to the next segment), waits for dwells and exact-stop windows, and — for the
kernel's batched steps — shortens a fill to end with the cycle of the next
block event (see :meth:`PlannedMotion.advance_cycles`).
"""

from __future__ import annotations

import math
from typing import Any, Callable

import numpy as np

from nck.canon import Source
from nck.errors import NcAlarmError
from nck.motion.planner import AlarmItem, DwellItem
from nck.motion.profile import build_profile
from nck.motion.runs import PathRun

RECHECK_CYCLES = 25
SCALAR_SAMPLES = 32  # a BRISK block of up to this many samples is sampled with Python floats
ALARM_CONTROLLER_ENABLE = 21612
MAX_DWELL_S = 1e9  # longer dwells are cut here (an infinite dwell would overflow the cycle count)


class PathInterpolator:
    """Setpoint generation of the planned motion (state lives in :class:`PlannedMotion`)."""

    # Provided by PlannedMotion.
    T: float
    la: Any
    run: PathRun | None
    servo: Any
    jog: Any
    _dwell_s: Any
    _spindle_settle_s: Any
    _spindles_to: Callable[[int], None]
    spindle_wait: bool
    spindle_feed_enable: bool  # the spindle wait is a machining block's (MD35500), not WAITS/SPOS
    spindle_checked: bool  # the spindle wait has been checked once after its first cycle
    exact_wait: tuple[np.ndarray, np.ndarray] | None
    disabled: set[int]
    names: list[str]
    _alarms: list[NcAlarmError]
    unsettled: tuple[list[bool], np.ndarray, np.ndarray] | None  # (moved axes as a mask, window, end point)
    settle_point: np.ndarray | None
    _fine: np.ndarray
    _coarse: np.ndarray
    wait_cycles: int  # standstill cycles still to give (dwell, exact stop, spindle wait)
    held: bool  # NC STOP: the path brakes and stays
    faulted: bool  # a motion alarm stopped the path
    hold_point: np.ndarray | None  # where a hold stopped the path (REPOS goes back there)
    is_idle: Callable[[], bool]
    current_source: Callable[[], Source | None]

    def _path_fill(self, rows: np.ndarray, flat_rows: np.ndarray, k: int, n: int,
                   stop_at_event: bool = False) -> tuple[int, bool, int]:
        """Fill path setpoints from row ``k``; stop early (sync=True) at an exact stop.

        ``flat_rows`` is ``rows`` as one flat view (``rows.reshape(-1)`` of the caller's fresh
        array), through which runs of Python floats are written.

        Returns the next row, whether an exact-stop check is due, and the row
        limit: with ``stop_at_event`` it shrinks to end with the cycle of the
        first block event (see :meth:`advance_cycles`).
        """
        T = self.T
        while k < n:
            if self.spindle_wait and self.wait_cycles == 0:
                # The first cycle of a spindle wait ran out (in a batch: in the last step, the
                # block's outputs have gone out since): wait on while the spindle moves.
                self._check_spindle(k)
            if self.wait_cycles > 0:
                if self.settle_point is not None:
                    self.cmd, self.settle_point = self.settle_point, None
                m = min(self.wait_cycles, n - k)
                rows[k:k + m] = self.cmd
                self.wait_cycles -= m
                k += m
                if self.wait_cycles == 0 and self.spindle_wait and self.spindle_checked:
                    self._check_spindle(k)
                    if self.spindle_wait:
                        continue  # waiting on: not a block event
                if self.wait_cycles == 0:
                    if stop_at_event:
                        n = k  # the dwell or the wait for the window ends in this cycle
                    if self.exact_wait is not None:
                        return k, True, n
                continue
            if self.exact_wait is not None:
                return k, True, n
            if self.run is None:
                buffered = len(self.la.items)
                started = self._start_next(0.0)
                if stop_at_event and len(self.la.items) != buffered:
                    n = k + 1  # a dwell or an alarm left the buffer in this cycle
                if not started:
                    if stop_at_event and not self.la.items:
                        n = min(n, k + self._cycles_to_idle(k))
                    rows[k:n] = self.cmd
                    return n, False, n
            if self.run is None:
                continue
            run = self.run
            room = n - k
            tau, profile = run.tau, run.profile
            m = _samples_within(tau, T, profile.duration_s + 1e-12, room)
            if m and len(run.chain) == 1 and (m == 1 or (m <= SCALAR_SAMPLES and profile.scalar_exact)):
                # A few samples of one segment: Python floats, the same values as the numpy form
                # below (see Profile.scalar_exact and Segment.points), cheaper on a handful of rows.
                flat = run.chain[0].segment.points(profile.distances_after(tau, T, m, run.s_begin))
                if m == 1:
                    rows[k] = flat  # (the first cycle of every block: no array made for it)
                else:
                    width = rows.shape[1]
                    flat_rows[k * width:(k + m) * width] = flat  # (no array made for it)
                run.tau = tau + T * m
                k += m
            elif m:
                taus = run.tau + self._sample_steps(m)
                rows[k:k + m] = run.positions(run.profile.distances(taus))
                run.tau = float(taus[m - 1])
                k += m
            # (self.cmd is not set from the last row: _finish_run sets it below, and after a
            # break the caller sets it from the rows the servo took before anyone reads it.)
            if m == room:
                break
            if stop_at_event:
                n = k + 1  # the run ends within this cycle
            carry = run.tau - run.profile.duration_s
            if self._finish_run(run):
                return k, True, n
            if self.run is None and not self.held and not self.faulted:
                self._start_next(carry)
        return k, False, n

    def _check_spindle(self, k: int) -> None:
        """Go on waiting while the spindle is not positioned or not in its set speed range;
        checked again at least every RECHECK_CYCLES (an override or a speed limit changed
        meanwhile moves the end; a drive that never gets there keeps the block waiting)."""
        self._spindles_to(k)
        self.spindle_checked = True
        left_s = self._spindle_settle_s()
        self.spindle_wait = left_s > 1e-9
        if self.spindle_wait:
            self.wait_cycles = max(1, min(int(math.ceil(min(left_s / self.T, 1e9) - 1e-9)), RECHECK_CYCLES))

    def _sample_steps(self, m: int) -> np.ndarray:
        """``T * [1, 2, … m]`` (the sample times of a fill after the last one; table grown on demand)."""
        table = self.__dict__.get("_steps_table")
        if table is None or len(table) < m:
            table = self.T * np.arange(1, max(m, 4096) + 1)
            self.__dict__["_steps_table"] = table
        return table[:m]

    def _cycles_to_idle(self, k: int) -> int:
        """Cycles of standstill setpoints until :meth:`is_idle` may turn true (≥ 1).

        Used to end a batch where the axes come to rest; a prediction one
        cycle short of the computed value, so the batch never runs past it.
        """
        if k > 0 or self.jog.runs:
            return 1
        if self.is_idle():
            return 1 << 30  # already at rest: nothing left to notice
        servo = self.servo
        servo.settle()
        if np.any(np.abs(servo.v_set) > 1e-9):
            return 1
        cycles = servo.cycles_to_window(np.arange(len(self.names)), self._coarse)
        if cycles is None:
            return 1 << 30  # a fault keeps the axis out of its window: never idle
        return max(cycles - 1, 1)

    def _finish_run(self, run: PathRun) -> bool:
        """Book-keeping at the end of a run; True when an exact-stop wait begins."""
        self.run = None
        if run.kind == "segment":
            seg = run.chain[0]
            reached = run.s_begin + run.profile.length
            if reached < seg.segment.length - 1e-6 and run.profile.length > 1e-9:
                # The profile stopped short of the end (should not happen): continue from there.
                seg.done_s = reached
                self.cmd = seg.segment.positions(np.array([reached]))[0]
                self.v_path = run.profile.v_end
                return False
            if self.la.items and self.la.items[0] is seg:
                self.la.pop_front()
            self.cmd = seg.segment.end.copy()
            self.v_path = run.profile.v_end
            self._last_source = seg.source
            window = self._coarse if seg.window == "G602" else self._fine
            self.unsettled = None
            if seg.exact_stop:
                # G603 (interpolator end): the end point once, no window to wait for; the
                # block change comes after it, so outputs at block end go out there.
                moved = np.flatnonzero(seg.moved) if seg.window != "G603" else np.zeros(0, dtype=np.int64)
                self.exact_wait = (moved, window)
                self.wait_source = seg.source
                self.v_path = 0.0
                # Output the end point once, then check the window.
                self.wait_cycles = 1
            elif seg.window != "G603":
                self.unsettled = (seg.moved, window, seg.segment.end)  # (never changed: see Segment)
            return False
        self.v_path = 0.0
        end_s = min(run.profile.length, float(run.offsets[-1]))
        self.cmd = run.positions(np.array([end_s]))[0]
        if run.kind == "abort":
            return False
        index, local = run.split_end()
        for _ in range(index):
            if self.la.items and self.la.items[0] is not run.chain[index]:
                self.la.pop_front()
        seg = run.chain[index]
        seg.done_s = local
        if seg.remaining <= 1e-9 and self.la.items and self.la.items[0] is seg:
            self.la.pop_front()
        self.hold_point = self.cmd.copy()
        return False

    def _start_next(self, carry: float) -> bool:
        """Begin the next buffered item; False when nothing can start."""
        if self.held or self.faulted or not self.la.items:
            return False
        head = self.la.items[0]
        if isinstance(head, AlarmItem):
            self.la.pop_front()
            self._alarms.append(head.alarm)
            self.faulted = True
            self.stop_source = head.source
            return False
        if isinstance(head, DwellItem):
            self.la.pop_front()
            unsettled, self.unsettled = self.unsettled, None
            if unsettled is not None:
                # The block before ends with its exact-stop criterion first (002 L4797-4809).
                moved, window, end = unsettled
                self.exact_wait = (np.flatnonzero(moved), window)
                self.settle_point = end.copy()  # held while waiting (a batch step may end on a profile sample)
            seconds = head.seconds if head.revolutions is None else self._dwell_s(head.revolutions)
            if head.wait_spindle:
                # One cycle: the spindle output before it goes out at its start; then
                # checked again until the spindle has settled (_path_fill).
                self.spindle_feed_enable = head.feed_enable
                seconds = self.T
                self.spindle_wait = True
                self.spindle_checked = False
            cycles = int(round(min(seconds, MAX_DWELL_S) / self.T))
            if unsettled is not None:
                cycles = max(cycles, 1)  # output the end point once, then check the window
            # An exact-stop wait just begun keeps its cycle of the end point.
            self.wait_cycles = max(self.wait_cycles, cycles)
            self.wait_source = head.source
            self.v_path = 0.0
            return True
        without_enable = [i for i in self.disabled if head.moved[i]] if self.disabled else None
        if without_enable:
            # An axis without controller enable cannot follow: 21612, the path stops here.
            self.la.pop_front()
            self._alarms.append(NcAlarmError(ALARM_CONTROLLER_ENABLE, self.names[without_enable[0]]))
            self.faulted = True
            self.stop_source = head.source
            return False
        vmax = self.la.v_max(head)
        if vmax <= 1e-9:
            self.v_path = 0.0
            return False
        self.unsettled = None
        exit_v = head.exit_limit
        if vmax < exit_v:  # min(exit limit, vmax) as the builtin decides
            exit_v = vmax
        profile = build_profile(head.remaining, self.v_path, exit_v, vmax, head.accel, head.jerk)
        self.run = PathRun([head], head.done_s, profile, tau=carry, kind="segment", exit_target=exit_v)
        return True

    def _check_exact_stop(self) -> None:
        if self.exact_wait is None or self.wait_cycles:
            return
        indices, window = self.exact_wait
        cycles = self.servo.cycles_to_window(indices, window)
        if cycles == 0:
            self.exact_wait = None
        else:
            self.wait_cycles = RECHECK_CYCLES if cycles is None else cycles

    def _on_trip(self, trip: Any) -> None:
        source = self.current_source()
        file = source.file if source else None
        line_no = source.line if source else None
        n = source.n if source else None
        self._alarms.append(NcAlarmError(trip.number, trip.axis, file=file, line=line_no, n=n))
        self.servo.enter_follow_up()
        self.cmd = self.servo.x_set.copy()
        self.run = None
        self.faulted = True
        self.stop_source = source
        self.wait_cycles = 0
        self.exact_wait = None
        self.jog.runs.clear()


def _samples_within(tau: float, T: float, end: float, room: int) -> int:
    """How many of ``tau + T*1``, ``tau + T*2``, … ``tau + T*room`` are ≤ ``end``.

    The same count as a search over those sample times, without building them.
    """
    if room <= 0 or tau + T > end:
        return 0
    estimate = (end - tau) / T
    if not estimate < room:
        m = room  # also for inf (huge moves)
    else:
        m = int(estimate)
        if not m > 1:  # max(1, m) as the builtin decides
            m = 1
    while m < room and tau + T * (m + 1) <= end:
        m += 1
    while m > 1 and tau + T * m > end:
        m -= 1
    return m
