"""Look-ahead planning: velocity limits of each segment and at each transition.

Each buffered segment gets the highest path velocity its axes allow (MD32000),
its path acceleration and jerk (MD32300/MD32431 scaled by the direction share
of each axis, with the G0/SOFT factors MD32434/32435/32433), arc limits from
the radial acceleration share MD20602, and the short-block limit
``0.9 · length / IPO cycle``. At each transition of continuous-path mode the
velocity is lowered until no axis's velocity jump exceeds
``MD32300 · (MD32310 − 1) · T`` (BRISK) or ``MD32431 · (MD32310 − 1) · T²``
(SOFT; plus the curvature jump). A backward pass then makes sure the path can
always brake to standstill at the end of the last buffered segment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from nck.canon import Source
from nck.errors import NcAlarmError
from nck.motion.dry_run import DryRun
from nck.motion.params import MotionParams
from nck.motion.path import Segment
from nck.motion.profile import reach_up

SHORT_BLOCK_FACTOR = 0.9


class AxisArrays:
    """Per-axis limits as numpy arrays (built once per machine, for vectorised planning)."""

    def __init__(self, params: MotionParams) -> None:
        axes = params.axes
        T = params.ipo_cycle_s
        self.vmax = np.array([a.max_velo_mm_s for a in axes])
        self.amax = np.array([a.max_accel_mm_s2 for a in axes])
        self.jmax = np.array([a.max_jerk_mm_s3 for a in axes])
        self.g0_accel = np.array([a.g0_accel_factor for a in axes])
        self.g0_jerk = np.array([a.g0_jerk_factor for a in axes])
        self.soft_accel = np.array([a.soft_accel_factor for a in axes])
        reserve = np.array([a.accel_ovl_factor - 1.0 for a in axes])
        self.corner_brisk = reserve * self.amax * T
        self.corner_soft = reserve * self.jmax * T * T
        self.curvature_soft = reserve * self.jmax * T
        # The same per axis as Python floats: on three axes a loop is cheaper than numpy.
        self.rows = list(zip(self.vmax.tolist(), self.amax.tolist(), self.jmax.tolist(), self.g0_accel.tolist(),
                             self.g0_jerk.tolist(), self.soft_accel.tolist()))
        self.corner_brisk_floats = self.corner_brisk.tolist()
        self.corner_soft_floats = self.corner_soft.tolist()


_ARRAYS: dict[int, tuple[MotionParams, AxisArrays]] = {}


def axis_arrays(params: MotionParams) -> AxisArrays:
    """The (cached) arrays of ``params``."""
    entry = _ARRAYS.get(id(params))
    if entry is None or entry[0] is not params:
        entry = (params, AxisArrays(params))
        _ARRAYS[id(params)] = entry
    return entry[1]


@dataclass
class PlannedSegment:
    """A segment with its dynamic limits and its place in the look-ahead chain."""

    segment: Segment
    source: Source | None
    rapid: bool
    feed_mm_s: float | None  # programmed path feed (after dry run); None for rapid traverse
    v_cap_mm_s: float  # axis, arc and short-block limits (no override)
    accel: float
    jerk: float | None  # None = BRISK
    exact_stop: bool
    window: str  # G601 / G602 / G603
    moved: list[bool]  # axes that move
    junction_out: float = 0.0  # velocity limit at the end (0 until a successor is known)
    exit_limit: float = 0.0  # result of the backward pass
    done_s: float = 0.0  # distance already travelled (after an interruption)
    feed_mm_rev: float | None = None  # revolutional feed: feed_mm_s follows the master spindle
    kind: str = "G0"  # the block's motion type (G1, G2, G33 …: dry run spares threads in SD42101 10-12)
    programmed_mm_min: float | None = None  # the programmed feed per minute (not G95)
    dry_run: DryRun | None = None  # the dry run this segment runs with (fixed once it executes)

    @property
    def remaining(self) -> float:
        """Path distance still to go."""
        # max(…, 0.0) as the builtin decides (the first argument unless the second is greater)
        remaining = self.segment.length - self.done_s
        return 0.0 if 0.0 > remaining else remaining

    def v_max(self, feed_pct: float, rapid_pct: float) -> float:
        """Velocity limit with the overrides applied."""
        # min(…) and max(…) as the builtins decide (the first argument unless the second
        # compares less, resp. greater), without their calls: asked several times per block
        if self.feed_mm_s is None:
            if 0.0 > rapid_pct:
                rapid_pct = 0.0
            if 100.0 < rapid_pct:
                rapid_pct = 100.0
            return self.v_cap_mm_s * rapid_pct / 100.0
        if 0.0 > feed_pct:
            feed_pct = 0.0
        cap = self.v_cap_mm_s
        feed = self.feed_mm_s * feed_pct / 100.0
        return feed if feed < cap else cap


@dataclass
class DwellItem:
    """G4: wait ``seconds``, or ``revolutions`` of the master spindle (counted when it starts)."""

    seconds: float
    source: Source | None
    revolutions: float | None = None
    wait_spindle: bool = False  # WAITS, SPOS, M19: until the master spindle has settled
    feed_enable: bool = False  # with wait_spindle: a machining block waits for the set speed range (MD35500)


@dataclass
class AlarmItem:
    """A block that must not start: when execution reaches it, raise the alarm and stop."""

    alarm: NcAlarmError
    source: Source | None


BufferItem = PlannedSegment | DwellItem | AlarmItem


def plan_segment(
    params: MotionParams,
    segment: Segment,
    *,
    rapid: bool,
    feed_mm_s: float | None,
    soft: bool,
    exact_stop: bool,
    window: str,
    source: Source | None,
    accel_factors: list[float] | None = None,
) -> PlannedSegment:
    """Compute the limits of one segment (``accel_factors``: ACC per axis, 1 = 100 %)."""
    share = segment.max_direction_share()
    moved: list[bool] = []
    axes = params.axes
    arrays = axis_arrays(params)
    v_cap = a_lin = j_lin = math.inf
    moving = False
    for index, (part, (vmax, amax, jmax, g0_accel, g0_jerk, soft_accel)) in enumerate(
            zip(share, arrays.rows)):
        moved.append(part > 1e-12)
        if part <= 1e-12:
            continue
        moving = True
        if accel_factors is not None:
            amax *= accel_factors[index]
        inv = 1.0 / part
        accel_ax, jerk_ax = amax, jmax
        if rapid:
            accel_ax, jerk_ax = accel_ax * g0_accel, jerk_ax * g0_jerk
        if soft:
            accel_ax = accel_ax * soft_accel
        # min(limit, value) as the builtin decides (the limit unless the value is less)
        value = vmax * inv
        if value < v_cap:
            v_cap = value
        value = accel_ax * inv
        if value < a_lin:
            a_lin = value
        value = jerk_ax * inv
        if value < j_lin:
            j_lin = value
    if not moving:
        v_cap, a_lin, j_lin = 0.0, 1.0, 1.0
    accel = a_lin
    jerk: float | None = j_lin if soft else None
    if segment.arc is not None:
        i1, i2 = segment.arc[0], segment.arc[1]
        radius = segment.min_radius
        f = params.curv_effect
        a_plane = min(axes[i1].max_accel_mm_s2, axes[i2].max_accel_mm_s2)
        if f > 0.0:
            v_cap = min(v_cap, math.sqrt(f * a_plane * radius))
            accel = max((1.0 - f) * a_lin, 1e-3)
        if soft:
            j_plane = min(axes[i1].max_jerk_mm_s3, axes[i2].max_jerk_mm_s3)
            v_cap = min(v_cap, (j_plane / 3.0 * radius * radius) ** (1.0 / 3.0))
            jerk = j_lin / 3.0
            if v_cap > 0.0:
                accel = min(accel, max(j_plane * radius / (9.0 * v_cap), 1e-3))
    short_block = SHORT_BLOCK_FACTOR * segment.length / params.ipo_cycle_s
    if short_block < v_cap:  # min(v_cap, short_block) as the builtin decides
        v_cap = short_block
    return PlannedSegment(
        segment=segment, source=source, rapid=rapid, feed_mm_s=feed_mm_s, v_cap_mm_s=v_cap,
        accel=accel, jerk=jerk, exact_stop=exact_stop, window=window, moved=moved,
    )


def junction_limit(params: MotionParams, prev: PlannedSegment, nxt: PlannedSegment) -> float:
    """Highest velocity at the transition from ``prev`` to ``nxt`` in continuous-path mode."""
    if prev.exact_stop or (prev.jerk is None) != (nxt.jerk is None):
        return 0.0
    arrays = axis_arrays(params)
    soft = nxt.jerk is not None
    limit = math.inf
    allowed = arrays.corner_soft_floats if soft else arrays.corner_brisk_floats
    for before, after, corner in zip(prev.segment.tangent_floats(True), nxt.segment.tangent_floats(False), allowed):
        jump = abs(after - before)
        if jump > 1e-12:
            value = corner / jump
            if value < limit:  # min(limit, value) as the builtin decides
                limit = value
    if soft and (prev.segment.arc is not None or nxt.segment.arc is not None):
        dk = np.abs(nxt.segment.curvature(False) - prev.segment.curvature(True))
        curved = dk > 1e-12
        if curved.any():
            limit = min(limit, float(np.min(np.sqrt(arrays.curvature_soft[curved] / dk[curved]))))
    return 0.0 if 0.0 > limit else limit  # max(limit, 0.0) as the builtin decides


@dataclass
class LookAhead:
    """The buffer of planned items and the backward pass over it."""

    params: MotionParams
    items: list[BufferItem] = field(default_factory=list)
    feed_pct: float = 100.0
    rapid_pct: float = 100.0
    ceiling_mm_s: float = 0.0  # the highest velocity limit of the segments buffered since the last recount
    left_since_recount: bool = False  # an item left the buffer since: the ceiling may be lower now

    def __len__(self) -> int:
        return len(self.items)

    def v_max(self, seg: PlannedSegment) -> float:
        """Velocity limit of ``seg`` with the current overrides."""
        return seg.v_max(self.feed_pct, self.rapid_pct)

    def entry_max(self, seg: PlannedSegment) -> float:
        """Highest velocity at which ``seg`` may be entered (its exit limit still reachable)."""
        return min(self.v_max(seg), reach_up(seg.exit_limit, seg.remaining, seg.accel, seg.jerk))

    def append(self, item: BufferItem) -> None:
        """Buffer an item; update the transition limits backwards."""
        if isinstance(item, PlannedSegment):
            item.exit_limit = 0.0
            ceiling = item.v_max(self.feed_pct, self.rapid_pct)
            if ceiling > self.ceiling_mm_s:
                self.ceiling_mm_s = ceiling
            prev = self.items[-1] if self.items else None
            if isinstance(prev, PlannedSegment):
                prev.junction_out = junction_limit(self.params, prev, item)
            self.items.append(item)
            self._propagate(len(self.items) - 2)
        else:
            self.items.append(item)

    def _propagate(self, index: int) -> None:
        """Backward pass from ``index`` down while limits keep changing."""
        items, feed_pct, rapid_pct = self.items, self.feed_pct, self.rapid_pct
        while index >= 0:
            seg = items[index]
            nxt = items[index + 1]
            if not isinstance(seg, PlannedSegment):
                return
            if isinstance(nxt, PlannedSegment):
                # min(junction, entry_max(nxt), v_max(seg)) with the two methods written out, and
                # the builtin min's choices too (the first value unless a later one is less)
                entry = nxt.v_max(feed_pct, rapid_pct)
                reach = reach_up(nxt.exit_limit, nxt.remaining, nxt.accel, nxt.jerk)
                if reach < entry:
                    entry = reach
                new = seg.junction_out
                if entry < new:
                    new = entry
                limit = seg.v_max(feed_pct, rapid_pct)
                if limit < new:
                    new = limit
            else:
                new = 0.0
            if abs(new - seg.exit_limit) <= 1e-12:
                return
            seg.exit_limit = new
            index -= 1

    def recount_ceiling(self) -> None:
        """:attr:`ceiling_mm_s` of the segments buffered now (with the current overrides)."""
        self.ceiling_mm_s = max((self.v_max(item) for item in self.items if isinstance(item, PlannedSegment)),
                                default=0.0)
        self.left_since_recount = False

    def current_ceiling(self) -> float:
        """:attr:`ceiling_mm_s` of the segments buffered now, counted again only when an item left
        the buffer since the last count: otherwise the buffer is the one counted plus the items
        appended since, each of which raised the ceiling to its limit as it came (and whatever
        changes a limit replans the buffer, which counts again)."""
        if self.left_since_recount:
            self.recount_ceiling()
        return self.ceiling_mm_s

    def replan_all(self) -> None:
        """Full backward pass (after an override change, a dry run or a revolutional feed's new
        spindle speed); the velocity ceiling is counted again."""
        self.recount_ceiling()
        for index in range(len(self.items) - 1, -1, -1):
            seg = self.items[index]
            if not isinstance(seg, PlannedSegment):
                continue
            nxt = self.items[index + 1] if index + 1 < len(self.items) else None
            if isinstance(nxt, PlannedSegment):
                seg.exit_limit = min(seg.junction_out, self.entry_max(nxt), self.v_max(seg))
            else:
                seg.exit_limit = 0.0

    def pop_front(self) -> BufferItem:
        """Remove and return the head item."""
        self.left_since_recount = True
        return self.items.pop(0)

    def clear(self) -> None:
        """Discard everything."""
        self.items.clear()
        self.ceiling_mm_s = 0.0
