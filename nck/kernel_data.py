"""Writes of retained NC data through operator commands, with protection levels (a mixin).

Mixed into :class:`nck.kernel.Nck` through :class:`nck.kernel_settings.ControlSettings`.
The Parameter and Setup areas change data only through these commands, so the
access level is checked in one place:

* ``WriteData`` with

  - ``R<n>`` — R parameter (level of ``write_r_parameter``);
  - ``$TC_DP<n>[t,d]`` — tool edge parameter; writing creates the edge
    (tool geometry or wear level, see :func:`nck.access.action_for_write`);
  - ``$P_UIFR[n,axis,comp]`` — settable frame n (1…4 = G54…G57, 5… = G505…),
    ``$P_UBFR[axis,comp]`` — base frame; ``comp`` TR, FI, RT, SC or MI
    (active at the next selection of the frame, as on the control);
  - ``GUD:<name>`` / ``GUD:<name>[i]`` — a global user variable that exists (its
    type is kept);
  - ``MD…`` / ``$M…`` / ``SD…`` / ``$S…`` — machine and setting data through
    :class:`nck.machine_data.MachineDataStore` (level, type and limit checks;
    activation po/re/cf/so);
* ``DeleteToolEdge``, ``ClearRParameters``, ``ChangePassword``,
  ``ActivateMachineData`` (NEW CONFIG).

Protection applies when the kernel has an access control (given at construction
— the HMI and the CLI on a data directory — or created by a password entry). A
bare kernel (unit tests, headless runs without a data directory) is a
commissioning bench without protection.

RESET and NEW CONFIG bring stored machine data into effect (:meth:`_activate_data`):
the kernel then adopts the store's active machine, rebuilding its interpreters
and its motion system (positions and reference state are kept).
"""

from __future__ import annotations

import math
import re
from typing import Any

from nck import commands as cmd
from nck.access import AccessDenied, AccessError, Action, action_for_write
from nck.commands import Accepted, Rejected, SubmitResult
from nck.machine_data import DataError, MachineDataStore
from nck.ncdata import ToolEdge, WorkOffset

TOOL_PARAM_COUNT = 25
TOOL_VALUE_LIMIT_MM = 100_000.0
FRAME_TRANSLATION_LIMIT_MM = 100_000.0
FRAME_COMPONENTS = ("TR", "FI", "RT", "SC", "MI")
_TC_DP = re.compile(r"^\$TC_DP(\d+)\[\s*(\d+)\s*,\s*(\d+)\s*\]$")
_UIFR = re.compile(r"^\$P_UIFR\[\s*(\d+)\s*,\s*([A-Z][A-Z0-9]*)\s*,\s*([A-Z]{2})\s*\]$")
_UBFR = re.compile(r"^\$P_UBFR\[\s*([A-Z][A-Z0-9]*)\s*,\s*([A-Z]{2})\s*\]$")
_GUD = re.compile(r"^GUD:([A-Z_][A-Z0-9_]*)(?:\[\s*(\d+)\s*\])?$")


def settable_frame_name(index: int) -> str:
    """The frame name of ``$P_UIFR[index]``: 1…4 → G54…G57, 5…99 → G505…G599."""
    if 1 <= index <= 4:
        return f"G{53 + index}"
    if 5 <= index <= 99:
        return f"G{500 + index}"
    raise ValueError(f"settable frame index {index} does not exist (1 … 99)")


def settable_frame_index(name: str) -> int:
    """Inverse of :func:`settable_frame_name` (``G54`` → 1, ``G505`` → 5)."""
    number = int(name.upper().lstrip("G"))
    return number - 53 if 54 <= number <= 57 else number - 500


def _finite(value: Any, what: str) -> float:
    if isinstance(value, bool):
        raise ValueError(f"{what}: a number is needed")
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(f"{what}: a finite number is needed")
    return number


