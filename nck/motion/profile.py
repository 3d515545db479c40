"""One-dimensional velocity profiles along a path coordinate.

A :class:`Profile` is a sequence of phases with constant jerk; it maps time
since its start to path distance, velocity and acceleration and is sampled
with numpy for a whole block at once. The builders make

* BRISK profiles (acceleration-limited, trapezoidal velocity: ``jerk=None``),
* SOFT profiles (jerk-limited S-curves: every velocity change starts and ends
  at zero acceleration, so a chain of such blocks is jerk-limited too).

Units are consistent but arbitrary (the planner uses mm, s).
"""

from __future__ import annotations

import math
from bisect import bisect_right

import numpy as np

TINY = 1e-12


class Profile:
    """Phases of constant jerk: start times, and distance/velocity/acceleration at each start.

    ``phases`` holds ``(t0, s0, v0, a0, j)`` of every phase as Python floats;
    ``duration_s`` is the end of the last phase; ``length`` the distance covered.
    The same columns as numpy arrays (``t0`` … ``j``) are made when a sampling
    over several phases first needs them (most blocks never do).
    """

    __slots__ = ("phases", "starts", "duration_s", "length", "v_end", "scalar_exact", "_columns")

    def __init__(self, phases: tuple[tuple[float, float, float, float, float], ...], duration_s: float,
                 length: float, v_end: float) -> None:
        self.phases = phases
        starts = []  # t0 of every phase
        jerk_free = True
        for row in phases:
            starts.append(row[0])
            if row[4]:
                jerk_free = False
        self.starts = tuple(starts)
        self.duration_s = duration_s
        self.length = length
        self.v_end = v_end
        # Without jerk (BRISK) and of sane duration, distances_after gives distances' values bit
        # for bit at any time: both add s0 + v0·dt, then the acceleration term; the jerk term
        # adds exactly zero (with jerk, numpy's and Python's dt**3 may round differently, and
        # dt**3 of a phase longer than 1e100 s could overflow).
        self.scalar_exact = duration_s < 1e100 and jerk_free
        self._columns: np.ndarray | None = None

    def _column(self, index: int) -> np.ndarray:
        columns = self._columns
        if columns is None:
            columns = self._columns = np.array(self.phases, dtype=float).T.copy()
        return columns[index]

    @property
    def t0(self) -> np.ndarray:
        """Start time of every phase."""
        return self._column(0)

    @property
    def s0(self) -> np.ndarray:
        """Distance at the start of every phase."""
        return self._column(1)

    @property
    def v0(self) -> np.ndarray:
        """Velocity at the start of every phase."""
        return self._column(2)

    @property
    def a0(self) -> np.ndarray:
        """Acceleration at the start of every phase."""
        return self._column(3)

    @property
    def j(self) -> np.ndarray:
        """Jerk of every phase."""
        return self._column(4)

    def sample(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Return distance, velocity and acceleration at times ``t`` (clipped to the profile)."""
        t = np.minimum(np.maximum(t, 0.0), self.duration_s)
        idx = np.searchsorted(self.t0, t, side="right") - 1
        np.maximum(idx, 0, out=idx)
        dt = t - self.t0[idx]
        j = self.j[idx]
        a = self.a0[idx]
        v = self.v0[idx]
        s = self.s0[idx] + v * dt + a * dt * dt / 2.0 + j * dt**3 / 6.0
        vel = v + a * dt + j * dt * dt / 2.0
        acc = a + j * dt
        return np.minimum(s, self.length), vel, acc

    def distances(self, t: np.ndarray) -> np.ndarray:
        """Distance only at increasing times ``t`` (the interpolator's hot path; same formula as :meth:`sample`)."""
        t = np.minimum(np.maximum(t, 0.0), self.duration_s)
        starts = self.starts
        if starts:
            first = bisect_right(starts, float(t[0])) - 1
            if first == bisect_right(starts, float(t[-1])) - 1:
                # All samples in one phase (mostly a cruise): scalar coefficients, fewer steps.
                # Terms whose coefficient is zero add exactly nothing (s is never -0.0 here).
                t0, s0, v0, a0, j = self.phases[max(first, 0)]
                dt = t - t0
                s = v0 * dt
                s += s0
                if a0 != 0.0:
                    s += a0 * dt * dt / 2.0
                if j != 0.0:
                    s += j * dt**3 / 6.0
                return np.minimum(s, self.length)
        idx = np.searchsorted(self.t0, t, side="right") - 1
        np.maximum(idx, 0, out=idx)
        dt = t - self.t0[idx]
        s = self.s0[idx] + self.v0[idx] * dt + self.a0[idx] * dt * dt / 2.0 + self.j[idx] * dt**3 / 6.0
        return np.minimum(s, self.length)

    def distances_after(self, tau: float, period: float, count: int, offset: float | None = None) -> list[float]:
        """Distances at ``tau + period·1`` … ``tau + period·count`` with Python floats (the same
        formula as :meth:`distances`, term by term; the interpolator's form for short blocks),
        each added to ``offset`` when given (``offset + distance``)."""
        phases, starts, duration, length = self.phases, self.starts, self.duration_s, self.length
        last = len(starts) - 1
        # Within a phase without jerk the cubic term adds exactly nothing when dt**3 is finite
        # (dt ≤ duration): +0.0 (j is never -0.0, dt never negative) to a distance that is never
        # -0.0 (s0 ≥ +0.0 plus terms); so it is left out there, as :meth:`distances` does.
        finite = duration < 1e100
        i = 0
        t0, s0, v0, a, j = phases[0]
        curved = a != 0.0 or j != 0.0
        cubic = j != 0.0 or not finite
        out: list[float] = []
        append = out.append
        for n in range(1, count + 1):
            # min(max(t, 0.0), duration) and min(s, length) as the builtins decide (the first
            # argument unless the second compares greater, resp. less), without their calls
            t = tau + period * n
            if 0.0 > t:
                t = 0.0
            if duration < t:
                t = duration
            if i < last and starts[i + 1] <= t:
                while i < last and starts[i + 1] <= t:
                    i += 1  # the times increase: the phase only moves forward
                t0, s0, v0, a, j = phases[i]
                curved = a != 0.0 or j != 0.0
                cubic = j != 0.0 or not finite
            dt = t - t0
            s = s0 + v0 * dt
            if curved:
                s = s + a * dt * dt / 2.0
                if cubic:
                    s = s + j * dt**3 / 6.0
            if length < s:
                s = length
            append(s if offset is None else offset + s)
        return out

    def state_at(self, t: float) -> tuple[float, float, float]:
        """Distance, velocity and acceleration at one instant (:meth:`sample`'s values).

        In a phase without jerk, with Python floats: the terms of :meth:`sample` with their
        jerk term exactly zero (the kernel asks this every IPO cycle while it steps single
        cycles, e.g. while a tool is in the material); with jerk through :meth:`sample`, whose
        ``dt**3`` numpy may round differently from Python."""
        t = min(max(t, 0.0), self.duration_s)
        index = max(bisect_right(self.starts, t) - 1, 0)
        t0, s0, v0, a0, j = self.phases[index]
        dt = t - t0
        if j != 0.0 or not dt < 1e100:
            s, v, a = self.sample(np.array([t]))
            return float(s[0]), float(v[0]), float(a[0])
        # sample's expressions, term by term; j·dt³ is a zero of j's sign however dt³ rounds
        distance = s0 + v0 * dt + a0 * dt * dt / 2.0 + j * (dt * dt * dt) / 6.0
        return min(distance, self.length), v0 + a0 * dt + j * dt * dt / 2.0, a0 + j * dt


class _Builder:
    """Accumulates constant-jerk phases."""

    def __init__(self, v: float, a: float = 0.0) -> None:
        self.t = 0.0
        self.s = 0.0
        self.v = v
        self.a = a
        self.rows: list[tuple[float, float, float, float, float]] = []

    def phase(self, duration: float, jerk: float) -> None:
        if duration <= TINY:
            return
        self.rows.append((self.t, self.s, self.v, self.a, jerk))
        d = duration
        if jerk == 0.0 and self.a == 0.0:
            self.s += self.v * d  # cruise (no powers of d: huge distances stay finite)
        else:
            self.s += self.v * d + self.a * d * d / 2.0 + jerk * d**3 / 6.0
        self.v += self.a * d + jerk * d * d / 2.0
        self.a += jerk * d
        self.t += d

    def accel_phase(self, duration: float, accel: float) -> None:
        """Constant acceleration (BRISK): the acceleration jumps to ``accel``."""
        if duration <= TINY:
            return
        self.a = accel
        self.phase(duration, 0.0)
        self.a = 0.0

    def ramp(self, v_target: float, accel: float, jerk: float | None) -> None:
        """Change velocity from the current value (at zero acceleration) to ``v_target``."""
        dv = v_target - self.v
        if abs(dv) <= TINY:
            self.v = v_target
            return
        sign = 1.0 if dv > 0 else -1.0
        dv = abs(dv)
        if jerk is None:
            self.accel_phase(dv / accel, sign * accel)
        else:
            if dv >= accel * accel / jerk:
                tj = accel / jerk
                ta = dv / accel - tj
            else:
                tj = math.sqrt(dv / jerk)
                ta = 0.0
            self.phase(tj, sign * jerk)
            self.phase(ta, 0.0)
            self.phase(tj, -sign * jerk)
            self.a = 0.0
        self.v = v_target

    def cruise(self, distance: float) -> None:
        if distance > TINY and self.v > TINY:
            self.a = 0.0
            self.phase(distance / self.v, 0.0)

    def build(self, length: float) -> Profile:
        if not self.rows:
            self.rows.append((0.0, 0.0, self.v, 0.0, 0.0))
        return Profile(tuple(self.rows), duration_s=self.t, length=min(length, self.s + 1e-9),
                       v_end=max(self.v, 0.0))


def ramp_distance(v_a: float, v_b: float, accel: float, jerk: float | None) -> float:
    """Distance needed to change velocity from ``v_a`` to ``v_b`` (zero acceleration at both ends)."""
    if jerk is None:
        return abs(v_b * v_b - v_a * v_a) / (2.0 * accel)
    dv = abs(v_b - v_a)
    if dv >= accel * accel / jerk:
        duration = dv / accel + accel / jerk
    else:
        duration = 2.0 * math.sqrt(dv / jerk)
    return (v_a + v_b) / 2.0 * duration


def reach_up(v_start: float, length: float, accel: float, jerk: float | None) -> float:
    """Highest velocity reachable from ``v_start`` within ``length`` (also: highest entry
    velocity from which ``v_start`` can still be reached by braking, by symmetry)."""
    if length <= 0.0:
        return v_start
    if jerk is None:
        return math.sqrt(v_start * v_start + 2.0 * accel * length)
    # Short ramp (no constant-acceleration phase): u = sqrt(dv), u^3 + 2 v u - L sqrt(j) = 0.
    sj = math.sqrt(jerk)
    p = 2.0 * v_start
    q = -length * sj
    disc = (q / 2.0) ** 2 + (p / 3.0) ** 3
    root = math.sqrt(disc)
    u = np.cbrt(-q / 2.0 + root) + np.cbrt(-q / 2.0 - root)
    dv = float(u) ** 2
    if dv <= accel * accel / jerk:
        return v_start + dv
    # Long ramp: (2v + dv)(dv/a + a/j) = 2L  ->  dv^2/a + dv (a/j + 2v/a) + 2 v a / j - 2L = 0
    qa = 1.0 / accel
    qb = accel / jerk + 2.0 * v_start / accel
    qc = 2.0 * v_start * accel / jerk - 2.0 * length
    dv = (-qb + math.sqrt(max(qb * qb - 4.0 * qa * qc, 0.0))) / (2.0 * qa)
    return v_start + max(dv, 0.0)


def reach_down(v_start: float, length: float, accel: float, jerk: float | None) -> float:
    """Lowest velocity reachable from ``v_start`` by braking within ``length``."""
    if ramp_distance(v_start, 0.0, accel, jerk) <= length:
        return 0.0
    lo, hi = 0.0, v_start
    for _ in range(60):
        mid = (lo + hi) / 2.0
        if ramp_distance(v_start, mid, accel, jerk) > length:
            lo = mid
        else:
            hi = mid
    return hi


def settle_acceleration(builder: _Builder, jerk: float | None) -> None:
    """Bring a non-zero starting acceleration to zero with the jerk limit (SOFT)."""
    if jerk is None or abs(builder.a) <= TINY:
        builder.a = 0.0
        return
    a = builder.a
    builder.phase(abs(a) / jerk, -math.copysign(jerk, a))
    builder.a = 0.0


def build_profile(
    length: float,
    v_start: float,
    v_end: float,
    v_max: float,
    accel: float,
    jerk: float | None,
    a_start: float = 0.0,
) -> Profile:
    """Fastest profile over ``length`` from ``v_start`` to ``v_end`` not above ``v_max``.

    If ``v_end`` cannot be reached within ``length`` the profile ends at the
    nearest reachable velocity (see ``Profile.v_end``).
    """
    if jerk is None:
        brisk = _brisk_profile(length, v_start, v_end, v_max, accel)
        if brisk is not None:
            return brisk
    return build_profile_stepwise(length, v_start, v_end, v_max, accel, jerk, a_start)


def build_profile_stepwise(
    length: float,
    v_start: float,
    v_end: float,
    v_max: float,
    accel: float,
    jerk: float | None,
    a_start: float = 0.0,
) -> Profile:
    """:func:`build_profile` phase by phase with the builder (every case; without jerk,
    :func:`build_profile` mostly takes a written-out form with the same floats)."""
    builder = _Builder(max(v_start, 0.0), a_start)
    settle_acceleration(builder, jerk)
    rest = length - builder.s
    v0 = builder.v
    v_max = max(v_max, 0.0)
    if rest <= TINY:
        return builder.build(max(builder.s, length))
    v_end = min(max(v_end, 0.0), v_max)
    # Feasibility of the end velocity.
    if v_end > v0:
        v_end = min(v_end, reach_up(v0, rest, accel, jerk))
    elif v_end < v0:
        v_end = max(v_end, reach_down(v0, rest, accel, jerk))
    if v0 > v_max:
        peak = max(v_max, v_end)
    else:
        peak = _peak(v0, v_end, v_max, rest, accel, jerk)
    if peak <= TINY and v0 <= TINY:
        # Nothing can move (feed 0): an empty profile that never ends the block.
        return builder.build(length)
    d1 = ramp_distance(v0, peak, accel, jerk)
    d3 = ramp_distance(peak, v_end, accel, jerk)
    if v0 > v_max and d1 + d3 > rest * (1.0 + 1e-9) + 1e-12:
        # Above the new limit and too close to the end to get down to it: cruise at the
        # lowest velocity from which the end velocity is still reached (between the
        # limit and the current velocity; the current one is feasible, see above).
        lo, hi = peak, v0
        for _ in range(50):
            mid = (lo + hi) / 2.0
            if _ramps_distance(v0, mid, v_end, accel, jerk) <= rest:
                hi = mid
            else:
                lo = mid
        peak = hi
        d1 = ramp_distance(v0, peak, accel, jerk)
        d3 = ramp_distance(peak, v_end, accel, jerk)
    builder.ramp(peak, accel, jerk)
    builder.cruise(rest - d1 - d3)
    builder.ramp(v_end, accel, jerk)
    return builder.build(length)


def _brisk_profile(length: float, v_start: float, v_end: float, v_max: float, accel: float) -> Profile | None:
    """:func:`build_profile` without jerk, the same floats in the same order (the builder's
    steps written out: ramp, cruise, ramp; BRISK starts at zero acceleration whatever
    ``a_start``), for the usual case; None for the rare ones (nothing left to go, no
    movement, braking that needs the bisections), which the builder then takes."""
    # (min and max written out as the builtins decide: the first argument unless the second
    # compares less, resp. greater; once per block, where their calls were a good part)
    v = 0.0 if 0.0 > v_start else v_start
    rest = length - 0.0
    if 0.0 > v_max:
        v_max = 0.0
    if rest <= TINY:
        return None
    if 0.0 > v_end:
        v_end = 0.0
    if v_max < v_end:
        v_end = v_max
    if v_end > v:
        reach = reach_up(v, rest, accel, None)
        if reach < v_end:
            v_end = reach
    elif v_end < v:
        if not ramp_distance(v, 0.0, accel, None) <= rest:
            return None  # reach_down's bisection
        if 0.0 > v_end:
            v_end = 0.0
    if v > v_max:
        peak = v_end if v_end > v_max else v_max
    else:
        peak = _peak(v, v_end, v_max, rest, accel, None)
    if peak <= TINY and v <= TINY:
        return None
    d1 = ramp_distance(v, peak, accel, None)
    d3 = ramp_distance(peak, v_end, accel, None)
    if v > v_max and d1 + d3 > rest * (1.0 + 1e-9) + 1e-12:
        return None
    # _Builder(v).ramp(peak), .cruise(rest - d1 - d3), .ramp(v_end), .build(length), with the
    # builder's tests as written (the same outcome for NaN) and without its dead updates (the
    # velocity after a ramp is its target, the acceleration is set before it is read again).
    t = s = 0.0
    rows: list[tuple[float, float, float, float, float]] = []
    for target, cruise in ((peak, rest - d1 - d3), (v_end, None)):
        dv = target - v
        if not abs(dv) <= TINY:  # _Builder.ramp, accel_phase, phase
            d = abs(dv) / accel
            a = (1.0 if dv > 0 else -1.0) * accel
            if not d <= TINY:
                rows.append((t, s, v, a, 0.0))
                s += v * d + a * d * d / 2.0 + 0.0 * d**3 / 6.0
                t += d
        v = target
        if cruise is not None and cruise > TINY and v > TINY:  # _Builder.cruise and phase
            d = cruise / v
            if not d <= TINY:
                rows.append((t, s, v, 0.0, 0.0))
                s += v * d
                v += 0.0 * d + 0.0 * d * d / 2.0
                t += d
    if not rows:
        rows.append((0.0, 0.0, v, 0.0, 0.0))
    return Profile(tuple(rows), duration_s=t, length=min(length, s + 1e-9), v_end=max(v, 0.0))


def _peak(v0: float, v1: float, v_max: float, length: float, accel: float, jerk: float | None) -> float:
    """Highest cruise velocity so that both ramps fit into ``length``."""
    # (min and max written out as the builtins decide: the first argument unless the second
    # compares less, resp. greater; once per block)
    low = v1 if v1 > v0 else v0
    if v_max <= low:
        return v_max if v_max >= v1 else v1
    if _ramps_distance(v0, v_max, v1, accel, jerk) <= length:
        return v_max
    if jerk is None:
        vp = math.sqrt((2.0 * accel * length + v0 * v0 + v1 * v1) / 2.0)
        peak = low if low > vp else vp
        return v_max if v_max < peak else peak
    lo, hi = low, v_max
    for _ in range(40):
        mid = (lo + hi) / 2.0
        if _ramps_distance(v0, mid, v1, accel, jerk) <= length:
            lo = mid
        else:
            hi = mid
    return lo


def _ramps_distance(v0: float, peak: float, v1: float, accel: float, jerk: float | None) -> float:
    """Distance of the two ramps ``v0`` → ``peak`` → ``v1``."""
    return ramp_distance(v0, peak, accel, jerk) + ramp_distance(peak, v1, accel, jerk)


def braking_profile(v_start: float, a_start: float, accel: float, jerk: float | None) -> Profile:
    """Stop as fast as the limits allow from (``v_start``, ``a_start``)."""
    builder = _Builder(max(v_start, 0.0), a_start)
    if jerk is None:
        builder.a = 0.0
        builder.ramp(0.0, accel, None)
        return builder.build(builder.s)
    if a_start >= 0.0:
        settle_acceleration(builder, jerk)
        builder.ramp(0.0, accel, jerk)
        return builder.build(builder.s)
    a1 = min(-a_start, accel)
    builder.a = -a1
    v = builder.v
    if v <= a1 * a1 / (2.0 * jerk):
        builder.phase(a1 / jerk, jerk)
        builder.a = 0.0
        builder.v = 0.0
        return builder.build(builder.s)
    drop_up = (accel * accel - a1 * a1) / (2.0 * jerk)
    drop_down = accel * accel / (2.0 * jerk)
    if v >= drop_up + drop_down:
        builder.phase((accel - a1) / jerk, -jerk)
        builder.phase((v - drop_up - drop_down) / accel, 0.0)
        builder.phase(accel / jerk, jerk)
    else:
        peak = math.sqrt((2.0 * jerk * v + a1 * a1) / 2.0)
        builder.phase((peak - a1) / jerk, -jerk)
        builder.phase(peak / jerk, jerk)
    builder.a = 0.0
    builder.v = 0.0
    return builder.build(builder.s)
