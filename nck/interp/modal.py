"""Modal state of the channel as the interpreter sees it.

Everything here survives from block to block: the active member of every modal
G group, the programmed positions, feed, spindle, tool and edge. The motion
builder reads and updates it; :meth:`ModalState.reset` restores the reset
state (power on, RESET, M2/M30). Add fields freely (frames, units, planes …):
the interpreter snapshots the whole object before each block.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

from nck.lang.gcodes import GTable
from nck.machine import MachineConfig


_ATOMIC = frozenset({str, int, float, bool, type(None)})
_FLAT_DICTS = frozenset({"gcodes", "position_wcs", "position_mcs", "aux"})
"""Fields that hold only immutable values (G codes and aux values as text, positions as numbers)."""


@dataclass
class ModalState:
    """Modal values of one channel.

    Attributes:
        gcodes: modal G group number → active G code.
        position_wcs: last programmed end point of every path axis (program units, WCS).
        position_mcs: the same point in machine coordinates (mm).
        feed: programmed path feed F (0 = none programmed since reset).
        spindle_speed_rpm: programmed S of the master spindle.
        spindle_state: ``M3``, ``M4``, ``M5`` or ``M19``.
        spindle_position_deg: last programmed position of the master spindle (SPOS/M19),
            the reference of ``SPOS=IC(…)``.
        tool_selected: T programmed (preselected) but not yet changed in.
        tool: active tool (after the change, M6 or T with change mode 0).
        edge: active cutting edge D (0 = no offset).
        wear_sign: SD42930 as it was when the edge was selected (the wear is evaluated at the
            selection, 002 L62080-62083); None: not selected since power on, read SD42930.
        aux: last output value per aux address (``M``, ``H``), for display.
    """

    gcodes: dict[int, str] = field(default_factory=dict)
    position_wcs: dict[str, float] = field(default_factory=dict)
    position_mcs: dict[str, float] = field(default_factory=dict)
    feed: float = 0.0
    spindle_speed_rpm: float = 0.0
    spindle_state: str = "M5"
    spindle_position_deg: float = 0.0
    tool_selected: int = 0
    tool: int = 0
    edge: int = 0
    wear_sign: int | None = None
    aux: dict[str, str] = field(default_factory=dict)
    geometry: Any = None  # nck.geometry.path_state.GeometryState, created by the motion builder

    @classmethod
    def initial(cls, machine: MachineConfig, table: GTable) -> "ModalState":
        """The power-on state: reset G codes, every path axis at 0."""
        state = cls()
        state.gcodes = table.reset_state(reset_overrides(machine, table), machine.kind)
        for axis in machine.path_axes:
            state.position_wcs[axis] = 0.0
            state.position_mcs[axis] = 0.0
        return state

    def __deepcopy__(self, memo: dict) -> "ModalState":
        """The per-block snapshot, fast: dicts of plain values are copied flat.

        Equivalent to a generic deep copy: the G codes, positions and aux values are
        immutable (str, numbers), the other dicts are checked value by value, and anything
        else (the geometry state, added fields) is deep-copied as usual. The copy is made
        without ``copy.copy``'s pickling protocol (a plain dataclass: the same fields).
        """
        new = object.__new__(type(self))
        fields = new.__dict__
        fields.update(self.__dict__)
        for name, value in self.__dict__.items():
            kind = type(value)
            if kind in _ATOMIC:
                continue
            if kind is dict:
                if name in _FLAT_DICTS:
                    fields[name] = dict(value)
                else:
                    fields[name] = {key: item if type(item) in _ATOMIC else copy.deepcopy(item, memo)
                                    for key, item in value.items()}
            else:
                fields[name] = copy.deepcopy(value, memo)
        return new

    def reset(self, machine: MachineConfig, table: GTable) -> None:
        """RESET / program end: G groups to their reset members (those of MD20152 = 1 keep
        theirs), F deleted.

        Positions, the active tool/edge and the spindle are kept (they are
        physical states or are reset by the channel according to machine data).
        """
        keeps = kept_groups(machine)
        kept = {group: code for group, code in self.gcodes.items() if group in keeps}
        self.gcodes = table.reset_state(reset_overrides(machine, table), machine.kind)
        self.gcodes.update(kept)
        self.feed = 0.0
        self.tool_selected = self.tool
        if self.geometry is not None:
            self.geometry.reset()  # programmable frame, pole, RNDM; settable frame re-read


def kept_groups(machine: MachineConfig) -> frozenset[int]:
    """The G groups that keep their current code at RESET and program end: MD20152
    GCODE_RESET_MODE[group − 1] = 1 (0: back to the reset member of MD20150; 002 L2770-2782,
    L21518-21530). An array given as one value holds for every group."""
    values = machine.md.get("MD20152", 0)
    if isinstance(values, list):
        return frozenset(index + 1 for index, mode in enumerate(values) if mode == 1)
    return frozenset(range(1, 61)) if values == 1 else frozenset()


def reset_overrides(machine: MachineConfig, table: GTable) -> dict[int, str]:
    """Reset members from MD20150 GCODE_RESET_VALUES of the machine file, if given.

    The MD holds, per group (index = group − 1), the 1-based position of the
    reset member inside the group; 0 or a missing entry keeps the table default.
    """
    values = machine.md.get("MD20150")
    overrides: dict[int, str] = {}
    if isinstance(values, list):
        for index, position in enumerate(values):
            group = table.groups.get(index + 1)
            if group is None or not isinstance(position, int) or position <= 0:
                continue
            if position <= len(group.members) and group.members[position - 1]:
                overrides[group.number] = group.members[position - 1]
    return overrides
