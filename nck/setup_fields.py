"""The machine set-up as named fields: what the Setup area lists and ``nck setup`` reads and writes.

The instructor moves the blank by typing its position, changes its size or shape, and
hides its position from the trainee, field by field. A field is ``part.item``:

* ``blank.shape`` — ``box``, ``cylinder`` or ``none``; ``reference.shape`` — ``box`` or ``none``;
* ``blank.x`` / ``.y`` / ``.z`` — where it stands in the MCS: a box's smallest corner, a
  cylinder's lower (lathe: chuck-side) face centre; the size stays when the position changes;
* ``blank.size_x`` / ``.size_y`` / ``.size_z`` and ``blank.rotation_z`` (box: degrees about the
  vertical axis through its centre, a blank clamped at an angle), ``blank.diameter`` /
  ``.length`` (cylinder);
* the same position and size fields for ``reference`` (always a box);
* ``hidden`` — ``yes`` / ``no`` (also ``1`` / ``0``, ``on`` / ``off``): the trainee is not shown
  the blank's position and size.

Trainer choice (no manual describes a simulated workpiece): a shape change keeps the
position and fits the new solid into the old one's extent (a cylinder's diameter is the
smaller side of the box, a box around a cylinder is its bounding box); a part that was
``none`` gets the machine's default solid. All lengths in mm.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from nck.number_text import trimmed
from nck.refused import Refused
from nck.workpiece import Box, Cylinder, MachineSetup, Solid, default_machine_setup

AXES = ("x", "y", "z")
SHAPES = {"blank": ("box", "cylinder", "none"), "reference": ("box", "none")}
YES = {"yes": True, "1": True, "on": True, "true": True, "no": False, "0": False, "off": False,
       "false": False}


class SetupFieldError(Refused):
    """A field name or value the set-up cannot take: a refusal of ``data/refusals.toml``
    (``setup_…``); ``str()`` says why in English."""


@dataclass(frozen=True, slots=True)
class SetupField:
    """One line of the set-up: ``name`` (``blank.x``), ``label``, the value as text, its unit."""

    name: str
    label: str
    text: str
    unit: str
    position: bool  # a position or size of the blank (not shown to the trainee while hidden)


def shape_of(solid: Solid | None) -> str:
    """``box``, ``cylinder`` or ``none``."""
    return "box" if isinstance(solid, Box) else "cylinder" if isinstance(solid, Cylinder) else "none"


def _measures(solid: Solid | None) -> list[tuple[str, str, float]]:
    """(item, label, value) of a solid's position and size fields."""
    if isinstance(solid, Box):
        return ([(a, f"Position {a.upper()} (smallest corner)", solid.low_mcs[i]) for i, a in enumerate(AXES)]
                + [(f"size_{a}", f"Size {a.upper()}", solid.high_mcs[i] - solid.low_mcs[i])
                   for i, a in enumerate(AXES)]
                + [("rotation_z", "Rotation about Z (about its centre)", solid.rotation_z_deg)])
    if isinstance(solid, Cylinder):
        return ([(a, f"Position {a.upper()} (lower face centre)", solid.base_mcs[i]) for i, a in enumerate(AXES)]
                + [("diameter", "Diameter", solid.diameter_mm), ("length", "Length", solid.length_mm)])
    return []


def setup_fields(setup: MachineSetup) -> list[SetupField]:
    """Every field of ``setup`` in display order."""
    fields: list[SetupField] = []
    for part, title in (("blank", "Blank"), ("reference", "Reference block")):
        solid = getattr(setup, part)
        fields.append(SetupField(f"{part}.shape", f"{title}: shape", shape_of(solid), "", False))
        fields += [SetupField(f"{part}.{item}", f"{title}: {label}", trimmed(value, 3),
                              "deg" if item == "rotation_z" else "mm", part == "blank")
                   for item, label, value in _measures(solid)]
    fields.append(SetupField("hidden", "Blank hidden from the trainee", "yes" if setup.hidden else "no", "", False))
    return fields


