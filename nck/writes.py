"""The one write path for NC data: one protection and validation rule, whatever the door.

The panel (``WriteData`` through the kernel), ``nck md``, ``nck run --set`` and
``--tools`` and part programs all write retained NC data through
:meth:`DataWriter.write`: the access level is checked against the datum's
protection level (:func:`nck.access.action_for_write`, the MD catalogue's
``protect`` and the ``USER_CLASS`` data), then the value is converted to the
datum's type and checked against its limits. A refused write changes nothing.

Names:

* ``R<n>`` / ``R[<n>]`` — R parameter;
* ``$TC_DP<n>[t,d]`` — tool edge parameter (writing creates the edge);
* ``$P_UIFR[n,axis,comp]`` — settable frame n (1…4 = G54…G57, 5… = G505…),
  ``$P_UBFR[axis,comp]`` — base frame; ``comp`` TR, FI, RT, SC or MI;
* ``GUD:<name>`` / ``GUD:<name>[i]`` — a global user variable that exists (its type is kept);
* ``MD…`` / ``$M…`` / ``SD…`` / ``$S…`` — machine and setting data
  (:class:`nck.machine_data.MachineDataStore`; activation po/re/cf/so).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from nck.access import AccessControl, AccessDenied, Action, action_for_write, required_level
from nck.alarm_ids import VALUE_ABOVE_UPPER_LIMIT, VALUE_BELOW_LOWER_LIMIT
from nck.machine_data import DataError, MachineDataStore, WriteResult
from nck.ncdata import NcData, ToolEdge, WorkOffset
from nck.refused import Refused
from nck.value_text import InvalidValue, number_from_text

TOOL_PARAM_COUNT = 25
TOOL_NUMBER_MAX = 99_999_999
TOOL_EDGE_MAX = 12
TOOL_VALUE_LIMIT_MM = 100_000.0
FRAME_TRANSLATION_LIMIT_MM = 100_000.0
FRAME_COMPONENTS = ("TR", "FI", "RT", "SC", "MI")
FRAME_COMPONENT_TEXT = {"TR": "offset", "FI": "fine offset", "RT": "rotation", "SC": "scale",
                        "MI": "mirror"}
"""How the work offset screens name a frame component (in messages); a refusal carries the
English word as its ``component`` field and the frame and axis as ``frame_axis``, so that a panel
says the name in its own language (``hmi.i18n.refusal_fields_in``)."""
_TC_DP = re.compile(r"^\$TC_DP(\d+)\[\s*(\d+)\s*,\s*(\d+)\s*\]$")
_UIFR = re.compile(r"^\$P_UIFR\[\s*(\d+)\s*,\s*([A-Z][A-Z0-9]*)\s*,\s*([A-Z]{2})\s*\]$")
_UBFR = re.compile(r"^\$P_UBFR\[\s*([A-Z][A-Z0-9]*)\s*,\s*([A-Z]{2})\s*\]$")
_GUD = re.compile(r"^GUD:([A-Z_][A-Z0-9_]*)(?:\[\s*(\d+)\s*\])?$")
_R = re.compile(r"^R(?:(\d+)|\[\s*(\d+)\s*\])$")


class WriteRefused(Refused):
    """The value does not fit the datum (type, limits) or the datum does not exist; nothing changed."""


class ValueOutOfLimits(WriteRefused):
    """A number outside the datum's limits; ``above`` says which (a part program's alarm:
    17090 above the upper limit, else 17080 below the lower one)."""

    def __init__(self, key: str, *, above: bool, **fields: object) -> None:
        super().__init__(key, **fields)
        self.above = above

    @property
    def alarm(self) -> int:
        """The NC alarm of a part program's write: 17090 above the upper limit, 17080 below the lower."""
        return VALUE_ABOVE_UPPER_LIMIT if self.above else VALUE_BELOW_LOWER_LIMIT


def _within(number: float, low: float, high: float, key: str, **fields: object) -> None:
    if not low <= number <= high:
        raise ValueOutOfLimits(key, above=not number < low, **fields)


def check_tool_value(param: int, number: float) -> None:
    """Raise unless ``number`` fits ``$TC_DP<param>`` — the rule of every door, part programs too.

    WriteRefused for a fraction in a whole-number datum (type, edge position), ValueOutOfLimits
    for a number outside its limits.
    """
    if param in (1, 2) and not number.is_integer():
        raise WriteRefused("tool_type_whole" if param == 1 else "edge_position_whole", name=f"$TC_DP{param}")
    if param == 1:
        _within(number, 0, 999, "tool_type_limits")
    if param == 2:
        _within(number, 0, 9, "edge_position_limits")
    _within(number, -TOOL_VALUE_LIMIT_MM, TOOL_VALUE_LIMIT_MM, "tool_value_limits", name=f"$TC_DP{param}",
            limit=f"{TOOL_VALUE_LIMIT_MM:g}")


