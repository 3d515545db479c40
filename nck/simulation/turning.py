"""Turning: the bar's rotational profile, cut by the insert swept along the path.

A turned part is a solid of revolution about the Z axis; outside turning only ever lowers
its outer radius. The profile is therefore one radius per Z cell (a height field in the
half section Z–X), held in a one-row :class:`nck.simulation.zmap.ZMap` whose "height" is the
radius: the Z-map's exact sweep of a rounded end mill along straight moves is the same
problem in the half section, with the insert's lower envelope as the "cutter".

The insert (002 W1 §18.4.3, L58653-58680; ``nck.geometry.cutting_edge``): the program path
is the theoretical tool tip P; the nose centre S lies at ``P − tip_offset`` (abscissa Z,
ordinate X, in radius); the nose radius is ``$TC_DP6`` plus wear. The insert's lower envelope
is the nose circle; a grooving tool (type 520) is an insert of width ``w`` with a nose at
both corners, its body reaching from the edge's nose away from the tip side along Z.

Our choices (the manuals are silent on a simulated part):

* ``w`` is the distance along Z between the tips of the tool's two edges with mirrored
  positions (D1 in position 3, D2 in position 4: ``|$TC_DP4(D1) − $TC_DP4(D2)|``, length 2
  along Z for G18); a grooving tool with one edge is swept as its nose alone.
* Inside machining (edges whose tip lies above the nose centre, positions 1, 2, 6: boring
  tools) and drills on the turning axis are not swept: the profile holds the outer radius
  only. Positions 5, 7, 9 count as outside tools.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from nck.geometry.cutting_edge import tip_offset
from nck.ncdata import NcData
from nck.simulation.blank import Blank
from nck.simulation.cutter import Cutter
from nck.simulation.zmap import ZMap

GROOVING_TYPES = frozenset({520})
INSIDE_POSITIONS = frozenset({1, 2, 6})
MIRRORED_POSITION = {3: 4, 4: 3, 1: 2, 2: 1}


@dataclass(frozen=True, slots=True)
class Insert:
    """A turning tool's cutting part in the half section.

    Attributes:
        nose_radius_mm: the nose (cutting edge) radius, ``$TC_DP6`` plus wear.
        position: the cutting edge position ``$TC_DP2`` (1…9).
        width_mm: a grooving insert's width along Z (0: the nose alone).
        tool: the T number.
    """

    nose_radius_mm: float
    position: int = 3
    width_mm: float = 0.0
    tool: int = 0

    @classmethod
    def from_edge(cls, data: NcData, tool: int, edge: int) -> Insert | None:
        """The insert of edge ``D<edge>`` of ``T<tool>`` (None: no such edge)."""
        params = data.edge(tool, edge)
        if params is None:
            return None
        radius = max(params.get(6) + params.get(15), 0.0)
        position = int(params.get(2)) or 9
        width = 0.0
        if int(params.get(1)) in GROOVING_TYPES and position in MIRRORED_POSITION:
            for (other_tool, other_edge), other in data.tools.items():
                if other_tool == tool and other_edge != edge and int(other.get(2)) == MIRRORED_POSITION[position]:
                    width = abs((params.get(4) + params.get(13)) - (other.get(4) + other.get(13)))
                    break
        return cls(radius, position, width, tool)

    @property
    def outside(self) -> bool:
        """True for a tool that cuts the outer profile (not a boring tool)."""
        return self.position not in INSIDE_POSITIONS

    @property
    def radius_mm(self) -> float:
        """The nose radius (what the view draws)."""
        return self.nose_radius_mm

    @property
    def reach_mm(self) -> float:
        """How far from the tip the insert touches anything along Z."""
        return max(self.width_mm, 2.0 * self.nose_radius_mm, 1e-6)

    def envelope(self) -> tuple[Cutter, float]:
        """The insert's lower envelope as a cutter of the half section, and the Z shift from
        the nose centre S to that cutter's axis (the middle of a grooving insert)."""
        nose = self.nose_radius_mm
        half = max(self.width_mm / 2.0, nose)
        toward_body = 1.0 if self.position in (3, 2) else -1.0 if self.position in (4, 1) else 0.0
        return Cutter(max(half, 1e-6), nose, 0.0, self.tool), toward_body * (half - nose)

    def nose_centre_from_tip(self) -> tuple[float, float]:
        """(dZ, dR): from the tip P to the nose centre S."""
        dz, dr = tip_offset(self.position, self.nose_radius_mm)
        return (-dz, -dr)

    def bottom_from_tip(self) -> tuple[float, float]:
        """(dZ, dR): from the tip P to the lowest point of the insert's axis (the cutter's tip)."""
        dz, dr = self.nose_centre_from_tip()
        _cutter, shift = self.envelope()
        return (dz + shift, dr - self.nose_radius_mm)


