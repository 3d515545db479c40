"""System variables (``$…``) that part programs can read and write.

Supported now:

* ``$AA_IM[ax]``, ``$AA_IW[ax]`` — actual machine / workpiece position of an axis
  (from the position source the channel installs; the programmed position otherwise);
* ``$AA_MM[ax]``, ``$AA_MW[ax]``, ``$AC_MEA[1]`` — the probe's trigger position (MCS / WCS)
  and status of the last ``MEAS``/``MEAW`` block (from the kernel, ``nck.kernel_contact``);
* ``$P_EP[ax]`` programmed end point, ``$P_F`` feed, ``$P_S`` spindle speed, ``$P_SDIR``
  programmed direction of the master spindle (3 = M3, 4 = M4, 5 = stopped: M5 or SPOS, 002
  L53786 names it among the spindle variables; the values are the M numbers, our reading),
  ``$P_TOOLNO`` active tool, ``$P_TOOL`` active edge, ``$P_GG[g]`` position of the
  active G code in group g, ``$P_AXN1..3`` geometry axes, ``$P_SEARCH``,
  ``$P_ISTEST``, ``$P_DRYRUN``, ``$P_STACK`` program level, ``$P_PROG`` program name;
* ``$TC_DP<n>[t,d]`` tool edge parameters (read/write ``NcData.tools``; writing creates
  the edge);
* ``$MN_…``, ``$MC_…``, ``$MA_…[ax]``, ``$SN_``/``$SC_``/``$SA_`` — machine and setting
  data read from the machine configuration (``MD<number>`` keys), by identifier via the
  machine-data catalogue, else via :data:`FALLBACK_MD_NUMBERS`.
"""

from __future__ import annotations

import re
from typing import Any, Protocol

from nck.alarm_ids import (
    DATA_WRITE_PROTECTED, ILLEGAL_ARRAY_INDEX_1, ILLEGAL_ARRAY_INDEX_2, ILLEGAL_AXIS_INDEX, NAME_NOT_DEFINED,
)
from nck.errors import NcAlarmError
from nck.geometry import frame_vars
from nck.interp.modal import ModalState
from nck.lang.values import Axis, to_number
from nck.lang.dialect import Dialect, InterpreterContext
from nck.machine import MachineConfig
from nck.machine_data import catalog, number_of
from nck.ncdata import NcData
from nck.lang.gcodes import gtable

TOOL_PARAM_COUNT = 25

# Identifier → MD/SD number for the data programs read most often, used only when the
# machine-data catalogue (nck.machine_data) is not available.
FALLBACK_MD_NUMBERS = {
    "MM_NUM_R_PARAM": 28050,
    "LUD_EXTENDED_SCOPE": 11120,
    "MAX_AX_VELO": 32000,
    "JOG_VELO": 32020,
    "JOG_VELO_RAPID": 32010,
    "MAX_AX_ACCEL": 32300,
    "CTRLOUT_SEGMENT_NR": 30100,
    "IS_ROT_AX": 30300,
    "POS_LIMIT_PLUS": 36100,
    "POS_LIMIT_MINUS": 36110,
    "GCODE_RESET_VALUES": 20150,
    "TOOL_CHANGE_MODE": 22550,
    "AXCONF_MACHAX_NAME_TAB": 10000,
    "IPO_SYSCLOCK_TIME_RATIO": 10050,
    "IPO_CYCLE_TIME": 10071,
    "DRY_RUN_FEED": 42100,
    "JOG_CONT_MODE_LEVELTRIGGRD": 41050,
}


class SysContext(InterpreterContext, Protocol):
    """What the system variables need from the interpreter."""

    machine: MachineConfig
    dialect: Dialect
    data: NcData

    @property
    def modal(self) -> ModalState:
        """The modal state."""

    def actual_position(self, axis: str) -> float:
        """Actual machine position of ``axis`` (mm or degrees)."""

    def measurement(self, name: str, axis: str) -> float:
        """``$AA_MM[axis]`` / ``$AA_MW[axis]`` / ``$AC_MEA[1]`` of the last measuring block."""

    def program_level(self) -> int:
        """Current program level (main program = 1)."""

    def program_name(self) -> str:
        """Name of the program of the current level."""

    def flag(self, name: str) -> bool:
        """Program-control flags: ``search``, ``test``, ``dry_run``."""

    def parameter_given(self, number: int) -> bool | None:
        """``$P_SUBPAR[n]``: parameter ``n`` of the current PROC programmed in its call."""

    def write_setting_data(self, name: str, indices: tuple[Any, ...], value: Any) -> None:
        """Write a setting datum (``SC_WEAR_SIGN``) at the current protection level."""

    def write_tool(self, tool: int, edge: int, param: int, value: float) -> None:
        """Write one tool edge parameter (journaled)."""