def check_frame_component(comp: str, number: float) -> None:
    """Raise ValueOutOfLimits unless ``number`` (mm, degrees or a factor) fits frame component
    ``comp`` (TR, FI, RT, SC) of a stored work offset — the rule of every door, part programs too."""
    if comp in ("TR", "FI"):
        _within(number, -FRAME_TRANSLATION_LIMIT_MM, FRAME_TRANSLATION_LIMIT_MM, "translation_limits",
                limit=f"{FRAME_TRANSLATION_LIMIT_MM:g}")
    elif comp == "RT":
        _within(number, -360.0, 360.0, "rotation_limits")
    elif comp == "SC" and (number <= 0.0 or number > 1000.0):
        raise ValueOutOfLimits("scale_limits", above=number > 0.0)


def settable_frame_name(index: int) -> str:
    """The frame name of ``$P_UIFR[index]``: 1…4 → G54…G57, 5…99 → G505…G599."""
    if 1 <= index <= 4:
        return f"G{53 + index}"
    if 5 <= index <= 99:
        return f"G{500 + index}"
    raise WriteRefused("no_settable_frame_index", index=index)


def settable_frame_index(name: str) -> int:
    """Inverse of :func:`settable_frame_name` (``G54`` → 1, ``G505`` → 5)."""
    number = int(name.upper().lstrip("G"))
    return number - 53 if 54 <= number <= 57 else number - 500


def finite_number(value: Any, what: str, **parts: str) -> float:
    """``value`` (a number or the operator's text, :mod:`nck.value_text`) as a finite float.

    Raises WriteRefused with the operator message (no value, not a number, out of range);
    ``parts`` are further fields of the refusal (the parts of ``what`` a panel translates).
    """
    try:
        return number_from_text(value, what)
    except InvalidValue as refusal:
        raise WriteRefused(refusal.key, **dict(refusal.fields), **parts) from None


@dataclass(frozen=True, slots=True)
class Written:
    """What a successful write did; ``md`` is set for machine and setting data."""

    name: str
    md: WriteResult | None = None


