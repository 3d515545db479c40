"""Writes of retained NC data through operator commands, a part of :class:`nck.kernel.Nck`.

The Parameter and Setup areas change data only through ``WriteData``, which goes through the
one write path :class:`nck.writes.DataWriter` (names, checks and limits are described there);
the part counters ``$AC_…_PARTS`` are written here. The other commands are
``DeleteToolEdge``, ``ClearRParameters`` and ``ActivateMachineData`` (NEW CONFIG).

Protection applies when the kernel has an access control (:mod:`nck.kernel_access`).

RESET and NEW CONFIG bring stored machine data into effect (:meth:`DataWrites.activate_data`):
the kernel then adopts the store's active machine, rebuilding its interpreters and its motion
system (positions and reference state are kept).
"""

from __future__ import annotations

from typing import Callable

from nck import commands as cmd
from nck.access import AccessError, Action, action_for_write
from nck.channel import RESET
from nck.channel_state import ChannelState, MachineOutputs, MachinePlant
from nck.commands import Accepted, SubmitResult
from nck.counters import PartCounters
from nck.kernel_access import Protection
from nck.kernel_interpreters import ChannelInterpreters
from nck.kernel_setup import JobSetup
from nck.machine_data import DataError, MachineDataStore
from nck.ncdata import NcData
from nck.refusals import refuse, rejected_by
from nck.value_text import InvalidValue, number_from_text
from nck.writes import DataWriter, WriteRefused

PART_COUNTER_FIELDS = {"$AC_TOTAL_PARTS": "total", "$AC_ACTUAL_PARTS": "actual",
                       "$AC_SPECIAL_PARTS": "special", "$AC_REQUIRED_PARTS": "required"}
PART_COUNTER_MAX = 999_999_999