_TC_DP = re.compile(r"^\$TC_DP(\d+)$")
_MD = re.compile(r"^\$\$?(M|S)(N|C|A)_(\w+)$")
_AXN = re.compile(r"^\$P_AXN([1-3])$")


def _axis_arg(ctx: SysContext, name: str, indices: tuple[Any, ...]) -> str:
    if len(indices) != 1:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    axis = indices[0]
    if not isinstance(axis, str) or axis not in ctx.machine.path_axes:
        raise NcAlarmError(ILLEGAL_AXIS_INDEX if not isinstance(axis, str) else NAME_NOT_DEFINED, name)
    return str(axis)


def read(ctx: SysContext, name: str, indices: tuple[Any, ...]) -> Any:
    """Read system variable ``name`` with evaluated ``indices``."""
    if name in frame_vars.NAMES:  # frames and $AA_IW (WCS through frames and tool length)
        return frame_vars.read(ctx, name, indices)
    dialect = ctx.dialect
    if dialect.reads_variable(name):  # ISO: $C_… macro arguments, H numbers, $P_EXTGG
        return dialect.read_variable(ctx, name, indices)
    modal = ctx.modal
    if name in ("$AA_IM", "$AA_IW", "$AA_IB"):
        axis = _axis_arg(ctx, name, indices)
        return float(ctx.actual_position(axis))
    if name in ("$AA_MM", "$AA_MW"):  # the probe's trigger position of MEAS/MEAW (MCS / WCS)
        axis = _axis_arg(ctx, name, indices)
        return float(ctx.measurement(name, axis))
    if name == "$AC_MEA":  # probe status of the last measuring block: 1 switched, 0 not
        number = to_number(indices[0], name) if len(indices) == 1 else 0
        if number != 1:  # one probe input
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        return float(ctx.measurement(name, ""))
    if name == "$P_EP":
        axis = _axis_arg(ctx, name, indices)
        return float(modal.position_wcs.get(axis, 0.0))
    if name == "$P_SUBPAR":  # was parameter n (1, 2, …) of this PROC programmed in the call?
        number = to_number(indices[0], name) if len(indices) == 1 else 0
        given = ctx.parameter_given(int(number)) if number == int(number) else None
        if given is None:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        return given
    if indices and name not in ("$P_GG", "$P_S", "$P_SDIR") and not _TC_DP.match(name) and not _MD.match(name):
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    if name == "$P_F":
        return float(modal.feed)
    if name == "$P_S":
        return float(modal.spindle_speed_rpm)
    if name == "$P_SDIR":
        return {"M3": 3, "M4": 4}.get(modal.spindle_state, 5)
    if name == "$P_TOOLNO":
        return int(modal.tool)
    if name == "$P_TOOL":
        return int(modal.edge)
    if name == "$P_GG":
        return _gg(ctx, indices)
    match = _AXN.match(name)
    if match:
        axes = ctx.machine.path_axes
        index = int(match.group(1)) - 1
        if index >= len(axes):
            raise NcAlarmError(NAME_NOT_DEFINED, name)
        return Axis(axes[index])
    if name == "$P_SEARCH":
        return ctx.flag("search")
    if name == "$P_ISTEST":
        return ctx.flag("test")
    if name == "$P_DRYRUN":
        return ctx.flag("dry_run")
    if name == "$P_STACK":
        return ctx.program_level()
    if name == "$P_PROG":
        return ctx.program_name()
    match = _TC_DP.match(name)
    if match:
        param, tool, edge = _tool_address(name, match, indices)
        found = ctx.data.edge(tool, edge)
        return float(found.get(param)) if found is not None else 0.0
    match = _MD.match(name)
    if match:
        return _machine_data(ctx, name, match, indices)
    raise NcAlarmError(NAME_NOT_DEFINED, name)


def write(ctx: SysContext, name: str, indices: tuple[Any, ...], value: Any) -> None:
    """Write system variable ``name``: frames, tool data, setting data, ISO internals."""
    if name in frame_vars.NAMES:  # $P_UIFR[n,ax,TR], $P_PFRAME[ax,RT], …
        frame_vars.write(ctx, name, indices, value)
        return
    dialect = ctx.dialect
    if dialect.writes_variable(name):  # ISO: $C_…, H numbers, $P_ISOFR_… frames
        dialect.write_variable(ctx, name, indices, value)
        return
    match = _TC_DP.match(name)
    if match:
        param, tool, edge = _tool_address(name, match, indices)
        number = float(to_number(value, name))
        ctx.write_tool(tool, edge, param, number)
        return
    md = _MD.match(name)
    if md and md.group(1) == "S":  # $SC_WEAR_SIGN = 1: setting data, at the program's level
        ctx.write_setting_data(name.lstrip("$"), indices, value)
        return
    if md or name.startswith("$P_") or name.startswith("$AA_"):
        raise NcAlarmError(DATA_WRITE_PROTECTED, name)
    raise NcAlarmError(NAME_NOT_DEFINED, name)