class TurnProfile:
    """The outer radius of the bar per Z cell, lowered by the inserts swept along the path.

    ``heights`` (one row, columns Z) holds the radius; the bar's ``Blank`` is a cylinder
    along Z: ``z_mm`` its back and front face, ``diameter_mm`` its diameter.
    """

    def __init__(self, bar: Blank, resolution_mm: float) -> None:
        self.blank = bar
        self.resolution_mm = float(resolution_mm)
        radius = bar.diameter_mm / 2.0
        section = Blank("box", bar.z_mm, (-resolution_mm / 2.0, resolution_mm / 2.0), (0.0, radius))
        self._map = ZMap(section, resolution_mm)
        self.x0_mm = self._map.x0_mm  # the Z of the first cell's edge
        self.y0_mm = self._map.y0_mm  # the one row's lower edge (its centre is the turning axis)
        self.radius_mm = radius

    @property
    def heights(self) -> np.ndarray:
        """The radius per Z cell (one row)."""
        return self._map.heights

    @property
    def initial(self) -> np.ndarray:
        """The bar's radius per Z cell."""
        return self._map.initial

    def fresh(self) -> TurnProfile:
        """The uncut bar at the same resolution."""
        return TurnProfile(self.blank, self.resolution_mm)

    def removed_volume_mm3(self) -> float:
        """Volume turned away so far (a ring per cell: π (R² − r²) · cell)."""
        before = self._map.initial.astype(np.float64)
        after = self._map.heights.astype(np.float64)
        return float(np.sum(before * before - after * after)) * math.pi * self.resolution_mm

    def radius_at(self, z_mm: float) -> float:
        """The outer radius at the cell containing ``z_mm``."""
        return self._map.height_at(z_mm, 0.0)

    def sweep(self, starts: np.ndarray, ends: np.ndarray, insert: Insert) -> np.ndarray:
        """Sweep ``insert`` with its tip P along the moves ``starts[i] → ends[i]`` (rows X as a
        diameter, Y, Z in the workpiece coordinate system); return per move the deepest cut
        (mm in radius) into material that was there before (0: none, and for inside tools)."""
        starts = np.asarray(starts, dtype=np.float64).reshape(-1, 3)
        ends = np.asarray(ends, dtype=np.float64).reshape(-1, 3)
        if not insert.outside or len(starts) == 0:
            return np.zeros(len(starts))
        cutter, _shift = insert.envelope()
        dz, dr = insert.bottom_from_tip()
        return self._map.sweep(_half_section(starts, dz, dr), _half_section(ends, dz, dr), cutter)



def half_section(points: np.ndarray) -> np.ndarray:
    """Rows (X diameter, Y, Z) → rows (Z, 0, X/2): the half section, drawn as X across, Z up."""
    return _half_section(np.asarray(points, dtype=np.float64).reshape(-1, 3), 0.0, 0.0)


def _half_section(points: np.ndarray, dz: float, dr: float) -> np.ndarray:
    """Rows (X diameter, Y, Z) → rows (Z + dz, 0, X/2 + dr): the half section as the Z-map's X, Y, Z."""
    out = np.zeros_like(points)
    out[:, 0] = points[:, 2] + dz
    out[:, 2] = points[:, 0] / 2.0 + dr
    return out


def bar_around(points: np.ndarray, reach_mm: float) -> Blank:
    """A bar around the cutting moves' tips (rows X diameter, Y, Z): as thick as the largest
    diameter they reach, from the front face Z 0 (or their highest Z, if above) back to the
    lowest Z they reach plus the insert and a margin (our choice)."""
    if points.size == 0:
        return bar(60.0, -100.0, 0.0, kind="path")
    diameter = max(float(np.abs(points[:, 0]).max()), 1.0)
    front = max(0.0, float(points[:, 2].max()) if points[:, 2].min() > 0.0 else 0.0)
    back = float(points[:, 2].min()) - reach_mm - 5.0
    return bar(diameter, back, front, kind="path")


def bar(diameter_mm: float, back_z_mm: float, front_z_mm: float, kind: str = "cylinder") -> Blank:
    """A round bar along Z of ``diameter_mm`` from ``back_z_mm`` to ``front_z_mm`` (``kind``
    ``path``: one put around the path)."""
    radius = diameter_mm / 2.0
    return Blank(kind, (-radius, radius), (-radius, radius), (back_z_mm, front_z_mm), diameter_mm)
