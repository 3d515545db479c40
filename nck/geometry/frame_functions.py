"""Frame functions in expressions: ``CTRANS()``, ``CROT()``, ``CRPL()``, ``CSCALE()``, ``CMIRROR()``, ``CFINE()``.

Each returns a FRAME value (:class:`GeoFrameValue`) that can be assigned to a
FRAME variable or to a frame system variable (``$P_PFRAME``, ``$P_IFRAME``,
``$P_UIFR[n]``, ``$P_UBFR``)::

    $P_PFRAME = CTRANS(X, 10, Y, 20)    ; programmable frame: translation only
    $P_UIFR[1] = CROT(Z, 45)            ; settable frame G54: rotation only
    $P_PFRAME = CTRANS()                ; zero frame
    $P_PFRAME = CTRANS(X,10) : CRPL(1,30) ; rotation about Z, chained

Arguments come in pairs axis, value (``CMIRROR`` takes axes only; ``CRPL`` takes
a plane number 0 = active plane, 1 = about Z, 2 = about Y, 3 = about X and an
angle). Lengths are in the programmed system (G70/G700 inch) and converted to mm here.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

from nck.alarm_ids import NAME_NOT_DEFINED, TYPE_CONVERSION_IMPOSSIBLE, WRONG_CALL_ARGUMENTS
from nck.errors import NcAlarmError
from nck.geometry.frames import Frame
from nck.geometry.planes import Plane, plane
from nck.lang.values import FrameValue

NAMES = frozenset(("CTRANS", "CROT", "CRPL", "CSCALE", "CMIRROR", "CFINE"))
CRPL_AXIS_INDEX = {1: 2, 2: 1, 3: 0}  # CRPL plane number → geometry axis index rotated about


@dataclass
class GeoFrameValue(FrameValue):
    """A FRAME value that carries a :class:`~nck.geometry.frames.Frame` (mm, degrees)."""

    frame: Frame = field(default_factory=Frame)


def call(name: str, args: Sequence[Any], length_mm: float = 1.0,
         active_plane: Plane | None = None) -> GeoFrameValue:
    """Evaluate a frame function with already evaluated arguments (``active_plane``: for CRPL(0, …), G17 if None)."""
    if name == "CRPL":
        return _value(_crpl(args, active_plane or plane("G17")))
    if name == "CMIRROR":
        axes = [_axis(a, name) for a in args]
        return _value(Frame.cmirror(axes))
    if len(args) % 2:
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
    pairs: dict[str, float] = {}
    for i in range(0, len(args), 2):
        axis = _axis(args[i], name)
        value = args[i + 1]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
        pairs[axis] = float(value)
    if name == "CTRANS":
        return _value(Frame.ctrans({a: v * length_mm for a, v in pairs.items()}))
    if name == "CFINE":
        return _value(Frame.cfine({a: v * length_mm for a, v in pairs.items()}))
    if name == "CROT":
        return _value(Frame.crot(pairs))
    if name == "CSCALE":
        return _value(Frame.cscale(pairs))
    raise NcAlarmError(NAME_NOT_DEFINED, name)


def _crpl(args: Sequence[Any], active_plane: Plane) -> Frame:
    """``CRPL(plane, angle)``: rotation in the active plane (0) or about Z (1), Y (2), X (3) (002 L28005-28020)."""
    if len(args) != 2 or any(isinstance(a, bool) or not isinstance(a, (int, float)) for a in args):
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, "CRPL")
    number, angle = args
    if number == 0:
        return Frame.crpl(active_plane, float(angle))
    if number not in CRPL_AXIS_INDEX:
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, "CRPL")
    axes = active_plane.geometry_axes
    return Frame.crot({axes[CRPL_AXIS_INDEX[int(number)]]: float(angle)}, axes)


def chain(left: Any, right: Any) -> GeoFrameValue:
    """The ``:`` operator: ``right`` acts inside ``left`` (alarm 14096 for non-frames)."""
    return _value(as_frame(left, ":").chain(as_frame(right, ":")))


def as_frame(value: Any, name: str) -> Frame:
    """The :class:`Frame` inside a FRAME value (alarm 14096 for anything else)."""
    if isinstance(value, GeoFrameValue):
        return value.frame
    if isinstance(value, FrameValue):
        return Frame.ctrans(value.trans).arot(value.rot) if value.rot else Frame.ctrans(value.trans)
    raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, name)


def _value(frame: Frame) -> GeoFrameValue:
    return GeoFrameValue(trans=dict(frame.trans), rot={}, frame=frame)


def _axis(value: Any, name: str) -> str:
    if not isinstance(value, str) or not value:
        raise NcAlarmError(WRONG_CALL_ARGUMENTS, name)
    return str(value)