def _tool_address(name: str, match: re.Match, indices: tuple[Any, ...]) -> tuple[int, int, int]:
    param = int(match.group(1))
    if not 1 <= param <= TOOL_PARAM_COUNT:
        raise NcAlarmError(NAME_NOT_DEFINED, name)
    if len(indices) != 2:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    tool_raw, edge_raw = (to_number(i, name) for i in indices)
    tool, edge = int(tool_raw), int(edge_raw)
    if tool != tool_raw or tool < 1 or tool > 99_999_999:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    if edge != edge_raw or edge < 1 or edge > 12:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_2, name)
    return param, tool, edge


def _gg(ctx: SysContext, indices: tuple[Any, ...]) -> int:

    if len(indices) != 1:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "$P_GG")
    group_no = int(to_number(indices[0], "$P_GG"))
    table = gtable()
    group = table.groups.get(group_no)
    if group is None:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "$P_GG")
    code = ctx.modal.gcodes.get(group_no)
    return group.position(code) if code in group.members else 0


def md_number(identifier: str) -> int | None:
    """Number of an MD/SD identifier (``MAX_AX_VELO`` → 32000), or None."""
    found = number_of(identifier)  # the machine-data catalogue is the authority
    return found if found is not None else FALLBACK_MD_NUMBERS.get(identifier)


def _catalog_definition(name: str) -> Any:
    """The machine-data catalogue entry of ``$MC_…``-style names, or None."""
    return catalog().get("$" + name.lstrip("$"))


def _from_catalog(ctx: SysContext, name: str, definition: Any, indices: tuple[Any, ...]) -> Any:
    axis = None
    rest = list(indices)
    if definition.per_axis:
        if not rest or not isinstance(rest[-1], str):
            raise NcAlarmError(ILLEGAL_AXIS_INDEX, name)
        axis = str(rest.pop())
        if axis not in [a.name for a in ctx.machine.axes]:
            raise NcAlarmError(ILLEGAL_AXIS_INDEX, name)
    if any(isinstance(i, str) for i in rest) or len(rest) > 1:
        raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    index = int(to_number(rest[0], name)) if rest else None
    sources: list[Any] = [ctx.machine.md]
    if definition.kind == "sd":
        sources.insert(0, ctx.data.setting_data)
    value = definition.default
    for source in sources:
        if definition.key in source:
            candidate = source[definition.key]
            if isinstance(candidate, dict):
                if axis in candidate:
                    value = candidate[axis]
                    break
                continue
            value = candidate
            break
    if isinstance(value, dict):
        value = value.get(axis, definition.default)
    if isinstance(value, list):
        if index is None:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        if not 0 <= index < max(len(value), definition.array or 0):
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        return value[index] if index < len(value) else value[-1]
    if index is not None and definition.array:
        if not 0 <= index < definition.array:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
    return value


def _machine_data(ctx: SysContext, name: str, match: re.Match, indices: tuple[Any, ...]) -> Any:
    definition = _catalog_definition(name)
    if definition is not None:
        return _from_catalog(ctx, name, definition, indices)
    kind, scope, ident = match.groups()
    number = md_number(ident)
    prefix = "MD" if kind == "M" else "SD"
    keys = [ident, name.lstrip("$")]
    if number is not None:
        keys.insert(0, f"{prefix}{number}")
    axis = None
    index = None
    if scope == "A":
        if len(indices) != 1 or not isinstance(indices[0], str):
            raise NcAlarmError(ILLEGAL_AXIS_INDEX, name)
        axis = str(indices[0])
        if axis not in [a.name for a in ctx.machine.axes]:
            raise NcAlarmError(ILLEGAL_AXIS_INDEX, name)
    elif indices:
        if len(indices) != 1:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
        index = int(to_number(indices[0], name))
    for key in keys:
        if key in ctx.machine.md:
            value = ctx.machine.md_value(key, axis)
            if isinstance(value, list):
                if index is None or not 0 <= index < len(value):
                    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
                return value[index]
            if value is None:
                raise NcAlarmError(ILLEGAL_AXIS_INDEX, name)
            return value
    defaults = {28050: 100, 11120: 0, 22550: 0}  # catalogue defaults of data the file may omit
    if number in defaults and index is None:
        return defaults[number]
    raise NcAlarmError(NAME_NOT_DEFINED, name)
