"""The real motion system: look-ahead planner, IPO-cycle interpolator, axes, JOG.

:class:`PlannedMotion` implements :class:`nck.motion.api.MotionSystem` and
:class:`nck.motion.api.JogControl`. ``advance(dt)`` produces one setpoint per
path axis per IPO cycle (MD10050 × MD10070), a whole block at a time with
numpy, runs the position controllers and monitors over them, and keeps an
optional trace of the setpoints. ``advance_cycles(n, on_block_event)`` is the
kernel's batched step: it ends with the cycle of the next block event (or
calls the kernel back there), so that many cycles per call give the same
result as one cycle per call.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Collection, Mapping

import numpy as np

from nck.canon import Dwell, Motion, Source, SpindleCommand
from nck.errors import NcAlarmError
from nck.machine import MachineConfig
from nck.motion.dry_run import DryRun
from nck.motion.interpolator import ALARM_CONTROLLER_ENABLE, PathInterpolator
from nck.motion.jog import JogUnit
from nck.motion.limits import EDGE_MM, Limits
from nck.motion.params import motion_params
from nck.motion.path import PLANE_AXES, Segment, arc, line
from nck.motion.planner import AlarmItem, DwellItem, LookAhead, PlannedSegment, plan_segment
from nck.motion.profile import braking_profile, build_profile
from nck.motion.runs import PathRun
from nck.motion.servo import AxisState, ServoBank, Trip
from nck.motion.spindle import Spindle

ALARM_VALUE_RANGE = 12160  # a target position that is not a finite number or out of range
POSITION_RANGE_MM = 1e9  # far beyond the value range of any axis (±999 999.999 mm at MD10200 = 1000)
RIGID_TAPPING = frozenset({"G331", "G332"})  # the spindle is interpolated with the axis: feed = S x lead from the block


class PlannedMotion(PathInterpolator):
    """Planner + interpolator + position control + JOG/referencing of one channel."""

    def __init__(
        self,
        machine: MachineConfig,
        positions_mcs: Mapping[str, float] | None = None,
        referenced: bool = False,
        setting_data: Mapping[str, Any] | None = None,
    ) -> None:
        self.machine = machine
        self.params = motion_params(machine)
        self.T = self.params.ipo_cycle_s
        self.names = [a.name for a in self.params.axes]
        self.index = {name: i for i, name in enumerate(self.names)}
        start = np.zeros(len(self.names))
        for name, value in (positions_mcs or {}).items():
            if name in self.index:
                start[self.index[name]] = float(value)
        self.linear_mask = tuple(not a.rotary for a in self.params.axes)
        self.cmd = start.copy()
        self.servo = ServoBank(self.params.axes, self.T, start)
        self.referenced = [bool(referenced)] * len(self.names)
        self.limits = Limits(self.params.axes, setting_data)
        self.jog = JogUnit(self.params, self.limits, self.referenced)
        self.la = LookAhead(self.params)
        self.spindles = {p.name: Spindle(p) for p in self.params.spindles}
        self.run: PathRun | None = None
        self.v_path = 0.0
        self.plan_pos: np.ndarray | None = None
        self.wait_cycles = 0
        self.dwell_rest_cycles = 0  # the rest of a dwell interrupted by NC STOP (MD11470 bit 0)
        self.wait_source: Source | None = None
        self.exact_wait: tuple[np.ndarray, np.ndarray] | None = None
        # The window of the last segment that ended without its exact-stop wait (continuous path):
        # a dwell or a block without path motion waits for it first (002 L4797-4809).
        self.unsettled: tuple[list[bool], np.ndarray, np.ndarray] | None = None
        self.disabled: set[int] = set()  # axes without controller enable
        self.settle_point: np.ndarray | None = None
        self.held = False
        self.faulted = False
        self.stop_source: Source | None = None  # the block a motion alarm stopped (refused or tripped)
        self.refused_source: Source | None = None  # the block whose segment a push refused last
        self.spindle_wait = False  # a WAITS/SPOS wait: checked again when its cycles ran out
        self.spindle_feed_enable = False  # that wait is a machining block's for the set speed range
        self.spindle_checked = False  # that wait has been checked once after its first cycle
        self.hold_point: np.ndarray | None = None
        self.repos_feed: float | None = None
        self.repos_pending = False
        self.dry_run: DryRun | None = None  # SD42100/SD42101 while dry run is switched on
        self.time_s = 0.0
        self.cycles = 0
        self._fraction = 0.0
        self._spun = 0
        self._alarms: list[NcAlarmError] = []
        self._last_source: Source | None = None
        self._trace: list[tuple[np.ndarray, np.ndarray]] | None = None
        self._saved_for_test: np.ndarray | None = None
        self._fine = np.array([a.stop_limit_fine_mm for a in self.params.axes])
        self._coarse = np.array([a.stop_limit_coarse_mm for a in self.params.axes])

    # ------------------------------------------------------------ MotionSystem
    @property
    def ipo_cycle_s(self) -> float:
        """The interpolation cycle in seconds."""
        return self.T

    def can_accept(self) -> bool:
        """True while the look-ahead buffer (MD28060) has room."""
        return len(self.la.items) < self.params.buffer_segments  # (asked several times a block)

    def buffer_fill(self) -> tuple[int, int]:
        """(items in the look-ahead buffer, its capacity MD28060)."""
        return len(self.la), int(self.params.buffer_segments)

    def push(self, item: Motion | Dwell) -> None:
        """Plan a segment (or buffer a dwell) behind the ones already buffered."""
        if isinstance(item, Dwell):
            if item.wait_spindle and item.feed_enable:
                master = self._master()
                if master is not None and master.params.on_speed_at_ipo_start and master.params.speed_tolerance > 0.0:
                    # MD35500 = 0, or MD35150 = 0 (the signal is always 1): no path control.
                    self.la.append(DwellItem(0.0, item.source, wait_spindle=True, feed_enable=True))
            elif item.wait_spindle:
                self.la.append(DwellItem(0.0, item.source, wait_spindle=True))
            elif item.seconds is None:
                # G4 S: counted in revolutions of the master spindle when the dwell starts.
                revolutions = max(float(item.revolutions or 0.0), 0.0)
                self.la.append(DwellItem(0.0, item.source, revolutions=revolutions))
            else:
                self.la.append(DwellItem(max(float(item.seconds), 0.0), item.source))
            return
        if not isinstance(item, Motion):
            return
        segment, alarm = self._checked_segment(item, self._plan_start())
        if alarm is not None:
            self.la.append(AlarmItem(alarm, item.source))
            self.refused_source = item.source
            return
        if segment is None:
            return
        rapid = item.kind == "G0"
        soft = item.gcodes.get(21, "BRISK") == "SOFT" if item.gcodes else False
        window = item.exact_stop_window or "G601"
        factors = None
        if item.accel_pct:
            factors = [float(item.accel_pct.get(name, 100.0)) / 100.0 for name in self.names]
        planned = plan_segment(
            self.params, segment, rapid=rapid, feed_mm_s=None, soft=soft,
            exact_stop=bool(item.exact_stop), window=window, source=item.source,
            accel_factors=factors,
        )
        if not rapid:
            planned.kind = item.kind
            planned.programmed_mm_min = item.feed_mm_min if item.feed_mm_min and item.feed_mm_min > 0 else None
            if item.feed_mm_rev is not None and self._master() is not None and item.kind not in RIGID_TAPPING:
                planned.feed_mm_rev = item.feed_mm_rev  # the feed follows the master spindle
            planned.dry_run = self.dry_run
            planned.feed_mm_s = self._segment_feed_mm_s(planned)
        self.la.append(planned)
        self._replan_if_exit_changed()

    def refusal_of(self, item: Motion) -> NcAlarmError | None:
        """The alarm ``item`` is refused with when it is pushed (software limit 10720, working
        area 10730, value range), without buffering it; the planned position moves on as in
        ``push``. ``nck check`` asks this so that it refuses what the run refuses."""
        start = self.plan_pos.copy() if self.plan_pos is not None else self.cmd.copy()
        return self._checked_segment(item, start)[1]

    def first_refused_end(self, axes: tuple[str, ...], ends_mcs: np.ndarray) -> int | None:
        """Row of the first straight-line end point (rows of ``ends_mcs``, columns ``axes``)
        beyond a software limit or the working area, or None (then the planned position moves
        to the last row). For runs of plain G0/G1 blocks, whose limits are checked at the ends."""
        columns = [(c, self.index[name]) for c, name in enumerate(axes) if name in self.index]
        bad = np.zeros(len(ends_mcs), dtype=bool)
        for c, i in columns:
            if not self.referenced[i]:
                continue
            minus, plus = self.limits.software(i)
            w_minus, w_plus = self.limits.workarea(i)
            values = ends_mcs[:, c]
            bad |= (values > min(plus, w_plus) + EDGE_MM) | (values < max(minus, w_minus) - EDGE_MM)
        rows = np.flatnonzero(bad)
        if rows.size:
            return int(rows[0])
        if len(ends_mcs):
            # A new array: the last buffered segment keeps the one it ended at as its end.
            plan_pos = self.cmd.copy() if self.plan_pos is None else self.plan_pos.copy()
            for c, i in columns:
                plan_pos[i] = float(ends_mcs[-1, c])
            self.plan_pos = plan_pos
        return None

    def _checked_segment(self, item: Motion, start: np.ndarray) -> tuple[Segment | None, NcAlarmError | None]:
        """The segment of ``item`` from ``start``, or the alarm that refuses it."""
        end = start.copy()
        index = self.index
        outside = None  # the first axis beyond POSITION_RANGE_MM
        for name, value in item.end_mcs.items():
            position = float(value)
            if outside is None and (position > POSITION_RANGE_MM or position < -POSITION_RANGE_MM):
                outside = name  # (|position| beyond the range, without the call of abs)
            i = index.get(name)
            if i is not None:
                end[i] = position
                if not math.isfinite(position):
                    return None, _value_range_alarm(item, name)  # an infinite or undefined position
        segment = self._segment(item, start, end)
        self.plan_pos = end
        if segment is None:
            return None, None
        if item.gcodes and 28 in item.gcodes:
            self.limits.workarea_on = item.gcodes[28] != "WALIMOF"
        violation = self.limits.check_segment(segment, self.referenced)
        if violation is not None:
            number, axis, sign = violation
            return None, NcAlarmError(number, axis, sign, file=item.source.file, line=item.source.line,
                                      n=item.source.n)
        if outside is None and segment.arc is not None:
            outside = _centre_outside_range(item)
        if outside is not None:
            # Not caught by a limit switch (axis not referenced): beyond any position the
            # control can represent, where the path arithmetic loses its precision.
            return None, _value_range_alarm(item, outside)
        return segment, None

    def advance(self, dt_s: float) -> None:
        """Advance by ``dt_s`` (rounded to whole IPO cycles, remainders carried)."""
        self._fraction += dt_s / self.T
        n = int(math.floor(self._fraction + 1e-9))
        if n <= 0:
            return
        self._fraction -= n
        self._run_cycles(n, stop_at_event=False)

    def advance_cycles(self, n_cycles: int, on_block_event: Callable[[int], int] | None = None) -> int:
        """Advance at most ``n_cycles`` IPO cycles; stop after the first block event.

        A block event is a cycle after which a program run or the kernel may
        act differently than before it: a segment or dwell ends (the buffer
        gains room, the current block changes), an exact-stop or dwell wait
        ends, a buffered alarm or a monitoring trip is raised, or the axes
        come to rest (``is_idle`` turns true). Returns the cycles advanced
        (≥ 1). Calling this repeatedly, with the caller's per-cycle work done
        between calls, gives the same motion, trace and alarms (in the same
        cycle) as calling ``advance`` with one IPO cycle at a time. While JOG
        moves an axis it advances all ``n_cycles`` (like ``advance``).

        ``on_block_event(cycles_done)``, when given, is called at such a stop
        instead (not after alarms): the caller does its per-cycle work for
        the next cycle there (feeding the program) and answers how many more
        cycles may run before it must be asked again (0 = stop now).
        """
        n = max(1, int(n_cycles))
        if self.jog.runs:
            return self._run_cycles(n, stop_at_event=False)
        return self._run_cycles(n, stop_at_event=True, on_block_event=on_block_event)

    def _run_cycles(self, n: int, stop_at_event: bool, on_block_event: Callable[[int], int] | None = None) -> int:
        """The IPO cycles of :meth:`advance` / :meth:`advance_cycles`; returns the cycles run."""
        self.servo.settle()
        for i, delta in self.jog.take_shifts().items():
            self.servo.x_set[i] += delta
            self.cmd[i] += delta
        done = 0
        while self._quiet():
            # At rest: whole stretches at once; a caller that feeds between cycles is
            # asked after the first cycle (a run may have just reached its end).
            stretch = n - done if on_block_event is None or done > 0 else 1
            self.servo.idle(stretch)
            self._record(np.repeat(self.cmd[None, :], stretch, axis=0))
            self._tick(stretch)
            self._advance_spindles(stretch)
            done += stretch
            if done >= n or on_block_event is None:
                return done
            allowed = on_block_event(done)
            if allowed <= 0:
                return done
            if allowed < n - done:
                n = done + allowed
        if done:
            return done + self._run_moving(n - done, stop_at_event, on_block_event, done)
        return self._run_moving(n, stop_at_event, on_block_event, 0)

    def _run_moving(self, n: int, stop_at_event: bool, on_block_event: Callable[[int], int] | None,
                    offset: int) -> int:
        """The cycles of :meth:`_run_cycles` once something moves (``offset`` cycles already run)."""
        columns = self.jog.fill(n, self.cmd.copy())
        rows = np.empty((n, len(self.names)))
        flat_rows = rows.reshape(-1)  # a view: the array is fresh, hence contiguous
        k = 0
        self._spun = 0  # cycles of this step the spindles have been advanced by
        limit = n
        while k < limit:
            k_end, sync, limit = self._path_fill(rows, flat_rows, k, limit, stop_at_event)
            for i, col in columns.items():
                rows[k:k_end, i] = col[k:k_end]
            actual, trip = self.servo.process(rows[k:k_end], defer=True)
            taken = actual.shape[0]
            if self._trace is not None:
                self._record(rows[k:k + taken])
            if taken:
                self.cmd = rows[k + taken - 1].copy()
            self._tick(taken)
            k += taken
            if trip is not None:
                self._on_trip(trip)
                columns = {}
                if stop_at_event:
                    limit = k
                continue
            if sync:
                waiting = self.exact_wait is not None
                self._check_exact_stop()
                if stop_at_event and waiting and self.exact_wait is None:
                    limit = max(k, 1)  # the exact stop is reached: the next block may start
            if (on_block_event is not None and k == limit and 0 < k < n
                    and not self._alarms and not self.jog.alarms and not self.faulted):
                self._spindles_to(k)  # the caller may read the spindle speeds
                allowed = on_block_event(offset + k)
                if allowed > 0:
                    limit = k + allowed
                    if not limit < n:  # min(n, limit) as the builtin decides (every block event)
                        limit = n
        self.servo.settle()  # the step ends: queued blocks through the position control now
        if k == 0:  # a trip in the very first cycle still took that cycle
            k = 1
        self._spindles_to(k)
        return k

    def _spindles_to(self, k: int) -> None:
        """Advance the spindles to row ``k`` of the step :meth:`_run_moving` is in."""
        self._advance_spindles(k - self._spun)
        self._spun = k

    def _advance_spindles(self, cycles: int) -> None:
        master = self._master()
        before = master.state.setpoint_rpm if master is not None else 0.0
        for spindle in self.spindles.values():
            spindle.advance(cycles * self.T)
        if master is not None and master.state.setpoint_rpm != before:
            self._follow_spindle()  # a speed limit in the setting data changed

    def is_idle(self) -> bool:
        """True when nothing is buffered or moving and every axis is in its coarse window."""
        if (self.run is not None or self.la.items or self.wait_cycles or self.spindle_wait
                or self.exact_wait is not None):
            return False
        if self.jog.active():
            return False
        self.servo.settle()
        return bool(np.all(np.abs(self.servo.v_set) <= 1e-9) and np.all(np.abs(self.servo.e) <= self._coarse))

    def hold(self) -> None:
        """NC STOP: brake along the path and stay interrupted.

        A running dwell (G4) is cancelled (001 L6467-6469), or, with MD11470 bit 0, its rest
        runs after NC START (002 L19242-19243)."""
        self.held = True
        if self.run is not None and self.run.kind == "segment":
            self._brake_path("brake")
        if self.wait_cycles and self.exact_wait is None and not self.spindle_wait:
            self.dwell_rest_cycles = self.wait_cycles if self.params.dwell_resumes else 0
            self.wait_cycles = 0

    def resume(self) -> None:
        """NC START: continue the interrupted segment (after the REPOS approach, if any)."""
        self.held = False
        self.wait_cycles, self.dwell_rest_cycles = max(self.wait_cycles, self.dwell_rest_cycles), 0
        if self.repos_pending and self.hold_point is not None:
            self.repos_pending = False
            start = self.cmd.copy()
            if float(np.max(np.abs(self.hold_point - start))) > 1e-9:
                segment = line(start, self.hold_point.copy(), self.linear_mask)
                rapid = self.repos_feed is None
                feed = None if self.repos_feed is None else self.repos_feed / 60.0
                planned = plan_segment(self.params, segment, rapid=rapid, feed_mm_s=feed, soft=False,
                                       exact_stop=True, window="G601", source=self._last_source)
                if not rapid:
                    planned.kind, planned.programmed_mm_min = "G1", self.repos_feed
                self.la.items.insert(0, planned)
                self.la.recount_ceiling()

    def abort(self, keep_spindles: Collection[str] = ()) -> None:
        """RESET: brake, discard everything buffered, leave follow-up, stop the spindles
        except those named in ``keep_spindles`` (a mode change, or MD35040 = 1)."""
        self.held = False
        self.faulted = False
        self.stop_source = None
        self.refused_source = None
        self.spindle_wait = False
        self.spindle_feed_enable = False
        self.wait_cycles = 0
        self.dwell_rest_cycles = 0
        self.exact_wait = None
        self.unsettled = None
        self.settle_point = None
        self.repos_pending = False
        self.hold_point = None
        self.plan_pos = None
        if self.run is not None and self.run.state()[1] > 1e-9:
            self._brake_path("abort")
            run = self.run
            assert run is not None
            self.plan_pos = run.positions(np.array([run.profile.length]))[0]
        else:
            self.run = None
        self.la.clear()
        self.jog.stop_all(abort_reference=True)
        self.servo.reset()
        self.cmd = self.servo.x_set.copy()
        self.limits.workarea_on = True
        for name, spindle in self.spindles.items():
            if name not in keep_spindles:
                spindle.stop()

    def positions_mcs(self) -> Mapping[str, float]:
        """Positions of every path axis (MCS) and the angle of every spindle.

        These are the position-controller setpoints: at standstill the actual
        value differs from them only by the decaying following error (inside
        the exact-stop window), so displays and REPOS see exact end points.
        The actual values, following errors and drive values are in
        :meth:`axis_states` (service screens).
        """
        self.servo.settle()
        setpoints = self.servo.x_set
        out = {name: float(setpoints[i]) for i, name in enumerate(self.names)}
        for name, spindle in self.spindles.items():
            out[name] = spindle.state.angle_deg
        return out

    def set_overrides(self, feed_percent: float, rapid_percent: float) -> None:
        """Feed and rapid override, on the fly (feed also scales JOG)."""
        feed = max(float(feed_percent), 0.0)
        rapid = max(float(rapid_percent), 0.0)
        if feed == self.la.feed_pct and rapid == self.la.rapid_pct:
            return
        self.la.feed_pct = feed
        self.la.rapid_pct = rapid
        self.la.replan_all()
        self.jog.set_override(feed, self.cmd)
        if self.run is not None and self.run.kind == "segment":
            self._replan_run()

    def reposition(self, feed_mm_min: float | None) -> None:
        """REPOS: on the next resume, return linearly to the hold point first."""
        self.repos_feed = feed_mm_min
        self.repos_pending = True

    def current_source(self) -> Source | None:
        """The block whose segment or dwell is executing."""
        if self.run is not None and self.run.kind != "abort":
            return self.run.chain[0].source
        if self.wait_cycles or self.spindle_wait or self.exact_wait is not None:
            return self.wait_source
        if self.la.items:
            return self.la.items[0].source
        return None

    def path_velocity_mm_min(self) -> float:
        """The interpolator's path velocity at the last IPO cycle (see the protocol)."""
        if self.run is not None:
            return abs(self.run.state()[1]) * 60.0
        return self.jog.velocity_mm_s() * 60.0

    def path_speed_ceiling_mm_s(self) -> float:
        """An upper bound of the path velocity (mm/s) until every segment buffered now has run
        (JOG not included); it also starts the count of :meth:`buffered_speed_ceiling_mm_s`.

        It is the higher of the velocity now and the velocity limit of each buffered segment
        with the overrides: a segment's profile never runs faster than the higher of its
        entry velocity and its limit (a braking run only slows down), and whatever raises a
        limit — an override, a dry run, a new spindle speed for a revolutional feed — replans
        the buffer, which counts the limits again. A profile replanned in a SOFT acceleration
        phase may overshoot its limit a little (the caller's margin)."""
        speed = max(self.v_path, self.la.current_ceiling())
        run = self.run
        if run is not None:
            speed = max(speed, abs(run.state()[1]))
            if run.kind == "segment":
                speed = max(speed, self.la.v_max(run.chain[0]))
        return speed

    def buffered_speed_ceiling_mm_s(self) -> float:
        """The highest velocity limit (mm/s, overrides applied) of the segments buffered since
        the last :meth:`path_speed_ceiling_mm_s` (cheap: kept as they are buffered). With that
        figure it bounds the path velocity until they have run."""
        return self.la.ceiling_mm_s

    def drain_alarms(self) -> list[NcAlarmError]:
        """Alarms raised by monitoring, limits and referencing since the last call."""
        out = self._alarms + self.jog.alarms
        self._alarms = []
        self.jog.alarms = []
        return out

    def cycles_until_block_change(self) -> int:
        """IPO cycles the current segment or dwell surely still runs (≥ 1).

        A caller with nothing else to do per cycle (the headless run) may
        advance this many cycles at once; the motion is the same as cycle by
        cycle, only computed as one numpy block.
        """
        if self.jog.runs or self.run is None:
            return max(self.wait_cycles, 1)
        run = self.run
        left = int((run.profile.duration_s - run.tau) / self.T)
        return max(left, 1)

    # --------------------------------------------------------------- JogControl
    def jog_continuous(self, axis: str, direction: int, velocity_mm_min: float) -> None:
        """Start (±1) or stop (0) continuous JOG of an axis or a spindle."""
        if axis in self.spindles:
            self.spindles[axis].jog(direction)
            return
        if axis in self.index:
            i = self.index[axis]
            if direction and self._refuse_without_enable(i):
                return
            if direction:
                self.plan_pos = None  # the axis leaves the planned end: the next path starts where it stands
            self.jog.continuous(i, direction, velocity_mm_min, float(self.cmd[i]))

    def jog_increment(self, axis: str, distance_mm: float, velocity_mm_min: float) -> None:
        """Traverse one axis by a signed increment."""
        if axis in self.index:
            i = self.index[axis]
            if self._refuse_without_enable(i):
                return
            self.plan_pos = None  # as for continuous JOG
            self.jog.increment(i, distance_mm, velocity_mm_min, float(self.cmd[i]))

    def set_controller_enable(self, axis: str, enabled: bool) -> None:
        """Set or remove the controller enable of a path axis (002 L735-790). Removed while the
        axis moves: every axis stops at once, 21612, follow-up (the trip reaction of the
        monitors); removed at standstill: no alarm, but the axis cannot be traversed."""
        i = self.index[axis]
        if enabled:
            self.disabled.discard(i)
            return
        self.disabled.add(i)
        if self._axis_moving(i):
            self._on_trip(Trip(0, ALARM_CONTROLLER_ENABLE, axis))

    def _axis_moving(self, i: int) -> bool:
        """True while axis ``i`` has a JOG run or takes part in the running path segment."""
        if i in self.jog.runs:
            return True
        run = self.run
        return run is not None and run.kind != "abort" and bool(run.chain[0].moved[i])

    def _refuse_without_enable(self, i: int) -> bool:
        """A traversing request for an axis without controller enable: 21612, nothing moves."""
        if i not in self.disabled:
            return False
        self._alarms.append(NcAlarmError(ALARM_CONTROLLER_ENABLE, self.names[i]))
        return True

    def start_reference(self, axis: str) -> None:
        """Start the reference point approach of one axis."""
        if axis in self.index:
            i = self.index[axis]
            self.jog.start_reference(i, float(self.cmd[i]))

    def is_referenced(self, axis: str) -> bool:
        """True once the axis is referenced (spindles count as referenced)."""
        if axis in self.index:
            return self.referenced[self.index[axis]]
        return True

    def jog_active(self) -> bool:
        """True while a JOG motion or a reference point approach is under way."""
        return self.jog.active()

    def set_referenced(self, axis: str, referenced: bool) -> None:
        """Mark an axis referenced (or not) without motion."""
        if axis in self.index:
            self.referenced[self.index[axis]] = bool(referenced)

    # ----------------------------------------------------------- extensions
    def drain_cleared_alarms(self) -> list[int]:
        """Numbers of self-clearing alarms (10621, 10631) whose cause has gone."""
        out = self.jog.cleared
        self.jog.cleared = []
        return out

    def set_dry_run(self, feed_mm_min: float | None, mode: int = 0) -> None:
        """Dry run on (SD42100 feed, SD42101 mode) or off (None), for every buffered segment
        that has not started yet; the segment in execution keeps its feed unless the path
        is held (002 L18181-18182: activated on interruption or at the end of a block)."""
        dry = DryRun(float(feed_mm_min), int(mode)) if feed_mm_min is not None else None
        if dry == self.dry_run:
            return
        self.dry_run = dry
        running = self.run.chain[0] if self.run is not None and self.run.kind == "segment" else None
        for item in self.la.items:
            if isinstance(item, PlannedSegment) and not item.rapid and item is not running:
                item.dry_run = dry
                item.feed_mm_s = self._segment_feed_mm_s(item)
        self.la.replan_all()
        if running is not None:
            self._replan_run()

    def set_program_test(self, active: bool) -> None:
        """Program test: the display moves, the machine does not (restored when switched off)."""
        if active and self._saved_for_test is None:
            self._saved_for_test = self.servo.actual.copy()
        elif not active and self._saved_for_test is not None:
            for i, value in enumerate(self._saved_for_test):
                self.servo.set_position(i, float(value))
            self.cmd = self._saved_for_test.copy()
            self._saved_for_test = None
            self.plan_pos = None

    def attach_setting_data(self, setting_data: Mapping[str, Any]) -> None:
        """Read the working-area (SD43400 … SD43430) and spindle-limit setting data live."""
        self.limits.setting_data = setting_data
        for spindle in self.spindles.values():
            spindle.setting_data = setting_data

    def set_workarea_monitoring(self, active: bool) -> None:
        """WALIMON / WALIMOF."""
        self.limits.workarea_on = bool(active)

    def spindle_command(self, command: SpindleCommand) -> None:
        """M3/M4/M5/M19/S for a spindle (``spindle`` 1 = the first spindle)."""
        names = list(self.spindles)
        if not names:
            return
        index = min(max(command.spindle, 1), len(names)) - 1
        self.spindles[names[index]].command(command.state, command.speed_rpm, command.position_deg,
                                            command.approach, command.positioning_rpm)
        if index == 0:
            self._follow_spindle()

    def set_spindle_override(self, percent: float) -> None:
        """Spindle override for every spindle."""
        for spindle in self.spindles.values():
            spindle.set_override(percent)
        self._follow_spindle()

    def axis_states(self) -> dict[str, AxisState]:
        """Service-screen values of every path axis."""
        return {name: self.servo.state(i) for i, name in enumerate(self.names)}

    def inject_fault(self, axis: str, **kwargs: float | None) -> None:
        """Simulate a mechanical fault (``jam_at_mm``, ``offset_mm``, ``runaway_mm_s``, ``push_mm``)."""
        self.servo.settle()
        fault = self.servo.faults[self.index[axis]]
        for key, value in kwargs.items():
            setattr(fault, key, value)

    def set_clamped(self, axis: str, clamped: bool) -> None:
        """Clamping in progress (clamping monitoring replaces zero-speed monitoring)."""
        self.servo.settle()
        self.servo.clamped[self.index[axis]] = bool(clamped)

    def enable_trace(self) -> None:
        """Start recording every IPO-cycle setpoint (for ``--trace``)."""
        self._trace = []

    def trace(self) -> tuple[np.ndarray, np.ndarray]:
        """Recorded times (s) and setpoints (rows × path axes, MCS)."""
        if not self._trace:
            return np.zeros(0), np.zeros((0, len(self.names)))
        times = np.concatenate([t for t, _ in self._trace])
        rows = np.concatenate([r for _, r in self._trace])
        return times, rows

    # ------------------------------------------------------------- internals
    def _tick(self, n: int) -> None:
        self.cycles += n
        self.time_s = self.cycles * self.T

    def _record(self, rows: np.ndarray) -> None:
        if self._trace is not None and rows.shape[0]:
            times = (self.cycles + np.arange(1, rows.shape[0] + 1)) * self.T
            self._trace.append((times, rows.copy()))

    def _quiet(self) -> bool:
        return (
            self.run is None and not self.la.items and not self.wait_cycles and self.exact_wait is None
            and not self.spindle_wait and not self.jog.runs and self.servo.settled()
        )

    def _plan_start(self) -> np.ndarray:
        if self.plan_pos is None or (self.run is None and not self.la.items and not self.wait_cycles
                                     and not self.spindle_wait):
            self.plan_pos = self.cmd.copy()
        # No copy: the planned position is only ever replaced, never written into (a buffered
        # segment keeps it as its end, the next one as its start; see Segment).
        return self.plan_pos

    def _segment(self, item: Motion, start: np.ndarray, end: np.ndarray) -> Segment | None:
        centre = item.center_mcs
        if item.kind in ("G2", "G3") and centre:
            name1, name2, _applicate = PLANE_AXES.get(item.plane) or PLANE_AXES["G17"]
            index = self.index
            if name1 in index and name2 in index:
                i1, i2 = index[name1], index[name2]
                # (the start's coordinate only where the centre has none: no numpy item read else)
                c1 = float(centre[name1] if name1 in centre else start[i1])
                c2 = float(centre[name2] if name2 in centre else start[i2])
                seg = arc(start, end, (c1, c2), (i1, i2), item.kind == "G2", item.turns, self.linear_mask)
                return seg if seg.length > 1e-9 else None
        seg = line(start, end, self.linear_mask)
        return seg if seg.length > 1e-9 else None

    def _master(self) -> Spindle | None:
        """The master spindle (the first one), None on a machine without spindles."""
        return next(iter(self.spindles.values()), None)

    def _spindle_feed_mm_min(self, feed_mm_rev: float) -> float:
        """Revolutional feed at the master spindle's speed (002 L55411-55420).

        The speed is the spindle's setpoint: programmed S with the spindle override,
        limited by G26/LIMS and the gear stage; the ramp towards it is not followed.
        """
        master = self._master()
        assert master is not None
        return feed_mm_rev * abs(master.state.setpoint_rpm)

    def _follow_spindle(self) -> None:
        """The master spindle's speed changed: buffered revolutional feeds follow it."""
        changed = False
        for item in self.la.items:
            if isinstance(item, PlannedSegment) and item.feed_mm_rev is not None:
                item.feed_mm_s = self._segment_feed_mm_s(item)
                changed = True
        if not changed:
            return
        self.la.replan_all()
        if self.run is not None and self.run.kind == "segment":
            self._replan_run()

    def _spindle_settle_s(self) -> float:
        """Seconds until the master spindle is positioned, stands or turns in its set speed
        range (for a machining block's wait: see :meth:`Spindle.settle_s`)."""
        master = self._master()
        return master.settle_s(self.spindle_feed_enable) if master is not None else 0.0

    @property
    def waiting_for_spindle(self) -> bool:
        """True while a machining block waits for the master spindle's set speed range
        (MD35500; DB31 DBX83.5 is 0)."""
        return self.spindle_wait and self.spindle_feed_enable and self.run is None

    def _dwell_s(self, revolutions: float) -> float:
        """Seconds the master spindle needs for ``revolutions`` from its speed now (0 if it stands)."""
        master = self._master()
        return master.seconds_for_revolutions(revolutions) if master is not None else 0.0

    def _segment_feed_mm_s(self, seg: PlannedSegment) -> float:
        """The path feed of a non-rapid segment: programmed, or F × the master spindle's speed
        under G95, replaced by the segment's dry run feed (002 L18151-18158)."""
        feed = seg.programmed_mm_min
        if seg.feed_mm_rev is not None:
            feed = self._spindle_feed_mm_min(seg.feed_mm_rev)
        if seg.dry_run is not None:
            feed = seg.dry_run.feed_for(seg.kind, feed)
        return (feed if feed is not None else 0.0) / 60.0

    def _replan_if_exit_changed(self) -> None:
        run = self.run
        if run is None or run.kind != "segment":
            return
        head = run.chain[0]
        exit_v = head.exit_limit
        vmax = self.la.v_max(head)
        if vmax < exit_v:  # min(exit limit, vmax) as the builtin decides (every push comes here)
            exit_v = vmax
        if abs(exit_v - run.exit_target) > 1e-9:
            self._replan_run()

    def _replan_run(self) -> None:
        """Rebuild the running segment's profile from the current state (override, look-ahead)."""
        run = self.run
        assert run is not None
        s, v, a = run.state()
        seg = run.chain[0]
        seg.done_s = run.s_begin + s
        vmax = self.la.v_max(seg)
        if vmax <= 1e-9:
            self._brake_path("brake")
            return
        exit_v = min(seg.exit_limit, vmax)
        profile = build_profile(seg.remaining, v, exit_v, vmax, seg.accel, seg.jerk, a_start=a)
        if profile.v_end > exit_v + 1e-6 and profile.v_end > run.profile.v_end + 1e-6:
            # Too late to brake harder within this segment: keep the running profile
            # (its end velocity is safe); the new limits apply from the next segment.
            seg.done_s = run.s_begin
            return
        self.run = PathRun([seg], seg.done_s, profile, tau=0.0, kind="segment", exit_target=exit_v)

    def _brake_path(self, kind: str) -> None:
        run = self.run
        assert run is not None
        s, v, a = run.state()
        head = run.chain[0]
        s_begin = run.s_begin + s
        profile = braking_profile(v, a, head.accel, head.jerk)
        chain = [head]
        covered = head.segment.length - s_begin
        if run.kind == "segment":
            items = self.la.items
            index = 1
            while covered < profile.length and index < len(items) and isinstance(items[index], PlannedSegment):
                chain.append(items[index])  # type: ignore[arg-type]
                covered += items[index].segment.length  # type: ignore[union-attr]
                index += 1
        else:
            chain = list(run.chain)
        self.run = PathRun(chain, s_begin, profile, tau=0.0, kind=kind)


def _centre_outside_range(item: Motion) -> str | None:
    """The first centre coordinate of ``item`` beyond :data:`POSITION_RANGE_MM`, else None."""
    for name, value in (item.center_mcs or {}).items():
        if abs(float(value)) > POSITION_RANGE_MM:
            return name
    return None


def planned_motion_factory(machine: MachineConfig) -> PlannedMotion:
    """``motion_factory`` for :class:`nck.kernel.Nck`: the real motion system."""
    return PlannedMotion(machine)


def _value_range_alarm(item: Motion, axis: str) -> NcAlarmError:
    return NcAlarmError(ALARM_VALUE_RANGE, axis, file=item.source.file, line=item.source.line, n=item.source.n)
