"""Writes of retained NC data through operator commands, with protection levels (a mixin).

Mixed into :class:`nck.kernel.Nck` through :class:`nck.kernel_settings.ControlSettings`.
The Parameter and Setup areas change data only through ``WriteData``, which
goes through the one write path :class:`nck.writes.DataWriter` (names, checks
and limits are described there); the other commands here are
``DeleteToolEdge``, ``ClearRParameters``, ``ChangePassword`` and
``ActivateMachineData`` (NEW CONFIG).

Protection applies when the kernel has an access control (given at construction
— the HMI and the CLI on a data directory — or created by a password entry). A
bare kernel (unit tests) is a commissioning bench without protection.

RESET and NEW CONFIG bring stored machine data into effect (:meth:`_activate_data`):
the kernel then adopts the store's active machine, rebuilding its interpreters
and its motion system (positions and reference state are kept).
"""

from __future__ import annotations

from typing import Any

from nck import commands as cmd
from nck.access import AccessDenied, AccessError, Action
from nck.commands import Accepted, Rejected, SubmitResult
from nck.machine import MachineConfig
from nck.machine_data import DataError, MachineDataStore
from nck.writes import DataWriter, WriteRefused


class DataWrites:
    """NC data writes, protection checks and machine-data activation; mixed into ``Nck``."""

    md_store: MachineDataStore | None = None
    """The machine/setting data store (the session's; created on first use when None)."""
    machine: MachineConfig
    """The active machine (set by ``Nck``; replaced when stored machine data come into effect)."""
    motion: Any
    """The motion system (set by ``Nck``; rebuilt for a new machine)."""

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

    def data_writer(self) -> DataWriter:
        """The one write path on this kernel's NC data, checked at the current access level."""
        return DataWriter(self.data, self.machine_data, self._access)  # type: ignore[attr-defined]

    def required_level(self, name: str) -> int:
        """The protection level writing the datum ``name`` needs (7 when unprotected)."""
        if not self.protected:
            return 7
        return self.data_writer().required_level(name)

    # ---------------------------------------------------------------- writes
    def _write_nc_datum(self, command: cmd.WriteData) -> SubmitResult | None:
        """Handle a ``WriteData`` of NC data; None leaves it to the kernel's own cases (counters)."""
        writer = self.data_writer()
        if not writer.handles(command.name):
            return None
        try:
            written = writer.write(command.name, command.value)
        except AccessError as error:
            return Rejected(str(error))
        except (WriteRefused, DataError) as error:
            return Rejected(str(error) or f"bad value for {command.name}")
        result = written.md
        if result is not None and result.active_now and result.ref.definition.kind == "md" \
                and result.ref.definition.scope != "display":
            self._adopt_active_machine()
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
        if command.tool == getattr(self, "_tool", 0) and self.channel.situation.channel != "reset":  # type: ignore[attr-defined]
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
        if self.channel.situation.channel != "reset":  # type: ignore[attr-defined]
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
        if self.channel.situation.channel != "reset":  # type: ignore[attr-defined]
            return  # a stopped program keeps its data; the RESET that ends it adopts the new one
        machine = self.machine_data.active_machine()
        if machine.md == self.machine.md:  # type: ignore[attr-defined]
            return
        motion = self.motion  # type: ignore[attr-defined]
        planned = motion.__class__.__name__ == "PlannedMotion"
        if planned and not motion.is_idle():
            return  # axes in motion keep their data; the next RESET / NEW CONFIG adopts it
        self.machine = machine
        self.interpreters.renew(self.outputs)  # type: ignore[attr-defined]
        if not planned:
            return  # the stand-in motion has no machine values
        positions = dict(motion.positions_mcs())
        referenced = {name: motion.is_referenced(name) for name in self.machine.path_axes}
        fresh = type(motion)(machine, positions, setting_data=self.data.setting_data)  # type: ignore[attr-defined]
        for name, done in referenced.items():
            fresh.set_referenced(name, done)
        self.motion = fresh
        self._apply_overrides()  # type: ignore[attr-defined]


__all__ = ["DataWrites"]
