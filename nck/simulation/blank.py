"""The blank (raw part) of a milling simulation: from ``WORKPIECE(...)``, else around the path.

``WORKPIECE`` is the blank statement SINUMERIK Operate writes into a program header (it is a
subprogram call the control itself ignores; our no-op is ``data/cycles/WORKPIECE.SPF``).
Parameter facts, taken from public example programs and a CAM post-processor for SINUMERIK
Operate (no manual in our library describes it):

- ``WORKPIECE(,"",,"BOX",bits,Z0,Z1,ZB,X0,Y0,X1,Y1)`` — a box from ``X0,Y0`` to ``X1,Y1``
  between the top ``Z0`` and the bottom ``Z1``;
- ``WORKPIECE(,"",,"CYLINDER",bits,Z0,Z1,ZB,D)`` — an upright cylinder of diameter ``D``
  about the Z axis of the workpiece zero, top ``Z0``, bottom ``Z1``;
- ``bits``: 16 and 32 — ``X1``/``Y1`` are absolute (else the lengths from ``X0``/``Y0``);
  64 — ``Z1`` is absolute (else measured from ``Z0``); 128 — ``ZB`` (the machining
  allowance plane) absolute. Examples: ``"BOX",240,25,0,0,-30,-20,30,20`` is the box
  X -30…30, Y -20…20, Z 0…25; ``"BOX",0,2,-30,-80,-2,-2,184,170`` is X -2…182, Y -2…168,
  Z -28…2.

The tube and polygon forms are not simulated (our choice: such a program falls back to the
clamped blank of the machine set-up, else a box around the path). Their argument order was
looked for again on 2026-11-27 in public source code (programs with ``WORKPIECE(`` and
``"PIPE"``, ``"N_CORNER"``/``"POLYGON"``, ``"CYLINDER"``): no program written by a control or a
known post-processor turned up, only one code generator writing ``"CYLINDER"`` and a
``"RECTANGLE"`` form with an argument order of its own — nothing whose meaning is clear.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from nck.workpiece import Cylinder

X1_ABSOLUTE = 16
Y1_ABSOLUTE = 32
Z1_ABSOLUTE = 64
PATH_MARGIN_MM = 5.0
"""A blank around the path reaches this far beyond the tool's reach (our choice)."""

_WORKPIECE = re.compile(r"^\s*(?:N\d+\s+)?WORKPIECE\s*\((?P<args>[^)]*)\)", re.IGNORECASE | re.MULTILINE)


