"""Path segments in axis space: straight lines, arcs and helices.

A segment maps the path distance ``s`` (0 … ``length``) to a position vector
over all path axes of the machine (numpy, vectorised over many ``s`` at
once) and knows its unit tangent and curvature vector at both ends, which the
planner needs for corner and curvature-jump limits.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from itertools import compress
from operator import sub

import numpy as np

#: Plane -> (abscissa, ordinate, applicate) axis names.
PLANE_AXES = {"G17": ("X", "Y", "Z"), "G18": ("Z", "X", "Y"), "G19": ("Y", "Z", "X")}
MIN_LENGTH_MM = 1e-9


class Segment:
    """One path element. ``arc`` is None for a straight line.

    Attributes:
        start, end: position vectors (all path axes, MCS); the segment keeps the arrays it is
            given (:func:`line` and :func:`arc` hand it their own), so nobody may change them.
        length: path length used for the feed (mm).
        arc: (i1, i2, c1, c2, r_start, r_end, theta0, sweep) for arcs and helices.
        delta: ``end - start`` (made on first use; :meth:`floats` has it as Python floats).
    """

    __slots__ = ("start", "end", "length", "arc", "_delta", "_tangents", "_floats", "_pairs")

    def __init__(self, start: np.ndarray, end: np.ndarray, length: float,
                 arc: tuple[int, int, float, float, float, float, float, float] | None = None) -> None:
        self.start = start
        self.end = end
        self.length = length
        self.arc = arc
        self._delta: np.ndarray | None = None
        self._tangents: dict[bool, list[float]] = {}
        # start, delta, end as Python floats (the same differences as numpy's end - start)
        starts, ends = start.tolist(), end.tolist()
        self._floats = (starts, list(map(sub, ends, starts)), ends)
        self._pairs: list[tuple[float, float]] | None = None  # (start, delta) of every axis, for points

    @property
    def delta(self) -> np.ndarray:
        """``end - start`` (made on first use)."""
        delta = self._delta
        if delta is None:
            delta = self._delta = self.end - self.start
        return delta

    def __repr__(self) -> str:
        return f"Segment(start={self.start!r}, end={self.end!r}, length={self.length!r}, arc={self.arc!r})"

    def positions(self, s: np.ndarray) -> np.ndarray:
        """Positions at path distances ``s`` (shape ``(len(s), n_axes)``)."""
        lam = np.minimum(np.maximum(s * (1.0 / self.length), 0.0), 1.0) if self.length > 0 else np.ones_like(s)
        out = self.start + lam[:, None] * self.delta
        if self.arc is not None:
            i1, i2, c1, c2, r0, r1, th0, sweep = self.arc
            theta = th0 + lam * sweep
            radius = r0 + lam * (r1 - r0)
            out[:, i1] = c1 + radius * np.cos(theta)
            out[:, i2] = c2 + radius * np.sin(theta)
            # Pin the end exactly (no cos/sin rounding at the block end).
            at_end = lam >= 1.0
            if np.any(at_end):
                out[at_end] = self.end
        return out

    def floats(self) -> tuple[list[float], list[float], list[float]]:
        """``start``, ``delta`` and ``end`` as lists of Python floats (the caller must not change
        them)."""
        return self._floats

    def points(self, distances: list[float]) -> list[float]:
        """Positions at path distances ``distances`` in Python floats, row after row in one flat
        list: the rows of :meth:`positions` bit for bit (the same operations in the same order,
        the arc's end pinned), cheaper than numpy for a handful of rows."""
        length = self.length
        inv = 1.0 / length if length > 0 else 0.0
        arc = self.arc
        out: list[float] = []
        append = out.append  # (a loop of appends: cheaper than a list comprehension per row)
        axes = self._pairs
        if axes is None:
            start, delta, _end = self._floats
            axes = self._pairs = list(zip(start, delta))
        if arc is not None:  # (unpacked once, not per row; r1 - r0 is the same float every row)
            i1, i2, c1, c2, r0, r1, th0, sweep = arc
            dr = r1 - r0
            end = self._floats[2]
        for s in distances:
            if length > 0:
                # min(max(s·inv, 0.0), 1.0) as the builtins decide, without their calls
                lam = s * inv
                if 0.0 > lam:
                    lam = 0.0
                if 1.0 < lam:
                    lam = 1.0
            else:
                lam = 1.0
            if arc is None:
                for x0, d in axes:
                    append(x0 + lam * d)
                continue
            if lam >= 1.0:
                out.extend(end)
                continue
            row = len(out)
            for x0, d in axes:
                append(x0 + lam * d)
            theta = th0 + lam * sweep
            radius = r0 + lam * dr
            out[row + i1] = c1 + radius * math.cos(theta)
            out[row + i2] = c2 + radius * math.sin(theta)
        return out

    def _arc_at(self, lam: float) -> tuple[int, int, float, float, float, float]:
        """The arc's plane axes, angle, radius, radius change and sweep at ``lam``."""
        i1, i2, _c1, _c2, r0, r1, th0, sweep = self.arc  # type: ignore[misc]
        return i1, i2, th0 + lam * sweep, r0 + lam * (r1 - r0), r1 - r0, sweep

    def _first_derivative(self, lam: float) -> list[float]:
        """d/ds of the position at ``lam`` (fraction of the length)."""
        length = self.length
        first = [d / length for d in self._floats[1]]
        if self.arc is not None:
            i1, i2, th, r, dr, sweep = self._arc_at(lam)
            first[i1] = (dr * math.cos(th) - r * sweep * math.sin(th)) / length
            first[i2] = (dr * math.sin(th) + r * sweep * math.cos(th)) / length
        return first

    def tangent(self, at_end: bool) -> np.ndarray:
        """Unit tangent at the start or the end."""
        return np.array(self.tangent_floats(at_end))

    def tangent_floats(self, at_end: bool) -> list[float]:
        """The unit tangent at the start or the end as Python floats (cached; the caller must
        not change the list)."""
        cached = self._tangents.get(at_end)
        if cached is not None:
            return cached
        if self.arc is None:
            length = self.length  # (Python's division: numpy's correctly rounded quotients)
            values = [d / length for d in self._floats[1]]
        else:
            values = self._first_derivative(1.0 if at_end else 0.0)
        first = np.array(values)
        norm = math.sqrt(first.dot(first))  # numpy's dot (BLAS, fused multiply-add)
        # (an element-wise division: the same correctly rounded quotients as numpy's)
        result = [value / norm for value in values] if norm > 0 else values
        if self.arc is None:
            self._tangents[True] = self._tangents[False] = result  # a line has one direction
        else:
            self._tangents[at_end] = result
        return result

    def curvature(self, at_end: bool) -> np.ndarray:
        """Curvature vector d²p/ds² at the start or the end (zero for lines)."""
        second = [0.0] * len(self._floats[1])
        if self.arc is not None:
            length = self.length
            i1, i2, th, r, dr, sweep = self._arc_at(1.0 if at_end else 0.0)
            second[i1] = (-2 * dr * sweep * math.sin(th) - r * sweep * sweep * math.cos(th)) / length**2
            second[i2] = (2 * dr * sweep * math.cos(th) - r * sweep * sweep * math.sin(th)) / length**2
        return np.array(second)

    def max_direction_share(self) -> list[float]:
        """Upper bound of |dp_k/ds| over the segment, per axis."""
        length = self.length
        share = [abs(d) / length for d in self._floats[1]]
        if self.arc is not None:
            i1, i2, _c1, _c2, r0, r1, _th0, sweep = self.arc
            # (max and min written out as the builtins decide: once per arc block)
            bound = (abs(r1 - r0) + (r1 if r1 > r0 else r0) * abs(sweep)) / self.length
            share[i1] = share[i2] = 1.0 if 1.0 < bound else bound
        return share

    @property
    def min_radius(self) -> float:
        """Smallest radius of an arc (infinite for a line)."""
        if self.arc is None:
            return math.inf
        r0, r1 = self.arc[4], self.arc[5]
        radius = r1 if r1 < r0 else r0  # max(min(r0, r1), 1e-6) as the builtins decide
        return 1e-6 if 1e-6 > radius else radius


def line(start: np.ndarray, end: np.ndarray, linear_mask: Sequence[bool] | np.ndarray) -> Segment:
    """A straight segment; its length counts the linear axes (rotary-only moves in degrees).
    The segment keeps ``start`` and ``end`` (see :class:`Segment`)."""
    segment = Segment(start, end, 0.0)
    deltas = segment.floats()[1]
    # math.hypot scales internally: no overflow for huge coordinates (1EX300).
    length = math.hypot(*compress(deltas, linear_mask))
    if length <= MIN_LENGTH_MM:
        length = math.hypot(*deltas)
    segment.length = length
    return segment


def arc(
    start: np.ndarray,
    end: np.ndarray,
    center: tuple[float, float],
    plane_idx: tuple[int, int],
    clockwise: bool,
    turns: int,
    linear_mask: Sequence[bool] | np.ndarray,
) -> Segment:
    """An arc (helix when other axes move too) in the plane of axes ``plane_idx``. The segment
    keeps ``start`` and ``end`` (see :class:`Segment`)."""
    i1, i2 = plane_idx
    c1, c2 = center
    segment = Segment(start, end, 0.0)  # its length and arc are set below
    # Python floats (the same float64 arithmetic as numpy's scalars, without their cost).
    starts, deltas, ends = segment.floats()
    r0 = math.hypot(starts[i1] - c1, starts[i2] - c2)
    r1 = math.hypot(ends[i1] - c1, ends[i2] - c2)
    th0 = math.atan2(starts[i2] - c2, starts[i1] - c1)
    th1 = math.atan2(ends[i2] - c2, ends[i1] - c1)
    two_pi = 2.0 * math.pi
    if clockwise:
        sweep = -((th0 - th1) % two_pi)
        if abs(sweep) < 1e-9:
            sweep = -two_pi
        sweep -= two_pi * max(turns, 0)
    else:
        sweep = (th1 - th0) % two_pi
        if abs(sweep) < 1e-9:
            sweep = two_pi
        sweep += two_pi * max(turns, 0)
    planar = abs(sweep) * (r0 + r1) / 2.0
    others = [d for i, (d, linear) in enumerate(zip(deltas, linear_mask)) if linear and i != i1 and i != i2]
    length = math.hypot(planar, *others)
    if r0 <= MIN_LENGTH_MM or length <= MIN_LENGTH_MM:
        return line(start, end, linear_mask)
    segment.length = length
    segment.arc = (i1, i2, c1, c2, r0, r1, th0, sweep)
    return segment
