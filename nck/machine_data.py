"""The store of machine-data and setting-data values (the catalogue itself is :mod:`nck.md_catalog`).

The catalogue (``data/md/*.toml``, described in ``data/md/README.md``) gives
each datum its number, identifier, scope, type, unit, default, limits,
protection levels and activation; its names are re-exported here. :class:`MachineDataStore` holds the values
of one machine in three layers — catalogue default, machine file, retained
changes — and keeps apart what is *stored* (shown on the MD screen) from what
is *active* (used by the kernel), following the activation of each datum:

* ``so`` immediately, ``re`` at RESET, ``cf`` at NEW CONFIG (the "Set MD
  active" softkey; RESET also activates it), ``po`` only at POWER ON (a
  restart builds a new store from the retained data, where everything is
  active).

Setting data (``SD…``) take effect at once and live in
``NcData.setting_data`` under their key (``"SD42100"``; axis data as
``{"X": value}``), so the kernel reads them there.
"""

from __future__ import annotations

import copy
import dataclasses
import re
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

from nck.access import AccessDenied, Action, LEVEL_FEWEST_RIGHTS, required_level
from nck.machine import MachineConfig
from nck.md_catalog import (
    ACTIVATION_TEXT, EVENT_ACTIVATES, PREFIX, Catalog, DataDefinition, DataError, DataValueError,
    UnknownDataError, catalog, format_value,
)

@dataclass(frozen=True, slots=True)
class DataRef:
    """A datum with its axis and array index as a name addresses it.

    ``axis`` is None for non-axis data (or "every axis" when reading axis data);
    ``index`` is None for scalars (or "the whole array").
    """

    definition: DataDefinition
    axis: str | None = None
    index: int | None = None

    @property
    def text(self) -> str:
        """Canonical name by number: ``MD32000[X]``, ``MD32200[1,X]``, ``MD20150[5]``."""
        return self.definition.key + self._brackets()

    @property
    def identifier_text(self) -> str:
        """Canonical name by identifier: ``$MA_MAX_AX_VELO[X]``."""
        return self.definition.identifier + self._brackets()

    def _brackets(self) -> str:
        parts = [str(self.index)] if self.index is not None else []
        if self.axis is not None:
            parts.append(self.axis)
        return f"[{','.join(parts)}]" if parts else ""


_NAME = re.compile(r"^\s*(?P<base>\$?[A-Za-z0-9_]+)\s*(?:\[(?P<args>[^\]]*)\])?\s*$")


def parse_ref(text: str, axes: Iterable[str], cat: Catalog | None = None) -> DataRef:
    """Resolve a name such as ``MD32000[X]``, ``$MA_MAX_AX_VELO[X]``, ``SD42100``,
    ``$SC_DRY_RUN_FEED``, ``MD32200[1,X]`` or ``$MC_GCODE_RESET_VALUES[5]``.

    ``axes`` are the machine's axis names; ``S1``, ``S2`` … also address the
    first, second … spindle when no axis has that name. Raises UnknownDataError.
    """
    cat = cat or catalog()
    axis_names = list(axes)
    match = _NAME.match(text)
    if not match:
        raise UnknownDataError("md_bad_name", name=repr(text))
    definition = cat.get(match["base"])
    if definition is None and match["base"].isdigit():  # a bare number: MD and SD share one range
        definition = cat.get("MD" + match["base"]) or cat.get("SD" + match["base"])
    if definition is None:
        raise UnknownDataError("md_not_in_catalogue", name=match['base'])
    args = [a.strip() for a in match["args"].split(",")] if match["args"] is not None else []
    axis: str | None = None
    index: int | None = None
    if definition.per_axis and args and not args[-1].lstrip("-").isdigit():
        axis = _axis_name(args.pop(), axis_names, definition)
    if args:
        if len(args) > 1 or not args[0].lstrip("-").isdigit():
            raise UnknownDataError("md_bad_index", name=text, index=match['args'])
        index = int(args[0])
        if not definition.array:
            raise UnknownDataError("md_not_array", name=definition.key)
        if not 0 <= index < definition.array:
            raise UnknownDataError("md_index_limits", name=definition.key, index=index, last=definition.array - 1)
    return DataRef(definition, axis, index)


