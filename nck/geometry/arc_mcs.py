"""How a canonical arc runs in the machine: plane and direction in the MCS.

:class:`nck.canon.Motion` keeps the programmed G code in ``kind`` (``G2``,
``G3``, ``CIP``, ``CT``). A mirroring frame reverses the direction in the
machine, a rotating frame may put the arc into another plane, and CIP/CT arcs
have no direction in their G code at all. ``arc_normal_mcs`` carries the
truth; this helper turns it into what a planar interpolator needs.
"""

from __future__ import annotations

import math
from typing import Mapping

import numpy as np

from nck.canon import Motion

ARC_KINDS = ("G2", "G3", "CIP", "CT")
# plane -> (abscissa, ordinate, applicate) axis names
PLANE_AXES = {"G17": ("X", "Y", "Z"), "G18": ("Z", "X", "Y"), "G19": ("Y", "Z", "X")}


def is_arc(motion: Motion) -> bool:
    """True for circular and helical motions (anything with a centre)."""
    return motion.kind in ARC_KINDS and motion.center_mcs is not None


def mcs_plane_and_direction(motion: Motion) -> tuple[str, bool] | None:
    """``(plane, clockwise)`` of an arc in the MCS, or None for a non-arc or an arc
    that does not lie in G17/G18/G19 of the machine (rotated out of the main planes:
    interpolate it with :func:`normal_of` or as a polyline).

    ``clockwise`` is seen from the positive applicate of that plane (G2 = True).
    """
    if not is_arc(motion):
        return None
    normal = normal_of(motion)
    for code, (_a, _o, applicate) in PLANE_AXES.items():
        component = normal.get(applicate, 0.0)
        others = [abs(v) for axis, v in normal.items() if axis != applicate]
        if abs(abs(component) - 1.0) <= 1e-6 and all(v <= 1e-6 for v in others):
            return code, component < 0
    return None


def normal_of(motion: Motion) -> Mapping[str, float]:
    """The MCS turning axis of an arc (from ``arc_normal_mcs``, else from the G code and plane)."""
    if motion.arc_normal_mcs is not None:
        return motion.arc_normal_mcs
    applicate = PLANE_AXES.get(motion.plane, PLANE_AXES["G17"])[2]
    sign = -1.0 if motion.kind == "G2" else 1.0
    return {axis: (sign if axis == applicate else 0.0) for axis in ("X", "Y", "Z")}


def arc_points_mcs(motion: Motion, count: int = 32) -> list[dict[str, float]]:
    """``count`` + 1 points along an arc or helix in the MCS, start to end (any plane).

    Works from ``start_mcs``, ``center_mcs``, ``end_mcs``, ``turns`` and the turning
    axis, so it also draws arcs that a frame has tilted out of G17/G18/G19. A line
    gives just its start and end.
    """
    axes = ("X", "Y", "Z")
    start = np.array([float(motion.start_mcs.get(a, motion.end_mcs.get(a, 0.0))) for a in axes])
    end = np.array([float(motion.end_mcs.get(a, 0.0)) for a in axes])
    others = {a: float(v) for a, v in motion.end_mcs.items() if a not in axes}
    if not is_arc(motion) or count < 1:
        return [dict(motion.start_mcs) or dict(motion.end_mcs), dict(motion.end_mcs)]
    assert motion.center_mcs is not None
    centre = np.array([float(motion.center_mcs.get(a, 0.0)) for a in axes])
    normal = np.array([float(normal_of(motion).get(a, 0.0)) for a in axes])
    normal = normal / float(np.linalg.norm(normal))
    lead = float(np.dot(end - start, normal))
    r0 = (start - centre) - float(np.dot(start - centre, normal)) * normal
    r1 = (end - centre) - float(np.dot(end - centre, normal)) * normal
    sweep = math.atan2(float(np.dot(np.cross(r0, r1), normal)), float(np.dot(r0, r1))) % (2 * math.pi)
    if sweep < 1e-9:
        sweep = 2 * math.pi
    sweep += 2 * math.pi * max(int(motion.turns), 0)
    radius0, radius1 = float(np.linalg.norm(r0)), float(np.linalg.norm(r1))
    unit0 = r0 / radius0 if radius0 > 0 else r0
    points = []
    for k in range(count + 1):
        t = k / count
        angle = sweep * t
        turned = unit0 * math.cos(angle) + np.cross(normal, unit0) * math.sin(angle)
        radius = radius0 + (radius1 - radius0) * t
        p = centre + float(np.dot(start - centre, normal)) * normal + turned * radius + normal * lead * t
        point = {a: float(p[i]) for i, a in enumerate(axes) if a in motion.end_mcs}
        point.update(others)
        points.append(point)
    points[-1] = dict(motion.end_mcs)
    return points
