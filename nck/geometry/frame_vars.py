"""Frame system variables: single frame components read and written by part programs.

* ``$P_UIFR[n, axis, comp]`` — settable frame n (0 = G500, 1…4 = G54…G57,
  5… = G505…) in the NC data; a write is not active until the frame is
  selected again (G500/G54…);
* ``$P_PFRAME[axis, comp]`` — the programmable frame, effective at once;
* ``$P_UBFR[axis, comp]`` — the (first) channel basic frame in the NC data;
* ``$P_SETFR[axis, TR]`` — the system frame for PRESET and scratching in the NC data
  (translations only; exists when MD28082 bit 0 is set, else alarm 12550: 002 L30640-30650);
  active again with G500/G54… or after RESET as MD24006 says;
* ``$P_UIFRNUM`` — index of the active settable frame;
* ``$AA_IW[axis]`` — the actual position in the WCS (through frames and tool length).

``comp`` is ``TR`` (translation), ``FI`` (fine translation), ``RT`` (rotation,
degrees), ``SC`` (scale factor) or ``MI`` (mirror, 0/1). Lengths are read and
written in the programmed system for the programmable frame, and per G70/G71
vs G700/G710 rules for stored frames (:mod:`nck.geometry.units`).
"""

from __future__ import annotations

import copy
from typing import Any

from nck.alarm_ids import DATA_WRITE_PROTECTED, ILLEGAL_ARRAY_INDEX_1, NAME_NOT_DEFINED, WRONG_AXIS_TYPE
from nck.errors import NcAlarmError
from nck.geometry.chain import frame_from_work_offset
from nck.geometry.frame_functions import GeoFrameValue, as_frame
from nck.geometry.frames import Frame, as_matrix3, rpy_matrix
from nck.lang.values import FrameValue, to_number
from nck.ncdata import WorkOffset
from nck.writes import ValueOutOfLimits, check_frame_component

COMPONENTS = frozenset(("TR", "FI", "RT", "SC", "MI"))
NAMES = frozenset(("$P_UIFR", "$P_PFRAME", "$P_UBFR", "$P_IFRAME", "$P_UIFRNUM", "$AA_IW", "$P_SETFR"))
SETFR_MASK_BIT = 1  # MD28082 bit 0: the system frame for PRESET and scratching is configured
ALARM_SCALE_ZERO = 18309


def settable_code(index: int) -> str:
    """The G code of settable frame ``$P_UIFR[index]``."""
    if index == 0:
        return "G500"
    if 1 <= index <= 4:
        return f"G{53 + index}"
    if 5 <= index <= 99:
        return f"G{500 + index}"
    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "$P_UIFR")


def settable_index(code: str) -> int:
    """Inverse of :func:`settable_code`."""
    number = int(code[1:])
    if number == 500:
        return 0
    if 54 <= number <= 57:
        return number - 53
    return number - 500


def read(interp: Any, name: str, indices: tuple[Any, ...]) -> Any:
    """Read one of :data:`NAMES` (``interp`` is the interpreter)."""
    modal = interp.modal
    path = interp.builder.path
    if name == "$P_UIFRNUM":
        return settable_index(modal.gcodes.get(8, "G500"))
    if name == "$AA_IW":
        axis = _axis(interp, name, indices[:1]) if len(indices) == 1 else _bad(name)
        actual = {a: float(interp.actual_position(a)) for a in interp.machine.path_axes}
        value = float(path.wcs_from_mcs(modal, actual)[axis])
        if interp.machine.axis(axis).kind != "linear":
            return value
        # A length-related system variable: G70/G71 read it in the basic system,
        # G700/G710 in the programmed one (002 L11680-11697, table L11793-11817).
        units = path.units(modal)
        return value * units.position_mm / units.data_mm
    if name == "$P_SETFR":
        axis, comp = _setframe_address(interp, name, indices)
        return _stored_component(interp.data.setframe, axis, comp, path.units(modal).data_mm)
    whole = _whole_frame_read(interp, name, indices)
    if whole is not None:
        return whole
    if name == "$P_PFRAME":
        axis, comp = _address(interp, name, indices)
        return _component(path.state(modal).frames.programmable, axis, comp,
                          path.units(modal).position_mm)
    if name == "$P_IFRAME":
        axis, comp = _address(interp, name, indices)
        return _component(path.state(modal).frames.settable, axis, comp, path.units(modal).data_mm)
    if name == "$P_UIFR":
        if len(indices) != 3:
            _bad(name)
        code = settable_code(_int(indices[0], name))
        axis, comp = _address(interp, name, indices[1:])
        offset = interp.data.settable_frames.get(code, WorkOffset())
        return _stored_component(offset, axis, comp, path.units(modal).data_mm)
    if name == "$P_UBFR":
        axis, comp = _address(interp, name, indices)
        return _stored_component(interp.data.base_frame, axis, comp, path.units(modal).data_mm)
    raise NcAlarmError(NAME_NOT_DEFINED, name)