def field_names(setup: MachineSetup) -> list[str]:
    """The names :func:`with_field` accepts for ``setup`` now (they depend on the shapes)."""
    return [field.name for field in setup_fields(setup)]


def with_field(setup: MachineSetup, name: str, text: str, machine_kind: str = "mill") -> MachineSetup:
    """``setup`` with field ``name`` set to ``text``; :class:`SetupFieldError` when it cannot be."""
    name, text = name.strip().lower(), text.strip()
    if name == "hidden":
        if text.lower() not in YES:
            raise SetupFieldError("setup_hidden_yes_no", text=text)
        return replace(setup, hidden=YES[text.lower()])
    part, _, item = name.partition(".")
    if part not in SHAPES:
        raise SetupFieldError("setup_unknown_field", name=name, fields=", ".join(field_names(setup)))
    solid = getattr(setup, part)
    if item == "shape":
        return _with_part(setup, part, _reshaped(solid, text.lower(), part, machine_kind))
    if name not in field_names(setup):
        raise SetupFieldError("setup_unknown_field_for_shape", name=name, shape=shape_of(solid),
                              fields=", ".join(field_names(setup)))
    value = _number(name, text)
    return _with_part(setup, part, _changed(solid, item, value, name))


def _with_part(setup: MachineSetup, part: str, solid: Solid | None) -> MachineSetup:
    if part == "blank":
        return replace(setup, blank=solid)
    assert solid is None or isinstance(solid, Box)  # the reference block's shapes are box / none
    return replace(setup, reference=solid)


def _number(name: str, text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise SetupFieldError("setup_not_a_number", name=name, text=text)
    return value


def _changed(solid: Solid | None, item: str, value: float, name: str) -> Solid:
    if item == "rotation_z":
        assert isinstance(solid, Box)
        return replace(solid, rotation_z_deg=value)
    if item in AXES:
        index = AXES.index(item)
        if isinstance(solid, Box):
            moved = list(solid.low_mcs)
            moved[index] = value
            size = [h - lo for lo, h in zip(solid.low_mcs, solid.high_mcs)]
            return Box(_point(moved), _point([m + s for m, s in zip(moved, size)]), solid.rotation_z_deg)
        assert isinstance(solid, Cylinder)
        base = list(solid.base_mcs)
        base[index] = value
        return replace(solid, base_mcs=_point(base))
    if value <= 0.0:
        raise SetupFieldError("setup_not_positive", name=name)
    if isinstance(solid, Box):
        index = AXES.index(item.removeprefix("size_"))
        high = list(solid.high_mcs)
        high[index] = solid.low_mcs[index] + value
        return Box(solid.low_mcs, _point(high), solid.rotation_z_deg)
    assert isinstance(solid, Cylinder)
    return replace(solid, diameter_mm=value) if item == "diameter" else replace(solid, length_mm=value)


def _reshaped(solid: Solid | None, shape: str, part: str, machine_kind: str) -> Solid | None:
    if shape not in SHAPES[part]:
        raise SetupFieldError("setup_bad_shape", name=f"{part}.shape", shapes=" / ".join(SHAPES[part]), text=shape)
    if shape == shape_of(solid):
        return solid
    if shape == "none":
        return None
    if solid is None:
        default = getattr(default_machine_setup(machine_kind), part) or getattr(default_machine_setup("mill"), part)
        return default if shape_of(default) == shape else _reshaped(default, shape, part, machine_kind)
    if shape == "cylinder":
        assert isinstance(solid, Box)
        (x0, y0, z0), (x1, y1, z1) = solid.low_mcs, solid.high_mcs
        return Cylinder(((x0 + x1) / 2, (y0 + y1) / 2, z0), min(x1 - x0, y1 - y0), z1 - z0)
    assert isinstance(solid, Cylinder)
    (cx, cy, cz), radius = solid.base_mcs, solid.diameter_mm / 2
    return Box((cx - radius, cy - radius, cz), (cx + radius, cy + radius, cz + solid.length_mm))


def _point(values: list[float]) -> tuple[float, float, float]:
    return (values[0], values[1], values[2])