class DataWriter:
    """Writes NC data by name after the protection and value checks.

    Args:
        data: the NC data written into.
        store: the machine/setting data store of the same NC data.
        access: the access control whose level applies; None = a commissioning bench
            without protection (a bare kernel in unit tests).
        level: check against this level instead of the access control's current one
            (``--password`` for one command).
    """

    def __init__(self, data: NcData, store: MachineDataStore, access: AccessControl | None,
                 level: int | None = None) -> None:
        self.data = data
        self.store = store
        self.access = access
        self._level = level

    @property
    def level(self) -> int:
        """The level writes are checked against (0 without access control)."""
        if self._level is not None:
            return self._level
        return self.access.level if self.access is not None else 0

    def handles(self, name: str) -> bool:
        """True when ``name`` denotes NC data this path writes."""
        upper = name.strip().upper()
        return bool(upper.startswith(("MD", "SD", "$M", "$S")) or _R.match(upper) or _TC_DP.match(upper)
                    or _UIFR.match(upper) or _UBFR.match(upper) or _GUD.match(upper))

    def required_level(self, name: str) -> int:
        """The protection level writing ``name`` needs (7 for names without protection)."""
        upper = name.strip().upper()
        if upper.startswith(("MD", "SD", "$M", "$S")):
            try:
                return self.store.required_write_level(upper)
            except DataError:
                return 7
        action = self._action(upper)
        needed = 7 if action is None else self._needed(action)
        if upper.startswith(("$P_UIFR", "$P_UBFR")) and upper.replace(" ", "").endswith(",FI]"):
            needed = min(needed, self._needed(Action.WRITE_FINE_OFFSET))  # as write() checks both
        return needed

    def write(self, name: str, value: Any) -> Written:
        """Write ``value`` into the datum ``name``.

        Raises AccessDenied (level too low), WriteRefused (type, limits, unknown datum)
        or a DataError of the MD store; nothing changes then.
        """
        upper = name.strip().upper()
        if upper.startswith(("MD", "SD", "$M", "$S")):
            return Written(upper, self.store.write(upper, value, level=self.level))
        action = self._action(upper)
        if action is not None:
            self._require(action, upper)
        match = _R.match(upper)
        if match:
            return self._write_r(int(match[1] or match[2]), value, upper)
        match = _TC_DP.match(upper)
        if match:
            return self._write_tool(int(match[2]), int(match[3]), int(match[1]), value, upper)
        match = _UIFR.match(upper)
        if match:
            frame = settable_frame_name(int(match[1]))
            return self._write_frame(self.data.settable_frame(frame), match[2], match[3], value, upper,
                                     frame)
        match = _UBFR.match(upper)
        if match:
            return self._write_frame(self.data.base_frame, match[1], match[2], value, upper, "Base frame")
        match = _GUD.match(upper)
        if match:
            return self._write_gud(match[1], None if match[2] is None else int(match[2]), value, upper)
        raise WriteRefused("not_writable_here", name=name.strip())

    # ---------------------------------------------------------------- checks
    @staticmethod
    def _action(upper: str) -> Action | None:
        if upper.startswith("$P_UBFR"):
            return Action.WRITE_WORK_OFFSET
        if upper.startswith("GUD:"):
            return Action.WRITE_USER_DATA
        return action_for_write(upper)

    def _needed(self, action: Action) -> int:
        if self.access is not None:
            return self.access.required(action)
        return required_level(action, self.store.user_class)

    def _require(self, action: Action, datum: str) -> None:
        if self.access is None and self._level is None:
            return  # a commissioning bench: no protection
        needed = self._needed(action)
        if self.level > needed:
            raise AccessDenied.of_action(action, needed, self.level, datum)

    # ---------------------------------------------------------------- writes
    def _write_r(self, index: int, value: Any, name: str) -> Written:
        r = self.data.r
        if index >= len(r):
            raise WriteRefused("no_r_parameter", index=index, last=len(r) - 1)
        r[index] = finite_number(value, name)
        return Written(name)

    def _write_tool(self, tool: int, edge: int, param: int, value: Any, name: str) -> Written:
        if not 1 <= param <= TOOL_PARAM_COUNT:
            raise WriteRefused("no_tool_parameter", name=f"$TC_DP{param}", count=TOOL_PARAM_COUNT)
        if not 1 <= tool <= TOOL_NUMBER_MAX:
            raise WriteRefused("tool_number_limits", tool=tool, max=TOOL_NUMBER_MAX)
        if not 1 <= edge <= TOOL_EDGE_MAX:
            raise WriteRefused("edge_number_limits", edge=f"D{edge}", max=TOOL_EDGE_MAX)
        number = finite_number(value, name)
        check_tool_value(param, number)
        edge_count = int(self.store.value("MD18100"))
        if not self.data.has_room_for_edge(tool, edge, edge_count):
            raise WriteRefused("tool_memory_full", count=edge_count, edge=f"T{tool} D{edge}")
        tools = self.data.tools
        edge_data = tools.get((tool, edge))
        if edge_data is None:
            edge_data = ToolEdge()
            if edge > 1 and (tool, 1) in tools:
                edge_data.params[1] = tools[(tool, 1)].get(1)  # a new edge of a tool keeps its type
            tools[(tool, edge)] = edge_data
        edge_data.params[param] = number
        return Written(name)

    def _write_frame(self, offset: WorkOffset, axis: str, comp: str, value: Any, name: str,
                     frame: str) -> Written:
        if axis not in [a for a in self.store.axes if a not in self.store.machine.spindles]:
            raise WriteRefused("machine_no_axis", axis=axis)
        if comp not in FRAME_COMPONENTS:
            raise WriteRefused("no_frame_component", component=comp)
        component = FRAME_COMPONENT_TEXT[comp]
        number = finite_number(value, f"{frame} {axis} {component}", frame_axis=f"{frame} {axis}",
                               component=component)
        check_frame_component(comp, number)
        if comp == "MI" and number not in (0.0, 1.0):
            raise WriteRefused("mirror_values")
        if comp == "FI":
            self._require(Action.WRITE_FINE_OFFSET, name)
        if comp == "MI":
            offset.mirror[axis] = bool(number)
        else:
            {"TR": offset.trans, "FI": offset.fine, "RT": offset.rot, "SC": offset.scale}[comp][axis] = number
        return Written(name)

    def _write_gud(self, name: str, index: int | None, value: Any, full: str) -> Written:
        gud = self.data.gud
        if name not in gud:
            raise WriteRefused("gud_missing", name=name)
        current = gud[name]
        if isinstance(current, list):
            if index is None or not 0 <= index < len(current):
                raise WriteRefused("gud_array", name=name, count=len(current))
            items = list(current)
            items[index] = _like(items[index], value, name)
            gud[name] = items
        else:
            if index is not None:
                raise WriteRefused("gud_not_array", name=name)
            gud[name] = _like(current, value, name)
        return Written(full)


def _like(current: Any, value: Any, name: str) -> Any:
    """``value`` converted to the type of ``current`` (a GUD keeps its type)."""
    if isinstance(current, bool):
        if isinstance(value, str):
            text = value.strip().upper()
            if text in ("TRUE", "1"):
                return True
            if text in ("FALSE", "0"):
                return False
            raise WriteRefused("gud_bool", name=name)
        return bool(value)
    if isinstance(current, int):
        number = finite_number(value, name)
        if not number.is_integer():
            raise WriteRefused("value_enter_whole_number", name=name)
        return int(number)
    if isinstance(current, float):
        return finite_number(value, name)
    if isinstance(current, str):
        return str(value)
    raise WriteRefused("not_writable_here", name=name)


__all__ = ["DataWriter", "ValueOutOfLimits", "WriteRefused", "Written", "check_frame_component",
           "check_tool_value", "finite_number", "settable_frame_index", "settable_frame_name"]