class DataWrites:
    """NC data writes, protection checks and machine-data activation on the parts it is given."""

    def __init__(self, plant: MachinePlant, data: NcData, channel: ChannelState, outputs: MachineOutputs,
                 interpreters: ChannelInterpreters, protection: Protection, counters: PartCounters,
                 setup: JobSetup, motion_renewed: Callable[[], None]) -> None:
        self.plant = plant  # the active machine and motion (replaced when stored MD come into effect)
        self.data = data
        self.channel = channel
        self.outputs = outputs  # the active tool (not deleted while a program runs)
        self.interpreters = interpreters  # renewed for a new machine
        self.protection = protection  # the access level writes are checked against
        self.counters = counters  # $AC_…_PARTS
        self.setup = setup  # activates edited work offsets (MD9440)
        self.motion_renewed = motion_renewed  # a new motion system gets the override and dry-run switches
        self.md_store: MachineDataStore | None = None
        """The machine/setting data store (the session's; created on first use when None)."""

    # ---------------------------------------------------------------- reading
    @property
    def machine_data(self) -> MachineDataStore:
        """The MD/SD store of this kernel (read it for the MD lists; write via ``WriteData``)."""
        if self.md_store is None:
            self.md_store = MachineDataStore(self.plant.machine, {}, self.data.setting_data)
        return self.md_store

    def data_writer(self) -> DataWriter:
        """The one write path on this kernel's NC data, checked at the current access level."""
        return DataWriter(self.data, self.machine_data, self.protection.control)

    def required_level(self, name: str) -> int:
        """The protection level writing the datum ``name`` needs (7 when unprotected)."""
        if not self.protection.protected:
            return 7
        return self.data_writer().required_level(name)

    # -------------------------------------------------------------- commands
    def write_data(self, command: cmd.WriteData) -> SubmitResult:
        """Write one datum: NC data through the one write path, else a part counter."""
        handled = self._write_nc_datum(command)  # protection, MD/SD, tools, frames, GUD
        if handled is not None:
            if isinstance(handled, Accepted) and (action_for_write(command.name) == Action.WRITE_WORK_OFFSET
                                                  or command.name.strip().upper().startswith("$P_UBFR")):
                self._work_offset_edited()
            return handled
        name = command.name.strip().upper()
        if name not in PART_COUNTER_FIELDS:
            return refuse("not_writable_here", name=command.name)
        try:
            value = int(number_from_text(command.value, name, whole=True))
        except InvalidValue as refusal:
            return rejected_by(refusal)
        if not 0 <= value <= PART_COUNTER_MAX:
            return refuse("part_counter_range", max=PART_COUNTER_MAX)
        setattr(self.counters, PART_COUNTER_FIELDS[name], value)
        return Accepted()

    def _write_nc_datum(self, command: cmd.WriteData) -> SubmitResult | None:
        """Handle a ``WriteData`` of NC data; None leaves it to the part counters."""
        writer = self.data_writer()
        if not writer.handles(command.name):
            return None
        try:
            written = writer.write(command.name, command.value)
        except (AccessError, WriteRefused, DataError) as error:
            return rejected_by(error)
        result = written.md
        if result is not None and result.active_now and result.ref.definition.kind == "md" \
                and result.ref.definition.scope != "display":
            self._adopt_active_machine()
        return Accepted()

    def delete_tool_edge(self, command: cmd.DeleteToolEdge) -> SubmitResult:
        """Delete a tool's edge (or all its edges); not the active tool of a running program."""
        try:
            self.protection.require(Action.WRITE_TOOL_GEOMETRY)
        except AccessError as error:
            return rejected_by(error)
        tools = self.data.tools
        keys = [k for k in tools if k[0] == command.tool and (command.edge is None or k[1] == command.edge)]
        if not keys:
            what = f"T{command.tool}" + (f" D{command.edge}" if command.edge is not None else "")
            return refuse("tool_missing", tool=what)
        if command.tool == self.outputs.tool and self.channel.situation.channel != RESET:
            return refuse("tool_in_use", tool=f"T{command.tool}")
        for key in keys:
            del tools[key]
        return Accepted()

    def clear_r_parameters(self, command: cmd.ClearRParameters) -> SubmitResult:
        """Set every R parameter to 0."""
        try:
            self.protection.require(Action.CLEAR_R_PARAMETERS)
        except AccessError as error:
            return rejected_by(error)
        r = self.data.r
        r[:] = [0.0] * len(r)
        return Accepted()

    def activate_machine_data(self, command: cmd.ActivateMachineData) -> SubmitResult:
        """NEW CONFIG: stored machine data of activation ``cf`` take effect (channel reset only)."""
        if self.channel.situation.channel != RESET:
            return refuse("md_active_needs_reset")
        self.activate_data("new_config")
        return Accepted()

    # ------------------------------------------------------------ work offsets
    def _work_offset_edited(self) -> None:
        """An edited work offset stays inactive until the program selects it again, RESET or
        program start; with MD9440 = 1 it is active at once in RESET and from the next NC
        START when entered while the program is stopped (002 L28128-28137, L31541-31546)."""
        if not int(self.machine_data.active_value("MD9440") or 0):
            return
        if self.channel.situation.channel == RESET:
            self.setup.activate_stored_frames()
        else:
            self.channel.offsets_edited = True

    def apply_offset_edits(self) -> None:
        """NC START: offsets edited while stopped under MD9440 = 1 become active."""
        if self.channel.offsets_edited:
            self.channel.offsets_edited = False
            self.setup.activate_stored_frames()

    # ------------------------------------------------------------ activation
    def activate_data(self, event: str) -> list[str]:
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
        if self.channel.situation.channel != RESET:
            return  # a stopped program keeps its data; the RESET that ends it adopts the new one
        machine = self.machine_data.active_machine()
        if machine.md == self.plant.machine.md:
            return
        motion = self.plant.motion
        planned = motion.__class__.__name__ == "PlannedMotion"
        if planned and not motion.is_idle():
            return  # axes in motion keep their data; the next RESET / NEW CONFIG adopts it
        self.plant.machine = machine
        self.interpreters.renew(self.outputs)
        if not planned:
            return  # the stand-in motion has no machine values
        positions = dict(motion.positions_mcs())
        referenced = {name: motion.is_referenced(name) for name in machine.path_axes}
        fresh = type(motion)(machine, positions, setting_data=self.data.setting_data)
        for name, done in referenced.items():
            fresh.set_referenced(name, done)
        self.plant.motion = fresh
        self.motion_renewed()


__all__ = ["DataWrites"]
