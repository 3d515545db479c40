"""The machine-data and setting-data catalogue: what each datum is (``data/md/*.toml``).

Number, identifier, scope, type, unit, default, limits, protection levels and
activation of every datum, as ``data/md/README.md`` describes them. The values
of one machine are held by :class:`nck.machine_data.MachineDataStore`; the
protection rules (:mod:`nck.access`) read the defaults of the USER_CLASS data here.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

from nck.number_text import trimmed
from nck.refused import Refused
from nck.resources import data_path, load_toml
from nck.value_text import InvalidValue, number_from_text

ACTIVATIONS = ("so", "re", "cf", "po")
ACTIVATION_TEXT = {
    "so": "immediately",
    "re": "at RESET",
    "cf": "at NEW CONFIG (Set MD active, or RESET)",
    "po": "at POWER ON (Reset (po))",
}
#: Which activation classes each event brings into effect.
EVENT_ACTIVATES = {
    "reset": frozenset({"so", "re", "cf"}),
    "new_config": frozenset({"so", "re", "cf"}),
    "power_on": frozenset(ACTIVATIONS),
}
PREFIX = {
    ("md", "general"): "$MN_",
    ("md", "channel"): "$MC_",
    ("md", "axis"): "$MA_",
    ("md", "display"): "$MM_",
    ("sd", "general"): "$SN_",
    ("sd", "channel"): "$SC_",
    ("sd", "axis"): "$SA_",
}
TYPES = ("real", "int", "bool", "string")
INVALID_VALUE_REFUSALS = {"bool": "md_invalid_bool", "int": "md_invalid_int", "real": "md_invalid_real"}
"""The refusal (``data/refusals.toml``) of a value that is not of the datum's type, by type."""
USER_CLASS_FIRST, USER_CLASS_LAST = 9200, 9299


class DataError(Refused):
    """A machine/setting datum could not be read or written; ``str()`` says why."""


class UnknownDataError(DataError):
    """The name does not denote a datum of the catalogue (or an axis of the machine)."""


class DataValueError(DataError):
    """The value has the wrong type or lies outside the datum's limits."""


@dataclass(frozen=True, slots=True)
class DataDefinition:
    """One machine or setting datum of the catalogue."""

    number: int
    name: str
    kind: str  # "md" or "sd"
    scope: str  # "general", "channel", "axis", "display"
    type: str
    unit: str
    default: Any
    min: float | None
    max: float | None
    array: int  # element count, 0 for a scalar
    activation: str
    write_level: int
    read_level: int
    title: str

    @property
    def key(self) -> str:
        """``"MD32000"`` / ``"SD42100"``: the key used in machine files and NcData."""
        return f"{self.kind.upper()}{self.number}"

    @property
    def identifier(self) -> str:
        """``"$MA_MAX_AX_VELO"``."""
        return PREFIX[(self.kind, self.scope)] + self.name

    @property
    def per_axis(self) -> bool:
        """True for axis data (one value per axis)."""
        return self.scope == "axis"

    @property
    def is_user_class(self) -> bool:
        """True for the ``USER_CLASS_*`` data that hold protection levels."""
        return self.kind == "md" and USER_CLASS_FIRST <= self.number <= USER_CLASS_LAST

    def coerce(self, value: Any) -> Any:
        """Return ``value`` converted to the datum's type and checked against its limits."""
        converted = _convert(self.type, value, self.key)
        if self.type in ("real", "int"):
            if self.min is not None and converted < self.min:
                raise DataValueError("md_below_limit", name=self.key, value=format_value(self, converted),
                                     limit=format_value(self, self.min))
            if self.max is not None and converted > self.max:
                raise DataValueError("md_above_limit", name=self.key, value=format_value(self, converted),
                                     limit=format_value(self, self.max))
        return converted


