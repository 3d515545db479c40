"""Values and variables of the NC language: data types, conversions, cells.

Runtime values are plain Python objects: ``int`` (INT, CHAR), ``float``
(REAL), ``bool`` (BOOL), ``str`` (STRING), :class:`Axis` (AXIS) and
:class:`FrameValue` (FRAME). A user variable lives in a :class:`Cell` that
knows its type, array dimensions and limits; every write goes through
:meth:`Cell.set`, which converts and checks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from nck.alarm_ids import (
    ILLEGAL_ARRAY_INDEX_1, ILLEGAL_ARRAY_INDEX_2, NAME_NOT_DEFINED, STRING_TOO_LONG,
    TYPE_CONVERSION_IMPOSSIBLE, VALUE_ABOVE_UPPER_LIMIT, VALUE_BELOW_LOWER_LIMIT, VALUE_RANGE_EXCEEDED,
)
from nck.errors import NcAlarmError

INT_MIN = -(2**31)
INT_MAX = 2**31 - 1
STRING_MAX = 200
LUD_VALUES_MEM_KB = 64  # MD28040 MM_LUD_VALUES_MEM when the machine does not set it (data/md/channel.toml)
GUD_VALUES_MEM_KB = 12  # MD18150 MM_GUD_VALUES_MEM (data/md/general.toml)
ELEMENT_BYTES = {"INT": 4, "REAL": 8, "BOOL": 1, "CHAR": 1, "AXIS": 4, "FRAME": 400}
"""Control memory one element of each type takes (the trainer's estimate; STRING[n] takes n + 1)."""


def memory_bytes(dtype: str, elements: int, string_len: int | None = None) -> int:
    """Bytes of variable memory ``elements`` values of ``dtype`` take (MD28040/MD18150 budget)."""
    each = (string_len or STRING_MAX) + 1 if dtype == "STRING" else ELEMENT_BYTES.get(dtype, 8)
    return each * elements


def stored_bytes(value: Any) -> int:
    """Bytes a stored value (a GUD in NcData) takes: strings by their length, numbers as REAL."""
    if isinstance(value, list):
        return sum(stored_bytes(item) for item in value)
    if isinstance(value, str):
        return len(value) + 1
    return ELEMENT_BYTES["REAL"]


class Axis(str):
    """An AXIS value: the name of a channel axis or spindle."""


@dataclass
class FrameValue:
    """A FRAME value (translations per axis, rotations in degrees); opaque for now."""

    trans: dict[str, float] = field(default_factory=dict)
    rot: dict[str, float] = field(default_factory=dict)


def default_value(dtype: str) -> Any:
    """The initial value of a variable of type ``dtype``."""
    return {
        "INT": 0,
        "REAL": 0.0,
        "BOOL": False,
        "CHAR": 0,
        "STRING": "",
        "AXIS": Axis(""),
        "FRAME": None,
    }[dtype]


def round_half_away(value: float) -> int:
    """Round like the NC: .5 away from zero."""
    return int(math.floor(abs(value) + 0.5)) * (1 if value >= 0 else -1)


def to_number(value: Any, what: str = "") -> int | float:
    """Return a numeric value (bool → 0/1); strings/axes/frames → alarm 14096."""
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (int, float)):
        return value
    raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, what or _show(value))


def to_bool(value: Any) -> bool:
    """Truth value: numbers ≠ 0, non-empty strings."""
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        return value != 0
    if isinstance(value, str):
        return value != ""
    raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, _show(value))


def to_string(value: Any) -> str:
    """Text form used by ``<<`` and STRING conversion (REAL without trailing zeros)."""
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if value == int(value) and abs(value) < 1e15:
            return str(int(value))
        text = f"{value:.10f}".rstrip("0").rstrip(".")
        return text if text not in ("-0", "") else "0"
    if isinstance(value, str):
        return value
    raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, _show(value))


def _show(value: Any) -> str:
    text = value if isinstance(value, str) else type(value).__name__
    return str(text)[:20]