@dataclass(frozen=True, slots=True)
class Blank:
    """A milling blank in the workpiece coordinate system (mm).

    Attributes:
        kind: ``box``, ``cylinder`` or ``path`` (a box around the path).
        x_mm, y_mm: (min, max) extents.
        z_mm: (bottom, top).
        diameter_mm: the cylinder's diameter (0 for a box).
        line: the source line of the ``WORKPIECE`` statement (None: none).
        rotation_z_deg: a box turned counter-clockwise (seen from +Z) about the centre of its
            extents, which then bound the turned box; ``sides_mm`` are its side lengths.
    """

    kind: str
    x_mm: tuple[float, float]
    y_mm: tuple[float, float]
    z_mm: tuple[float, float]
    diameter_mm: float = 0.0
    line: int | None = None
    rotation_z_deg: float = 0.0
    sides_mm: tuple[float, float] = (0.0, 0.0)

    @property
    def centre_xy_mm(self) -> tuple[float, float]:
        """The centre of the extents in X/Y."""
        return (sum(self.x_mm) / 2.0, sum(self.y_mm) / 2.0)

    def outline_xy(self) -> np.ndarray:
        """The outline seen from above as a closed polygon's corners (rows X, Y): a box's four
        corners (turned), a cylinder as a 72-gon."""
        cx, cy = self.centre_xy_mm
        if self.kind == "cylinder":
            angles = np.linspace(0.0, 2.0 * math.pi, 72, endpoint=False)
            radius = self.diameter_mm / 2.0
            return np.column_stack([cx + radius * np.cos(angles), cy + radius * np.sin(angles)])
        if self.rotation_z_deg:
            hx, hy = self.sides_mm[0] / 2.0, self.sides_mm[1] / 2.0
            local = np.array([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]])
            a = math.radians(self.rotation_z_deg)
            turn = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
            return local @ turn.T + np.array([cx, cy])
        return np.array([[self.x_mm[0], self.y_mm[0]], [self.x_mm[1], self.y_mm[0]],
                         [self.x_mm[1], self.y_mm[1]], [self.x_mm[0], self.y_mm[1]]])

    def material_mask(self, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
        """Which points (cell centres, broadcast) hold material: inside the outline."""
        inside = ((xs >= self.x_mm[0]) & (xs <= self.x_mm[1])) & ((ys >= self.y_mm[0]) & (ys <= self.y_mm[1]))
        if self.kind == "box" and self.rotation_z_deg:
            cx, cy = self.centre_xy_mm
            a = math.radians(self.rotation_z_deg)
            u = (xs - cx) * math.cos(a) + (ys - cy) * math.sin(a)  # into the box's own axes
            v = -(xs - cx) * math.sin(a) + (ys - cy) * math.cos(a)
            return (np.abs(u) <= self.sides_mm[0] / 2.0) & (np.abs(v) <= self.sides_mm[1] / 2.0)
        if self.kind == "cylinder":
            radius = self.diameter_mm / 2.0
            cx, cy = sum(self.x_mm) / 2.0, sum(self.y_mm) / 2.0
            inside = inside & ((xs - cx) ** 2 + (ys - cy) ** 2 <= radius * radius)
        return inside

    @property
    def volume_mm3(self) -> float:
        """The exact volume of the blank."""
        height = self.z_mm[1] - self.z_mm[0]
        if self.kind == "cylinder":
            return math.pi * (self.diameter_mm / 2.0) ** 2 * height
        if self.kind == "box" and self.rotation_z_deg:
            return self.sides_mm[0] * self.sides_mm[1] * height
        return (self.x_mm[1] - self.x_mm[0]) * (self.y_mm[1] - self.y_mm[0]) * height


def _number(text: str) -> float | None:
    text = text.strip()
    if not text:
        return None
    try:
        return float(text)
    except ValueError:
        return None


def blank_from_text(text: str) -> Blank | None:
    """The blank of the first ``WORKPIECE`` box or cylinder statement in ``text`` (None: none).

    Only literal numbers are read (a blank computed from variables is not a blank we show).
    """
    match = _WORKPIECE.search(text)
    if match is None:
        return None
    args = [a.strip() for a in match.group("args").split(",")]
    line = text.count("\n", 0, match.start()) + 1
    if len(args) < 9:
        return None
    kind = args[3].strip('"').upper()
    values = [_number(a) for a in args[4:]]
    bits = int(values[0] or 0)
    z0, z1 = values[1], values[2]
    if z0 is None or z1 is None:
        return None
    bottom = z1 if bits & Z1_ABSOLUTE else z0 + z1
    z_mm = (min(bottom, z0), max(bottom, z0))
    if kind == "CYLINDER" and len(values) >= 5 and values[4]:
        radius = abs(values[4]) / 2.0
        return Blank("cylinder", (-radius, radius), (-radius, radius), z_mm, 2.0 * radius, line)
    if kind == "BOX" and len(values) >= 8 and None not in values[4:8]:
        x0, y0, x1, y1 = (float(v) for v in values[4:8])  # type: ignore[arg-type]
        if not bits & X1_ABSOLUTE:
            x1 = x0 + x1
        if not bits & Y1_ABSOLUTE:
            y1 = y0 + y1
        return Blank("box", (min(x0, x1), max(x0, x1)), (min(y0, y1), max(y0, y1)), z_mm, 0.0, line)
    return None


def blank_from_setup(solid: Any, mcs_minus_wcs_mm: tuple[float, float, float]) -> Blank:
    """The machine set-up's clamped blank (``nck.workpiece`` Box or Cylinder, MCS) in the
    workpiece coordinate system: shifted by the work offset ``mcs_minus_wcs_mm`` (a frame's
    rotation is not taken in; a box clamped at an angle keeps its angle)."""
    dx, dy, dz = mcs_minus_wcs_mm
    if isinstance(solid, Cylinder):
        radius = solid.diameter_mm / 2.0
        cx, cy, bz = solid.base_mcs[0] - dx, solid.base_mcs[1] - dy, solid.base_mcs[2] - dz
        return Blank("cylinder", (cx - radius, cx + radius), (cy - radius, cy + radius),
                     (bz, bz + solid.length_mm), solid.diameter_mm)
    low, high = solid.low_mcs, solid.high_mcs
    z_mm = (low[2] - dz, high[2] - dz)
    sides = (high[0] - low[0], high[1] - low[1])
    angle = float(solid.rotation_z_deg) % 360.0
    if angle == 0.0:
        return Blank("box", (low[0] - dx, high[0] - dx), (low[1] - dy, high[1] - dy), z_mm)
    cx, cy = (low[0] + high[0]) / 2.0 - dx, (low[1] + high[1]) / 2.0 - dy
    a = math.radians(angle)
    half_x = (abs(sides[0] * math.cos(a)) + abs(sides[1] * math.sin(a))) / 2.0  # the turned box's extents
    half_y = (abs(sides[0] * math.sin(a)) + abs(sides[1] * math.cos(a))) / 2.0
    return Blank("box", (cx - half_x, cx + half_x), (cy - half_y, cy + half_y), z_mm, 0.0, None, angle, sides)


def blank_around(points: np.ndarray, reach_mm: float) -> Blank:
    """A box around the cutting moves' points (rows X, Y, Z): as wide as the path plus the tool
    and a margin, from the lowest point up to Z0 (or the highest point if the path stays below)."""
    if points.size == 0:
        return Blank("path", (-50.0, 50.0), (-50.0, 50.0), (-20.0, 0.0))
    margin = reach_mm + PATH_MARGIN_MM
    low = points.min(axis=0)
    high = points.max(axis=0)
    top = 0.0 if low[2] < 0.0 else float(high[2])
    bottom = min(float(low[2]), top - 1.0) - 1.0
    return Blank("path", (float(low[0]) - margin, float(high[0]) + margin),
                 (float(low[1]) - margin, float(high[1]) + margin), (bottom, top))
