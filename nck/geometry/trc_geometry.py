"""Plane-local 2D geometry for tool radius compensation.

Everything here works in the two coordinates of the active plane
(abscissa, ordinate): G17 → (X, Y), G18 → (Z, X), G19 → (Y, Z). With that
order the plane normal points along the third axis, so "left of the direction
of travel" is the counter-clockwise side in these coordinates for every plane.

A :class:`Curve` is a line or a circular arc with explicit start and end
points. Helpers give tangents, left normals, lengths (mm for lines, radians for
arcs), the parameter of a point along a curve, the offset curve at a signed
distance (positive = to the left), and the intersections of the underlying
infinite lines / full circles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

Vec = tuple[float, float]

#: Two points closer than this (mm) are the same point.
EPS_MM = 1e-7
#: Two directions whose cross product is below this are parallel.
EPS_PARALLEL = 1e-9

PLANE_AXES: dict[str, tuple[str, str, str]] = {
    "G17": ("X", "Y", "Z"),
    "G18": ("Z", "X", "Y"),
    "G19": ("Y", "Z", "X"),
}


def plane_axes(plane: str) -> tuple[str, str, str]:
    """Return (abscissa, ordinate, applicate) geometry-axis names of a plane G17/G18/G19."""
    return PLANE_AXES[plane]


def add(a: Vec, b: Vec) -> Vec:
    """Vector sum."""
    return (a[0] + b[0], a[1] + b[1])


def sub(a: Vec, b: Vec) -> Vec:
    """Vector difference a - b."""
    return (a[0] - b[0], a[1] - b[1])


def scale(a: Vec, k: float) -> Vec:
    """Vector times scalar."""
    return (a[0] * k, a[1] * k)


def dot(a: Vec, b: Vec) -> float:
    """Scalar product."""
    return a[0] * b[0] + a[1] * b[1]


def cross(a: Vec, b: Vec) -> float:
    """z component of a × b (positive when b turns left from a)."""
    return a[0] * b[1] - a[1] * b[0]


def norm(a: Vec) -> float:
    """Length of a vector."""
    return math.hypot(a[0], a[1])


def dist(a: Vec, b: Vec) -> float:
    """Distance between two points."""
    return math.hypot(a[0] - b[0], a[1] - b[1])


def unit(a: Vec) -> Vec:
    """Unit vector along a (zero vector stays zero)."""
    length = norm(a)
    if length < 1e-15:
        return (0.0, 0.0)
    return (a[0] / length, a[1] / length)


def left_normal(t: Vec) -> Vec:
    """The direction rotated 90° counter-clockwise (left of travel)."""
    return (-t[1], t[0])


def same_point(a: Vec, b: Vec, tol: float = EPS_MM) -> bool:
    """True if two points coincide within ``tol`` mm."""
    return dist(a, b) <= tol


@dataclass(frozen=True, slots=True)
class Curve:
    """A line (``center is None``) or an arc from ``start`` to ``end``.

    Attributes:
        start: start point (plane coordinates, mm).
        end: end point.
        center: arc centre, None for a line.
        ccw: arc direction, True for counter-clockwise (G3), False for clockwise (G2).
        full_circle: an arc whose start equals its end and which turns a full 360°.
    """

    start: Vec
    end: Vec
    center: Vec | None = None
    ccw: bool = True
    full_circle: bool = False

    @property
    def is_arc(self) -> bool:
        """True for a circular arc."""
        return self.center is not None

    @property
    def radius(self) -> float:
        """Arc radius (distance from centre to start); 0 for a line."""
        if self.center is None:
            return 0.0
        return dist(self.start, self.center)

    def with_start(self, point: Vec) -> "Curve":
        """The same curve starting at ``point`` (no longer a full circle)."""
        return replace(self, start=point, full_circle=False)

    def with_end(self, point: Vec) -> "Curve":
        """The same curve ending at ``point`` (no longer a full circle)."""
        return replace(self, end=point, full_circle=False)


def line(start: Vec, end: Vec) -> Curve:
    """A straight line."""
    return Curve(start=start, end=end)


def arc(start: Vec, end: Vec, center: Vec, ccw: bool) -> Curve:
    """An arc; start == end makes a full circle."""
    return Curve(start=start, end=end, center=center, ccw=ccw, full_circle=same_point(start, end))


def _angle(center: Vec, point: Vec) -> float:
    return math.atan2(point[1] - center[1], point[0] - center[0])


def sweep(curve: Curve) -> float:
    """Swept angle of an arc in radians, in (0, 2π] (0 for a zero-length arc)."""
    assert curve.center is not None
    if same_point(curve.start, curve.end):
        return 2.0 * math.pi if curve.full_circle else 0.0
    a0 = _angle(curve.center, curve.start)
    a1 = _angle(curve.center, curve.end)
    delta = (a1 - a0) if curve.ccw else (a0 - a1)
    return delta % (2.0 * math.pi)


def length(curve: Curve) -> float:
    """Length in the curve's parameter: mm for a line, radians for an arc."""
    if curve.center is None:
        return dist(curve.start, curve.end)
    return sweep(curve)


