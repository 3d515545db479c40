"""Software limit switches (MD36100/MD36110) and working-area limitation (G25/G26, SD434xx).

Both act only on referenced axes. In AUTO/MDA a segment is checked before it
starts (alarms 10720 / 10730); in JOG the axis is sent no further than the
limit, and a further key press at the limit raises 10621 / 10631.
"""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from nck.motion.params import AxisParams
from nck.motion.path import Segment

ALARM_SW_LIMIT_AUTO = 10720
ALARM_WORKAREA_AUTO = 10730
ALARM_SW_LIMIT_JOG = 10621
ALARM_WORKAREA_JOG = 10631
ARC_BOX_MARGIN_MM = 1e-6  # covers the rounding of cos/sin in the sampled positions
EDGE_MM = 1e-6


_KEYS: dict[tuple[int, str], tuple[str, str]] = {}


def axis_setting(data: Mapping[str, Any] | None, number: int, axis: str, default: Any) -> Any:
    """Read setting datum ``SD<number>`` for ``axis`` (``{"SD43420": {"X": 1}}`` or ``"SD43420[X]"``)."""
    if not data:
        return default
    keys = _KEYS.get((number, axis))
    if keys is None:
        keys = _KEYS[(number, axis)] = (f"SD{number}", f"SD{number}[{axis}]")
    value = data.get(keys[0])
    if value is None:
        return data.get(keys[1], default)
    if type(value) is dict or isinstance(value, Mapping):
        return value.get(axis, default)
    return value


class Limits:
    """The active travel limits of every path axis."""

    def __init__(self, axes: tuple[AxisParams, ...], setting_data: Mapping[str, Any] | None) -> None:
        self.axes = axes
        self.setting_data = setting_data
        self.workarea_on = True  # WALIMON (reset position); WALIMOF switches it off
        self._software = [(axis.pos_limit_minus_mm, axis.pos_limit_plus_mm) for axis in axes]

    def software(self, i: int) -> tuple[float, float]:
        """(minus, plus) software limit of axis ``i``."""
        return self._software[i]

    def workarea(self, i: int) -> tuple[float, float]:
        """(minus, plus) working-area limit of axis ``i`` (infinite when not enabled)."""
        name = self.axes[i].name
        if not self.workarea_on:
            return -math.inf, math.inf
        data = self.setting_data
        minus = -math.inf
        plus = math.inf
        if bool(axis_setting(data, 43410, name, 0)):
            minus = float(axis_setting(data, 43430, name, -math.inf))
        if bool(axis_setting(data, 43400, name, 0)):
            plus = float(axis_setting(data, 43420, name, math.inf))
        return minus, plus

    def check_segment(self, segment: Segment, referenced: list[bool]) -> tuple[int, str, str] | None:
        """First violation of a segment: (alarm number, axis name, ``+``/``-``), or None."""
        if segment.arc is None:
            _starts, deltas, ends = segment.floats()
            software = self._software
            for i, delta in enumerate(deltas):
                if delta == 0.0 or not referenced[i]:
                    continue
                value = ends[i]
                minus, plus = software[i]
                w_minus, w_plus = self.workarea(i) if self.setting_data else (-math.inf, math.inf)
                name = self.axes[i].name
                if value > plus + EDGE_MM:
                    return ALARM_SW_LIMIT_AUTO, name, "+"
                if value < minus - EDGE_MM:
                    return ALARM_SW_LIMIT_AUTO, name, "-"
                if value > w_plus + EDGE_MM:
                    return ALARM_WORKAREA_AUTO, name, "+"
                if value < w_minus - EDGE_MM:
                    return ALARM_WORKAREA_AUTO, name, "-"
            return None
        if self._arc_inside(segment, referenced):
            return None  # the arc's bounding box is inside every limit: no sample can be outside
        points = segment.positions(np.linspace(0.0, segment.length, 65))
        low = points.min(axis=0)
        high = points.max(axis=0)
        moved = np.abs(segment.end - segment.start) > 0
        if segment.arc is not None:
            moved[segment.arc[0]] = moved[segment.arc[1]] = True
        for i, axis in enumerate(self.axes):
            if not referenced[i] or not moved[i]:
                continue
            minus, plus = self.software(i)
            if high[i] > plus + EDGE_MM:
                return ALARM_SW_LIMIT_AUTO, axis.name, "+"
            if low[i] < minus - EDGE_MM:
                return ALARM_SW_LIMIT_AUTO, axis.name, "-"
            w_minus, w_plus = self.workarea(i)
            if high[i] > w_plus + EDGE_MM:
                return ALARM_WORKAREA_AUTO, axis.name, "+"
            if low[i] < w_minus - EDGE_MM:
                return ALARM_WORKAREA_AUTO, axis.name, "-"
        return None

    def _arc_inside(self, segment: Segment, referenced: list[bool]) -> bool:
        """True when a box around the whole arc (centre ± the larger radius in its plane, start
        and end in the other axes) lies inside the software limits and the working area of every
        referenced axis; then the sampled check below cannot find a violation."""
        i1, i2, c1, c2, r0, r1, _, _ = segment.arc  # type: ignore[misc]
        size0, size1 = abs(r0), abs(r1)  # max(size0, size1) as the builtin decides:
        reach = (size1 if size1 > size0 else size0) + ARC_BOX_MARGIN_MM
        starts, _deltas, ends = segment.floats()
        software = self._software
        # (min and max written out as the builtins decide: the first argument unless the
        # second compares less, resp. greater; every arc block comes here)
        for i, on in enumerate(referenced):
            if not on:
                continue
            low = high = starts[i]
            end = ends[i]
            if end < low:
                low = end
            if end > high:
                high = end
            if i == i1 or i == i2:
                centre = c1 if i == i1 else c2
                edge = centre - reach
                if edge < low:
                    low = edge
                edge = centre + reach
                if edge > high:
                    high = edge
            minus, plus = software[i]
            w_minus, w_plus = self.workarea(i) if self.setting_data else (-math.inf, math.inf)
            upper = w_plus if w_plus < plus else plus
            lower = w_minus if w_minus > minus else minus
            if high > upper + EDGE_MM or low < lower - EDGE_MM:
                return False
        return True

    def jog_limit(self, i: int, direction: float, referenced: bool) -> tuple[float, int]:
        """The limit a JOG motion in ``direction`` stops at, and the alarm for pressing on."""
        if not referenced:
            return (math.inf if direction > 0 else -math.inf), 0
        minus, plus = self.software(i)
        w_minus, w_plus = self.workarea(i)
        if direction > 0:
            return (plus, ALARM_SW_LIMIT_JOG) if plus <= w_plus else (w_plus, ALARM_WORKAREA_JOG)
        return (minus, ALARM_SW_LIMIT_JOG) if minus >= w_minus else (w_minus, ALARM_WORKAREA_JOG)