def _axis_name(name: str, axes: list[str], definition: DataDefinition) -> str:
    upper = name.upper()
    for axis in axes:
        if axis.upper() == upper:
            return axis
    raise UnknownDataError("md_no_axis", name=definition.key, axis=name)


@dataclass(frozen=True, slots=True)
class WriteResult:
    """What a successful write did."""

    ref: DataRef
    old: Any
    new: Any
    activation: str
    active_now: bool

    @property
    def takes_effect(self) -> str:
        """``"immediately"``, ``"at RESET"``, … (the activation of the datum)."""
        return ACTIVATION_TEXT[self.activation]


@dataclass(frozen=True, slots=True)
class DataRow:
    """One line of a machine/setting data list as the Setup and Parameter screens show it."""

    ref: DataRef
    value_text: str
    unit: str
    activation: str  # so / re / cf / po
    write_level: int
    pending: bool  # stored value not active yet
    title: str


ROTARY_UNITS = {"mm": "deg", "mm/min": "deg/min", "mm/rev": "deg/rev"}
"""The unit of an axis datum written in linear units, for a rotary axis (the kernel
reads positions in degrees and velocities in degrees per minute there)."""

SPINDLE_UNITS = {"mm": "deg", "mm/min": "rev/min", "mm/rev": "deg/rev"}
"""The same for a spindle: positions in degrees, velocities in rev/min (the kernel
takes MD32000 of a spindle as its maximum speed)."""


