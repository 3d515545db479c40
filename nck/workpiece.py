"""What is clamped on the machine: the blank and the tool-setting reference block.

Plain data only (no geometry of contact, no persistence): :mod:`nck.contact` finds
contacts with these solids, :mod:`nck.persistence` keeps them in the retained data
(section ``machine_setup``), a material-removal simulation may take the blank as its
stock. All coordinates are machine coordinates (MCS) of the geometry axes X, Y, Z in
mm; a lathe has no Y axis, its Y coordinate is 0.

* :class:`Box` — a rectangular blank or block given by its smallest and its largest
  corner, faces parallel to the axes or turned about Z by ``rotation_z_deg`` around the
  centre of that rectangle (a blank clamped at an angle: what the rotated-corner measuring
  finds).
* :class:`Cylinder` — a round blank with its axis parallel to Z (on a mill standing on
  the table, on a lathe the bar in the chuck on the turning axis), given by the centre
  of its lower (lathe: chuck-side) face, its diameter and its length along Z.
* :class:`MachineSetup` — the blank (or none), the reference block (or none) and the
  instructor's switch ``hidden`` (the trainee's screens do not show where the blank is:
  the trainee must find it by measuring; only the data and the switch live here).

Trainer choice (the manuals are silent on a simulated workpiece): the shipped default on
a mill is a 100 × 80 × 30 mm block in the middle of the table with its top at Z −220 and a
reference block of 50 mm height beside it (:func:`default_machine_setup`); on a lathe a
bar of 60 mm diameter standing out 100 mm from the chuck face at Z 200 (free end at Z 300;
the reference point X 0 Z 0 of the shipped lathe stays clear of it). A fresh lathe data
directory also starts with G54 on the centre of the bar's free face
(:func:`default_part_zero_mcs`), so a turning program's X0 Z0 (the face of the part, as the
samples are written) lies on the bar in the chuck without a set-up step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping

Point = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class Box:
    """A block ``low_mcs`` ≤ points ≤ ``high_mcs`` (X, Y, Z), turned by ``rotation_z_deg``
    (counter-clockwise seen from +Z) about the vertical axis through its centre."""

    low_mcs: Point
    high_mcs: Point
    rotation_z_deg: float = 0.0

    @property
    def centre_xy_mcs(self) -> tuple[float, float]:
        """The centre of the rectangle in X/Y, the point the box is turned about."""
        return ((self.low_mcs[0] + self.high_mcs[0]) / 2.0, (self.low_mcs[1] + self.high_mcs[1]) / 2.0)

    @property
    def top_z_mcs(self) -> float:
        """The Z of the top face."""
        return self.high_mcs[2]


@dataclass(frozen=True, slots=True)
class Cylinder:
    """A round bar with its axis parallel to Z: lower face centre ``base_mcs``, diameter, length."""

    base_mcs: Point
    diameter_mm: float
    length_mm: float

    @property
    def top_z_mcs(self) -> float:
        """The Z of the upper (lathe: free) face."""
        return self.base_mcs[2] + self.length_mm


Solid = Box | Cylinder


@dataclass(frozen=True, slots=True)
class MachineSetup:
    """What is clamped: ``blank`` and ``reference`` (a block of known height), each optional.

    ``hidden`` is the instructor's switch: the blank's position is not shown to the trainee.
    ``tool_lengths`` are the true lengths (mm, along the spindle) of tools whose length in the
    tool list is wrong — a tool changed, its data not yet measured (an exercise's set-up):
    the tool touches what is clamped with its true length, whatever its data say, so
    measuring it finds the true one. Tools not named are as long as their data.
    """

    blank: Solid | None = None
    reference: Box | None = None
    hidden: bool = False
    tool_lengths: tuple[tuple[int, float], ...] = ()

    def true_length(self, tool: int) -> float | None:
        """The true length of tool ``tool`` when it differs from its data, else None."""
        return next((length for number, length in self.tool_lengths if number == tool), None)

    def solids(self) -> tuple[tuple[str, Solid], ...]:
        """The solids a tool can touch, named ``"blank"`` / ``"reference"``."""
        named = (("blank", self.blank), ("reference", self.reference))
        return tuple((name, solid) for name, solid in named if solid is not None)


def default_machine_setup(machine_kind: str) -> MachineSetup:
    """The set-up a fresh data directory starts with on a ``mill`` or a ``lathe`` (module docstring)."""
    if machine_kind == "lathe":
        return MachineSetup(blank=Cylinder((0.0, 0.0, 200.0), 60.0, 100.0))
    return MachineSetup(
        blank=Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0)),
        reference=Box((150.0, -20.0, -250.0), (190.0, 20.0, -200.0)),
    )


def default_part_zero_mcs(machine_kind: str, setup: MachineSetup) -> dict[str, float]:
    """The G54 translation a fresh data directory starts with: on a lathe with a bar clamped
    the centre of its free face (X on the turning axis, Z the face); elsewhere none (empty)."""
    blank = setup.blank
    if machine_kind != "lathe" or not isinstance(blank, Cylinder):
        return {}
    return {"X": blank.base_mcs[0], "Z": blank.top_z_mcs}


# --------------------------------------------------------------------- plain form
def solid_to_plain(solid: Solid | None) -> dict[str, Any] | None:
    """A solid as JSON-ready data (``None`` stays ``None``)."""
    if isinstance(solid, Box):
        plain: dict[str, Any] = {"shape": "box", "low_mcs": list(solid.low_mcs), "high_mcs": list(solid.high_mcs)}
        if solid.rotation_z_deg:
            plain["rotation_z_deg"] = solid.rotation_z_deg
        return plain
    if isinstance(solid, Cylinder):
        return {"shape": "cylinder", "base_mcs": list(solid.base_mcs), "diameter_mm": solid.diameter_mm,
                "length_mm": solid.length_mm}
    return None


def _point(value: Any) -> Point:
    if not isinstance(value, (list, tuple)) or len(value) != 3:
        raise ValueError("a position is three numbers X, Y, Z")
    return (_finite(value[0]), _finite(value[1]), _finite(value[2]))


def _finite(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{value!r} is not a finite number")
    return float(value)


def _positive(value: Any, what: str) -> float:
    number = _finite(value)
    if number <= 0.0:
        raise ValueError(f"the {what} must be greater than 0")
    return number


def solid_from_plain(data: Any) -> Solid | None:
    """The solid of :func:`solid_to_plain`'s form; ``ValueError`` when it is not one."""
    if data is None:
        return None
    if not isinstance(data, Mapping):
        raise ValueError("a solid is a table")
    shape = data.get("shape")
    if shape == "box":
        low, high = _point(data["low_mcs"]), _point(data["high_mcs"])
        if any(h <= lo for lo, h in zip(low, high)):
            raise ValueError("a box's high corner must lie above its low corner on every axis")
        return Box(low, high, _finite(data.get("rotation_z_deg", 0.0)))
    if shape == "cylinder":
        return Cylinder(_point(data["base_mcs"]), _positive(data["diameter_mm"], "diameter"),
                        _positive(data["length_mm"], "length"))
    raise ValueError(f"unknown shape {shape!r}")


def setup_to_plain(setup: MachineSetup) -> dict[str, Any]:
    """The whole set-up as JSON-ready data."""
    plain: dict[str, Any] = {"blank": solid_to_plain(setup.blank), "reference": solid_to_plain(setup.reference),
                             "hidden": setup.hidden}
    if setup.tool_lengths:  # only an exercise's set-up has them
        plain["tool_lengths"] = {str(tool): length for tool, length in setup.tool_lengths}
    return plain


def setup_from_plain(data: Mapping[str, Any]) -> MachineSetup:
    """The set-up of :func:`setup_to_plain`'s form; ``ValueError`` when it is not one."""
    reference = solid_from_plain(data.get("reference"))
    if reference is not None and not isinstance(reference, Box):
        raise ValueError("the reference block is a box")
    hidden = data.get("hidden", False)
    if not isinstance(hidden, bool):
        raise ValueError("hidden is true or false")
    lengths = data.get("tool_lengths", {})
    if not isinstance(lengths, dict) or not all(
            key.isdigit() and isinstance(value, (int, float)) and not isinstance(value, bool) and value > 0.0
            for key, value in lengths.items()):
        raise ValueError("tool_lengths maps tool numbers to lengths above 0 mm")
    return MachineSetup(solid_from_plain(data.get("blank")), reference, hidden,
                        tuple(sorted((int(key), float(value)) for key, value in lengths.items())))