def path_length_mm(curve: Curve) -> float:
    """Path length in mm (arc: radius × swept angle)."""
    if curve.center is None:
        return dist(curve.start, curve.end)
    return curve.radius * sweep(curve)


def param(curve: Curve, point: Vec) -> float:
    """Position of ``point`` along the curve from its start, in the units of :func:`length`.

    For a line this is signed (negative before the start). For an arc it is the
    angle travelled from the start in the arc's direction, in [0, 2π).
    """
    if curve.center is None:
        direction = unit(sub(curve.end, curve.start))
        return dot(sub(point, curve.start), direction)
    a0 = _angle(curve.center, curve.start)
    a1 = _angle(curve.center, point)
    delta = (a1 - a0) if curve.ccw else (a0 - a1)
    value = delta % (2.0 * math.pi)
    # A point at the start itself must read 0, not 2π.
    if value > 2.0 * math.pi - 1e-12:
        value = 0.0
    return value


def param_tolerance(curve: Curve) -> float:
    """Tolerance in parameter units equivalent to EPS_MM on the curve."""
    if curve.center is None:
        return EPS_MM * 10
    return EPS_MM * 10 / max(curve.radius, 1e-9)


def contains(curve: Curve, point: Vec) -> bool:
    """True if ``point`` (known to lie on the underlying line/circle) is within the curve."""
    p = param(curve, point)
    tol = param_tolerance(curve)
    total = length(curve)
    if curve.center is not None and p > total + tol:
        # An arc point just before the start reads close to 2π.
        return 2.0 * math.pi - p <= tol
    return -tol <= p <= total + tol


def tangent_start(curve: Curve) -> Vec:
    """Unit tangent at the start in the direction of travel."""
    if curve.center is None:
        return unit(sub(curve.end, curve.start))
    radial = unit(sub(curve.start, curve.center))
    return left_normal(radial) if curve.ccw else scale(left_normal(radial), -1.0)


def tangent_end(curve: Curve) -> Vec:
    """Unit tangent at the end in the direction of travel."""
    if curve.center is None:
        return unit(sub(curve.end, curve.start))
    radial = unit(sub(curve.end, curve.center))
    return left_normal(radial) if curve.ccw else scale(left_normal(radial), -1.0)


def point_at(curve: Curve, p: float) -> Vec:
    """The point at parameter ``p`` along the curve."""
    if curve.center is None:
        direction = unit(sub(curve.end, curve.start))
        return add(curve.start, scale(direction, p))
    a0 = _angle(curve.center, curve.start)
    angle = a0 + p if curve.ccw else a0 - p
    r = curve.radius
    return (curve.center[0] + r * math.cos(angle), curve.center[1] + r * math.sin(angle))


def offset_radius(curve: Curve, distance_left: float) -> float:
    """Radius of the offset of an arc at ``distance_left`` (left = towards the centre of a G3 arc)."""
    assert curve.center is not None
    return curve.radius - distance_left if curve.ccw else curve.radius + distance_left


