"""Frame functions in expressions: ``CTRANS()``, ``CROT()``, ``CSCALE()``, ``CMIRROR()``, ``CFINE()``.

Each returns a FRAME value (:class:`GeoFrameValue`) that can be assigned to a
FRAME variable or to a frame system variable (``$P_PFRAME``, ``$P_IFRAME``,
``$P_UIFR[n]``, ``$P_UBFR``)::

    $P_PFRAME = CTRANS(X, 10, Y, 20)    ; programmable frame: translation only
    $P_UIFR[1] = CROT(Z, 45)            ; settable frame G54: rotation only
    $P_PFRAME = CTRANS()                ; zero frame

Arguments come in pairs axis, value (``CMIRROR`` takes axes only). Lengths are
in the programmed system (G70/G700 inch) and converted to mm here.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

from nck.errors import NcAlarmError
from nck.geometry.frames import Frame
from nck.interp.values import FrameValue

NAMES = frozenset(("CTRANS", "CROT", "CSCALE", "CMIRROR", "CFINE"))
ALARM_PARAMETERS = 14020  # wrong value or number of parameters in a function call


@dataclass
class GeoFrameValue(FrameValue):
    """A FRAME value that carries a :class:`~nck.geometry.frames.Frame` (mm, degrees)."""

    frame: Frame = field(default_factory=Frame)


def call(name: str, args: Sequence[Any], length_mm: float = 1.0) -> GeoFrameValue:
    """Evaluate a frame function with already evaluated arguments."""
    if name == "CMIRROR":
        axes = [_axis(a, name) for a in args]
        return _value(Frame.cmirror(axes))
    if len(args) % 2:
        raise NcAlarmError(ALARM_PARAMETERS, name)
    pairs: dict[str, float] = {}
    for i in range(0, len(args), 2):
        axis = _axis(args[i], name)
        value = args[i + 1]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise NcAlarmError(ALARM_PARAMETERS, name)
        pairs[axis] = float(value)
    if name == "CTRANS":
        return _value(Frame.ctrans({a: v * length_mm for a, v in pairs.items()}))
    if name == "CFINE":
        return _value(Frame.cfine({a: v * length_mm for a, v in pairs.items()}))
    if name == "CROT":
        return _value(Frame.crot(pairs))
    if name == "CSCALE":
        return _value(Frame.cscale(pairs))
    raise NcAlarmError(12550, name)


def chain(left: Any, right: Any) -> GeoFrameValue:
    """The ``:`` operator: ``right`` acts inside ``left`` (alarm 14096 for non-frames)."""
    return _value(as_frame(left, ":").chain(as_frame(right, ":")))


def as_frame(value: Any, name: str) -> Frame:
    """The :class:`Frame` inside a FRAME value (alarm 14096 for anything else)."""
    if isinstance(value, GeoFrameValue):
        return value.frame
    if isinstance(value, FrameValue):
        return Frame.ctrans(value.trans).arot(value.rot) if value.rot else Frame.ctrans(value.trans)
    raise NcAlarmError(14096, name)


def _value(frame: Frame) -> GeoFrameValue:
    return GeoFrameValue(trans=dict(frame.trans), rot={}, frame=frame)


def _axis(value: Any, name: str) -> str:
    if not isinstance(value, str) or not value:
        raise NcAlarmError(ALARM_PARAMETERS, name)
    return str(value)
