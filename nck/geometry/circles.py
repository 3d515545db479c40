"""Circles and helices: every way a Siemens-mode program can define an arc.

All coordinates are geometry-axis vectors (axis 1, 2, 3) in millimetres of the
WCS; in-plane quantities use the (abscissa, ordinate) of the active
:class:`~nck.geometry.planes.Plane`.

Definitions (Programming Manual Fundamentals, "circular interpolation"):

* centre ``I J K`` (incremental from the start point, or ``=AC(…)`` absolute)
  with an end point — :func:`arc_from_center`;
* radius ``CR=`` with an end point; ``CR>0`` sweeps at most 180°, ``CR<0``
  more than 180° — :func:`arc_from_radius`;
* opening angle ``AR=`` with an end point — :func:`arc_from_end_and_angle`,
  or with a centre — :func:`arc_from_center_and_angle`;
* ``CIP`` through an intermediate point — :func:`arc_through_point`;
* ``CT`` tangential to the previous path — :func:`arc_tangential`;
* a helix: an end point that differs along the applicate, plus ``TURN=``
  extra full turns.

End-point monitoring (alarm 14040): the start and end radius may differ by at
most ``max(MD21000 CIRCLE_ERROR_CONST, MD21010 CIRCLE_ERROR_FACTOR · radius)``
(defaults 0.01 mm and 0.001). A smaller difference is absorbed: the end point
is trusted and the centre is moved onto the perpendicular bisector of the chord.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from nck.errors import NcAlarmError
from nck.geometry.planes import Plane
from nck.geometry.vec3 import dot3, norm3

Vec3 = tuple[float, float, float]
Vec2 = tuple[float, float]

ALARM_CIRCLE_END_POINT = 14040  # error in end point of circle
ALARM_TANGENTIAL_CIRCLE = 14045  # error in programming of tangential circle
ALARM_CIRCLE_TURNS = 14048  # wrong number of revolutions in circle programming
ALARM_RADIUS_TOO_SMALL = 14095  # radius for circle programming too small
ALARM_CIP_POINT = 14920  # intermediate point of circle incorrect

CIRCLE_ERROR_CONST_MM = 0.01  # MD21000 default
CIRCLE_ERROR_FACTOR = 0.001  # MD21010 default
MAX_TURNS = 999
MAX_CIP_RADIUS_MM = 1e6  # a CIP circle larger than this counts as a straight line
POINT_EPS = 1e-9
TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class CircleTolerance:
    """The circle end-point tolerance from machine data (MD21000, MD21010)."""

    const_mm: float = CIRCLE_ERROR_CONST_MM
    factor: float = CIRCLE_ERROR_FACTOR

    def allowed(self, radius_mm: float) -> float:
        """Largest allowed difference between start and end radius."""
        return max(self.const_mm, self.factor * abs(radius_mm))


DEFAULT_TOLERANCE = CircleTolerance()


@dataclass(slots=True)
class Arc:
    """A circular arc or helix in space.

    Immutable by contract (change one with :func:`dataclasses.replace`), but not a frozen
    dataclass: a frozen one sets each of its seven fields through ``object.__setattr__``
    (~1.45 against ~0.3 us, an arc per G2/G3 block); nothing hashes an arc.

    Attributes:
        start: start point (geometry axes, mm).
        end: end point.
        center: centre of the circle, in the plane of the start point.
        axis: unit vector the arc turns about counter-clockwise (right-hand rule);
            for G3 in G17 it is +Z, for G2 -Z.
        radius: circle radius.
        sweep_rad: angle swept, > 0, including full turns.
        turns: the programmed ``TURN=`` value.
    """

    start: Vec3
    end: Vec3
    center: Vec3
    axis: Vec3
    radius: float
    sweep_rad: float
    turns: int = 0

    @property
    def lead(self) -> float:
        """Travel along ``axis`` from start to end (0 for a plane circle)."""
        s, e = self.start, self.end
        return dot3((e[0] - s[0], e[1] - s[1], e[2] - s[2]), self.axis)

    @property
    def sweep_deg(self) -> float:
        """Swept angle in degrees."""
        return math.degrees(self.sweep_rad)

    def clockwise_in(self, plane: Plane) -> bool:
        """True when the arc runs clockwise seen from the positive applicate of ``plane`` (G2)."""
        return dot3(self.axis, plane.normal()) < 0.0

    def point_at(self, fraction: float) -> Vec3:
        """The point reached after ``fraction`` (0…1) of the sweep."""
        t = self._turned(self.sweep_rad * fraction)
        c, k, lead = self.center, self.axis, self.lead
        return ((c[0] + t[0]) + k[0] * lead * fraction, (c[1] + t[1]) + k[1] * lead * fraction,
                (c[2] + t[2]) + k[2] * lead * fraction)

    def tangent_at(self, fraction: float) -> Vec3:
        """Unit direction of travel after ``fraction`` of the sweep (including the helix lead)."""
        k, sweep, lead = self.axis, self.sweep_rad, self.lead
        x = _cross(k, self._turned(sweep * fraction))
        direction = (x[0] * sweep + k[0] * lead, x[1] * sweep + k[1] * lead, x[2] * sweep + k[2] * lead)
        norm = norm3(direction)
        if norm < POINT_EPS:
            return (0.0, 0.0, 0.0)
        return (direction[0] / norm, direction[1] / norm, direction[2] / norm)

    def _turned(self, angle: float) -> Vec3:
        """The start radius (its part across ``axis``) turned by ``angle`` about ``axis``."""
        s, c, k = self.start, self.center, self.axis
        radial = (s[0] - c[0], s[1] - c[1], s[2] - c[2])
        along = dot3(radial, k)
        return _rotate((radial[0] - along * k[0], radial[1] - along * k[1], radial[2] - along * k[2]), k, angle)

    def length(self) -> float:
        """Path length of the arc or helix.

        About a coordinate axis (every circle of G17/G18/G19) the lead is the end's difference
        along it: ``dot3`` of the difference and a unit axis adds only exact zero products, so
        it is that difference up to the sign of a zero, which ``hypot`` ignores."""
        s, e, k = self.start, self.end, self.axis
        along = _UNIT_AXES.get(k) if type(k) is tuple else None
        if along is not None:
            d = (e[0] - s[0], e[1] - s[1], e[2] - s[2])
            if math.isfinite(d[0] + d[1] + d[2]):
                return math.hypot(self.radius * self.sweep_rad, d[along[0]] * along[1])
        return math.hypot(self.radius * self.sweep_rad, self.lead)


_UNIT_AXES: dict[tuple[float, float, float], tuple[int, float]] = {
    (1.0, 0.0, 0.0): (0, 1.0), (-1.0, 0.0, 0.0): (0, -1.0), (0.0, 1.0, 0.0): (1, 1.0),
    (0.0, -1.0, 0.0): (1, -1.0), (0.0, 0.0, 1.0): (2, 1.0), (0.0, 0.0, -1.0): (2, -1.0),
}
"""The coordinate axes as (index, sign): a zero of either sign matches a key (-0.0 == 0.0)."""


def _rotate(v: Vec3, k: Vec3, angle: float) -> Vec3:
    """Rodrigues rotation of ``v`` about unit axis ``k`` (the operations of the numpy form
    ``v·cos + (k × v)·sin + k·(k·v)·(1 − cos)``, element by element)."""
    cos, sin = math.cos(angle), math.sin(angle)
    x = _cross(k, v)
    along = dot3(k, v)
    rest = 1 - cos
    return (v[0] * cos + x[0] * sin + k[0] * along * rest, v[1] * cos + x[1] * sin + k[1] * along * rest,
            v[2] * cos + x[2] * sin + k[2] * along * rest)


def _cross(a: Any, b: Any) -> Vec3:
    """``np.cross`` of two 3-vectors with the same products and differences (bit for bit),
    without its general-shape machinery."""
    a0, a1, a2 = float(a[0]), float(a[1]), float(a[2])
    b0, b1, b2 = float(b[0]), float(b[1]), float(b[2])
    return (a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0)


def _check_turns(turns: int) -> int:
    if turns < 0 or turns > MAX_TURNS or int(turns) != turns:
        raise NcAlarmError(ALARM_CIRCLE_TURNS)
    return int(turns)


def _ccw_angle(from_vec: Vec2, to_vec: Vec2) -> float:
    """Counter-clockwise angle from one plane vector to another, in [0, 2π)."""
    a = math.atan2(from_vec[1], from_vec[0])
    b = math.atan2(to_vec[1], to_vec[0])
    delta = (b - a) % TWO_PI
    return 0.0 if abs(delta - TWO_PI) < 1e-12 else delta


def plane_arc(
    plane: Plane, start: Vec3, end: Vec3, center_ao: Vec2, clockwise: bool, turns: int
) -> Arc:
    """Assemble an arc in ``plane`` from a centre that is already consistent with the end."""
    s = plane.to_plane(start)
    e = plane.to_plane(end)
    rs = (s[0] - center_ao[0], s[1] - center_ao[1])
    re = (e[0] - center_ao[0], e[1] - center_ao[1])
    radius = math.hypot(*rs)
    chord = math.hypot(e[0] - s[0], e[1] - s[1])
    if chord < POINT_EPS:
        sweep = TWO_PI
    else:
        ccw = _ccw_angle(rs, re)
        sweep = (TWO_PI - ccw) % TWO_PI if clockwise else ccw
        if sweep < 1e-12:
            sweep = TWO_PI
    sweep += TWO_PI * turns
    center = plane.from_plane((center_ao[0], center_ao[1], s[2]))
    normal = plane.normal()
    axis = (-normal[0], -normal[1], -normal[2]) if clockwise else normal
    return Arc(start=tuple(map(float, start)), end=tuple(map(float, end)), center=center,  # type: ignore[arg-type]
               axis=axis, radius=radius, sweep_rad=sweep, turns=turns)  # type: ignore[arg-type]


def arc_from_center(
    plane: Plane,
    start: Vec3,
    end: Vec3,
    center_ao: Vec2,
    clockwise: bool,
    turns: int = 0,
    tolerance: CircleTolerance = DEFAULT_TOLERANCE,
) -> Arc:
    """G2/G3 with a centre (from ``I J K`` or ``=AC``) and an end point.

    Raises:
        NcAlarmError: 14040 when the centre is the start point (zero radius) or the
            start and end radius differ by more than the tolerance; 14048 for a bad TURN.
    """
    turns = _check_turns(turns)
    s = plane.to_plane(start)
    e = plane.to_plane(end)
    r_start = math.hypot(s[0] - center_ao[0], s[1] - center_ao[1])
    r_end = math.hypot(e[0] - center_ao[0], e[1] - center_ao[1])
    if r_start < POINT_EPS:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    if abs(r_start - r_end) > tolerance.allowed(r_start):
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    center = center_ao
    chord = math.hypot(e[0] - s[0], e[1] - s[1])
    if chord >= POINT_EPS and abs(r_start - r_end) > 1e-12:
        center = _center_on_bisector(s, e, r_start, near=center_ao)
    return plane_arc(plane, start, end, center, clockwise, turns)


def _center_on_bisector(s: Vec3 | Vec2, e: Vec3 | Vec2, radius: float, near: Vec2) -> Vec2:
    """The centre of radius ``radius`` through s and e that lies closest to ``near``."""
    mx, my = (s[0] + e[0]) / 2.0, (s[1] + e[1]) / 2.0
    dx, dy = e[0] - s[0], e[1] - s[1]
    half = math.hypot(dx, dy) / 2.0
    dist = math.sqrt(max(radius * radius - half * half, 0.0))
    nx, ny = -dy / (2.0 * half), dx / (2.0 * half)
    c1 = (mx + nx * dist, my + ny * dist)
    c2 = (mx - nx * dist, my - ny * dist)
    d1 = math.hypot(c1[0] - near[0], c1[1] - near[1])
    d2 = math.hypot(c2[0] - near[0], c2[1] - near[1])
    return c1 if d1 <= d2 else c2


def arc_from_radius(
    plane: Plane,
    start: Vec3,
    end: Vec3,
    radius: float,
    clockwise: bool,
    turns: int = 0,
    tolerance: CircleTolerance = DEFAULT_TOLERANCE,
) -> Arc:
    """G2/G3 with ``CR=`` and an end point (``CR<0``: more than a semicircle).

    Raises:
        NcAlarmError: 14040 when start and end coincide (the circle is not
            determined, so a full circle cannot be written with CR); 14095 when
            ``|CR|`` is zero or smaller than half the chord (beyond the tolerance).
    """
    turns = _check_turns(turns)
    s = plane.to_plane(start)
    e = plane.to_plane(end)
    dx, dy = e[0] - s[0], e[1] - s[1]
    chord = math.hypot(dx, dy)
    if chord < POINT_EPS:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    r = abs(float(radius))
    half = chord / 2.0
    if r < POINT_EPS or r < half - tolerance.allowed(r):
        raise NcAlarmError(ALARM_RADIUS_TOO_SMALL)
    r = max(r, half)
    dist = math.sqrt(max(r * r - half * half, 0.0))
    large = radius < 0
    # The centre of a counter-clockwise arc of at most 180° lies left of the chord.
    left = (not clockwise) != large
    nx, ny = -dy / chord, dx / chord
    sign = 1.0 if left else -1.0
    center = (s[0] + dx / 2.0 + sign * nx * dist, s[1] + dy / 2.0 + sign * ny * dist)
    return plane_arc(plane, start, end, center, clockwise, turns)


def arc_from_end_and_angle(
    plane: Plane,
    start: Vec3,
    end: Vec3,
    angle_deg: float,
    clockwise: bool,
    turns: int = 0,
) -> Arc:
    """G2/G3 with ``AR=`` (opening angle, 0 < AR < 360) and an end point.

    Raises:
        NcAlarmError: 14040 for an angle outside (0, 360) or start = end.
    """
    turns = _check_turns(turns)
    if not 0.0 < angle_deg < 360.0:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    s = plane.to_plane(start)
    e = plane.to_plane(end)
    dx, dy = e[0] - s[0], e[1] - s[1]
    chord = math.hypot(dx, dy)
    if chord < POINT_EPS:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    half_angle = math.radians(angle_deg) / 2.0
    # Signed distance from the chord midpoint to the centre: negative beyond 180°.
    dist = (chord / 2.0) / math.tan(half_angle)
    sign = -1.0 if clockwise else 1.0
    nx, ny = -dy / chord, dx / chord
    center = (s[0] + dx / 2.0 + sign * nx * dist, s[1] + dy / 2.0 + sign * ny * dist)
    return plane_arc(plane, start, end, center, clockwise, turns)


def arc_from_center_and_angle(
    plane: Plane,
    start: Vec3,
    center_ao: Vec2,
    angle_deg: float,
    clockwise: bool,
    end_applicate: float | None = None,
    turns: int = 0,
) -> Arc:
    """G2/G3 with ``AR=`` and a centre: the end point follows from the angle.

    Raises:
        NcAlarmError: 14040 for an angle outside (0, 360] or a zero radius.
    """
    turns = _check_turns(turns)
    if not 0.0 < angle_deg <= 360.0:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    s = plane.to_plane(start)
    rx, ry = s[0] - center_ao[0], s[1] - center_ao[1]
    if math.hypot(rx, ry) < POINT_EPS:
        raise NcAlarmError(ALARM_CIRCLE_END_POINT)
    angle = math.radians(angle_deg) * (-1.0 if clockwise else 1.0)
    c, si = math.cos(angle), math.sin(angle)
    ea = center_ao[0] + rx * c - ry * si
    eo = center_ao[1] + rx * si + ry * c
    ep = s[2] if end_applicate is None else float(end_applicate)
    end = plane.from_plane((ea, eo, ep))
    arc = plane_arc(plane, start, end, center_ao, clockwise, turns)
    if angle_deg >= 360.0 - 1e-9:
        arc = Arc(arc.start, arc.end, arc.center, arc.axis, arc.radius, TWO_PI * (1 + turns), turns)
    return arc


def arc_through_point(start: Vec3, intermediate: Vec3, end: Vec3, turns: int = 0) -> Arc | None:
    """``CIP``: the circle through start, intermediate and end point (in space).

    The direction follows from the order of the points. Returns ``None`` when
    the three points lie on a line with the intermediate point between start and
    end (the control then runs a straight line).

    Raises:
        NcAlarmError: 14920 when the points are collinear otherwise, or coincide.
    """
    turns = _check_turns(turns)
    s, m, e = (np.asarray(p, dtype=float) for p in (start, intermediate, end))
    u, v = m - s, e - s
    normal = np.cross(u, v)
    norm = float(np.linalg.norm(normal))
    if norm < 1e-9 * max(1.0, float(np.dot(u, u)), float(np.dot(v, v))):
        vv = float(np.dot(v, v))
        t = float(np.dot(u, v)) / vv if vv > 0 else -1.0
        if turns == 0 and 0.0 < t < 1.0:
            return None
        raise NcAlarmError(ALARM_CIP_POINT)
    axis = normal / norm
    # Circumcentre of the triangle s, m, e.
    center = s + np.cross(float(np.dot(u, u)) * v - float(np.dot(v, v)) * u, normal) / (2.0 * norm * norm)
    chord = float(np.linalg.norm(v))
    if chord > POINT_EPS:  # the end point is trusted: keep the centre on the chord's bisector
        d = v / chord
        center = center - float(np.dot(center - (s + e) / 2.0, d)) * d
    radius = float(np.linalg.norm(s - center))
    if radius > MAX_CIP_RADIUS_MM:  # practically a straight line
        vv = float(np.dot(v, v))
        t = float(np.dot(u, v)) / vv if vv > 0 else -1.0
        if turns == 0 and 0.0 < t < 1.0:
            return None
        raise NcAlarmError(ALARM_CIP_POINT)
    rs, re = s - center, e - center
    sweep = math.atan2(float(np.dot(np.cross(rs, re), axis)), float(np.dot(rs, re))) % TWO_PI
    if sweep < 1e-12:
        sweep = TWO_PI
    sweep += TWO_PI * turns
    return Arc(
        start=tuple(map(float, s)), end=tuple(map(float, e)),  # type: ignore[arg-type]
        center=tuple(map(float, center)), axis=tuple(map(float, axis)),  # type: ignore[arg-type]
        radius=radius, sweep_rad=sweep, turns=turns,
    )


def arc_tangential(plane: Plane, start: Vec3, end: Vec3, tangent: Vec3, turns: int = 0) -> Arc:
    """``CT``: the arc from ``start`` to ``end`` that leaves ``start`` along ``tangent``.

    ``tangent`` is the direction of travel at the end of the previous path
    segment (geometry axes); only its in-plane part counts.

    Raises:
        NcAlarmError: 14045 when there is no in-plane tangent or the end point lies
            on the tangent line (no circle fits).
    """
    turns = _check_turns(turns)
    s = plane.to_plane(start)
    e = plane.to_plane(end)
    t = plane.to_plane(tangent)
    tn = math.hypot(t[0], t[1])
    if tn < POINT_EPS:
        raise NcAlarmError(ALARM_TANGENTIAL_CIRCLE)
    ta, to = t[0] / tn, t[1] / tn
    na, no = -to, ta  # left normal of the tangent
    da, do = e[0] - s[0], e[1] - s[1]
    across = na * da + no * do
    if abs(across) < POINT_EPS:
        raise NcAlarmError(ALARM_TANGENTIAL_CIRCLE)
    k = (da * da + do * do) / (2.0 * across)  # signed distance of the centre along the normal
    center = (s[0] + k * na, s[1] + k * no)
    return plane_arc(plane, start, end, center, clockwise=k < 0, turns=turns)
