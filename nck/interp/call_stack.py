"""Call frames (the levels of the call stack) and variable bindings of the interpreter.

A :class:`Frame` is one program level (main program or subprogram) with its
program counter and local variables. Variables are reached through bindings:
a :class:`~nck.lang.values.Cell` (own variable), or a reference used for
by-reference parameters (:class:`RRef` R parameter, :class:`ElemRef` array
element, :class:`GudRef` global user datum). :class:`VariableScope` is what
expressions use to read names; writes go through :func:`write_binding`, which
journals the old value so that a failing block can be undone.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Protocol

from nck.alarm_ids import (
    DATA_WRITE_PROTECTED, ILLEGAL_ARRAY_INDEX_1, NAME_NOT_DEFINED, OPERATION_DOES_NOT_FIT_TYPE,
)
from nck.errors import NcAlarmError
from nck.interp import sysvars
from nck.interp.program import Program
from nck.lang.values import Axis, Cell, convert, to_number
from nck.ncdata import NcData

@dataclass
class RRef:
    """By-reference binding to an R parameter."""

    index: int


@dataclass
class ElemRef:
    """By-reference binding to one element of an array variable."""

    cell: Cell
    indices: tuple[Any, ...]


@dataclass
class GudRef:
    """By-reference binding to a global user variable stored in NcData.gud."""

    name: str


Binding = Cell | RRef | ElemRef | GudRef


@dataclass
class Frame:
    """One program level on the call stack."""

    program: Program
    pc: int = 0
    locals: dict[str, Binding] = field(default_factory=dict)
    params: dict[str, Binding] = field(default_factory=dict)
    passes_left: int = 0
    def_open: bool = True
    for_ends: dict[int, Any] = field(default_factory=dict)
    lud_bytes: int = 0  # variable memory of this level's DEFs (MD28040 budget over the call stack)
    is_main: bool = False
    saved_gcodes: dict[int, str] | None = None  # PROC … SAVE: G groups restored at the return
    saved_pframe: Any = None  # PROC … SAVE: the programmable frame restored at the return
    single_block_off: bool = False  # SBLOF active at this level (inherited by calls)
    display_off: bool = False  # DISPLOF: blocks of this level are not displayed
    modal_call: Any = None  # MCALL: the ast.Call made after every motion block of this level
    given_params: tuple[bool, ...] = ()  # $P_SUBPAR: which PROC parameters the call programmed
    iso_macro: Any = None  # ISO G65/G66: the $C_… arguments of this level (nck.iso.macros)
    # active REPEAT sections: (last line index, first line index, passes left, return index)
    repeats: list[tuple[int, int, int, int]] = field(default_factory=list)


class VariableHost(Protocol):
    """What variable access needs of the interpreter."""

    data: NcData
    access_level: Callable[[], int]
    """The protection level the program runs with (GUD access rights)."""
    undo_journal: list[tuple[str, Any, Any]]
    """Old values of the current block's writes (undone if the block fails)."""

    def lookup(self, name: str) -> Binding | None:
        """The binding of a variable name at the current level (None: not a variable)."""

    def is_axis(self, name: str) -> bool:
        """True if ``name`` is an axis of the channel."""

    def r_index(self, index: Any) -> int:
        """A valid R parameter index (alarm otherwise)."""

    def write_r(self, index: Any, value: Any) -> None:
        """Write an R parameter (journaled)."""

    def write_gud(self, name: str, value: Any) -> None:
        """Write a global user datum (journaled)."""