def convert(value: Any, dtype: str, name: str = "", string_len: int | None = None) -> Any:
    """Convert ``value`` for storage in a variable of type ``dtype`` (alarms on failure)."""
    if dtype == "REAL":
        number = float(to_number(value, name))
        if not math.isfinite(number):
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, name)
        return number
    if dtype == "INT":
        number = to_number(value, name)
        if isinstance(number, float):
            if not math.isfinite(number):
                raise NcAlarmError(VALUE_RANGE_EXCEEDED, name)
            number = round_half_away(number)
        if not INT_MIN <= number <= INT_MAX:
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, name)
        return int(number)
    if dtype == "BOOL":
        return to_bool(value)
    if dtype == "CHAR":
        if isinstance(value, str) and not isinstance(value, Axis):
            if len(value) != 1:
                raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, name)
            value = ord(value)
        number = to_number(value, name)
        number = round_half_away(number) if isinstance(number, float) else number
        if not 0 <= number <= 255:
            raise NcAlarmError(VALUE_RANGE_EXCEEDED, name)
        return int(number)
    if dtype == "STRING":
        text = to_string(value)
        limit = string_len or STRING_MAX
        if len(text) > limit:
            raise NcAlarmError(STRING_TOO_LONG, name)
        return text
    if dtype == "AXIS":
        if isinstance(value, str):
            return Axis(value)
        raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, name)
    if dtype == "FRAME":
        if value is None or isinstance(value, FrameValue):
            return value
        raise NcAlarmError(TYPE_CONVERSION_IMPOSSIBLE, name)
    raise NcAlarmError(NAME_NOT_DEFINED, dtype)


@dataclass
class Cell:
    """A user variable (LUD/PUD, or a GUD defined at run time): scalar or array.

    ``dims`` is empty for a scalar; arrays keep their elements in a flat list in
    row-major order. ``lower``/``upper`` are the LLI/ULI limits (numbers) or None.
    """

    name: str
    dtype: str
    value: Any
    dims: tuple[int, ...] = ()
    lower: float | None = None
    upper: float | None = None
    string_len: int | None = None

    @classmethod
    def create(cls, name: str, dtype: str, dims: tuple[int, ...] = (), lower: float | None = None,
               upper: float | None = None, string_len: int | None = None) -> "Cell":
        """A new variable holding the type default (moved inside its limits)."""
        initial = default_value(dtype)
        if isinstance(initial, (int, float)) and not isinstance(initial, bool):
            if lower is not None and initial < lower:
                initial = convert(lower, dtype, name)
            if upper is not None and initial > upper:
                initial = convert(upper, dtype, name)
        size = 1
        for d in dims:
            size *= d
        value = [initial] * size if dims else initial
        return cls(name, dtype, value, dims, lower, upper, string_len)

    def offset(self, indices: tuple[Any, ...]) -> int:
        """Flat position of an element; alarms 17020/17030 for bad indices."""
        if len(indices) != len(self.dims):
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1 if not self.dims else ILLEGAL_ARRAY_INDEX_2, self.name)
        flat = 0
        for position, (raw, size) in enumerate(zip(indices, self.dims)):
            index = convert(raw, "INT", self.name)
            if not 0 <= index < size:
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1 if position == 0 else ILLEGAL_ARRAY_INDEX_2, self.name)
            flat = flat * size + index
        return flat

    def get(self, indices: tuple[Any, ...] = ()) -> Any:
        """Read the scalar or one element."""
        if not self.dims:
            if indices:
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, self.name)
            return self.value
        return self.value[self.offset(indices)]

    def set(self, value: Any, indices: tuple[Any, ...] = ()) -> None:
        """Write the scalar or one element (converted; limits checked)."""
        converted = convert(value, self.dtype, self.name, self.string_len)
        if isinstance(converted, (int, float)) and not isinstance(converted, bool):
            if self.lower is not None and converted < self.lower:
                raise NcAlarmError(VALUE_BELOW_LOWER_LIMIT, self.name)
            if self.upper is not None and converted > self.upper:
                raise NcAlarmError(VALUE_ABOVE_UPPER_LIMIT, self.name)
        if not self.dims:
            if indices:
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, self.name)
            self.value = converted
        else:
            self.value[self.offset(indices)] = converted
