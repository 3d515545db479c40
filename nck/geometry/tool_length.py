"""Tool length compensation: which length acts on which geometry axis.

Each cutting edge has three length components (``$TC_DP3..5`` geometry,
``$TC_DP12..14`` wear, ``$TC_DP21..23`` base dimension); the effective length
``Lk = geometry + wear + base``. Their assignment to geometry axes 1..3 depends
on the tool class and the plane (Function Manual W1, "tool length and plane
change", ``SD42940 TOOL_LENGTH_CONST``, ``SD42950 TOOL_LENGTH_TYPE``):

* milling and other tools (type < 400 or > 599), G17: L1 → axis 3 (Z),
  L2 → axis 2 (Y), L3 → axis 1 (X); G18: L1 → Y, L2 → X, L3 → Z;
  G19: L1 → X, L2 → Z, L3 → Y;
* turning and grinding tools (400…599), G17: L1 → Y, L2 → X, L3 → Z;
  G18: L1 → X, L2 → Z, L3 → Y; G19: L1 → Z, L2 → Y, L3 → X.

A non-zero ``SD42940`` freezes the assignment (±17, ±18, ±19; any other
non-zero value counts as 17 for milling tools and 18 for turning tools).
``SD42930 WEAR_SIGN`` ≠ 0 inverts the wear.

The lengths run from the tool tip to the toolholder reference point, so the
machine position is ``MCS = BCS (tool tip) + offset vector``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from nck.errors import NcAlarmError
from nck.ncdata import NcData, ToolEdge

ALARM_ILLEGAL_D = 17180  # illegal D number: the edge does not exist for this tool
ALARM_T_NOT_DEFINED = 17191  # T number not defined

# (L1, L2, L3) -> geometry axis index 0..2, per tool class and SD42940 / plane value.
_MILLING_AXES: dict[int, tuple[int, int, int]] = {
    17: (2, 1, 0), 18: (1, 0, 2), 19: (0, 2, 1),
    -17: (2, 0, 1), -18: (1, 2, 0), -19: (0, 1, 2),
}
_TURNING_AXES: dict[int, tuple[int, int, int]] = {
    17: (1, 0, 2), 18: (0, 2, 1), 19: (2, 1, 0),
    -17: (0, 1, 2), -18: (2, 0, 1), -19: (1, 2, 0),
}
_PLANE_NUMBER = {"G17": 17, "G18": 18, "G19": 19}


def is_turning_type(tool_type: int, length_type: int = 0) -> bool:
    """True when the edge uses the turning/grinding assignment (types 400…599 or SD42950 = 2)."""
    if length_type == 1:
        return False
    if length_type == 2:
        return True
    return 400 <= tool_type <= 599


def length_axes(
    tool_type: int, plane_code: str, length_const: int = 0, length_type: int = 0
) -> tuple[int, int, int]:
    """Geometry-axis index (0..2) that L1, L2 and L3 act on."""
    turning = is_turning_type(tool_type, length_type)
    table = _TURNING_AXES if turning else _MILLING_AXES
    key = _PLANE_NUMBER[plane_code] if length_const == 0 else int(length_const)
    if key not in table:
        key = 18 if turning else 17
    return table[key]


def active_wear_sign(modal: Any, setting_data: Mapping[str, Any]) -> int:
    """SD42930 for the active edge: the value at its selection (``modal.wear_sign``; a change
    of the datum acts from the next D or tool change on, 002 L62080-62083), else the datum now."""
    frozen = getattr(modal, "wear_sign", None)
    if frozen is not None:
        return int(frozen)
    return int(setting_data.get("SD42930", 0) or 0)


def effective_lengths(edge: ToolEdge, wear_sign: int = 0) -> tuple[float, float, float]:
    """L1, L2, L3 = geometry + wear + base (wear negated when SD42930 ≠ 0)."""
    sign = -1.0 if wear_sign else 1.0
    return tuple(  # type: ignore[return-value]
        edge.get(3 + k) + sign * edge.get(12 + k) + edge.get(21 + k) for k in range(3)
    )


def length_offset(
    edge: ToolEdge | None,
    plane_code: str,
    geometry_axes: tuple[str, str, str] = ("X", "Y", "Z"),
    *,
    length_const: int = 0,
    length_type: int = 0,
    wear_sign: int = 0,
    data_mm: float = 1.0,
) -> dict[str, float]:
    """The tool length vector (mm, per geometry axis) that is added to the BCS to get the MCS.

    ``edge=None`` (D0 or no tool) gives a zero vector. ``data_mm`` converts the
    stored values into mm (1.0 for a metric basic system).
    """
    out = {axis: 0.0 for axis in geometry_axes}
    if edge is None:
        return out
    lengths = effective_lengths(edge, wear_sign)
    for length, index in zip(lengths, length_axes(edge.tool_type, plane_code, length_const, length_type)):
        out[geometry_axes[index]] += length * data_mm
    return out


def resolve_edge(data: NcData, tool: int, edge: int) -> ToolEdge | None:
    """The cutting edge to compensate with, or None for D0 / T0.

    Raises:
        NcAlarmError: 17180 when ``D<edge>`` does not exist for tool ``T<tool>``.
    """
    if edge == 0 or tool == 0:
        return None
    found = data.edge(tool, edge)
    if found is None:
        raise NcAlarmError(ALARM_ILLEGAL_D, f"T{tool}", f"D{edge}")
    return found
