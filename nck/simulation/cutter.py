"""The shape of a milling tool or drill as seen from below: height of its surface above the tip.

A rotating tool is a solid of revolution about its axis (Z here). Its lower envelope is
``h(r)``: how far above the tool tip the tool's surface is at distance ``r`` from the axis
(0 at the tip, infinite outside the radius). Sweeping a tool means taking, for every point
of the Z-map, the lowest ``tip_z + h(r)`` over the path.

Tool types and parameters (002 L62525-62558, L62606-62609): ``$TC_DP1`` type, ``$TC_DP6``
radius, ``$TC_DP7`` corner radius, ``$TC_DP24`` tip angle of a drill (type 2xx). Types:
110/111 ball end mill, 120 end mill, 121 end mill with corner rounding, 2xx drills. Any other
type is swept as a flat end mill of its radius (our choice; a turning tool has no meaning on
the Z-map). A drill without a tip angle gets 118° (the common twist-drill point; our choice).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

DEFAULT_TIP_ANGLE_DEG = 118.0
BALL_TYPES = frozenset({110, 111})
CORNER_TYPES = frozenset({121})


@dataclass(frozen=True, slots=True)
class Cutter:
    """A tool's lower envelope.

    Attributes:
        radius_mm: the cutting radius (``$TC_DP6`` plus wear).
        corner_radius_mm: torus radius at the end face (ball mill: equal to the radius).
        tip_angle_deg: drill point angle (0: no point, a flat or rounded end).
        tool: the T number (0: no tool).
        length_mm: length 1 (``$TC_DP3`` plus wear): from the tip to the toolholder reference
            point, where the holder begins (0: unknown).
    """

    radius_mm: float
    corner_radius_mm: float = 0.0
    tip_angle_deg: float = 0.0
    tool: int = 0
    length_mm: float = 0.0

    @classmethod
    def flat(cls, radius_mm: float, tool: int = 0) -> Cutter:
        """A flat end mill."""
        return cls(radius_mm, 0.0, 0.0, tool)

    @classmethod
    def ball(cls, radius_mm: float, tool: int = 0) -> Cutter:
        """A ball end mill (the corner radius is the whole radius)."""
        return cls(radius_mm, radius_mm, 0.0, tool)

    @classmethod
    def drill(cls, radius_mm: float, tip_angle_deg: float = DEFAULT_TIP_ANGLE_DEG, tool: int = 0) -> Cutter:
        """A drill with a conical point."""
        return cls(radius_mm, 0.0, tip_angle_deg, tool)

    @classmethod
    def from_edge(cls, tool: int, params: dict[int, float]) -> Cutter:
        """The cutter of a cutting edge's ``$TC_DPn`` values (geometry plus wear)."""
        kind = int(params.get(1, 120))
        radius = max(params.get(6, 0.0) + params.get(15, 0.0), 0.0)
        length = max(params.get(3, 0.0) + params.get(12, 0.0), 0.0)
        if kind in BALL_TYPES:
            return cls(radius, radius, 0.0, tool, length)
        if kind in CORNER_TYPES:
            corner = min(max(params.get(7, 0.0) + params.get(16, 0.0), 0.0), radius)
            return cls(radius, corner, 0.0, tool, length)
        if 200 <= kind < 300:
            angle = params.get(24, 0.0)
            return cls(radius, 0.0, angle if 0.0 < angle < 180.0 else DEFAULT_TIP_ANGLE_DEG, tool, length)
        return cls(radius, 0.0, 0.0, tool, length)

    @property
    def reach_mm(self) -> float:
        """How far from the axis the tool touches anything (at least a hair, for a zero radius)."""
        return max(self.radius_mm, 1e-6)

    def height_above_tip(self, r2: np.ndarray) -> np.ndarray:
        """``h`` at squared distances ``r2`` from the axis (inf beyond the radius), in the
        precision of ``r2`` (floating point; integers as double)."""
        radius = self.reach_mm
        r2 = np.asarray(r2)
        if r2.dtype.kind != "f":
            r2 = r2.astype(np.float64)
        kind = r2.dtype.type
        beyond = r2 > kind(radius * radius * (1.0 + 1e-12))
        if self.tip_angle_deg > 0.0:
            out = np.sqrt(r2)
            out *= kind(1.0 / math.tan(math.radians(self.tip_angle_deg) / 2.0))
        elif self.corner_radius_mm > 0.0:
            rc = self.corner_radius_mm
            flat = radius - rc
            if flat > 0.0:
                side = np.sqrt(r2)
                side -= kind(flat)
                np.maximum(side, kind(0.0), out=side)
                side *= side
            else:
                side = r2.copy()
            # rc - sqrt(max(rc² - side², 0)) where side is the distance beyond the flat face
            out = np.subtract(kind(rc * rc), side, out=side)
            np.maximum(out, kind(0.0), out=out)
            np.sqrt(out, out=out)
            np.subtract(kind(rc), out, out=out)
        else:
            out = np.zeros(r2.shape, dtype=r2.dtype)
        out[beyond] = np.inf
        return out
