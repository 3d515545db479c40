"""The direction of travel at the end of a path element (what a tangential circle CT
continues, :func:`nck.geometry.circles.arc_tangential`)."""

from __future__ import annotations

import math

from nck.geometry.circles import Arc
from nck.geometry.contour_aids import LineElement


def end_tangent(element: LineElement | Arc) -> tuple[float, float, float] | None:
    """The unit direction at the end of ``element``; ``None`` for a line of no (or no finite) length."""
    if isinstance(element, Arc):
        return element.tangent_at(1.0)
    return line_tangent(element.start, element.end)


def line_tangent(start: tuple[float, float, float], end: tuple[float, float, float]
                 ) -> tuple[float, float, float] | None:
    """The unit direction of the line from ``start`` to ``end``; ``None`` for no (or no finite) length."""
    d0, d1, d2 = float(end[0]) - float(start[0]), float(end[1]) - float(start[1]), float(end[2]) - float(start[2])
    n = math.hypot(d0, d1, d2)  # no overflow for huge coordinates (numpy's norm warns)
    if n < 1e-12 or not math.isfinite(n):
        return None
    return (d0 / n, d1 / n, d2 / n)