def offset(curve: Curve, distance_left: float) -> Curve:
    """The equidistant curve at ``distance_left`` mm to the left (negative: right).

    For an arc whose offset radius is zero or negative the result is a
    zero-length line at the centre; callers check :func:`offset_radius` first.
    """
    if curve.center is None:
        n = left_normal(unit(sub(curve.end, curve.start)))
        shift = scale(n, distance_left)
        return Curve(start=add(curve.start, shift), end=add(curve.end, shift))
    new_r = offset_radius(curve, distance_left)
    c = curve.center
    if new_r <= EPS_MM:
        return Curve(start=c, end=c)
    u0 = unit(sub(curve.start, c))
    u1 = unit(sub(curve.end, c))
    return Curve(
        start=add(c, scale(u0, new_r)),
        end=add(c, scale(u1, new_r)),
        center=c,
        ccw=curve.ccw,
        full_circle=curve.full_circle,
    )


def _line_line(p: Vec, u: Vec, q: Vec, v: Vec) -> list[Vec]:
    denom = cross(u, v)
    if abs(denom) < EPS_PARALLEL:
        return []
    t = cross(sub(q, p), v) / denom
    return [add(p, scale(u, t))]


def _line_circle(p: Vec, u: Vec, c: Vec, r: float) -> list[Vec]:
    # Points p + t u with |p + t u - c| = r, u a unit vector.
    w = sub(p, c)
    b = dot(w, u)
    cc = dot(w, w) - r * r
    disc = b * b - cc
    if disc < -1e-9 * max(1.0, r * r):
        return []
    if disc <= 1e-12 * max(1.0, r * r):
        return [add(p, scale(u, -b))]
    root = math.sqrt(disc)
    return [add(p, scale(u, -b - root)), add(p, scale(u, -b + root))]


def _circle_circle(c0: Vec, r0: float, c1: Vec, r1: float) -> list[Vec]:
    d = dist(c0, c1)
    if d < EPS_MM:
        return []
    if d > r0 + r1 + 1e-9 or d < abs(r0 - r1) - 1e-9:
        return []
    a = (r0 * r0 - r1 * r1 + d * d) / (2 * d)
    h2 = r0 * r0 - a * a
    direction = unit(sub(c1, c0))
    base = add(c0, scale(direction, a))
    if h2 <= 1e-12 * max(1.0, r0 * r0):
        return [base]
    h = math.sqrt(h2)
    n = left_normal(direction)
    return [add(base, scale(n, h)), add(base, scale(n, -h))]


def intersections(a: Curve, b: Curve) -> list[Vec]:
    """Intersections of the infinite line / full circle under ``a`` and under ``b``."""
    a_point = a.center is None and same_point(a.start, a.end)
    b_point = b.center is None and same_point(b.start, b.end)
    if a_point or b_point:
        point, other = (a.start, b) if a_point else (b.start, a)
        if other.center is None:
            if same_point(other.start, other.end):
                return [point] if same_point(point, other.start) else []
            u = unit(sub(other.end, other.start))
            off = abs(cross(sub(point, other.start), u))
        else:
            off = abs(dist(point, other.center) - other.radius)
        return [point] if off <= EPS_MM * 10 else []
    if a.center is None and b.center is None:
        return _line_line(a.start, unit(sub(a.end, a.start)), b.start, unit(sub(b.end, b.start)))
    if a.center is None:
        assert b.center is not None
        return _line_circle(a.start, unit(sub(a.end, a.start)), b.center, b.radius)
    if b.center is None:
        return _line_circle(b.start, unit(sub(b.end, b.start)), a.center, a.radius)
    return _circle_circle(a.center, a.radius, b.center, b.radius)


def distance_to_curve(point: Vec, curve: Curve) -> float:
    """Shortest distance from ``point`` to the (bounded) curve."""
    if curve.center is None:
        seg = sub(curve.end, curve.start)
        seg_len2 = dot(seg, seg)
        if seg_len2 < 1e-30:
            return dist(point, curve.start)
        t = max(0.0, min(1.0, dot(sub(point, curve.start), seg) / seg_len2))
        return dist(point, add(curve.start, scale(seg, t)))
    c = curve.center
    r = curve.radius
    if dist(point, c) > 1e-15:
        radial_foot = add(c, scale(unit(sub(point, c)), r))
        if contains(curve, radial_foot):
            return abs(dist(point, c) - r)
    return min(dist(point, curve.start), dist(point, curve.end))


def sample(curve: Curve, count: int) -> list[Vec]:
    """``count`` + 1 points evenly spaced along the curve, both ends included."""
    total = length(curve)
    return [point_at(curve, total * i / count) for i in range(count + 1)]