def write(interp: Any, name: str, indices: tuple[Any, ...], value: Any) -> None:
    """Write one of :data:`NAMES` (read-only ones give alarm 17070)."""
    if isinstance(value, FrameValue):
        _whole_frame_write(interp, name, indices, value)
        return
    number = float(to_number(value, name))
    modal = interp.modal
    path = interp.builder.path
    if name == "$P_SETFR":
        axis, comp = _setframe_address(interp, name, indices)
        _guard_setframe(interp)
        _set_stored(interp.data.setframe, name, axis, comp, number, path.units(modal).data_mm)
        return
    if name == "$P_PFRAME":
        axis, comp = _address(interp, name, indices)
        _guard_active(interp)
        geo = path.state(modal)
        frame = _set_component(geo.frames.programmable, axis, comp, number, path.units(modal).position_mm)
        geo.frames = geo.frames.with_programmable(frame)
        return
    if name == "$P_IFRAME":
        axis, comp = _address(interp, name, indices)
        _guard_active(interp)
        geo = path.state(modal)
        frame = _set_component(geo.frames.settable, axis, comp, number, path.units(modal).data_mm)
        geo.frames = geo.frames.with_settable(geo.frames.settable_code, frame)
        return
    if name in ("$P_UIFR", "$P_UBFR"):
        if name == "$P_UIFR":
            if len(indices) != 3:
                _bad(name)
            code = settable_code(_int(indices[0], name))
            _guard_stored(interp, name, code)
            offset = interp.data.settable_frame(code) if code != "G500" else \
                interp.data.settable_frames.setdefault("G500", WorkOffset())
            rest = indices[1:]
        else:
            _guard_stored(interp, name, None)
            offset = interp.data.base_frame
            rest = indices
        axis, comp = _address(interp, name, rest)
        _set_stored(offset, name, axis, comp, number, path.units(modal).data_mm)
        return
    raise NcAlarmError(DATA_WRITE_PROTECTED, name)


# --------------------------------------------------------------------------- rollback
def _journal(interp: Any, undo: Any) -> None:
    """Let a failing block undo a frame write (the interpreter's journal, kind ``undo``)."""
    journal = getattr(interp, "undo_journal", None)
    if journal is not None:
        journal.append(("undo", undo, None))


def _guard_active(interp: Any) -> None:
    geo = interp.builder.path.state(interp.modal)
    frames = geo.frames

    def undo() -> None:
        geo.frames = frames

    _journal(interp, undo)


def _setframe_address(interp: Any, name: str, indices: tuple[Any, ...]) -> tuple[str, str]:
    """``$P_SETFR[axis, TR]``: configured by MD28082 bit 0, translations only (our model)."""
    if not int(interp.machine.md_value("MD28082", None, 33) or 0) & SETFR_MASK_BIT:
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    axis, comp = _address(interp, name, indices)
    if comp != "TR":
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return axis, comp


def _guard_setframe(interp: Any) -> None:
    data = interp.data
    old = copy.deepcopy(data.setframe)

    def undo() -> None:
        data.setframe = old

    _journal(interp, undo)


def _guard_stored(interp: Any, name: str, code: str | None) -> None:
    data = interp.data
    if name == "$P_UBFR":
        old = copy.deepcopy(data.base_frame)

        def undo_base() -> None:
            data.base_frame = old

        _journal(interp, undo_base)
        return
    assert code is not None
    had = code in data.settable_frames
    old_offset = copy.deepcopy(data.settable_frames.get(code))

    def undo_settable() -> None:
        if had:
            data.settable_frames[code] = old_offset
        else:
            data.settable_frames.pop(code, None)

    _journal(interp, undo_settable)


# --------------------------------------------------------------------------- whole frames
def _whole_frame_read(interp: Any, name: str, indices: tuple[Any, ...]) -> Any:
    """``$P_PFRAME``, ``$P_IFRAME``, ``$P_UBFR``, ``$P_UIFR[n]`` as FRAME values (None: not whole)."""
    path = interp.builder.path
    modal = interp.modal
    frame: Frame | None = None
    if name in ("$P_PFRAME", "$P_IFRAME", "$P_UBFR") and not indices:
        geo = path.state(modal)
        if name == "$P_PFRAME":
            frame = geo.frames.programmable
        elif name == "$P_IFRAME":
            frame = geo.frames.settable
        else:
            frame = frame_from_work_offset(interp.data.base_frame)
    elif name == "$P_UIFR" and len(indices) == 1:
        code = settable_code(_int(indices[0], name))
        frame = frame_from_work_offset(interp.data.settable_frames.get(code, WorkOffset()))
    if frame is None:
        return None
    return GeoFrameValue(trans=dict(frame.trans), rot={}, frame=frame)


def _whole_frame_write(interp: Any, name: str, indices: tuple[Any, ...], value: Any) -> None:
    frame = as_frame(value, name)
    path = interp.builder.path
    modal = interp.modal
    if name in ("$P_PFRAME", "$P_IFRAME") and not indices:
        _guard_active(interp)
        geo = path.state(modal)
        if name == "$P_PFRAME":
            geo.frames = geo.frames.with_programmable(frame)
        else:
            geo.frames = geo.frames.with_settable(geo.frames.settable_code, frame)
        return
    if name == "$P_UBFR" and not indices:
        _guard_stored(interp, name, None)
        interp.data.base_frame = _checked_offset(name, frame)
        return
    if name == "$P_UIFR" and len(indices) == 1:
        code = settable_code(_int(indices[0], name))
        _guard_stored(interp, name, code)
        interp.data.settable_frames[code] = _checked_offset(name, frame)
        return
    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)