class VariableScope:
    """Variable access for expressions (see :class:`nck.interp.evaluator.Scope`)."""

    __slots__ = ("interp",)

    def __init__(self, interp: VariableHost) -> None:
        self.interp = interp

    def read_r(self, index: Any) -> float:
        return self.interp.data.r[self.interp.r_index(index)]

    def read_name(self, name: str) -> Any:
        interp = self.interp
        binding = interp.lookup(name)
        if binding is not None:
            return read_binding(interp, binding, ())
        if name.startswith("$"):
            return sysvars.read(interp, name, ())  # type: ignore[arg-type]
        if interp.is_axis(name):
            return Axis(name)
        raise NcAlarmError(NAME_NOT_DEFINED, name)

    def read_index(self, name: str, indices: tuple[Any, ...]) -> Any:
        interp = self.interp
        if name == "R":
            if len(indices) != 1:
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "R")
            return self.read_r(indices[0])
        binding = interp.lookup(name)
        if binding is not None:
            return read_binding(interp, binding, indices)
        if name.startswith("$"):
            return sysvars.read(interp, name, indices)  # type: ignore[arg-type]
        raise NcAlarmError(NAME_NOT_DEFINED, name)

    def is_axis(self, name: str) -> bool:
        return self.interp.is_axis(name)

    def has_name(self, name: str) -> bool:
        return self.interp.lookup(name) is not None


def journal_cell(interp: VariableHost, cell: Cell, indices: tuple[Any, ...]) -> None:
    """Record the old value of a variable (or one array element) before a write."""
    if cell.dims:
        offset = cell.offset(indices)
        interp.undo_journal.append(("cell", (cell, offset), cell.value[offset]))
    else:
        interp.undo_journal.append(("cell", (cell, None), cell.value))


def read_binding(interp: VariableHost, binding: Binding, indices: tuple[Any, ...]) -> Any:
    """Read through a variable binding."""
    if isinstance(binding, Cell):
        if binding.dims and not indices:
            raise NcAlarmError(OPERATION_DOES_NOT_FIT_TYPE, binding.name)
        return binding.get(indices)
    if isinstance(binding, RRef):
        if indices:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, f"R{binding.index}")
        return interp.data.r[binding.index]
    if isinstance(binding, ElemRef):
        if indices:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.cell.name)
        return binding.cell.get(binding.indices)
    check_gud_access(interp, binding.name, "read")
    value = interp.data.gud[binding.name]
    if isinstance(value, list):
        if len(indices) != 1:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
        i = int(to_number(indices[0], binding.name))
        if not 0 <= i < len(value):
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
        return value[i]
    if indices:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
    return value


def write_binding(interp: VariableHost, binding: Binding, indices: tuple[Any, ...], value: Any) -> None:
    """Write through a variable binding (converted to the variable's type)."""
    if isinstance(binding, Cell):
        if binding.dims and not indices:
            raise NcAlarmError(OPERATION_DOES_NOT_FIT_TYPE, binding.name)
        journal_cell(interp, binding, indices)
        binding.set(value, indices)
        return
    if isinstance(binding, RRef):
        if indices:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, f"R{binding.index}")
        interp.write_r(binding.index, value)
        return
    if isinstance(binding, ElemRef):
        if indices:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.cell.name)
        journal_cell(interp, binding.cell, binding.indices)
        binding.cell.set(value, binding.indices)
        return
    check_gud_access(interp, binding.name, "write")
    current = interp.data.gud[binding.name]
    if isinstance(current, list):
        if len(indices) != 1:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
        i = int(to_number(indices[0], binding.name))
        if not 0 <= i < len(current):
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
        new = list(current)
        new[i] = _like(current[i], value, binding.name)
        interp.write_gud(binding.name, new)
    else:
        if indices:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, binding.name)
        interp.write_gud(binding.name, _like(current, value, binding.name))


def check_gud_access(interp: VariableHost, name: str, kind: str) -> None:
    """A GUD protected by APRP/APWP (004 L428-429) may be read/written by a part program only
    when the protection level it runs with is that level or one with more rights: else 17070.
    (The manuals name no separate alarm for a read-protected variable; 17070 says "read".)"""
    needed = interp.data.gud_access.get(name, {}).get(kind)
    if needed is not None and interp.access_level() > needed:
        raise NcAlarmError(DATA_WRITE_PROTECTED, name if kind == "write" else f"{name} (read)")


def _like(current: Any, value: Any, name: str) -> Any:
    if isinstance(current, bool):
        return convert(value, "BOOL", name)
    if isinstance(current, int):
        return convert(value, "INT", name)
    if isinstance(current, float):
        return convert(value, "REAL", name)
    if isinstance(current, str):
        return convert(value, "STRING", name)
    return value
