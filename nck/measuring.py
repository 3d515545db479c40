"""Manual measuring ("scratching", 002 L31279-31290): pure arithmetic on touch positions.

A *touch* is where the tool stood when it touched the workpiece: the centre of the cutter
(or of the probe's ball) in the machine coordinates, in mm. The measuring screens collect
touches (the current position when the operator presses the softkey, or a probe's trigger
position) and turn them into workpiece points here; the point then goes into a work offset
with ``nck.commands.SetActualValue(axis, value, target, point_mcs=…)`` (a rotation first
with ``SetWorkOffsetRotation``), a tool length or radius into the tool data.

Conventions:

* ``approach`` is the direction the tool moved in when it touched: +1 / −1 along one axis,
  or a 2-D vector in the working plane. The surface lies ``radius`` beyond the tool centre
  in that direction (a cutter's radius, or the ball radius of a 3D probe).
* Lengths: the machine position of the tool axis (``machine_mm``) is the tool carrier
  reference point; the tool tip is ``tool_length_mm`` below it. A 3D probe's length is to
  the centre of its ball (trainer choice, written down here; the ball's lowest point is a
  further ball radius down).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np

Vector2 = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Corner:
    """A measured corner: its position in the plane and the angle of its first edge
    against the plane's first axis (degrees, folded into −45 … 45: a right-angled corner
    repeats every 90°)."""

    x_mm: float
    y_mm: float
    angle_deg: float


@dataclass(frozen=True, slots=True)
class Circle:
    """A measured hole or spigot: centre in the plane and diameter."""

    x_mm: float
    y_mm: float
    diameter_mm: float


def edge_position(touch_mm: float, approach: int, radius_mm: float) -> float:
    """The edge touched from ``touch_mm`` moving in direction ``approach`` (±1) with a tool
    of radius ``radius_mm``: the surface is one radius beyond the tool centre."""
    if approach not in (1, -1):
        raise ValueError("approach is +1 or -1")
    return touch_mm + approach * radius_mm


def offset_for(point_mm: float, setpoint_mm: float) -> float:
    """The translation that makes ``point_mm`` read ``setpoint_mm`` (no other frame active)."""
    return point_mm - setpoint_mm


def corner(x_touch_mm: float, x_approach: int, y_touch_mm: float, y_approach: int,
           radius_mm: float) -> Vector2:
    """A right-angled corner parallel to the axes from one touch on each edge."""
    return (edge_position(x_touch_mm, x_approach, radius_mm), edge_position(y_touch_mm, y_approach, radius_mm))


def _unit(vector: Sequence[float]) -> np.ndarray:
    array = np.asarray(vector, dtype=float)
    length = float(np.hypot(array[0], array[1]))
    if length == 0.0:
        raise ValueError("a direction of length 0")
    return array / length


def rotated_corner(first: Vector2, second: Vector2, first_approach: Vector2,
                   third: Vector2, third_approach: Vector2, radius_mm: float) -> Corner:
    """A right-angled corner at any angle: touches ``first`` and ``second`` on edge 1 (moving
    in ``first_approach``), ``third`` on edge 2 (moving in ``third_approach``).

    The two centres on edge 1 give its direction; the edge lies one radius further along
    its normal towards the material; edge 2 is perpendicular to it through the third touch
    shifted the same way. The corner is where they meet.
    """
    p1, p2, p3 = (np.asarray(p, dtype=float) for p in (first, second, third))
    along = _unit(p2 - p1)
    normal = np.array([-along[1], along[0]])
    if float(normal @ np.asarray(first_approach, dtype=float)) < 0.0:
        normal = -normal
    across = along if float(along @ np.asarray(third_approach, dtype=float)) >= 0.0 else -along
    on_edge1 = p1 + radius_mm * normal
    on_edge2 = p3 + radius_mm * across
    point = on_edge1 + float((on_edge2 - on_edge1) @ along) * along
    angle = math.degrees(math.atan2(along[1], along[0]))
    folded = (angle + 45.0) % 90.0 - 45.0
    return Corner(float(point[0]), float(point[1]), folded)


def circle(touches: Sequence[Vector2], radius_mm: float, hole: bool) -> Circle:
    """A hole (``hole=True``, touched from inside) or a spigot (from outside) from 3 or
    more touches: the tool centres lie on a circle one tool radius smaller (hole) or
    larger (spigot) than the workpiece's; its centre is the workpiece's centre."""
    if len(touches) < 3:
        raise ValueError("a circle needs 3 touches or more")
    points = np.asarray(touches, dtype=float)
    # x² + y² + a·x + b·y + c = 0, least squares (exact for points on a circle).
    matrix = np.column_stack([points[:, 0], points[:, 1], np.ones(len(points))])
    rhs = -(points[:, 0] ** 2 + points[:, 1] ** 2)
    (a, b, c), *_ = np.linalg.lstsq(matrix, rhs, rcond=None)
    cx, cy = -a / 2.0, -b / 2.0
    centre_radius = math.sqrt(max(cx * cx + cy * cy - c, 0.0))
    radius = centre_radius + radius_mm if hole else centre_radius - radius_mm
    return Circle(float(cx), float(cy), 2.0 * radius)


def z_surface(machine_z_mm: float, tool_length_mm: float, ball_radius_mm: float = 0.0) -> float:
    """The Z of a surface touched from above: the tool tip (a 3D probe: its ball's lowest
    point) is on it."""
    return machine_z_mm - tool_length_mm - ball_radius_mm


def tool_length(machine_z_mm: float, surface_z_mm: float) -> float:
    """Tool length from touching a surface of known machine Z (the blank's top, or the
    reference block's top: its fixed-point value) with the tool tip from above."""
    return machine_z_mm - surface_z_mm


def tool_radius(touch_mm: float, approach: int, edge_mm: float) -> float:
    """Tool radius from touching an edge of known machine position ``edge_mm``."""
    if approach not in (1, -1):
        raise ValueError("approach is +1 or -1")
    return approach * (edge_mm - touch_mm)
