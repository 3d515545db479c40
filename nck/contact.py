"""Contact of the tool with what is clamped: pure, deterministic geometry.

The tool is a :class:`ToolBody`: a cutter is a cylinder standing on its tip (radius of
the cutting edge, length L1 up the tool axis Z), a 3D probe (tool type 710) a ball whose
centre is the tip point (its length is to the ball centre: ``nck.measuring``); a turning
tool is a ball of its cutting-edge radius. Solids are the blank and the reference block
of :mod:`nck.workpiece` (boxes, parallel to the axes or turned about Z; cylinders along Z).

:func:`clearance` is a gap function ``g(tip)``: positive apart, ≤ 0 in contact (its
negative is how deep: a signed distance), never larger than the distance the tip must
still travel to touch (each part is 1-Lipschitz), and convex in the tip position (signed
distances to convex sets, and maxima of them, are convex).
Along one interpolation step (a straight segment from one IPO setpoint to the next)
``g`` is therefore convex in the path parameter, so :func:`first_contact` finds the first
parameter where it reaches 0 exactly: it locates the minimum (golden section) and then the
root before it (bisection). A contact is never missed because a step jumped over a
surface — no points are sampled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from nck.workpiece import Box, Cylinder, Point, Solid

CUTTER = "cutter"
BALL = "ball"
_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
_SEARCH_STEPS = 90  # golden-section steps: the interval shrinks to 0.618**90 ≈ 1.6e-19
_ROOT_STEPS = 64  # bisection steps of the root: 2**-64 of the step


@dataclass(frozen=True, slots=True)
class ToolBody:
    """The shape of the active tool around its tip: ``CUTTER`` (cylinder up the Z axis) or
    ``BALL`` (sphere around the tip), with its radius and (cutter) length in mm."""

    shape: str
    radius_mm: float
    length_mm: float = 0.0


def _signed(outside: tuple[float, ...]) -> float:
    """Signed distance from per-axis signed excesses (positive outside the slab, negative in)."""
    beyond = math.sqrt(sum(max(q, 0.0) ** 2 for q in outside))
    return beyond + min(max(outside), 0.0)


def _in_box_frame(box: Box, tip: Point) -> Point:
    """The tip turned back about the box's centre: in that frame its faces are parallel to the
    axes. A rotation about Z keeps distances and the cutter's axis, so the gap stays exact."""
    if not box.rotation_z_deg:
        return tip
    (cx, cy), angle = box.centre_xy_mcs, math.radians(box.rotation_z_deg)
    dx, dy, cos, sin = tip[0] - cx, tip[1] - cy, math.cos(angle), math.sin(angle)
    return (cx + dx * cos + dy * sin, cy - dx * sin + dy * cos, tip[2])


def _box_gap(body: ToolBody, box: Box, tip: Point) -> float:
    (x, y, z), (lx, ly, lz), (hx, hy, hz) = _in_box_frame(box, tip), box.low_mcs, box.high_mcs
    qx, qy = max(lx - x, x - hx), max(ly - y, y - hy)
    if body.shape == BALL:
        return _signed((qx, qy, max(lz - z, z - hz))) - body.radius_mm
    # A cylinder from z to z + length: its side against the XY rectangle, its extent in Z.
    gap_z = max(lz - (z + body.length_mm), z - hz)
    return max(_signed((qx, qy)) - body.radius_mm, gap_z)


def _cylinder_gap(body: ToolBody, solid: Cylinder, tip: Point) -> float:
    (x, y, z), (cx, cy, bottom) = tip, solid.base_mcs
    top = bottom + solid.length_mm
    radial = math.hypot(x - cx, y - cy) - solid.diameter_mm / 2.0
    if body.shape == BALL:
        return _signed((radial, max(bottom - z, z - top))) - body.radius_mm
    gap_z = max(bottom - (z + body.length_mm), z - top)
    return max(radial - body.radius_mm, gap_z)


def clearance(body: ToolBody, solid: Solid, tip_mcs: Point) -> float:
    """The gap function of the module docstring for the tool tip at ``tip_mcs`` (mm)."""
    if isinstance(solid, Box):
        return _box_gap(body, solid, tip_mcs)
    return _cylinder_gap(body, solid, tip_mcs)


def _along(start: Point, end: Point, t: float) -> Point:
    return (start[0] + (end[0] - start[0]) * t, start[1] + (end[1] - start[1]) * t,
            start[2] + (end[2] - start[2]) * t)


def point_along(start: Point, end: Point, t: float) -> Point:
    """The point at parameter ``t`` (0 … 1) of the segment from ``start`` to ``end``."""
    return _along(start, end, t)


def first_contact(body: ToolBody, solid: Solid, start: Point, end: Point, depth_mm: float = 0.0) -> float | None:
    """The first parameter ``t`` in 0 … 1 where the tip moving from ``start`` to ``end`` is
    ``depth_mm`` deep in contact (``clearance ≤ −depth_mm``; 0: touching); ``None`` if never.

    0.0 when it already is at ``start``.
    """

    def gap(t: float) -> float:
        return clearance(body, solid, _along(start, end, t)) + depth_mm

    at_start = gap(0.0)
    if at_start <= 0.0:
        return 0.0
    if at_start > math.dist(start, end):
        return None  # the gap shrinks at most as fast as the tip travels (1-Lipschitz)
    if gap(1.0) <= 0.0:
        low_t, high_t = 0.0, 1.0
    else:
        # Minimum of the convex gap on [0, 1] (golden section).
        a, b = 0.0, 1.0
        c, d = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
        gc, gd = gap(c), gap(d)
        for _ in range(_SEARCH_STEPS):
            if min(gc, gd) <= 0.0:
                break
            if gc <= gd:
                b, d, gd = d, c, gc
                c = b - _GOLDEN * (b - a)
                gc = gap(c)
            else:
                a, c, gc = c, d, gd
                d = a + _GOLDEN * (b - a)
                gd = gap(d)
        if gc <= 0.0:
            high_t = c
        elif gd <= 0.0:
            high_t = d
        else:
            return None
        low_t = 0.0
    for _ in range(_ROOT_STEPS):  # gap(low) > 0 >= gap(high)
        middle = (low_t + high_t) / 2.0
        if gap(middle) <= 0.0:
            high_t = middle
        else:
            low_t = middle
    return high_t
