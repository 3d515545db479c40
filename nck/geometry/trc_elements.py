"""Input and output records of tool radius compensation, and its machine data.

:class:`ContourElement` is one programmed block as the compensation sees it,
:class:`CompensatedElement` one element of the tool-centre path,
:class:`TrcSettings` the machine data (MD20210 … MD20250). The compensator
itself is :mod:`nck.geometry.radius_comp`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from nck.geometry.trc_geometry import Curve, Vec, arc, line, same_point

ALARM_D0_WHILE_ACTIVE = 10750
ALARM_COLLISION = 10751
ALARM_SELECT_NOT_LINEAR = 10753
ALARM_DESELECT_NOT_LINEAR = 10754
ALARM_CURVATURE_TOO_SMALL = 10758
ALARM_TOO_MANY_DUMMY_BLOCKS = 10762
WARNING_BLOCK_SKIPPED = 10763

LINEAR_KINDS = ("G0", "G1")
ARC_KINDS = ("G2", "G3")


@dataclass(frozen=True, slots=True)
class TrcSettings:
    """Machine data of the compensation (defaults marked (ext) are not in the manual).

    Attributes:
        corner_limit_deg: MD20210 CUTCOM_CORNER_LIMIT; above this change of direction
            G451 inserts a circle instead of the intersection (ext default 100°).
        curve_insert_limit_deg: MD20230 CUTCOM_CURVE_INSERT_LIMIT; below this change of
            direction G450 uses the intersection instead of a circle (ext default 10°).
        max_check_blocks: MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS, look-ahead for
            intersections (ext default 3).
        max_dummy_blocks: MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS, consecutive blocks without
            plane motion (ext default 3).
    """

    corner_limit_deg: float = 100.0
    curve_insert_limit_deg: float = 10.0
    max_check_blocks: int = 3
    max_dummy_blocks: int = 3

    @classmethod
    def from_machine(cls, machine: Any) -> "TrcSettings":
        """Read the values from a :class:`nck.machine.MachineConfig` (``md_value``)."""
        base = cls()
        md = getattr(machine, "md_value", None)
        if md is None:
            return base
        return cls(
            corner_limit_deg=float(md("MD20210", default=base.corner_limit_deg)),
            curve_insert_limit_deg=float(md("MD20230", default=base.curve_insert_limit_deg)),
            max_check_blocks=max(1, int(md("MD20240", default=base.max_check_blocks))),
            max_dummy_blocks=max(0, int(md("MD20250", default=base.max_dummy_blocks))),
        )


@dataclass(frozen=True, slots=True)
class ContourElement:
    """One programmed block as the compensation sees it (plane coordinates, mm).

    Attributes:
        kind: motion G code of the block: ``G0``, ``G1``, ``G2`` or ``G3``.
        start: programmed start point in the plane.
        end: programmed end point in the plane.
        source: opaque id of the block (e.g. :class:`nck.canon.Source`); copied to the output.
        center: arc centre (G2/G3 only).
        side: ``G40``, ``G41`` or ``G42`` in force in this block.
        radius_mm: compensation radius of the active edge ($TC_DP6 + $TC_DP15, signed).
        edge: active D number (0 = D0).
        corner_mode: ``G450`` or ``G451``.
        approach: ``NORM`` or ``KONT``.
        collision_detection: True under CDON.
        mirrored: True if an odd number of the plane axes is mirrored (swaps G41/G42).
        plane_motion: override of the computed "moves in the plane" (None = compute).
        geometry_axis: the block programs a geometry axis (matters for G40 without plane motion).
    """

    kind: str
    start: Vec
    end: Vec
    source: Any = None
    center: Vec | None = None
    side: str = "G40"
    radius_mm: float = 0.0
    edge: int = 1
    corner_mode: str = "G450"
    approach: str = "NORM"
    collision_detection: bool = False
    mirrored: bool = False
    plane_motion: bool | None = None
    geometry_axis: bool = False

    @property
    def is_arc(self) -> bool:
        """True for G2/G3."""
        return self.kind in ARC_KINDS

    @property
    def moves_in_plane(self) -> bool:
        """True if the block moves in the plane (arcs always; lines of non-zero length)."""
        if self.plane_motion is not None:
            return self.plane_motion
        if self.is_arc:
            return True
        return not same_point(self.start, self.end)

    @property
    def effective_side(self) -> str:
        """The side after mirroring (an odd mirror swaps G41 and G42)."""
        if self.mirrored and self.side in ("G41", "G42"):
            return "G42" if self.side == "G41" else "G41"
        return self.side

    @property
    def offset_mm(self) -> float:
        """Signed offset to the left of travel: +r for G41, −r for G42, 0 for G40."""
        side = self.effective_side
        if side == "G41":
            return self.radius_mm
        if side == "G42":
            return -self.radius_mm
        return 0.0

    def curve(self) -> Curve:
        """The programmed element as a :class:`Curve`."""
        if self.is_arc:
            assert self.center is not None, "an arc needs a centre"
            return arc(self.start, self.end, self.center, ccw=self.kind == "G3")
        return line(self.start, self.end)


@dataclass(frozen=True, slots=True)
class CompensatedElement:
    """One element of the tool-centre path.

    Attributes:
        kind: ``G0``, ``G1``, ``G2``, ``G3``, or ``dummy`` (no motion in the plane).
        start: start point of the tool centre in the plane.
        end: end point.
        source: the block it belongs to (inserted elements: the block that caused them).
        center: arc centre for G2/G3.
        role: ``contour`` (offset of a programmed element), ``approach`` / ``retract``
            (selection / deselection block), ``corner`` (transition at an outside corner),
            ``link`` (line joining two offsets), ``dummy``, ``skipped`` (block left out
            by bottleneck detection) or ``uncompensated`` (TRC off).
        inserted: True if the NC inserted the element (not a programmed block).
        warning: a warning number to report for this element (10763 for skipped blocks).
        programmed: the programmed element this output belongs to.
    """

    kind: str
    start: Vec
    end: Vec
    source: Any
    center: Vec | None = None
    role: str = "contour"
    inserted: bool = False
    warning: int | None = None
    programmed: ContourElement | None = None

    def curve(self) -> Curve:
        """The element as a :class:`Curve` (dummies: a zero-length line)."""
        if self.kind in ARC_KINDS and self.center is not None:
            return arc(self.start, self.end, self.center, ccw=self.kind == "G3")
        return line(self.start, self.end)
