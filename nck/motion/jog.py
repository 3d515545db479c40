"""JOG (continuous, incremental) and the reference point approach, per axis.

Each moving axis has an :class:`AxisRun` (BRISK, MD32300, velocity from the
caller times the feed override). The reference point approach runs the three
phases of the manual for an incremental encoder with cam:

1. to the cam at MD34020 in the direction of MD34010 (skipped when the axis
   already stands on the cam or MD34000 = 0); no cam within MD34030 → 20000;
2. off the cam at creep speed MD34040 (override not active) to the first zero
   mark after the cam edge (marks every leadscrew pitch MD31030); none within
   MD34060 → 20002;
3. on by MD34080 + MD34090 at MD34070; then the position is set to MD34100
   and the axis is referenced.

RESET (``abort``) during the approach leaves the axis unreferenced.
"""

from __future__ import annotations

import math

import numpy as np

from nck.errors import NcAlarmError
from nck.motion.limits import EDGE_MM, Limits
from nck.motion.params import MotionParams
from nck.motion.profile import braking_profile, build_profile
from nck.motion.runs import AxisRun

UNLIMITED_MM = 1e6
ALARM_NO_CAM = 20000
ALARM_NO_ZERO_MARK = 20002
ALARM_HW_LIMIT = 21614


class JogUnit:
    """Single-axis motions of JOG and referencing."""

    def __init__(self, params: MotionParams, limits: Limits, referenced: list[bool]) -> None:
        self.params = params
        self.limits = limits
        self.referenced = referenced
        self.T = params.ipo_cycle_s
        self.runs: dict[int, AxisRun] = {}
        self.feed_pct = 100.0
        self.alarms: list[NcAlarmError] = []
        self.cleared: list[int] = []
        self.limit_alarm: dict[int, int] = {}
        self.pending_shift: dict[int, float] = {}
        self.raw_offset = [0.0] * len(params.axes)  # referenced coordinate − raw encoder coordinate

    # -- commands ----------------------------------------------------------
    def active(self) -> bool:
        """True while any axis moves in JOG or referencing."""
        return bool(self.runs) or bool(self.pending_shift)

    def velocity_mm_s(self) -> float:
        """Resulting velocity of the axes moving now (their vector sum; 0 when none moves)."""
        squares = sum(run.profile.state_at(max(run.tau, 0.0))[1] ** 2 for run in self.runs.values())
        return math.sqrt(squares)

    def referencing(self, i: int) -> bool:
        """True while axis ``i`` runs its reference point approach."""
        run = self.runs.get(i)
        return run is not None and run.purpose.startswith("ref")

    def continuous(self, i: int, direction: int, velocity_mm_min: float, position: float) -> None:
        """Start continuous JOG, or stop it (``direction`` 0)."""
        if direction == 0:
            self.stop(i)
            return
        self._start_to_limit(i, 1.0 if direction > 0 else -1.0, velocity_mm_min, position, None)

    def increment(self, i: int, distance_mm: float, velocity_mm_min: float, position: float) -> None:
        """Traverse axis ``i`` by ``distance_mm`` (stopping at an active limit)."""
        if abs(distance_mm) <= EDGE_MM:
            return
        self._start_to_limit(i, math.copysign(1.0, distance_mm), velocity_mm_min, position, abs(distance_mm))

    def _start_to_limit(self, i: int, direction: float, velocity_mm_min: float, position: float,
                        distance: float | None) -> None:
        if self.referencing(i):
            return
        limit, alarm = self.limits.jog_limit(i, direction, self.referenced[i])
        room = (limit - position) * direction
        if alarm and room <= EDGE_MM:
            sign = "+" if direction > 0 else "-"
            self.alarms.append(NcAlarmError(alarm, self.params.axes[i].name, sign))
            self.limit_alarm[i] = alarm
            return
        switch = self._hardware_switch(i, direction)
        to_switch = (switch - position) * direction
        if to_switch <= EDGE_MM:
            # Standing on the switch: the traversing keys of this direction are blocked.
            self.alarms.append(NcAlarmError(ALARM_HW_LIMIT, self.params.axes[i].name, "+" if direction > 0 else "-"))
            return
        self._clear_limit_alarm(i)
        room = min(room, UNLIMITED_MM)
        length = room if distance is None else min(distance, room)
        if length > to_switch - EDGE_MM:
            self._begin_past_switch(i, position, direction, to_switch, velocity_mm_min / 60.0, switch)
            return
        self._begin(i, position, direction, length, velocity_mm_min / 60.0, "jog", override=True)

    def _hardware_switch(self, i: int, direction: float) -> float:
        """Position (current coordinate) of the hardware limit switch in ``direction``."""
        axis = self.params.axes[i]
        raw = axis.hw_limit_plus_mm if direction > 0 else axis.hw_limit_minus_mm
        return raw + self.raw_offset[i]

    def _begin_past_switch(self, i: int, position: float, direction: float, to_switch: float,
                           v_mm_s: float, switch: float) -> None:
        """A JOG motion that reaches the hardware limit switch (002 L2355-2375): on at JOG
        velocity up to the switch, then braked as MD36600 says: 0 with the axial acceleration
        MD32300 (the axis stops beyond the switch), 1 setpoint velocity zero at the switch."""
        axis = self.params.axes[i]
        accel = axis.max_accel_mm_s2
        current = self.runs.get(i)
        v0 = 0.0
        if current is not None and current.direction == direction and not current.purpose.startswith("ref"):
            _s, v0, _a = current.profile.state_at(max(current.tau, 0.0))
        vmax = self._capped(i, v_mm_s * self.feed_pct / 100.0)
        v_switch = min(vmax, math.sqrt(v0 * v0 + 2.0 * accel * to_switch))
        if axis.brake_mode_choice == 1:
            profile = build_profile(to_switch, v0, v_switch, vmax, accel, None)
        else:
            overrun = v_switch * v_switch / (2.0 * accel)
            profile = build_profile(to_switch + overrun, v0, 0.0, vmax, accel, None)
        self.runs[i] = AxisRun(i, position, direction, profile, "jog", v_mm_s, True, limit_switch_mm=switch)

    def stop(self, i: int) -> None:
        """Brake a JOG motion of axis ``i`` (not a reference approach)."""
        self._clear_limit_alarm(i)
        run = self.runs.get(i)
        if run is None or run.purpose.startswith("ref") or run.stopping:
            return
        self._brake(i, run)

    def stop_all(self, abort_reference: bool) -> None:
        """Brake every JOG motion; with ``abort_reference`` also the reference approaches."""
        for i, run in list(self.runs.items()):
            if run.purpose.startswith("ref"):
                if not abort_reference:
                    continue
                self.referenced[i] = False
            if not run.stopping:
                self._brake(i, run)

    def start_reference(self, i: int, position: float) -> None:
        """Start the reference point approach of axis ``i``."""
        if self.referencing(i):
            return
        axis = self.params.axes[i]
        self.referenced[i] = False
        self._clear_limit_alarm(i)
        direction = -1.0 if axis.ref_cam_dir_minus else 1.0
        raw = position - self.raw_offset[i]
        cam = axis.ref_cam_mm
        if not axis.ref_cam_active or (raw - cam) * direction >= 0.0:
            self._phase2(i, position)
            return
        distance = (cam - raw) * direction
        v = axis.ref_velo_search_cam_mm_s
        overrun = v * v / (2.0 * axis.max_accel_mm_s2)
        if distance > axis.ref_max_cam_dist_mm:
            self._begin(i, position, direction, axis.ref_max_cam_dist_mm, v, "ref_fail_cam", override=True)
            return
        self._begin(i, position, direction, distance + overrun, v, "ref1", override=True)

    def set_override(self, percent: float, positions: np.ndarray) -> None:
        """Feed override for JOG: replan moving axes from their current state."""
        self.feed_pct = max(float(percent), 0.0)
        for i, run in list(self.runs.items()):
            if run.override and not run.stopping:
                s, v, a = run.profile.state_at(max(run.tau, 0.0))
                rest = run.profile.length - s
                vmax = self._capped(i, run.velocity_mm_s * self.feed_pct / 100.0)
                profile = build_profile(rest, v, 0.0, vmax, self.params.axes[i].max_accel_mm_s2, None)
                self.runs[i] = AxisRun(i, run.origin + run.direction * s, run.direction, profile, run.purpose,
                                       run.velocity_mm_s, run.override, limit_switch_mm=run.limit_switch_mm)

    def take_shifts(self) -> dict[int, float]:
        """Coordinate shifts of axes whose approach just ended; they count as referenced now."""
        shifts = dict(self.pending_shift)
        self.pending_shift.clear()
        for i in shifts:
            self.referenced[i] = True
        return shifts

    # -- sampling ----------------------------------------------------------
    def fill(self, n: int, positions: np.ndarray) -> dict[int, np.ndarray]:
        """Setpoint columns of every moving axis for the next ``n`` IPO cycles."""
        columns: dict[int, np.ndarray] = {}
        T = self.T
        for i in list(self.runs):
            col = np.empty(n)
            k = 0
            run: AxisRun | None = self.runs[i]
            value = positions[i]
            while run is not None and k < n:
                room = n - k
                taus = run.tau + T * np.arange(1, room + 1)
                m = int(np.searchsorted(taus, run.profile.duration_s + 1e-12, side="right"))
                if m:
                    s = run.profile.sample(taus[:m])[0]
                    col[k:k + m] = run.position_at(s)
                    run.tau = float(taus[m - 1])
                    value = float(col[k + m - 1])
                    k += m
                    self._check_switch(run, value)
                if m == room:
                    break
                carry = run.tau - run.profile.duration_s
                value = run.end_position
                self._check_switch(run, value + run.direction * 2.0 * EDGE_MM)
                run = self._on_end(i, run, value)
                if run is not None:
                    run.tau = carry
            col[k:] = value
            columns[i] = col
        return columns

    # -- internals ---------------------------------------------------------
    def _check_switch(self, run: AxisRun, position: float) -> None:
        """Alarm 21614 once the run has reached its hardware limit switch."""
        switch = run.limit_switch_mm
        if switch is None or (position - switch) * run.direction < 0.0:
            return
        run.limit_switch_mm = None
        sign = "+" if run.direction > 0 else "-"
        self.alarms.append(NcAlarmError(ALARM_HW_LIMIT, self.params.axes[run.index].name, sign))

    def _begin(self, i: int, position: float, direction: float, length: float, v_mm_s: float,
               purpose: str, override: bool) -> None:
        accel = self.params.axes[i].max_accel_mm_s2
        current = self.runs.get(i)
        v0 = 0.0
        if current is not None and current.direction == direction and not current.purpose.startswith("ref"):
            _s, v0, _a = current.profile.state_at(max(current.tau, 0.0))
        vmax = self._capped(i, v_mm_s * (self.feed_pct / 100.0 if override else 1.0))
        profile = build_profile(max(length, 0.0), v0, 0.0, vmax, accel, None)
        self.runs[i] = AxisRun(i, position, direction, profile, purpose, v_mm_s, override)

    def _capped(self, i: int, v_mm_s: float) -> float:
        """No JOG velocity (rapid, override) beyond the axis' maximum velocity MD32000."""
        return min(v_mm_s, self.params.axes[i].max_velo_mm_s)

    def _brake(self, i: int, run: AxisRun) -> None:
        s, v, a = run.profile.state_at(max(run.tau, 0.0))
        profile = braking_profile(v, 0.0, self.params.axes[i].max_accel_mm_s2, None)
        origin = run.origin + run.direction * s
        purpose = "brake"
        self.runs[i] = AxisRun(i, origin, run.direction, profile, purpose, v, False, stopping=True)

    def _phase2(self, i: int, position: float) -> None:
        axis = self.params.axes[i]
        direction = -1.0 if axis.ref_cam_dir_minus else 1.0
        raw = position - self.raw_offset[i]
        grid = max(axis.leadscrew_pitch_mm, 1e-3)
        edge = axis.ref_cam_mm if axis.ref_cam_active else raw
        # First zero mark beyond the cam edge, moving against the approach direction.
        if direction > 0:
            mark = math.floor((min(edge, raw) - 1e-9) / grid) * grid
        else:
            mark = math.ceil((max(edge, raw) + 1e-9) / grid) * grid
        distance = (raw - mark) * direction
        if abs(mark - edge) > axis.ref_max_marker_dist_mm:
            self._begin(i, position, -direction, axis.ref_max_marker_dist_mm + abs(raw - edge),
                        axis.ref_velo_search_marker_mm_s, "ref_fail_mark", override=False)
            return
        self._begin(i, position, -direction, distance, axis.ref_velo_search_marker_mm_s, "ref2", override=False)

    def _on_end(self, i: int, run: AxisRun, position: float) -> AxisRun | None:
        axis = self.params.axes[i]
        del self.runs[i]
        if run.purpose == "ref1":
            self._phase2(i, position)
        elif run.purpose == "ref2":
            move = axis.ref_move_dist_mm
            direction = -1.0 if axis.ref_cam_dir_minus else 1.0
            sign = direction if move >= 0 else -direction
            self._begin(i, position, sign, abs(move), axis.ref_velo_pos_mm_s, "ref3", override=True)
        elif run.purpose == "ref3":
            delta = axis.ref_set_pos_mm - position
            self.pending_shift[i] = self.pending_shift.get(i, 0.0) + delta
            self.raw_offset[i] += delta
        elif run.purpose == "ref_fail_cam":
            self.alarms.append(NcAlarmError(ALARM_NO_CAM, axis.name))
        elif run.purpose == "ref_fail_mark":
            self.alarms.append(NcAlarmError(ALARM_NO_ZERO_MARK, axis.name))
        return self.runs.get(i)

    def _clear_limit_alarm(self, i: int) -> None:
        number = self.limit_alarm.pop(i, None)
        if number is not None:
            self.cleared.append(number)