def _convert(kind: str, value: Any, key: str) -> Any:
    """Convert a value (possibly text from a command line) to the catalogue type."""
    text = value.strip() if isinstance(value, str) else None
    try:
        if kind == "bool":
            if isinstance(value, bool):
                return value
            if isinstance(value, (int, float)) and value in (0, 1):
                return bool(value)
            if text is not None and text.upper() in ("TRUE", "1", "FALSE", "0"):
                return text.upper() in ("TRUE", "1")
        elif kind == "int":
            if isinstance(value, bool):
                return int(value)
            if isinstance(value, int):
                return value
            if isinstance(value, float) and value.is_integer():
                return int(value)
            if text is not None:
                upper = text.upper()
                if re.fullmatch(r"'?H[0-9A-F]+'?", upper):
                    return int(upper.strip("'")[1:], 16)
                if re.fullmatch(r"'?B[01]+'?", upper):
                    return int(upper.strip("'")[1:], 2)
                number = number_from_text(text, key)
                if number.is_integer():
                    return int(number)
        elif kind == "real":
            if isinstance(value, bool):
                return float(value)
            if isinstance(value, (int, float)):
                result = float(value)
            elif text is not None:
                result = number_from_text(text, key)
            else:
                result = None
            if result is not None and result == result and abs(result) != float("inf"):
                return result
        elif kind == "string":
            if isinstance(value, str):
                return value
    except (ValueError, OverflowError, InvalidValue):
        pass
    if text == "":
        raise DataValueError("value_missing", name=key)
    shown = text if text is not None else str(value)
    raise DataValueError(INVALID_VALUE_REFUSALS.get(kind, "md_invalid_string"), name=key, value=shown)


def format_value(definition: DataDefinition, value: Any) -> str:
    """Return a value as the MD screens show it."""
    if isinstance(value, list):
        return "[" + ", ".join(format_value(definition, v) for v in value) + "]"
    if isinstance(value, dict):
        return ", ".join(f"{axis}: {format_value(definition, v)}" for axis, v in value.items())
    if definition.type == "bool" or isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if definition.type == "real" and isinstance(value, (int, float)):
        number = float(value)
        if abs(number) >= 1e7 or 0 < abs(number) < 1e-6:
            return f"{number:g}"
        return trimmed(number)
    return str(value)


class Catalog:
    """All data definitions, found by key, number or identifier."""

    def __init__(self, definitions: Iterable[DataDefinition]) -> None:
        self.definitions: tuple[DataDefinition, ...] = tuple(
            sorted(definitions, key=lambda d: (d.kind != "md", d.number))
        )
        self._by_key: dict[str, DataDefinition] = {}
        self._by_identifier: dict[str, DataDefinition] = {}
        for definition in self.definitions:
            if definition.key in self._by_key:
                raise ValueError(f"{definition.key} defined twice in data/md")
            self._by_key[definition.key] = definition
            self._by_identifier[definition.identifier] = definition

    def __iter__(self):
        return iter(self.definitions)

    def __len__(self) -> int:
        return len(self.definitions)

    def get(self, key: str) -> DataDefinition | None:
        """Return the datum for ``"MD32000"``, ``"SD42100"`` or ``"$MA_MAX_AX_VELO"``."""
        upper = key.strip().upper()
        return self._by_key.get(upper) or self._by_identifier.get(upper)

    def get_md(self, number: int) -> DataDefinition:
        """Return machine datum ``number`` (KeyError when it is not in the catalogue)."""
        return self._by_key[f"MD{number}"]

    def find(self, text: str) -> list[DataDefinition]:
        """Search by number or by part of the identifier or title (case-insensitive)."""
        needle = text.strip().upper()
        return [
            d for d in self.definitions
            if needle in d.key or needle in d.identifier or needle in d.title.upper()
        ]


def _definition(entry: Mapping[str, Any], kind: str, scope: str | None, source: str) -> DataDefinition:
    number = int(entry["number"])
    if scope is None:  # setting data: 41xxx general, 42xxx channel, 43xxx axis
        scope = entry.get("scope") or {41: "general", 42: "channel", 43: "axis"}[number // 1000]
    protect = entry.get("protect", [2, 7] if kind == "md" else [7, 7])
    definition = DataDefinition(
        number=number,
        name=str(entry["name"]),
        kind=kind,
        scope=scope,
        type=str(entry["type"]),
        unit=str(entry.get("unit", "")),
        default=entry["default"],
        min=entry.get("min"),
        max=entry.get("max"),
        array=int(entry.get("array", 0)),
        activation=str(entry["activation"]),
        write_level=int(protect[0]),
        read_level=int(protect[1]),
        title=str(entry.get("title", "")),
    )
    if definition.type not in TYPES or definition.activation not in ACTIVATIONS:
        raise ValueError(f"{source}: {definition.key} has a bad type or activation")
    if (kind, scope) not in PREFIX:
        raise ValueError(f"{source}: {definition.key} has a bad scope {scope!r}")
    return definition


@functools.cache
def catalog() -> Catalog:
    """Return the catalogue of ``data/md/*.toml`` (cached)."""
    definitions = []
    for path in sorted(data_path("md").glob("*.toml")):
        table = load_toml("md", path.name)
        kind = table["kind"]
        for entry in table["data"]:
            definitions.append(_definition(entry, kind, table.get("scope"), path.name))
    return Catalog(definitions)
