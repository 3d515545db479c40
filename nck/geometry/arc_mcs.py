"""How a canonical arc runs in the machine: plane and direction in the MCS.

:class:`nck.canon.Motion` keeps the programmed G code in ``kind`` (``G2``,
``G3``, ``CIP``, ``CT``). A mirroring frame reverses the direction in the
machine, a rotating frame may put the arc into another plane, and CIP/CT arcs
have no direction in their G code at all. ``arc_normal_mcs`` carries the
truth; this helper turns it into what a planar interpolator needs.
"""

from __future__ import annotations

from typing import Mapping

from nck.canon import Motion

ARC_KINDS = ("G2", "G3", "CIP", "CT")
# plane -> (abscissa, ordinate, applicate) axis names
PLANE_AXES = {"G17": ("X", "Y", "Z"), "G18": ("Z", "X", "Y"), "G19": ("Y", "Z", "X")}
AXIS_TOL = 1e-9


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