def _checked_offset(name: str, frame: Frame) -> WorkOffset:
    """``frame`` as a stored work offset, each component checked (:func:`_check_stored`)."""
    offset = work_offset_of(frame)
    for comp, values in (("TR", offset.trans), ("FI", offset.fine), ("RT", offset.rot), ("SC", offset.scale)):
        for value in values.values():
            _check_stored(name, comp, value)
    return offset


def work_offset_of(frame: Frame) -> WorkOffset:
    """Store a frame's components as a work offset (translations in mm, RPY angles)."""
    angles = frame.rotation_deg
    return WorkOffset(
        trans={a: v for a, v in frame.trans.items() if v},
        fine={a: v for a, v in frame.fine.items() if v},
        rot={axis: angle for axis, angle in zip(frame.geometry_axes, angles) if angle},
        scale={a: v for a, v in frame.scale.items() if v != 1.0},
        mirror={a: True for a in frame.mirror},
    )


# --------------------------------------------------------------------------- helpers
def _bad(name: str) -> Any:
    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)


def _int(value: Any, name: str) -> int:
    number = to_number(value, name)
    if int(number) != number:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return int(number)


def _axis(interp: Any, name: str, indices: tuple[Any, ...]) -> str:
    axis = indices[0]
    if not isinstance(axis, str) or axis not in interp.machine.path_axes and axis not in ("X", "Y", "Z"):
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return str(axis)


def _address(interp: Any, name: str, indices: tuple[Any, ...]) -> tuple[str, str]:
    if len(indices) != 2:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    axis = _axis(interp, name, indices[:1])
    comp = str(indices[1]).upper()
    if comp not in COMPONENTS:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return axis, comp


def _component(frame: Frame, axis: str, comp: str, length_mm: float) -> float:
    if comp == "TR":
        return float(frame.trans.get(axis, 0.0)) / length_mm
    if comp == "FI":
        return float(frame.fine.get(axis, 0.0)) / length_mm
    if comp == "RT":
        geo = frame.geometry_axes
        return frame.rotation_deg[geo.index(axis)] if axis in geo else 0.0
    if comp == "SC":
        return float(frame.scale.get(axis, 1.0))
    return 1.0 if axis in frame.mirror else 0.0


def _set_component(frame: Frame, axis: str, comp: str, value: float, length_mm: float) -> Frame:
    if comp == "TR":
        trans = dict(frame.trans)
        trans[axis] = value * length_mm
        return frame._replace(trans=trans)
    if comp == "FI":
        fine = dict(frame.fine)
        fine[axis] = value * length_mm
        return frame._replace(fine=fine)
    if comp == "RT":
        geo = frame.geometry_axes
        if axis not in geo:
            raise NcAlarmError(WRONG_AXIS_TYPE, axis)
        angles = list(frame.rotation_deg)
        angles[geo.index(axis)] = value
        return frame._replace(rotation=as_matrix3(rpy_matrix((angles[0], angles[1], angles[2]))))
    if comp == "SC":
        if value == 0.0:
            raise NcAlarmError(ALARM_SCALE_ZERO, axis)
        scale = dict(frame.scale)
        scale[axis] = value
        return frame._replace(scale=scale)
    mirror = set(frame.mirror)
    if value:
        mirror.add(axis)
    else:
        mirror.discard(axis)
    return frame._replace(mirror=frozenset(mirror))


def _stored_component(offset: WorkOffset, axis: str, comp: str, data_mm: float) -> float:
    frame = frame_from_work_offset(offset, data_mm=1.0)
    if comp in ("TR", "FI"):
        table = offset.trans if comp == "TR" else offset.fine
        return float(table.get(axis, 0.0)) * (1.0 / data_mm if data_mm != 1.0 else 1.0)
    return _component(frame, axis, comp, 1.0)


def _check_stored(name: str, comp: str, value: float) -> None:
    """A stored frame takes what every door's write takes (nck.writes); else alarm 17080/17090."""
    try:
        check_frame_component(comp, value)
    except ValueOutOfLimits as exc:
        raise NcAlarmError(exc.alarm, name) from None


def _set_stored(offset: WorkOffset, name: str, axis: str, comp: str, value: float, data_mm: float) -> None:
    if comp == "SC" and value == 0.0:
        raise NcAlarmError(ALARM_SCALE_ZERO, axis)
    _check_stored(name, comp, value * data_mm if comp in ("TR", "FI") else value)
    if comp == "TR":
        offset.trans[axis] = value * data_mm
    elif comp == "FI":
        offset.fine[axis] = value * data_mm
    elif comp == "RT":
        offset.rot[axis] = value
    elif comp == "SC":
        offset.scale[axis] = value
    else:
        offset.mirror[axis] = bool(value)
