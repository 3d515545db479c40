"""Chamfers and roundings between two path elements: ``CHF=``, ``CHR=``, ``RND=``, ``RNDM=``.

A chamfer or rounding written in a block is inserted at the corner between
that block's path element and the next one, in the active plane:

* ``CHR=c``: a chamfer whose legs along both elements are ``c`` long (measured
  from the corner in the original direction of motion);
* ``CHF=f``: a chamfer whose own length is ``f`` (equal legs);
* ``RND=r`` / modal ``RNDM=r``: a circle of radius ``r`` tangent to both elements.

Both elements may be straight lines or plane arcs. When an element is too
short for the requested size the control reduces the chamfer or rounding to
what fits. A negative value is alarm 16500. Elements that already meet
tangentially get nothing inserted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from nck.alarm_ids import CHAMFER_OR_ROUNDING_NEGATIVE
from nck.errors import NcAlarmError
from nck.geometry.circles import Arc, plane_arc
from nck.geometry.planes import Plane


Vec3 = tuple[float, float, float]
Vec2 = tuple[float, float]
TANGENT_EPS = 1e-9
SEARCH_STEPS = 60


@dataclass(slots=True)
class LineElement:
    """A straight path element from ``start`` to ``end`` (geometry axes, mm); immutable by
    contract, not frozen for the cost of construction (as :class:`Arc`)."""

    start: Vec3
    end: Vec3


Element = LineElement | Arc


@dataclass(frozen=True, slots=True)
class Corner:
    """The two elements after trimming and what was inserted between them.

    ``inserted`` is a :class:`LineElement` (chamfer), an :class:`Arc` (rounding)
    or None (nothing fits / tangent transition / zero size).
    """

    first: Element
    inserted: Element | None
    second: Element


# --- element helpers (plane coordinates) ---------------------------------------------------
class FlatElement:
    """An element seen in the plane: a line or an arc, with the applicate kept linear."""

    def __init__(self, plane: Plane, element: Element) -> None:
        self.plane = plane
        self.element = element
        self.s = plane.to_plane(element.start)
        self.e = plane.to_plane(element.end)
        if isinstance(element, Arc):
            c = plane.to_plane(element.center)
            self.center: Vec2 | None = (c[0], c[1])
            self.radius = element.radius
            self.ccw = not element.clockwise_in(plane)
            self.sweep = element.sweep_rad
            self.length = self.radius * self.sweep
        else:
            self.center = None
            self.radius = 0.0
            self.ccw = True
            self.sweep = 0.0
            self.length = math.hypot(self.e[0] - self.s[0], self.e[1] - self.s[1])

    # point at in-plane arc length u from the start (0 … length)
    def point(self, u: float) -> Vec3:
        frac = 0.0 if self.length <= 0 else u / self.length
        app = self.s[2] + (self.e[2] - self.s[2]) * frac
        if self.center is None:
            a = self.s[0] + (self.e[0] - self.s[0]) * frac
            o = self.s[1] + (self.e[1] - self.s[1]) * frac
        else:
            angle = (u / self.radius) * (1.0 if self.ccw else -1.0)
            rx, ry = self.s[0] - self.center[0], self.s[1] - self.center[1]
            c, si = math.cos(angle), math.sin(angle)
            a = self.center[0] + rx * c - ry * si
            o = self.center[1] + rx * si + ry * c
        return self.plane.from_plane((a, o, app))

    def tangent(self, u: float) -> Vec2:
        if self.center is None:
            d = (self.e[0] - self.s[0], self.e[1] - self.s[1])
            n = math.hypot(*d)
            return (d[0] / n, d[1] / n) if n > 0 else (0.0, 0.0)
        p = self.plane.to_plane(self.point(u))
        rx, ry = p[0] - self.center[0], p[1] - self.center[1]
        sign = 1.0 if self.ccw else -1.0
        return (-ry * sign / self.radius, rx * sign / self.radius)

    def param_of(self, point_ao: Vec2) -> float:
        """In-plane arc length from the start to the foot of ``point_ao`` on the element."""
        if self.center is None:
            dx, dy = self.e[0] - self.s[0], self.e[1] - self.s[1]
            if self.length <= 0:
                return 0.0
            return ((point_ao[0] - self.s[0]) * dx + (point_ao[1] - self.s[1]) * dy) / self.length
        rs = (self.s[0] - self.center[0], self.s[1] - self.center[1])
        rp = (point_ao[0] - self.center[0], point_ao[1] - self.center[1])
        ang = (math.atan2(rp[1], rp[0]) - math.atan2(rs[1], rs[0])) % (2 * math.pi)
        if not self.ccw:
            ang = (2 * math.pi - ang) % (2 * math.pi)
        if ang > self.sweep + 1e-9 and ang > math.pi + self.sweep / 2:
            ang -= 2 * math.pi  # before the start
        return ang * self.radius

    def trimmed(self, u_from: float, u_to: float) -> Element:
        start, end = self.point(u_from), self.point(u_to)
        if self.center is None:
            return LineElement(start, end)
        arc = self.element
        assert isinstance(arc, Arc)
        sweep = (u_to - u_from) / self.radius
        center = self.plane.from_plane((self.center[0], self.center[1], self.plane.to_plane(start)[2]))
        return Arc(start, end, center, arc.axis, self.radius, sweep, 0)


def _chord_point_back(flat: FlatElement, dist: float) -> float | None:
    """Arc length from the start of the point at straight distance ``dist`` before the end."""
    if flat.center is None:
        return flat.length - dist if dist <= flat.length + 1e-12 else None
    if dist > 2 * flat.radius:
        return None
    u = 2 * flat.radius * math.asin(min(1.0, dist / (2 * flat.radius)))
    return flat.length - u if u <= flat.length + 1e-12 else None


def _chord_point_forward(flat: FlatElement, dist: float) -> float | None:
    """Arc length from the start of the point at straight distance ``dist`` after the start."""
    if flat.center is None:
        return dist if dist <= flat.length + 1e-12 else None
    if dist > 2 * flat.radius:
        return None
    u = 2 * flat.radius * math.asin(min(1.0, dist / (2 * flat.radius)))
    return u if u <= flat.length + 1e-12 else None


def corner_turn(first: FlatElement, second: FlatElement) -> tuple[float, float]:
    """(cross, dot) of the end tangent of ``first`` and the start tangent of ``second`` in the plane."""
    t1 = first.tangent(first.length)
    t2 = second.tangent(0.0)
    return t1[0] * t2[1] - t1[1] * t2[0], t1[0] * t2[0] + t1[1] * t2[1]


def _check(value: float) -> None:
    if value < 0.0:
        raise NcAlarmError(CHAMFER_OR_ROUNDING_NEGATIVE)


# --- chamfer ------------------------------------------------------------------------------
def chamfer(plane: Plane, first: Element, second: Element, size: float, kind: str = "CHF") -> Corner:
    """Insert a chamfer ``CHF=size`` (chamfer length) or ``CHR=size`` (leg length).

    Raises:
        NcAlarmError: 16500 for a negative size.
    """
    _check(size)
    f, s = FlatElement(plane, first), FlatElement(plane, second)
    cross, dot = corner_turn(f, s)
    if size == 0.0 or (abs(cross) < TANGENT_EPS and dot > 0):
        return Corner(first, None, second)

    def legs(leg: float) -> tuple[float, float] | None:
        u1 = _chord_point_back(f, leg)
        u2 = _chord_point_forward(s, leg)
        if u1 is None or u2 is None or u1 < -1e-12 or u2 > s.length + 1e-12:
            return None
        return (max(u1, 0.0), min(u2, s.length))

    def chord(leg: float) -> float:
        got = legs(leg)
        assert got is not None
        p, q = plane.to_plane(f.point(got[0])), plane.to_plane(s.point(got[1]))
        return math.hypot(q[0] - p[0], q[1] - p[1])

    max_leg = _largest(lambda leg: legs(leg) is not None, min(f.length, s.length) + 1.0)
    if kind == "CHR":
        leg = min(size, max_leg)
    else:
        if max_leg <= 0.0:
            return Corner(first, None, second)
        if chord(max_leg) <= size:
            leg = max_leg
        else:
            lo, hi = 0.0, max_leg
            for _ in range(SEARCH_STEPS):
                mid = (lo + hi) / 2.0
                if chord(mid) < size:
                    lo = mid
                else:
                    hi = mid
            leg = (lo + hi) / 2.0
    got = legs(leg)
    if got is None or leg <= 0.0:
        return Corner(first, None, second)
    u1, u2 = got
    a = f.trimmed(0.0, u1)
    b = s.trimmed(u2, s.length)
    return Corner(a, LineElement(a.end, b.start), b)


def _largest(ok, upper: float) -> float:
    """Largest value in [0, upper] for which ``ok`` holds (ok is monotone: true then false)."""
    if ok(upper):
        return upper
    lo, hi = 0.0, upper
    for _ in range(SEARCH_STEPS):
        mid = (lo + hi) / 2.0
        if ok(mid):
            lo = mid
        else:
            hi = mid
    return lo


# --- rounding -----------------------------------------------------------------------------
def rounding(plane: Plane, first: Element, second: Element, radius: float) -> Corner:
    """Insert a tangent rounding ``RND=radius`` at the corner.

    Raises:
        NcAlarmError: 16500 for a negative radius.
    """
    _check(radius)
    f, s = FlatElement(plane, first), FlatElement(plane, second)
    cross, dot = corner_turn(f, s)
    if radius == 0.0 or abs(cross) < TANGENT_EPS:
        return Corner(first, None, second)
    side = 1.0 if cross > 0 else -1.0
    corner = plane.to_plane(f.point(f.length))

    def solve(r: float) -> tuple[Vec2, float, float] | None:
        centre = _offset_intersection(f, s, side, r, (corner[0], corner[1]))
        if centre is None:
            return None
        u1 = f.param_of(_foot(f, centre))
        u2 = s.param_of(_foot(s, centre))
        if u1 < -1e-9 or u1 > f.length + 1e-9 or u2 < -1e-9 or u2 > s.length + 1e-9:
            return None
        return centre, min(max(u1, 0.0), f.length), min(max(u2, 0.0), s.length)

    r = radius if solve(radius) is not None else _largest(lambda x: x > 0 and solve(x) is not None, radius)
    found = solve(r) if r > 0 else None
    if found is None:
        return Corner(first, None, second)
    centre, u1, u2 = found
    a = f.trimmed(0.0, u1)
    b = s.trimmed(u2, s.length)
    arc = plane_arc(plane, a.end, b.start, centre, clockwise=side < 0, turns=0)
    if arc.sweep_rad > math.pi * 2 - 1e-9:  # zero-length rounding (degenerate): drop it
        return Corner(first, None, second)
    return Corner(a, arc, b)


def _foot(flat: FlatElement, point: Vec2) -> Vec2:
    if flat.center is None:
        u = flat.param_of(point)
        dx, dy = flat.e[0] - flat.s[0], flat.e[1] - flat.s[1]
        frac = u / flat.length if flat.length > 0 else 0.0
        return (flat.s[0] + dx * frac, flat.s[1] + dy * frac)
    cx, cy = flat.center
    d = math.hypot(point[0] - cx, point[1] - cy)
    return (cx + (point[0] - cx) * flat.radius / d, cy + (point[1] - cy) * flat.radius / d)


def _offset(flat: FlatElement, side: float, r: float):
    """The element moved sideways by ``r`` (left for side=+1): ('line', p, d) or ('circle', c, R)."""
    if flat.center is None:
        t = flat.tangent(0.0)
        n = (-t[1] * side, t[0] * side)
        return ("line", (flat.s[0] + n[0] * r, flat.s[1] + n[1] * r), t)
    radius = flat.radius - side * r * (1.0 if flat.ccw else -1.0)
    return ("circle", flat.center, radius)


def _offset_intersection(f: FlatElement, s: FlatElement, side: float, r: float, near: Vec2) -> Vec2 | None:
    points = _intersect(_offset(f, side, r), _offset(s, side, r))
    if not points:
        return None
    return min(points, key=lambda p: math.hypot(p[0] - near[0], p[1] - near[1]))


def _intersect(g1, g2) -> list[Vec2]:
    if g1[0] == "line" and g2[0] == "line":
        (p, d), (q, e) = (g1[1], g1[2]), (g2[1], g2[2])
        den = d[0] * e[1] - d[1] * e[0]
        if abs(den) < 1e-15:
            return []
        t = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
        return [(p[0] + d[0] * t, p[1] + d[1] * t)]
    if g1[0] == "circle" and g2[0] == "line":
        g1, g2 = g2, g1
    if g1[0] == "line" and g2[0] == "circle":
        p, d = g1[1], g1[2]
        c, rad = g2[1], g2[2]
        fx, fy = p[0] - c[0], p[1] - c[1]
        b = fx * d[0] + fy * d[1]
        cc = fx * fx + fy * fy - rad * rad
        disc = b * b - cc
        if disc < 0 or rad <= 0:
            return []
        root = math.sqrt(disc)
        return [(p[0] + d[0] * t, p[1] + d[1] * t) for t in (-b - root, -b + root)]
    (c1, r1), (c2, r2) = (g1[1], g1[2]), (g2[1], g2[2])
    if r1 <= 0 or r2 <= 0:
        return []
    dx, dy = c2[0] - c1[0], c2[1] - c1[1]
    dist = math.hypot(dx, dy)
    if dist < 1e-15 or dist > r1 + r2 or dist < abs(r1 - r2):
        return []
    a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    mx, my = c1[0] + a * dx / dist, c1[1] + a * dy / dist
    return [(mx - h * dy / dist, my + h * dx / dist), (mx + h * dy / dist, my - h * dx / dist)]