class MachineDataStore:
    """Machine and setting data values of one machine, with stored vs active values.

    Args:
        machine: the machine as loaded from its file (its ``md`` is the commissioning layer).
        changes: retained MD values that override the machine file, in the machine
            file's shape (``{"MD32000": {"X": 5000.0}}``); all of them are active.
        setting_data: the ``NcData.setting_data`` dict (shared, mutated in place).
    """

    def __init__(self, machine: MachineConfig, changes: Mapping[str, Any] | None = None,
                 setting_data: dict[str, Any] | None = None, cat: Catalog | None = None) -> None:
        self.machine = machine
        self.catalog = cat or catalog()
        self.changes: dict[str, Any] = copy.deepcopy(dict(changes or {}))
        self._active: dict[str, Any] = copy.deepcopy(self.changes)
        self.setting_data: dict[str, Any] = setting_data if setting_data is not None else {}

    # ----------------------------------------------------------------- names
    @property
    def axes(self) -> tuple[str, ...]:
        """Every axis and spindle name of the machine."""
        return tuple(a.name for a in self.machine.axes)

    def resolve(self, text: str) -> DataRef:
        """Resolve a name for this machine (see :func:`parse_ref`); spindles as S1, S2 …"""
        try:
            return parse_ref(text, self.axes, self.catalog)
        except UnknownDataError:
            spindle = re.fullmatch(r"(.*\[(?:-?\d+\s*,\s*)?)S(\d+)\]\s*", text, re.IGNORECASE)
            spindles = self.machine.spindles
            if spindle and 1 <= int(spindle[2]) <= len(spindles):
                return parse_ref(f"{spindle[1]}{spindles[int(spindle[2]) - 1]}]", self.axes,
                                 self.catalog)
            raise

    def unit(self, ref: DataRef | str) -> str:
        """The unit of a datum for its axis: ``mm`` of a linear axis is ``deg`` on a
        rotary axis or spindle, ``mm/min`` is ``deg/min`` or ``rev/min``."""
        ref = self._ref(ref)
        kind = next((a.kind for a in self.machine.axes if a.name == ref.axis), "linear")
        table = {"rotary": ROTARY_UNITS, "spindle": SPINDLE_UNITS}.get(kind, {})
        return table.get(ref.definition.unit, ref.definition.unit)

    # ---------------------------------------------------------------- values
    def _full(self, layer: Mapping[str, Any], d: DataDefinition, axis: str | None) -> Any:
        """The whole value (list for arrays) of a datum for one axis from a layer stack."""
        if d.kind == "sd":
            sources: tuple[Mapping[str, Any], ...] = (self.setting_data,)
        else:
            sources = (layer, self.machine.md)
        for source in sources:
            if d.key in source:
                value = source[d.key]
                if d.per_axis and isinstance(value, dict):
                    if axis in value:
                        return value[axis]
                    continue
                return value
        return d.default

    @staticmethod
    def _element(value: Any, index: int | None) -> Any:
        if index is None or not isinstance(value, list):
            return value
        return value[index] if index < len(value) else value[-1]

    def _read(self, layer: Mapping[str, Any], ref: DataRef) -> Any:
        d = ref.definition
        if d.per_axis and ref.axis is None:
            return {axis: self._element(self._full(layer, d, axis), ref.index) for axis in self.axes}
        return self._element(self._full(layer, d, ref.axis), ref.index)

    def value(self, ref: DataRef | str) -> Any:
        """The stored value (what the MD screen shows, maybe not active yet).

        For axis data without an axis: a dict axis -> value.
        """
        return self._read(self.changes, self._ref(ref))

    def active_value(self, ref: DataRef | str) -> Any:
        """The value in effect in the kernel."""
        return self._read(self._active, self._ref(ref))

    def is_pending(self, ref: DataRef | str) -> bool:
        """True when a stored value waits for its activation."""
        ref = self._ref(ref)
        return self.value(ref) != self.active_value(ref)

    def pending(self) -> list[str]:
        """Keys of the machine data whose stored value is not active yet."""
        return sorted(k for k in self.changes if self.changes.get(k) != self._active.get(k))

    def _ref(self, ref: DataRef | str) -> DataRef:
        return self.resolve(ref) if isinstance(ref, str) else ref

    def user_class(self, number: int) -> int | None:
        """Active value of a USER_CLASS display datum (for :mod:`nck.access`)."""
        definition = self.catalog.get(f"MD{number}")
        if definition is None:
            return None
        return int(self._read(self._active, DataRef(definition)))

    def rows(self, kind: str = "md", scope: str | None = None, axis: str | None = None,
             search: str | None = None, level: int = 0) -> list[DataRow]:
        """The list of a data area: ``kind`` ``md``/``sd``, ``scope`` ``general``,
        ``channel``, ``axis`` or ``display`` (None = all), axis data for ``axis``
        (default: the first axis); only data ``level`` may read; ``search`` filters
        by number, identifier or title."""
        found = self.catalog.find(search) if search else list(self.catalog)
        chosen_axis = axis or (self.axes[0] if self.axes else None)
        rows = []
        for d in found:
            if d.kind != kind or (scope is not None and d.scope != scope) or level > d.read_level:
                continue
            ref = DataRef(d, chosen_axis if d.per_axis else None)
            rows.append(DataRow(ref, format_value(d, self.value(ref)), self.unit(ref), d.activation,
                                self.required_write_level(ref), self.is_pending(ref), d.title))
        return rows

    # ---------------------------------------------------------------- writes
    def required_write_level(self, ref: DataRef | str) -> int:
        """The protection level a write of this datum needs."""
        d = self._ref(ref).definition
        if d.kind == "sd":
            return min(d.write_level, required_level(Action.WRITE_SETTING_DATA, self.user_class))
        return d.write_level

    def check_read(self, ref: DataRef | str, level: int) -> None:
        """Raise AccessDenied when ``level`` may not read the datum."""
        ref = self._ref(ref)
        if level > ref.definition.read_level:
            raise AccessDenied("md_read", ref.definition.read_level, level, datum=ref.text)

    def check_write(self, ref: DataRef | str, value: Any, level: int) -> Any:
        """Validate a write without doing it; return the converted value.

        Raises AccessDenied (level) or DataValueError / UnknownDataError.
        """
        ref = self._ref(ref)
        d = ref.definition
        needed = self.required_write_level(ref)
        if level > needed:
            raise AccessDenied("md_write", needed, level, datum=ref.text, identifier=d.identifier)
        if d.per_axis and ref.axis is None:
            raise UnknownDataError("md_axis_data", name=d.key, axis=self.axes[0])
        if d.array and ref.index is None:
            raise UnknownDataError("md_array_element", name=d.key)
        new = d.coerce(value)
        if d.is_user_class and new < level:
            raise AccessDenied("md_user_class", new, level, datum=ref.text, level=new)
        return new

    def write(self, ref: DataRef | str, value: Any, *, level: int) -> WriteResult:
        """Write a datum after the level and limit checks; nothing changes when they fail."""
        ref = self._ref(ref)
        new = self.check_write(ref, value, level)
        d = ref.definition
        old = self.value(ref)
        if d.kind == "sd":
            self._assign(self.setting_data, ref, new)
            return WriteResult(ref, old, new, d.activation, True)
        self._assign(self.changes, ref, new)
        active_now = d.activation == "so"
        if active_now:
            self._assign(self._active, ref, new)
        return WriteResult(ref, old, new, d.activation, active_now)

    def _assign(self, layer: dict[str, Any], ref: DataRef, new: Any) -> None:
        """Store ``new`` for ``ref`` in ``layer`` (MD) or in the setting data (SD)."""
        d = ref.definition
        target = layer if d.kind == "md" else self.setting_data
        if d.array:
            assert ref.index is not None, "an array element is written by its index (checked by write)"
            current = self._full(layer, d, ref.axis)
            elements = list(current) if isinstance(current, list) else [current] * d.array
            elements += [elements[-1]] * (d.array - len(elements))
            elements[ref.index] = new
            new = elements
        if d.per_axis:
            slot = target.get(d.key)
            slot = dict(slot) if isinstance(slot, dict) else {}
            slot[ref.axis] = new
            target[d.key] = slot
        else:
            target[d.key] = new

    # ------------------------------------------------------------ activation
    def activate(self, event: str) -> list[str]:
        """Bring stored values into effect for ``event`` (``reset``, ``new_config``,
        ``power_on``); return the keys that became active."""
        classes = EVENT_ACTIVATES[event]
        changed = []
        for key, value in self.changes.items():
            definition = self.catalog.get(key)
            if definition is None or definition.activation in classes:
                if self._active.get(key) != value:
                    self._active[key] = copy.deepcopy(value)
                    changed.append(key)
        return sorted(changed)

    def active_machine(self) -> MachineConfig:
        """The machine with every active MD value merged into ``md`` (for building a kernel)."""
        merged = copy.deepcopy(dict(self.machine.md))
        for key, value in self._active.items():
            if isinstance(value, dict) and isinstance(merged.get(key), dict):
                merged[key] = {**merged[key], **value}
            else:
                merged[key] = copy.deepcopy(value)
        return dataclasses.replace(self.machine, md=merged)

    def retained_changes(self) -> dict[str, Any]:
        """The stored MD values to persist (same shape as a machine file's ``[md]``)."""
        return copy.deepcopy(self.changes)