class DataWrites:
    """NC data writes, protection checks and machine-data activation; mixed into ``Nck``."""

    md_store: MachineDataStore | None = None
    """The machine/setting data store (the session's; created on first use when None)."""

    # ---------------------------------------------------------------- access
    @property
    def machine_data(self) -> MachineDataStore:
        """The MD/SD store of this kernel (read it for the MD lists; write via ``WriteData``)."""
        if self.md_store is None:
            self.md_store = MachineDataStore(self.machine, {}, self.data.setting_data)  # type: ignore[attr-defined]
        return self.md_store

    @property
    def protected(self) -> bool:
        """True when writes are checked against the access level."""
        return self._access is not None  # type: ignore[attr-defined]

    def _write_level(self) -> int:
        return self._access_level() if self.protected else 0  # type: ignore[attr-defined]

    def _require(self, action: Action, what: str | None = None) -> None:
        if self.protected:
            self._access.require(action, what)  # type: ignore[attr-defined]

    @property
    def access_state(self) -> Any:
        """Keyswitch position and password state (``nck.access.AccessState``), None when unprotected."""
        return self._access.state if self.protected else None  # type: ignore[attr-defined]

    def action_level(self, action: Action | str) -> int:
        """The protection level ``action`` (an Action or its name, ``"READ_TOOL"``) needs;
        7 when unprotected. Creates nothing."""
        if isinstance(action, str):
            action = Action[action.strip().upper()]
        return self._access.required(action) if self.protected else 7  # type: ignore[attr-defined]

    def required_level(self, name: str) -> int:
        """The protection level writing the datum ``name`` needs (7 when unprotected)."""
        if not self.protected:
            return 7
        upper = name.strip().upper()
        try:
            if upper.startswith(("MD", "SD", "$M", "$S")):
                return self.machine_data.required_write_level(upper)
        except DataError:
            return 7
        if upper.startswith("GUD:"):
            action: Action | None = Action.WRITE_USER_DATA
        elif upper.startswith("$P_UBFR"):
            action = Action.WRITE_WORK_OFFSET
        else:
            action = action_for_write(upper)
        if action is None:
            return 7
        return self.access.required(action)  # type: ignore[attr-defined]

    # ---------------------------------------------------------------- writes
    def _write_nc_datum(self, command: cmd.WriteData) -> SubmitResult | None:
        """Handle a ``WriteData``; None leaves it to the kernel's own cases (R, counters)."""
        name = command.name.strip().upper()
        try:
            if self.protected:
                if name.startswith("$P_UBFR"):
                    self._require(Action.WRITE_WORK_OFFSET, f"Writing the base frame ({name})")
                elif name.startswith("GUD:"):
                    self._require(Action.WRITE_USER_DATA, f"Writing user variables ({name[4:]})")
                else:
                    self._access.require_write(name)  # type: ignore[attr-defined]
            if name.startswith(("MD", "SD", "$M", "$S")):
                return self._write_machine_datum(name, command.value)
            match = _TC_DP.match(name)
            if match:
                return self._write_tool(int(match[2]), int(match[3]), int(match[1]), command.value)
            match = _UIFR.match(name)
            if match:
                frame = settable_frame_name(int(match[1]))
                return self._write_frame(self.data.settable_frame(frame), match[2], match[3],  # type: ignore[attr-defined]
                                         command.value)
            match = _UBFR.match(name)
            if match:
                return self._write_frame(self.data.base_frame, match[1], match[2], command.value)  # type: ignore[attr-defined]
            match = _GUD.match(name)
            if match:
                return self._write_gud(match[1], None if match[2] is None else int(match[2]), command.value)
        except AccessError as error:
            return Rejected(str(error))
        except (TypeError, ValueError, DataError) as error:
            return Rejected(str(error) or f"bad value for {command.name}")
        return None

    def _write_machine_datum(self, name: str, value: Any) -> SubmitResult:
        result = self.machine_data.write(name, value, level=self._write_level())
        definition = result.ref.definition
        if result.active_now and definition.kind == "md" and definition.scope != "display":
            self._adopt_active_machine()
        return Accepted()

    def _write_tool(self, tool: int, edge: int, param: int, value: Any) -> SubmitResult:
        if not 1 <= param <= TOOL_PARAM_COUNT:
            return Rejected(f"$TC_DP{param} does not exist (1 … {TOOL_PARAM_COUNT})")
        if not 1 <= tool <= 99_999_999:
            return Rejected(f"tool number {tool} outside 1 … 99999999")
        if not 1 <= edge <= 12:
            return Rejected(f"cutting edge D{edge} outside 1 … 12")
        number = _finite(value, f"$TC_DP{param}")
        if param in (1, 2) and not number.is_integer():
            return Rejected(f"$TC_DP{param} ({'tool type' if param == 1 else 'edge position'}) is a whole number")
        if param == 1 and not 0 <= number <= 999:
            return Rejected("tool type outside 0 … 999")
        if param == 2 and not 0 <= number <= 9:
            return Rejected("cutting edge position outside 0 … 9")
        if abs(number) > TOOL_VALUE_LIMIT_MM:
            return Rejected(f"$TC_DP{param} outside ±{TOOL_VALUE_LIMIT_MM:g}")
        tools = self.data.tools  # type: ignore[attr-defined]
        edge_data = tools.get((tool, edge))
        if edge_data is None:
            edge_data = ToolEdge()
            if edge > 1 and (tool, 1) in tools:
                edge_data.params[1] = tools[(tool, 1)].get(1)  # a new edge of a tool keeps its type
            tools[(tool, edge)] = edge_data
        edge_data.params[param] = number
        return Accepted()

    def _write_frame(self, offset: WorkOffset, axis: str, comp: str, value: Any) -> SubmitResult:
        axes = [a.name for a in self.machine.axes if a.kind != "spindle"]  # type: ignore[attr-defined]
        if axis not in axes:
            return Rejected(f"the machine has no axis {axis}")
        if comp not in FRAME_COMPONENTS:
            return Rejected(f"frame component {comp} does not exist (TR FI RT SC MI)")
        number = _finite(value, f"{axis} {comp}")
        if comp in ("TR", "FI") and abs(number) > FRAME_TRANSLATION_LIMIT_MM:
            return Rejected(f"translation outside ±{FRAME_TRANSLATION_LIMIT_MM:g} mm")
        if comp == "RT" and not -360.0 <= number <= 360.0:
            return Rejected("rotation outside -360 … 360 degrees")
        if comp == "SC" and (number <= 0.0 or number > 1000.0):
            return Rejected("scale factor outside 0 … 1000 (0 not allowed)")
        if comp == "MI" and number not in (0.0, 1.0):
            return Rejected("mirror is 0 or 1")
        if comp == "FI":
            self._require(Action.WRITE_FINE_OFFSET)
        table = {"TR": offset.trans, "FI": offset.fine, "RT": offset.rot, "SC": offset.scale}
        if comp == "MI":
            offset.mirror[axis] = bool(number)
        else:
            table[comp][axis] = number
        return Accepted()

    def _write_gud(self, name: str, index: int | None, value: Any) -> SubmitResult:
        gud = self.data.gud  # type: ignore[attr-defined]
        if name not in gud:
            return Rejected(f"user variable {name} is not defined")
        current = gud[name]
        if isinstance(current, list):
            if index is None or not 0 <= index < len(current):
                return Rejected(f"{name} is an array of {len(current)}: name the element")
            items = list(current)
            items[index] = _like(items[index], value, name)
            gud[name] = items
        else:
            if index is not None:
                return Rejected(f"{name} is not an array")
            gud[name] = _like(current, value, name)
        return Accepted()

    # -------------------------------------------------------------- commands
    def _delete_tool_edge(self, command: cmd.DeleteToolEdge) -> SubmitResult:
        try:
            self._require(Action.WRITE_TOOL_GEOMETRY, "Deleting tool data")
        except AccessError as error:
            return Rejected(str(error))
        tools = self.data.tools  # type: ignore[attr-defined]
        keys = [k for k in tools if k[0] == command.tool and (command.edge is None or k[1] == command.edge)]
        if not keys:
            what = f"T{command.tool}" + (f" D{command.edge}" if command.edge is not None else "")
            return Rejected(f"{what} does not exist")
        if command.tool == getattr(self, "_tool", 0) and self._sit.channel != "reset":  # type: ignore[attr-defined]
            return Rejected(f"T{command.tool} is the active tool of a running program")
        for key in keys:
            del tools[key]
        return Accepted()

    def _clear_r_parameters(self, command: cmd.ClearRParameters) -> SubmitResult:
        try:
            self._require(Action.CLEAR_R_PARAMETERS)
        except AccessError as error:
            return Rejected(str(error))
        r = self.data.r  # type: ignore[attr-defined]
        r[:] = [0.0] * len(r)
        return Accepted()

    def _change_password(self, command: cmd.ChangePassword) -> SubmitResult:
        try:
            self.access.change_password(command.level, command.password)  # type: ignore[attr-defined]
        except AccessDenied as error:
            return Rejected(str(error))
        except AccessError as error:
            return Rejected(str(error) or "Password not accepted")
        return Accepted()

    def _activate_machine_data(self, command: cmd.ActivateMachineData) -> SubmitResult:
        if self._sit.channel != "reset":  # type: ignore[attr-defined]
            return Rejected("Set MD active is possible only in channel reset")
        self._activate_data("new_config")
        return Accepted()

    # ------------------------------------------------------------ activation
    def _activate_data(self, event: str) -> list[str]:
        """Bring stored MD into effect for ``event`` (``reset`` / ``new_config``)."""
        if self.md_store is None:
            return []
        changed = self.md_store.activate(event)
        self._adopt_active_machine()  # also picks up values a moving axis deferred
        return changed

    def _adopt_active_machine(self) -> None:
        """Use the store's active machine: new interpreters, a motion system with its values.

        Only in channel reset with the axes at rest; otherwise the next RESET / NEW CONFIG does it.
        """
        if self._sit.channel != "reset":  # type: ignore[attr-defined]
            return  # a stopped program keeps its data; the RESET that ends it adopts the new one
        machine = self.machine_data.active_machine()
        if machine.md == self.machine.md:  # type: ignore[attr-defined]
            return
        motion = self.motion  # type: ignore[attr-defined]
        planned = motion.__class__.__name__ == "PlannedMotion"
        if planned and not motion.is_idle():
            return  # axes in motion keep their data; the next RESET / NEW CONFIG adopts it
        self.machine = machine
        self._interpreters.clear()  # type: ignore[attr-defined]
        if not planned:
            return  # the stand-in motion has no machine values
        positions = dict(motion.positions_mcs())
        referenced = {name: motion.is_referenced(name) for name in self.machine.path_axes}
        fresh = type(motion)(machine, positions, setting_data=self.data.setting_data)  # type: ignore[attr-defined]
        for name, done in referenced.items():
            fresh.set_referenced(name, done)
        self.motion = fresh
        self._apply_overrides()  # type: ignore[attr-defined]


def _like(current: Any, value: Any, name: str) -> Any:
    """``value`` converted to the type of ``current`` (a GUD keeps its type)."""
    if isinstance(current, bool):
        if isinstance(value, str):
            text = value.strip().upper()
            if text in ("TRUE", "1"):
                return True
            if text in ("FALSE", "0"):
                return False
            raise ValueError(f"{name} is BOOL: TRUE or FALSE")
        return bool(value)
    if isinstance(current, int):
        number = _finite(value, name)
        if not number.is_integer():
            raise ValueError(f"{name} is INT: a whole number is needed")
        return int(number)
    if isinstance(current, float):
        return _finite(value, name)
    if isinstance(current, str):
        return str(value)
    raise ValueError(f"{name} cannot be written here")


__all__ = ["DataWrites", "settable_frame_index", "settable_frame_name"]
