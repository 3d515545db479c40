"""A minimal stand-in motion system: straight lines at constant speed, no dynamics.

It implements :class:`nck.motion.api.MotionSystem` and :class:`JogControl`
so the channel can be built and tested before the real planner exists:

* a path segment moves every axis linearly from where it stands to
  ``end_mcs`` at the (overridden) feed, rapid traverse at the axis maximum
  velocity (``MD32000``, default 10 000 mm/min); arcs are run as chords;
* NC STOP (``hold``) stops at once (no braking ramp), ``resume`` continues;
* JOG moves one axis at the given velocity; an increment stops at its end;
* a reference point approach takes :data:`REFERENCE_TIME_S` without motion.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass
from typing import Collection, Mapping

from nck.canon import Dwell, Motion, Source
from nck.errors import NcAlarmError
from nck.machine import MachineConfig
from nck.motion.dry_run import DryRun

BUFFER_SEGMENTS = 8
REFERENCE_TIME_S = 0.5
DEFAULT_RAPID_MM_MIN = 10000.0
EPSILON_MM = 1e-9


@dataclass
class _Segment:
    """A straight move to ``target`` at ``feed_mm_min`` (None = rapid): the programmed
    ``programmed_mm_min`` of a ``kind`` block, with the dry run it runs with."""

    target: dict[str, float]
    feed_mm_min: float | None
    source: Source | None
    kind: str = "G0"
    programmed_mm_min: float | None = None
    moved: bool = False  # has started: keeps its feed when dry run is switched while running


@dataclass
class _Pause:
    """A dwell of ``remaining_s`` seconds."""

    remaining_s: float
    source: Source | None


@dataclass
class _Jog:
    """One axis moving in JOG: continuous (``target`` None) or to ``target``."""

    axis: str
    direction: int
    velocity_mm_min: float
    target: float | None


class InstantMotion:
    """Straight-line motion at constant speed; see the module docstring."""

    def __init__(
        self,
        machine: MachineConfig,
        positions_mcs: Mapping[str, float] | None = None,
        referenced: bool = False,
    ) -> None:
        self._machine = machine
        self._axes = machine.path_axes
        self._pos = {name: 0.0 for name in self._axes}
        if positions_mcs:
            for name, value in positions_mcs.items():
                if name in self._pos:
                    self._pos[name] = float(value)
        self._queue: deque[_Segment | _Pause] = deque()
        self._held = False
        self._hold_point: dict[str, float] | None = None
        self._feed_pct = 100.0
        self._rapid_pct = 100.0
        self._jogs: dict[str, _Jog] = {}
        self._referenced = {name: referenced for name in self._axes}
        self._ref_timers: dict[str, float] = {}
        self._alarms: list[NcAlarmError] = []
        self._dry_run: DryRun | None = None

    # -- MotionSystem -------------------------------------------------------
    def can_accept(self) -> bool:
        """True while fewer than :data:`BUFFER_SEGMENTS` items are buffered."""
        return len(self._queue) < BUFFER_SEGMENTS

    def buffer_fill(self) -> tuple[int, int]:
        """(items buffered, :data:`BUFFER_SEGMENTS`)."""
        return len(self._queue), BUFFER_SEGMENTS

    def path_speed_ceiling_mm_s(self) -> float | None:
        """None: the stand-in jumps to its targets, it has no path velocity to bound."""
        return None

    def buffered_speed_ceiling_mm_s(self) -> float:
        """0: nothing of the stand-in's is planned."""
        return 0.0

    def push(self, item: Motion | Dwell) -> None:
        """Buffer a segment (target = its MCS end point) or a dwell."""
        if isinstance(item, Dwell):
            self._queue.append(_Pause(float(item.seconds or 0.0), item.source))
            return
        target = {name: float(item.end_mcs.get(name, math.nan)) for name in self._axes}
        target = {k: v for k, v in target.items() if not math.isnan(v)}
        programmed = None if item.kind == "G0" else item.feed_mm_min
        feed = programmed if self._dry_run is None else self._dry_run.feed_for(item.kind, programmed)
        self._queue.append(_Segment(target, feed, item.source, item.kind, programmed))

    def advance(self, dt_s: float) -> None:
        """Move everything by ``dt_s`` seconds of simulated time."""
        self._advance_reference(dt_s)
        self._advance_jog(dt_s)
        if self._held:
            return
        remaining = dt_s
        while remaining > 0.0 and self._queue:
            item = self._queue[0]
            if isinstance(item, _Pause):
                used = min(remaining, item.remaining_s)
                item.remaining_s -= used
                remaining -= used
                if item.remaining_s <= 0.0:
                    self._queue.popleft()
                continue
            remaining = self._advance_segment(item, remaining)
            if remaining > 0.0 or self._distance(item.target) <= EPSILON_MM:
                self._queue.popleft()

    def is_idle(self) -> bool:
        """True when nothing is buffered, no JOG and no referencing is under way."""
        return not self._queue and not self._jogs and not self._ref_timers


    def hold(self) -> None:
        """Stop at once and remember the hold point for REPOS."""
        if not self._held:
            self._held = True
            self._hold_point = dict(self._pos)

    def resume(self) -> None:
        """Continue after :meth:`hold`."""
        self._held = False
        self._hold_point = None

    def abort(self, keep_spindles: Collection[str] = ()) -> None:
        """Discard everything buffered and stop JOG and referencing (no spindles here)."""
        self._queue.clear()
        self._jogs.clear()
        self._ref_timers.clear()
        self._held = False
        self._hold_point = None

    def positions_mcs(self) -> Mapping[str, float]:
        """Actual positions (a copy)."""
        return dict(self._pos)

    def set_overrides(self, feed_percent: float, rapid_percent: float) -> None:
        """Set feed override (also JOG) and rapid override in percent."""
        self._feed_pct = max(0.0, float(feed_percent))
        self._rapid_pct = max(0.0, float(rapid_percent))

    def reposition(self, feed_mm_min: float | None) -> None:
        """Insert the way back to the hold point in front of the remainder."""
        if self._hold_point is None:
            return
        self._queue.appendleft(_Segment(dict(self._hold_point), feed_mm_min, None))

    def current_source(self) -> Source | None:
        """Source of the item at the head of the buffer."""
        for item in self._queue:
            if item.source is not None:
                return item.source
        return None

    def set_dry_run(self, feed_mm_min: float | None, mode: int = 0) -> None:
        """Dry run on (SD42100, SD42101) or off (None) for the segments not yet started (all
        of them while held)."""
        self._dry_run = DryRun(float(feed_mm_min), int(mode)) if feed_mm_min is not None else None
        for item in self._queue:
            if isinstance(item, _Segment) and item.kind != "G0" and (self._held or not item.moved):
                item.feed_mm_min = (item.programmed_mm_min if self._dry_run is None
                                    else self._dry_run.feed_for(item.kind, item.programmed_mm_min))

    def path_velocity_mm_min(self) -> float:
        """Velocity of the head segment (0 while held or in a dwell), else of the JOG motion."""
        head = self._queue[0] if self._queue and not self._held else None
        if isinstance(head, _Segment) and self._distance(head.target) > EPSILON_MM:
            return self._speed_mm_min(head)
        squares = sum((jog.velocity_mm_min * self._feed_pct / 100.0) ** 2 for jog in self._jogs.values())
        return math.sqrt(squares)

    def drain_alarms(self) -> list[NcAlarmError]:
        """The stand-in monitors nothing; always empty."""
        alarms, self._alarms = self._alarms, []
        return alarms

    # -- JogControl ---------------------------------------------------------
    def jog_continuous(self, axis: str, direction: int, velocity_mm_min: float) -> None:
        """Start (±1) or stop (0) continuous JOG of ``axis``."""
        if axis not in self._pos:
            return
        if direction == 0:
            self._jogs.pop(axis, None)
            return
        self._jogs[axis] = _Jog(axis, 1 if direction > 0 else -1, float(velocity_mm_min), None)

    def jog_increment(self, axis: str, distance_mm: float, velocity_mm_min: float) -> None:
        """Move ``axis`` by ``distance_mm``."""
        if axis not in self._pos or abs(distance_mm) <= EPSILON_MM:
            return
        direction = 1 if distance_mm > 0 else -1
        running = self._jogs.get(axis)
        base = running.target if running is not None and running.target is not None else self._pos[axis]
        self._jogs[axis] = _Jog(axis, direction, float(velocity_mm_min), base + distance_mm)

    def start_reference(self, axis: str) -> None:
        """Reference ``axis`` after :data:`REFERENCE_TIME_S`."""
        if axis in self._pos and axis not in self._ref_timers:
            self._ref_timers[axis] = REFERENCE_TIME_S

    def is_referenced(self, axis: str) -> bool:
        """True once referenced (spindles always count as referenced)."""
        return self._referenced.get(axis, True)

    def jog_active(self) -> bool:
        """True while a JOG motion or a reference point approach is under way."""
        return bool(self._jogs or self._ref_timers)

    def set_referenced(self, axis: str, referenced: bool) -> None:
        """Set the referenced flag directly."""
        if axis in self._referenced:
            self._referenced[axis] = bool(referenced)

    # -- internals ----------------------------------------------------------
    def _rapid_mm_min(self) -> float:
        velocities = [
            float(self._machine.md_value("MD32000", name, DEFAULT_RAPID_MM_MIN) or DEFAULT_RAPID_MM_MIN)
            for name in self._axes
        ]
        return min(velocities) if velocities else DEFAULT_RAPID_MM_MIN

    def _speed_mm_min(self, seg: _Segment) -> float:
        """The segment's velocity: its feed or rapid traverse, with the override."""
        if seg.feed_mm_min is None:
            return self._rapid_mm_min() * self._rapid_pct / 100.0
        return seg.feed_mm_min * self._feed_pct / 100.0

    def _distance(self, target: Mapping[str, float]) -> float:
        return math.sqrt(sum((target[k] - self._pos[k]) ** 2 for k in target))

    def _advance_segment(self, seg: _Segment, dt_s: float) -> float:
        """Move towards the segment end; return the unused time."""
        speed = self._speed_mm_min(seg)
        distance = self._distance(seg.target)
        if distance <= EPSILON_MM:
            self._pos.update(seg.target)
            return dt_s
        if speed <= 0.0:
            return 0.0
        seg.moved = True
        needed_s = distance / (speed / 60.0)
        if needed_s <= dt_s:
            self._pos.update(seg.target)
            return dt_s - needed_s
        fraction = dt_s / needed_s
        for name, end in seg.target.items():
            self._pos[name] += (end - self._pos[name]) * fraction
        return 0.0

    def _advance_jog(self, dt_s: float) -> None:
        for axis in list(self._jogs):
            jog = self._jogs[axis]
            step = jog.velocity_mm_min * self._feed_pct / 100.0 / 60.0 * dt_s
            if jog.target is None:
                self._pos[axis] += jog.direction * step
                continue
            left = jog.target - self._pos[axis]
            if abs(left) <= step:
                self._pos[axis] = jog.target
                del self._jogs[axis]
            else:
                self._pos[axis] += math.copysign(step, left)

    def _advance_reference(self, dt_s: float) -> None:
        for axis in list(self._ref_timers):
            self._ref_timers[axis] -= dt_s
            if self._ref_timers[axis] <= 1e-12:
                del self._ref_timers[axis]
                self._referenced[axis] = True


def instant_motion_factory(machine: MachineConfig) -> InstantMotion:
    """``motion_factory`` for :class:`nck.kernel.Nck`: the stand-in motion system."""
    return InstantMotion(machine)