def number_of(identifier: str) -> int | None:
    """Number of a datum by identifier, with or without prefix (``MAX_AX_VELO`` → 32000)."""
    upper = identifier.strip().upper().lstrip("$")
    if "_" in upper[:4] and upper[:3] in {p[1:] for p in PREFIX.values()}:
        definition = catalog().get("$" + upper)
        return definition.number if definition is not None else None
    for definition in catalog():
        if definition.name == upper:
            return definition.number
    return None


def fill_setting_defaults(setting_data: dict[str, Any], machine: MachineConfig,
                          cat: Catalog | None = None) -> None:
    """Put the catalogue default of every setting datum not yet present into ``setting_data``.

    Axis setting data get a dict axis -> value; values already there are kept.
    """
    for definition in cat or catalog():
        if definition.kind != "sd":
            continue
        if definition.per_axis:
            slot = setting_data.get(definition.key)
            slot = dict(slot) if isinstance(slot, dict) else {}
            for axis in machine.axes:
                slot.setdefault(axis.name, copy.deepcopy(definition.default))
            setting_data[definition.key] = slot
        else:
            setting_data.setdefault(definition.key, copy.deepcopy(definition.default))


def unknown_machine_keys(machine: MachineConfig, cat: Catalog | None = None) -> list[str]:
    """Keys of a machine file's ``[md]`` table that the catalogue does not know."""
    cat = cat or catalog()
    return sorted(key for key in machine.md if cat.get(key) is None)


__all__ = [
    "ACTIVATION_TEXT", "Catalog", "DataDefinition", "DataError", "DataRef", "DataRow", "DataValueError",
    "LEVEL_FEWEST_RIGHTS", "MachineDataStore", "UnknownDataError", "WriteResult", "catalog",
    "fill_setting_defaults", "format_value", "number_of", "parse_ref", "unknown_machine_keys",
]
