"""The bar in a lathe's chuck as it is turned: what is left of it for contact detection.

A turning tool cutting with the spindle turning removes, over the length along Z its cutting
edge swept, everything farther from the turning axis than the edge. What is left of the bar is
therefore a stack of coaxial discs (:class:`~nck.workpiece.Cylinder` s of the bar's axis, one
per Z interval, each with the smallest radius turned there). The stack is a union of convex
solids, so the gap function of :mod:`nck.contact` to it is the smallest gap to any disc, and
the first contact along a step is the earliest first contact with a disc.

Trainer choice (the manuals do not describe a simulated workpiece): the cut leaves the disc
:data:`CUT_CLEARANCE_MM` (one increment of the position display) inside the edge's sweep, so
that a rapid move back along a path the tool has just cut is not a contact with the surface it
left (radially and along Z). A cut step's radius is the smaller of its two ends, over the whole Z range of the step
widened to the next :data:`Z_GRID_MM` (a taper or an arc removes at most that much more along
Z than the edge swept: the stack stays short, at most one disc per 0.1 mm of the bar).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field

from nck.contact import BALL, ToolBody, clearance, first_contact
from nck.workpiece import Cylinder, Point

CUT_CLEARANCE_MM = 0.001
Z_GRID_MM = 0.1
MERGE_MM = 1e-9


@dataclass
class TurnedBar:
    """The bar ``blank`` with the discs left of it: ``starts`` / ``ends`` (Z, MCS) and ``radii``,
    sorted by Z, not overlapping; Z ranges of the blank not listed are cut away entirely."""

    blank: Cylinder
    starts: list[float] = field(default_factory=list)
    ends: list[float] = field(default_factory=list)
    radii: list[float] = field(default_factory=list)

    @classmethod
    def of(cls, blank: Cylinder) -> "TurnedBar":
        """The uncut bar: one disc, the blank itself."""
        bottom = blank.base_mcs[2]
        return cls(blank, [bottom], [bottom + blank.length_mm], [blank.diameter_mm / 2.0])

    def _radial(self, point: Point) -> float:
        return math.hypot(point[0] - self.blank.base_mcs[0], point[1] - self.blank.base_mcs[1])

    def discs_near(self, low_z: float, high_z: float) -> list[Cylinder]:
        """The discs that reach into ``low_z`` … ``high_z``."""
        first = max(bisect.bisect_right(self.ends, low_z) - 1, 0)
        x, y, _ = self.blank.base_mcs
        found = []
        for index in range(first, len(self.starts)):
            if self.starts[index] > high_z:
                break
            if self.ends[index] >= low_z and self.radii[index] > 0.0:
                found.append(Cylinder((x, y, self.starts[index]), 2.0 * self.radii[index],
                                      self.ends[index] - self.starts[index]))
        return found

    def _reach(self, body: ToolBody, start: Point, end: Point) -> tuple[float, float]:
        return min(start[2], end[2]) - body.radius_mm, max(start[2], end[2]) + body.radius_mm

    def first_contact(self, body: ToolBody, start: Point, end: Point) -> float | None:
        """The first parameter along ``start`` → ``end`` where the tool touches what is left."""
        discs = self.discs_near(*self._reach(body, start, end))
        planar = self._planar(start, end)
        if planar is not None and body.shape == BALL:  # the exact entry, in the plane through the axis
            hits = [t for disc in discs if (t := _ball_entry(planar, disc, body.radius_mm)) is not None]
        else:
            hits = [t for disc in discs if (t := first_contact(body, disc, start, end)) is not None]
        return min(hits) if hits else None

    def _planar(self, start: Point, end: Point) -> tuple[float, float, float, float] | None:
        """(radius, Z) of both ends when the tip moves in a plane through the turning axis on one
        side of it (a lathe's X/Z: the radius then changes linearly along the step), else None."""
        x, y, _ = self.blank.base_mcs
        if start[1] != y or end[1] != y or (start[0] - x) * (end[0] - x) < 0.0:
            return None
        return abs(start[0] - x), start[2], abs(end[0] - x), end[2]

    def clearance(self, body: ToolBody, tip: Point) -> float:
        """The gap function of :mod:`nck.contact` to what is left (large when nothing is)."""
        reach = body.radius_mm + body.length_mm  # a disc farther along Z than its gap + reach is farther
        middle = bisect.bisect_right(self.starts, tip[2])
        best = math.inf
        for index in range(middle - 1, -1, -1):  # the disc under the tip, then towards the chuck
            if tip[2] - self.ends[index] - reach >= best:
                break
            best = min(best, self._gap(body, index, tip))
        for index in range(middle, len(self.starts)):  # towards the free end
            if self.starts[index] - tip[2] - reach >= best:
                break
            best = min(best, self._gap(body, index, tip))
        return best

    def _gap(self, body: ToolBody, index: int, tip: Point) -> float:
        if self.radii[index] <= 0.0:
            return math.inf
        x, y, _ = self.blank.base_mcs
        disc = Cylinder((x, y, self.starts[index]), 2.0 * self.radii[index], self.ends[index] - self.starts[index])
        return clearance(body, disc, tip)

    def cut(self, body: ToolBody, start: Point, end: Point) -> None:
        """The edge swept from ``start`` to ``end`` cutting: the discs it passed are turned down."""
        radius = min(self._radial(start), self._radial(end)) - body.radius_mm - CUT_CLEARANCE_MM
        low, high = self._reach(body, start, end)
        low = math.floor((low - CUT_CLEARANCE_MM) / Z_GRID_MM) * Z_GRID_MM
        high = math.ceil((high + CUT_CLEARANCE_MM) / Z_GRID_MM) * Z_GRID_MM
        pieces: list[tuple[float, float, float]] = []
        for z0, z1, r in zip(self.starts, self.ends, self.radii):
            if z1 <= low or z0 >= high or r <= radius:
                pieces.append((z0, z1, r))
                continue
            if z0 < low:
                pieces.append((z0, low, r))
            pieces.append((max(z0, low), min(z1, high), max(radius, 0.0)))
            if z1 > high:
                pieces.append((high, z1, r))
        merged: list[tuple[float, float, float]] = []
        for z0, z1, r in pieces:
            if merged and abs(merged[-1][2] - r) <= MERGE_MM and abs(merged[-1][1] - z0) <= MERGE_MM:
                merged[-1] = (merged[-1][0], z1, r)
            else:
                merged.append((z0, z1, r))
        self.starts = [p[0] for p in merged]
        self.ends = [p[1] for p in merged]
        self.radii = [p[2] for p in merged]


def _box_entry(start: tuple[float, float], delta: tuple[float, float],
               low: tuple[float, float], high: tuple[float, float]) -> float | None:
    """First parameter in 0 … 1 where ``start + t·delta`` lies in the box ``low`` … ``high``."""
    enter, leave = 0.0, 1.0
    for p, d, lo, hi in zip(start, delta, low, high):
        if d == 0.0:
            if p < lo or p > hi:
                return None
            continue
        t0, t1 = sorted(((lo - p) / d, (hi - p) / d))
        enter, leave = max(enter, t0), min(leave, t1)
        if enter > leave:
            return None
    return enter


def _circle_entry(start: tuple[float, float], delta: tuple[float, float],
                  centre: tuple[float, float], radius: float) -> float | None:
    """First parameter in 0 … 1 where ``start + t·delta`` lies within ``radius`` of ``centre``."""
    fx, fz = start[0] - centre[0], start[1] - centre[1]
    c = fx * fx + fz * fz - radius * radius
    if c <= 0.0:
        return 0.0
    a = delta[0] ** 2 + delta[1] ** 2
    b = 2.0 * (fx * delta[0] + fz * delta[1])
    disc = b * b - 4.0 * a * c
    if a == 0.0 or disc < 0.0:
        return None
    t = (-b - math.sqrt(disc)) / (2.0 * a)
    return t if 0.0 <= t <= 1.0 else None


def _ball_entry(planar: tuple[float, float, float, float], disc: Cylinder, radius: float) -> float | None:
    """First parameter where a ball of ``radius`` centred on the tip, moving from (r0, z0) to
    (r1, z1) in the plane through the axis, touches ``disc``: the disc's section widened by the
    ball is two rectangles and two quarter circles at its outer corners."""
    r0, z0, r1, z1 = planar
    start, delta = (r0, z0), (r1 - r0, z1 - z0)
    outer, bottom = disc.diameter_mm / 2.0, disc.base_mcs[2]
    top = bottom + disc.length_mm
    hits = [_box_entry(start, delta, (-math.inf, bottom), (outer + radius, top)),
            _box_entry(start, delta, (-math.inf, bottom - radius), (outer, top + radius)),
            _circle_entry(start, delta, (outer, bottom), radius),
            _circle_entry(start, delta, (outer, top), radius)]
    found = [t for t in hits if t is not None]
    return min(found) if found else None
