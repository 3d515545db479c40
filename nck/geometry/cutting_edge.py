"""Cutting edges of turning tools, tool classes, the compensation radius, DIAMON/DIAMOF.

Turning tools (types 500–599, grinding 400–499 alike) are measured to the
theoretical tool tip P; the nose radius r has its centre S. The cutting edge
position ``$TC_DP2`` (1–9) says where P lies relative to S in the plane
(abscissa, ordinate) — for G18 with the tool behind the turning centre the
abscissa is Z and the ordinate X (Function Manual W1 §18.4.3 / §18.7.3):

====  =========  ==========================
SL    P − S      distance
====  =========  ==========================
1     (+r, +r)   r·√2, on the diagonal
2     (−r, +r)
3     (−r, −r)   the usual external tool
4     (+r, −r)
5     (+r, 0)    r, on an axis
6     (0, +r)
7     (−r, 0)
8     (0, −r)
9     (0, 0)     length measured to S
====  =========  ==========================

With G41/G42 the compensation moves S along the offset contour; the tool
length still refers to P, so the point the length compensation places is
``S + (P − S)``. Without compensation P follows the programmed contour and the
nose leaves a radius error on tapers and arcs.

Tool classes follow ``$TC_DP1``: 1xx milling, 2xx drilling, 4xx grinding,
5xx turning, 7xx special (700 slotting saw). Milling and turning tools carry a
radius for the compensation; drills do not. Which length acts on which axis
is :mod:`nck.geometry.tool_length`.
"""

from __future__ import annotations

import math

from nck.errors import NcAlarmError
from nck.ncdata import ToolEdge

Vec = tuple[float, float]

#: Alarm for an invalid cutting edge position ($TC_DP2 outside 1–9, e.g. 0); own choice of number.
ALARM_CUTTING_EDGE_POSITION = 10799

# Direction of P relative to S per cutting edge position, in units of r.
_TIP_DIRECTION: dict[int, Vec] = {
    1: (1.0, 1.0),
    2: (-1.0, 1.0),
    3: (-1.0, -1.0),
    4: (1.0, -1.0),
    5: (1.0, 0.0),
    6: (0.0, 1.0),
    7: (-1.0, 0.0),
    8: (0.0, -1.0),
    9: (0.0, 0.0),
}

#: Allowed cut directions $TC_DP11 per position (1 ordinate −, 2 ordinate +, 3 abscissa −, 4 abscissa +).
CUT_DIRECTIONS: dict[int, tuple[int, int]] = {
    1: (2, 4),
    2: (2, 3),
    3: (1, 3),
    4: (1, 4),
    5: (1, 2),
    6: (3, 4),
    7: (1, 2),
    8: (3, 4),
}


def tool_class(tool_type: int) -> str:
    """``milling`` (1xx), ``drilling`` (2xx), ``grinding`` (4xx), ``turning`` (5xx),
    ``special`` (7xx) or ``none`` (0 or unknown)."""
    hundreds = int(tool_type) // 100
    return {1: "milling", 2: "drilling", 4: "grinding", 5: "turning", 7: "special"}.get(
        hundreds, "none"
    )


def has_cutting_edge_position(tool_type: int) -> bool:
    """True for the tools whose $TC_DP2 matters for the compensation (turning and grinding)."""
    return tool_class(tool_type) in ("turning", "grinding")


def uses_radius(tool_type: int) -> bool:
    """True if the tool type carries a radius for the compensation (not drills)."""
    return tool_class(tool_type) in ("milling", "turning", "grinding", "special")


def effective_radius(edge: ToolEdge | None, wear_sign: int = 0) -> float:
    """Compensation radius $TC_DP6 + $TC_DP15 (wear negated with SD42930 ≠ 0); 0 for D0.

    Drills (2xx) compensate with their radius too if one is entered; the
    manual only says one need not be entered.
    """
    if edge is None:
        return 0.0
    sign = -1.0 if wear_sign else 1.0
    return edge.get(6) + sign * edge.get(15)


def tip_offset(position: int, radius_mm: float) -> Vec:
    """P − S in plane coordinates (abscissa, ordinate) for cutting edge position 1–9.

    Raises:
        NcAlarmError: 10799 for a position outside 1–9 (0 is not allowed).
    """
    direction = _TIP_DIRECTION.get(int(position))
    if direction is None:
        raise NcAlarmError(ALARM_CUTTING_EDGE_POSITION, str(position))
    return (direction[0] * radius_mm, direction[1] * radius_mm)


def tip_distance(position: int, radius_mm: float) -> float:
    """|P − S|: r·√2 for positions 1–4, r for 5–8, 0 for 9."""
    dx, dy = tip_offset(position, radius_mm)
    return math.hypot(dx, dy)


def tip_from_centre(centre: Vec, position: int, radius_mm: float) -> Vec:
    """The theoretical tip P for a nose centre S (what the length compensation places)."""
    dx, dy = tip_offset(position, radius_mm)
    return (centre[0] + dx, centre[1] + dy)


def centre_from_tip(tip: Vec, position: int, radius_mm: float) -> Vec:
    """The nose centre S for a theoretical tip P."""
    dx, dy = tip_offset(position, radius_mm)
    return (tip[0] - dx, tip[1] - dy)


def reference_offset(tool_type: int, position: int, radius_mm: float) -> Vec:
    """Shift from the compensated tool-centre path to the point the length refers to.

    Turning/grinding tools: P − S by the cutting edge position. Every other
    class: (0, 0) — the length of a milling tool refers to its axis.
    """
    if not has_cutting_edge_position(tool_type):
        return (0.0, 0.0)
    return tip_offset(position, radius_mm)


def cut_direction_fits(position: int, cut_direction: int) -> bool:
    """True if $TC_DP11 suits the cutting edge position (table in W1 §18.7.3)."""
    return int(cut_direction) in CUT_DIRECTIONS.get(int(position), ())


# ------------------------------------------------------------------ DIAMON / DIAMOF


def program_to_radius(value: float, diameter_programming: bool) -> float:
    """A programmed transverse-axis (lathe X) value as a radius coordinate.

    Under DIAMON the program gives diameters: the axis moves to half the value.
    Under DIAMOF the value is already a radius.
    """
    return value / 2.0 if diameter_programming else value


def radius_to_program(value: float, diameter_programming: bool) -> float:
    """The displayed/programmed value of a transverse-axis radius coordinate."""
    return value * 2.0 if diameter_programming else value
