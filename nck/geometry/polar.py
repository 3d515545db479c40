"""Polar coordinates: pole G110 / G111 / G112, polar radius ``RP=`` and angle ``AP=``.

The pole lives in the active plane (abscissa, ordinate) of the WCS. ``RP``
and ``AP`` are modal. The angle is measured from the abscissa towards the
ordinate (counter-clockwise seen from the positive applicate).

Pole definitions (non-modal, they do not move the axes and ignore G90/G91):

* ``G110``: relative to the last programmed position;
* ``G111``: absolute in the WCS;
* ``G112``: relative to the last valid pole.

Each may be written with plane axes (``G111 X.. Y..``) or in polar form
(``G111 AP=.. RP=..``: the new pole lies at that radius and angle from the
reference point of the code).

If no pole has been defined, the origin of the current WCS acts as the pole
(Programming Manual Fundamentals, "defining the pole"), so a polar move
without a pole is not an error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from nck.alarm_ids import VALUE_RANGE_EXCEEDED
from nck.errors import NcAlarmError

Vec2 = tuple[float, float]

# A polar radius must not be negative: reported as "value range exceeded" (12160).
POLE_CODES = ("G110", "G111", "G112")


@dataclass(frozen=True, slots=True)
class PolarState:
    """Modal polar-coordinate data of the channel.

    Attributes:
        pole: the pole in (abscissa, ordinate) of the WCS, mm; None = not defined
            (the WCS origin then acts as the pole).
        radius_mm: modal polar radius ``RP``.
        angle_deg: modal polar angle ``AP``.
    """

    pole: Vec2 | None = None
    radius_mm: float = 0.0
    angle_deg: float = 0.0

    @property
    def effective_pole(self) -> Vec2:
        """The pole in use: the defined one, else the WCS origin."""
        return self.pole if self.pole is not None else (0.0, 0.0)

    def define_pole(
        self,
        code: str,
        last_position: Vec2,
        axes: Vec2 | None = None,
        polar: tuple[float, float] | None = None,
    ) -> "PolarState":
        """Return the state after ``G110``/``G111``/``G112``.

        Args:
            code: the pole code.
            last_position: last programmed position in the plane (for G110).
            axes: plane-axis values (missing axis = 0), or None.
            polar: ``(RP, AP)`` of the pole definition, or None.
        """
        if code not in POLE_CODES:
            raise ValueError(f"not a pole definition: {code}")
        if code == "G110":
            reference = last_position
        elif code == "G111":
            reference = (0.0, 0.0)
        else:
            reference = self.effective_pole
        if polar is not None:
            rp, ap = polar
            offset = _polar_to_xy(rp, ap)
        elif axes is not None:
            offset = axes
        else:
            offset = (0.0, 0.0)
        return replace(self, pole=(reference[0] + offset[0], reference[1] + offset[1]))

    def with_values(self, radius_mm: float | None = None, angle_deg: float | None = None) -> "PolarState":
        """Return the state with a new modal ``RP`` and/or ``AP`` (absolute values)."""
        if radius_mm is not None and radius_mm < 0.0:
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, "RP")
        return replace(
            self,
            radius_mm=self.radius_mm if radius_mm is None else float(radius_mm),
            angle_deg=self.angle_deg if angle_deg is None else float(angle_deg),
        )

    def target(self) -> Vec2:
        """The (abscissa, ordinate) the current ``RP``/``AP`` point to."""
        dx, dy = _polar_to_xy(self.radius_mm, self.angle_deg)
        px, py = self.effective_pole
        return (px + dx, py + dy)

    def from_point(self, point: Vec2) -> "PolarState":
        """Return the state whose ``RP``/``AP`` describe ``point`` around the current pole."""
        px, py = self.effective_pole
        dx, dy = point[0] - px, point[1] - py
        return replace(self, radius_mm=math.hypot(dx, dy), angle_deg=math.degrees(math.atan2(dy, dx)))


def _polar_to_xy(radius: float, angle_deg: float) -> Vec2:
    angle = math.radians(angle_deg)
    c, s = math.cos(angle), math.sin(angle)
    # Exact zeros at multiples of 90° keep golden values clean.
    if abs(c) < 1e-15:
        c = 0.0
    if abs(s) < 1e-15:
        s = 0.0
    return (radius * c, radius * s)
