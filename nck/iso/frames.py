"""ISO M frame functions: rotation G68/G69, scaling G51/G50, mirroring G51.1/G50.1, G52/G92.1.

The ISO frame functions all act in the workpiece coordinate system. This
trainer keeps them in the Siemens **programmable frame** (``$P_PFRAME``), so
they are shared with Siemens mode and cleared by RESET/program end like any
programmable frame. (The 840D maps G51.1 and G68 onto channel base frames
1–3; the trainer models one basic frame only.) A programmed WCS point ``p``
is mapped, in this order (the Fanuc order of processing)::

    mirror (G51.1, about a position)  →  scale (G51, about the workpiece zero)
      →  second rotation  →  first rotation (G68, about its pivot)  →  + G52/G92 offsets

The translator (:mod:`nck.iso.translate`) turns each ISO frame block into
assignments to internal system variables ``$P_ISOFR_…`` (handled by
:func:`write`, hooked into :mod:`nck.interp.sysvars`), because pivots taken
from the current position and the setting-data defaults are only known at
run time:

* ``$P_ISOFR_ROT[mask, x, y, z, i, j, k]=r`` — G68 (mask bits: 1/2/4 X/Y/Z
  programmed, 8 = 3D vector I/J/K programmed, 16 = R programmed);
* ``$P_ISOFR_ROTOFF=0`` — G69; ``$P_ISOFR_SCALE[mask, i, j, k]=p`` — G51
  (mask bits 1/2/4 I/J/K, 8 P); ``$P_ISOFR_SCALEOFF=0`` — G50;
* ``$P_ISOFR_MIRROR[axis]=position`` — G51.1; ``$P_ISOFR_MIRROROFF[axis]=0``
  (no index: every axis) — G50.1;
* ``$P_ISOFR_TRANS[mask, x, y, z]=0`` — G52: replaces the coarse translation of the
  programmed axes (mask bits 1/2/4), keeps the G92 preset (booked as fine translation by
  ``ATRANS``) and the ISO rotation, scale and mirror; ``$P_ISOFR_TRANSOFF=0`` — G92.1:
  clears G52 and G92;
* ``$P_ISOFR_POLAROFF=0`` — G15: pole, polar radius and angle are deleted;
  ``$P_ISOFR_POLARON=0`` — G16 (for the G-group display, :func:`display_codes`);
* ``$P_ISOFR_SYNC=0`` / ``$P_ISOFR_PRESET=0`` — after an offset change with SD 42440 = 0,
  and after G92 always: the programmed position becomes the actual one.

Rules (ISO dialects manual §2.2.11–2.2.12): 2D G68 rotates about the applicate
of the active plane; a missing pivot coordinate is the current position, R
missing → SD 42150. 3D G68 (I/J/K programmed) rotates about the vector; a
missing pivot coordinate is the workpiece zero; a zero vector raises 12560.
A G68 while one is active is chained in series (second stage); a further G68
replaces the second stage (G90) or adds to it (G91). G69 cancels both. G51:
factors I/J/K (axial, only with MD 22914 = 1) or P (all axes, P < 0 → 12560)
in units of 0.001 (MD 22910 = 0) or 0.00001 (MD 22910 = 1); a missing factor
uses SD 43120 / SD 42140 in the same units, or 1.0 when that setting data is
not set. G51.1 mirrors are additive per axis.

The state lives on the geometry state (attribute ``iso_frame``). It is valid
only while the programmable frame still has the rotation/scale/mirror it
produced: a RESET, a Siemens ``TRANS``/``ROT`` … after G290 discard it.

:class:`FrameTracker` and :func:`frame_codes` / :func:`polar_words` are the
translate-time half: they turn the ISO words into the blocks above, and
polar coordinates G16/G15 into Siemens poles (G110/G111) with ``RP``/``AP``.
Not modelled: G02/G03 with R or I/J under G16 (the Siemens polar circle runs
about the pole, so such a block raises 14040); drilling cycles under G16 raise
61814; ISO T's G68/G69 (double turret).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from nck.alarm_ids import (
    DATA_WRITE_PROTECTED, G_FUNCTION_UNKNOWN, ILLEGAL_ARRAY_INDEX_1, SYNTAX_ERROR, VALUE_OUTSIDE_LIMITS,
)
from nck.errors import NcAlarmError
from nck.lang.values import to_number
from nck.number_text import trimmed
from nck.geometry.frames import Frame, as_matrix3, axis_rotation
from nck.geometry.polar import PolarState

ALARM_SCALE_ZERO = 18309
ALARM_CYCLE_POLAR = 61814
PREFIX = "$P_ISOFR_"
GEO = ("X", "Y", "Z")
_PLANE_AXES = {"G17": ("X", "Y", "Z"), "G18": ("Z", "X", "Y"), "G19": ("Y", "Z", "X")}
_PLANE_NORMAL = {"G17": 2, "G18": 1, "G19": 0}


# =========================================================================== run time
@dataclass(frozen=True)
class IsoFrameState:
    """The ISO frame components, WCS lengths in mm.

    Attributes:
        mirror_mm: axis → mirror position (G51.1).
        scale: axis → signed scale factor (G51).
        rotations: up to two stages ``(pivot_mm, matrix)`` (G68), first stage first.
        linear: the 3x3 part of the composition last written into the programmable frame.
        offset_mm: its translation part.
    """

    mirror_mm: tuple[tuple[str, float], ...] = ()
    scale: tuple[tuple[str, float], ...] = ()
    rotations: tuple[tuple[tuple[float, float, float], tuple[tuple[float, ...], ...]], ...] = ()
    linear: tuple[tuple[float, ...], ...] = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    offset_mm: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def pre_rotation(self, point: np.ndarray) -> np.ndarray:
        """A WCS point after mirroring and scaling (the space the rotations act in)."""
        out = np.array(point, dtype=float)
        for axis, centre in self.mirror_mm:
            i = GEO.index(axis)
            out[i] = 2.0 * centre - out[i]
        for axis, factor in self.scale:
            out[GEO.index(axis)] *= factor
        return out

    def affine(self) -> tuple[np.ndarray, np.ndarray]:
        """``(L, a)`` with ``A(p) = L·p + a`` for the whole ISO mapping."""
        offset = self.pre_rotation(np.zeros(3))
        columns = [self.pre_rotation(np.eye(3)[i]) - offset for i in range(3)]
        linear = np.array(columns).T
        for pivot, matrix in reversed(self.rotations):  # the second stage acts first
            q = np.array(pivot)
            m = np.array(matrix)
            linear = m @ linear
            offset = m @ (offset - q) + q
        return linear, offset

    def rotation_matrix(self) -> np.ndarray:
        """The product of the rotation stages."""
        out = np.eye(3)
        for _pivot, matrix in self.rotations:
            out = out @ np.array(matrix)
        return out


def _state(geo: Any) -> IsoFrameState:
    """The stored ISO state if the programmable frame still carries it, else an empty one."""
    state = getattr(geo, "iso_frame", None)
    if state is None:
        return IsoFrameState()
    current = geo.frames.programmable.linear()
    if not np.allclose(current, np.array(state.linear), atol=1e-9):
        return IsoFrameState()
    return state


def _base(geo: Any, state: IsoFrameState) -> tuple[dict[str, float], dict[str, float]]:
    """Coarse and fine translation of the programmable frame without the ISO part."""
    prog = geo.frames.programmable
    trans = dict(prog.trans)
    for i, axis in enumerate(GEO):
        if state.offset_mm[i]:
            trans[axis] = float(trans.get(axis, 0.0)) - state.offset_mm[i]
    return trans, dict(prog.fine)


def _install(interp: Any, geo: Any, new: IsoFrameState, trans: dict[str, float],
             fine: dict[str, float]) -> None:
    """Write ``new`` on top of the translations ``trans``/``fine`` into the programmable frame."""
    linear, offset = new.affine()
    rotation = new.rotation_matrix()
    factors = {axis: 1.0 for axis in GEO}
    for axis, _centre in new.mirror_mm:
        factors[axis] = -factors[axis]
    for axis, factor in new.scale:
        factors[axis] *= factor
    total = dict(trans)
    for i, axis in enumerate(GEO):
        value = float(total.get(axis, 0.0)) + float(offset[i])
        if abs(value) < 1e-12:
            total.pop(axis, None)
        else:
            total[axis] = value
    old_frames, old_state = geo.frames, getattr(geo, "iso_frame", None)
    frame = Frame(
        geometry_axes=geo.frames.geometry_axes,
        trans=total,
        fine={a: v for a, v in fine.items() if v},
        rotation=as_matrix3(rotation),
        scale={a: abs(f) for a, f in factors.items() if abs(f) != 1.0},
        mirror=frozenset(a for a, f in factors.items() if f < 0),
    )
    geo.frames = geo.frames.with_programmable(frame)
    geo.iso_frame = replace(new, linear=tuple(tuple(float(v) for v in row) for row in frame.linear()),
                            offset_mm=tuple(float(v) for v in offset))  # type: ignore[arg-type]

    def undo() -> None:
        geo.frames = old_frames
        geo.iso_frame = old_state

    interp.journal_undo(undo)


def write(interp: Any, name: str, indices: tuple[Any, ...], value: Any) -> None:
    """Execute one ``$P_ISOFR_…`` assignment (see module docstring)."""
    op = name[len(PREFIX):]
    number = float(to_number(value, name))
    args = [a if isinstance(a, str) else float(to_number(a, name)) for a in indices]
    path = interp.builder.path
    modal = interp.modal
    geo = path.state(modal)
    mm = path.units(modal).position_mm
    state = _state(geo)
    trans, fine = _base(geo, state)
    if op == "TRANS":  # G52: the programmed axes; G92 (fine) and other axes stay
        if len(args) != 4:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        for i, axis in enumerate(GEO):
            if int(args[0]) & (1 << i):
                trans[axis] = float(args[1 + i]) * mm
    elif op == "TRANSOFF":  # G92.1: G52 and G92 go
        trans, fine = {}, {}
    elif op in ("SYNC", "PRESET"):
        _sync(interp, geo, always=op == "PRESET")
        return
    elif op == "POLAROFF":  # G15 deletes pole, polar radius and angle
        _polar_off(interp, geo)
        return
    elif op == "POLARON":  # G16: only for the G-group display
        _set_polar_flag(interp, geo, True)
        return
    elif op == "ROT":
        state = _rotate(interp, geo, state, args, number, mm)
    elif op == "ROTOFF":
        state = replace(state, rotations=())
    elif op == "SCALE":
        state = replace(state, scale=_scale_factors(interp, args, number))
    elif op == "SCALEOFF":
        state = replace(state, scale=())
    elif op == "MIRROR":
        axis = _axis(args, name)
        mirrors = dict(state.mirror_mm)
        mirrors[axis] = number * mm
        state = replace(state, mirror_mm=tuple(sorted(mirrors.items())))
    elif op == "MIRROROFF":
        if args:
            axis = _axis(args, name)
            state = replace(state, mirror_mm=tuple(m for m in state.mirror_mm if m[0] != axis))
        else:
            state = replace(state, mirror_mm=())
    else:
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)
    _install(interp, geo, state, trans, fine)


def _sync(interp: Any, geo: Any, always: bool = False) -> None:
    """SD 42440 = 0: after a zero-offset change the programmed position is the actual one.

    An incremental move then starts from where the tool is, seen in the new
    system, so the offset change is not travelled (with SD 42440 = 1, the
    default, the Siemens rule applies: the programmed WCS point is kept).
    ``always``: after G92 the axes it does not name also read their actual position.
    """
    if not always and bool(interp.data.setting_data.get("SD42440", True)):
        return
    path, modal = interp.builder.path, interp.modal
    old_frames, old_wcs = geo.frames, dict(geo.wcs_mm)
    old_view = dict(modal.position_wcs)
    path.sync_position(modal, dict(modal.position_mcs))

    def undo() -> None:
        geo.frames = old_frames
        geo.wcs_mm = old_wcs
        modal.position_wcs = old_view

    interp.journal_undo(undo)


def _polar_off(interp: Any, geo: Any) -> None:

    old = geo.polar
    geo.polar = PolarState()
    _set_polar_flag(interp, geo, False)

    def undo() -> None:
        geo.polar = old

    interp.journal_undo(undo)


def _set_polar_flag(interp: Any, geo: Any, on: bool) -> None:
    old = getattr(geo, "iso_polar", False)
    geo.iso_polar = on

    def undo() -> None:
        geo.iso_polar = old

    interp.journal_undo(undo)


def display_codes(geo: Any) -> dict[int, str]:
    """ISO M groups 11, 16, 17 and 22 (G51/G50, G68/G69, G16/G15, G51.1/G50.1) for the
    G-group display, from the geometry state ``geo`` (None: the reset codes)."""
    if geo is None:
        return {11: "G50", 16: "G69", 17: "G15", 22: "G50.1"}
    state = _state(geo)
    polar = bool(getattr(geo, "iso_polar", False)) and geo.polar.pole is not None
    return {11: "G51" if state.scale else "G50", 16: "G68" if state.rotations else "G69",
            17: "G16" if polar else "G15", 22: "G51.1" if state.mirror_mm else "G50.1"}


def _axis(args: list[Any], name: str) -> str:
    if len(args) != 1 or args[0] not in GEO:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return str(args[0])


def _rotate(interp: Any, geo: Any, state: IsoFrameState, args: list[Any], angle: float,
            mm: float) -> IsoFrameState:
    if len(args) != 7:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, PREFIX + "ROT")
    mask = int(args[0])
    programmed = [float(v) * mm for v in args[1:4]]
    vector = np.array([float(v) for v in args[4:7]])
    if not mask & 16:
        angle = float(interp.data.setting_data.get("SD42150", 0.0) or 0.0)
    if mask & 8:  # 3D: rotation about the vector I/J/K, missing pivot = workpiece zero
        length = float(np.linalg.norm(vector))
        if length < 1e-12:
            raise NcAlarmError(VALUE_OUTSIDE_LIMITS, "I J K")
        pivot = [programmed[i] if mask & (1 << i) else 0.0 for i in range(3)]
        matrix = _about_vector(vector / length, angle)
    else:  # 2D: about the applicate of the plane, missing pivot = current position
        plane = interp.modal.gcodes.get(6, "G17")
        current = state.pre_rotation(np.array([float(geo.wcs_mm.get(a, 0.0)) for a in GEO]))
        pivot = [programmed[i] if mask & (1 << i) else float(current[i]) for i in range(3)]
        matrix = axis_rotation(_PLANE_NORMAL.get(plane, 2), angle)
    stage = (tuple(pivot), tuple(tuple(float(v) for v in row) for row in matrix))
    stages = list(state.rotations)
    incremental = interp.modal.gcodes.get(14, "G90") == "G91"
    if len(stages) < 2:
        stages.append(stage)  # type: ignore[arg-type]
    elif incremental:  # a further G68 in G91 turns the second stage on
        old_pivot, old_matrix = stages[1]
        stages[1] = (old_pivot, tuple(tuple(float(v) for v in row)
                                      for row in np.array(old_matrix) @ matrix))
    else:
        stages[1] = stage  # type: ignore[assignment]
    return replace(state, rotations=tuple(stages))  # type: ignore[arg-type]


def _about_vector(unit: np.ndarray, angle_deg: float) -> np.ndarray:
    """Right-hand rotation about the unit vector ``unit`` (Rodrigues)."""
    angle = math.radians(angle_deg)
    x, y, z = unit
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    out = np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)
    out[np.abs(out) < 1e-15] = 0.0
    return out


def _scale_factors(interp: Any, args: list[Any], p_value: float) -> tuple[tuple[str, float], ...]:
    if len(args) != 4:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, PREFIX + "SCALE")
    machine, sd = interp.machine, interp.data.setting_data
    unit = 0.00001 if int(machine.md_value("MD22910", default=0) or 0) else 0.001
    axial = bool(int(machine.md_value("MD22914", default=0) or 0))
    mask = int(args[0])
    if mask & 8 or not axial:
        raw = p_value if mask & 8 else sd.get("SD42140")
        if mask & 8 and p_value < 0:
            raise NcAlarmError(VALUE_OUTSIDE_LIMITS, "P")
        factor = float(raw) * unit if raw else 1.0
        factors = {axis: factor for axis in GEO}
    else:
        defaults = sd.get("SD43120")
        factors = {}
        for i, axis in enumerate(GEO):
            if mask & (1 << i):
                factors[axis] = float(args[1 + i]) * unit
            else:
                default = defaults.get(axis) if isinstance(defaults, dict) else defaults
                factors[axis] = float(default) * unit if default else 1.0
    for axis, factor in factors.items():
        if factor == 0.0:
            raise NcAlarmError(ALARM_SCALE_ZERO, axis)
    return tuple((axis, factor) for axis, factor in factors.items() if factor != 1.0)


# =========================================================================== translate time
@dataclass
class FrameTracker:
    """What the translator remembers between ISO lines for frames and polar coordinates."""

    plane: str | None = None
    polar: bool = False
    polar_fresh: bool = False  # G15 deleted radius and angle: a block without angle uses 0
    start_absolute: bool = True  # G90 at the start of the current block


@dataclass
class FrameBlocks:
    """Result of :func:`frame_codes`: blocks to run first, and whether the line is done."""

    blocks: list[str] = field(default_factory=list)
    done: bool = False
    selects_offset: bool = False  # G54…G59 / G54.1: a settable zero offset is selected

    def head(self, siemens_g: list[str], absolute: bool, has_words: bool) -> list[str]:
        """Blocks before the motion: the frame operations, and for an offset selection its
        G codes followed by :data:`SYNC` (``siemens_g`` is emptied then).

        A selection in a G90 block with axis words stays one block (the programmed
        axes go to their new WCS position either way)."""
        if not self.selects_offset or not siemens_g or (absolute and has_words):
            return self.blocks
        head = " ".join(siemens_g)
        siemens_g.clear()
        return self.blocks + [head, SYNC]


SYNC = f"{PREFIX}SYNC=0"
"""After a zero-offset change: SD 42440 = 0 takes the actual position as the programmed one."""
PRESET = f"{PREFIX}PRESET=0"
"""After G92: the programmed position of every axis is the actual one (regardless of SD 42440)."""
_OFFSET_SELECTIONS = {"G54", "G55", "G56", "G57", "G58", "G59", "G54.1"}
_ALONE_G68 = {"G68", "G90", "G91", "G17", "G18", "G19"}
_ALONE_MIRROR = {"G51.1", "G50.1", "G90", "G91"}


def _alone(words: list[Any], gcodes: list[str], allowed_g: set[str], letters: str, code: str) -> None:
    for word in words:
        if word.letter == "G":
            continue
        if word.letter != "N" and word.letter not in letters:
            raise NcAlarmError(SYNTAX_ERROR, f"{code} not alone in block")
    for g in gcodes:
        if g not in allowed_g:
            raise NcAlarmError(SYNTAX_ERROR, f"{code} not alone in block")


def frame_codes(words: list[Any], gcodes: list[str], values: dict[str, float],
                tracker: FrameTracker, absolute: bool, turning: bool) -> FrameBlocks:
    """Handle G68/G69, G51/G50, G51.1/G50.1, G16/G15 of one ISO block.

    ``gcodes`` and ``values`` are edited in place (the frame codes and their
    words are removed). Raises 12080 when G68/G51.1/G50.1 are not alone in
    their block and 12560 for a 3D G68 with a zero vector.
    """
    tracker.start_absolute = absolute
    if turning:  # ISO T: G68/G69 is the double turret, no G51/G51.1/G16 (not modelled)
        for code in gcodes:
            if code in ("G68", "G51", "G51.1", "G16"):
                raise NcAlarmError(G_FUNCTION_UNKNOWN, code)
        return FrameBlocks()
    for code in gcodes:
        if code in ("G17", "G18", "G19"):
            tracker.plane = code
    out = FrameBlocks(selects_offset=bool(_OFFSET_SELECTIONS.intersection(gcodes)))
    present = set(gcodes) & {"G68", "G69", "G51", "G50", "G51.1", "G50.1", "G15", "G16"}
    if not present:
        return out
    if "G15" in present:
        tracker.polar = False
        out.blocks.append(f"{PREFIX}POLAROFF=0")
    if "G16" in present:
        tracker.polar = True
        tracker.polar_fresh = True
        out.blocks.append(f"{PREFIX}POLARON=0")
    if "G69" in present:
        out.blocks.extend([f"{PREFIX}ROTOFF=0", SYNC])
    if "G50" in present:
        out.blocks.extend([f"{PREFIX}SCALEOFF=0", SYNC])
    raw = {word.letter: word.value for word in words}
    if "G68" in present:
        _alone(words, gcodes, _ALONE_G68, "XYZIJKR", "G68")
        mask = sum(1 << i for i, axis in enumerate(GEO) if axis in values)
        vector = [raw.get(letter, 0.0) for letter in "IJK"]
        if any(letter in raw for letter in "IJK"):
            mask |= 8
            if not any(vector):
                raise NcAlarmError(VALUE_OUTSIDE_LIMITS, "I0 J0 K0")
        if "R" in values:
            mask |= 16
        args = [str(mask)] + [trimmed(values.get(axis, 0.0)) for axis in GEO] + [trimmed(v) for v in vector]
        head = " ".join(g for g in gcodes if g != "G68")
        if head:
            out.blocks.append(head)
        out.blocks.extend([f"{PREFIX}ROT[{', '.join(args)}]={trimmed(values.get('R', 0.0))}", SYNC])
        out.done = True
        return out
    if "G51.1" in present or "G50.1" in present:
        code = "G51.1" if "G51.1" in present else "G50.1"
        _alone(words, gcodes, _ALONE_MIRROR, "XYZ", code)
        axes = [axis for axis in GEO if axis in values]
        if code == "G51.1":
            parts = [f"{PREFIX}MIRROR[{axis}]={trimmed(values[axis])}" for axis in axes]
        else:
            parts = [f"{PREFIX}MIRROROFF[{axis}]=0" for axis in axes] or [f"{PREFIX}MIRROROFF=0"]
        out.blocks.extend([" ".join(parts), SYNC])
        out.done = True
        return out
    if "G51" in present:
        mask = sum(1 << i for i, letter in enumerate("IJK") if letter in raw)
        if "P" in raw:
            mask |= 8
        args = [str(mask)] + [trimmed(raw.get(letter, 0.0)) for letter in "IJK"]
        out.blocks.extend([f"{PREFIX}SCALE[{', '.join(args)}]={trimmed(raw.get('P', 0.0))}", SYNC])
        for letter in ("X", "Y", "Z", "I", "J", "K", "P"):  # X/Y/Z: no centre (workpiece zero)
            values.pop(letter, None)
    gcodes[:] = [g for g in gcodes if g not in present]
    if not gcodes and not values and not any(w.letter == "M" for w in words):
        out.done = True
    return out


def trans_blocks(number: str, values: dict[str, float]) -> list[str]:
    """G52 (``values`` = its offsets) or G92.1 (no axis values), then :data:`SYNC`."""
    mask = sum(1 << i for i, axis in enumerate(GEO) if axis in values)
    if not mask:
        return [f"{number}{PREFIX}TRANSOFF=0", SYNC]
    offsets = ", ".join(trimmed(values.get(axis, 0.0)) for axis in GEO)
    return [f"{number}{PREFIX}TRANS[{mask}, {offsets}]=0", SYNC]


def polar_words(words: list[Any], values: dict[str, float], siemens_g: list[str],
                tracker: FrameTracker, turning: bool) -> tuple[list[str], str]:
    """G16 active: turn the plane words into a pole block and ``RP=``/``AP=`` words.

    The first plane axis is the radius, the second the angle. ``G90 X`` puts
    the pole at the workpiece zero, ``G91 X`` at the current position; without
    the radius word the pole is the workpiece zero and the radius the distance
    of the current position from it. The radius is always absolute, the angle
    follows G90/G91 at its place in the block. Returns (blocks to run first,
    words to add to the motion block); values and siemens_g are edited.
    """
    if not tracker.polar:
        return [], ""
    plane = tracker.plane or ("G18" if turning else "G17")
    first, second, _ = _PLANE_AXES[plane]
    if first not in values and second not in values:
        return [], ""
    absolute = tracker.start_absolute
    modes: dict[str, bool] = {}
    for word in words:
        if word.letter == "G" and word.text.lstrip("0") in ("90", "91"):
            absolute = word.text.lstrip("0") == "90"
        elif word.letter in (first, second):
            modes[word.letter] = absolute
    group3 = [g for g in siemens_g if g in ("G90", "G91")]
    if len(group3) > 1:
        siemens_g[:] = [g for g in siemens_g if g not in ("G90", "G91")] + group3[-1:]
    pole_axes = f"{first}0 {second}0"
    extra: list[str] = []
    if first in values:
        radius = values.pop(first)
        pole = f"G111 {pole_axes}" if modes.get(first, True) else f"G110 {pole_axes}"
        extra.append(f"RP=AC({trimmed(radius)})")
    else:
        pole = f"G111 {pole_axes}"
        ep_a, ep_o = f"$P_EP[{first}]", f"$P_EP[{second}]"
        extra.append(f"RP=AC(SQRT({ep_a}*{ep_a}+{ep_o}*{ep_o}))")
    if second in values:
        angle = values.pop(second)
        mode = "AC" if modes.get(second, True) else "IC"
        extra.append(f"AP={mode}({trimmed(angle)})")
    elif tracker.polar_fresh:
        extra.append("AP=AC(0)")
    tracker.polar_fresh = False
    return [pole], " ".join(extra)


def check_cycle(tracker: FrameTracker, code: int | None) -> None:
    """A drilling cycle under G16 raises 61814 (the cycles here take Cartesian hole positions)."""
    if tracker.polar:
        raise NcAlarmError(ALARM_CYCLE_POLAR, f"G{code}")
