"""The channel's interpreters, a part of :class:`nck.kernel.Nck`: one per mode that runs
programs (AUTO, MDA), created on first use by the kernel's interpreter factory for the
active machine.

The interpreter whose program ended (or was reset) last *holds the channel's state*: its
tool and frames give the WCS display while nothing runs, and Set WO works on its frames.
The G groups of MD20152 = 1 (kept over RESET and program end, e.g. the work offset chosen in
T,S,M) go from it to the others. Before any program has run, nobody holds the state: the
snapshot shows the power-on state read from the stored frames.
"""

from __future__ import annotations

from typing import Any, Callable, Mapping

from nck.channel_state import MachinePlant, MachineOutputs
from nck.interp.api import Interpreter, ProgramSource
from nck.interp.modal import kept_groups
from nck.machine import MachineConfig
from nck.ncdata import NcData

InterpreterFactory = Callable[[MachineConfig, ProgramSource, NcData], Interpreter]


class ChannelInterpreters:
    """The interpreters by mode, the one holding the channel's state and the kept G codes."""

    def __init__(self, plant: MachinePlant, programs: ProgramSource, data: NcData,
                 factory: InterpreterFactory, wire: Callable[[Interpreter], None]) -> None:
        self.plant = plant  # the active machine (an interpreter is made for it)
        self.programs = programs
        self.data = data
        self.factory = factory
        self.wire = wire  # the kernel connects a new interpreter to itself (positions, probe, access, skip levels)
        self.by_kind: dict[str, Interpreter] = {}
        self.holder: Interpreter | None = None  # the interpreter holding the channel's state (None: power on)
        self.kept_gcodes: dict[int, str] = {}  # group -> code of MD20152 = 1, from the last program

    def get(self, kind: str) -> Interpreter:
        """The interpreter of mode ``kind`` (``"AUTO"``, ``"MDA"``), created on first use."""
        interp = self.by_kind.get(kind)
        if interp is None:
            interp = self.factory(self.plant.machine, self.programs, self.data)
            self.wire(interp)
            self.take_kept_gcodes(interp)
            self.by_kind[kind] = interp
        return interp

    def existing(self, kind: str) -> Interpreter | None:
        """The interpreter of mode ``kind`` if it was created (creates none)."""
        return self.by_kind.get(kind)

    def all(self) -> tuple[Interpreter, ...]:
        """Every interpreter created so far."""
        return tuple(self.by_kind.values())

    def renew(self, outputs: MachineOutputs) -> None:
        """Stored machine data came into effect: the interpreters of the old machine go; the
        new AUTOMATIC one takes over the channel's state (the tool of ``outputs``, the kept G
        codes) if an interpreter held it (the others are created on first use)."""
        held = self.holder is not None
        self.by_kind.clear()
        self.holder = None
        auto = self.get("AUTO")
        if held:
            sync_tool = getattr(auto, "sync_tool", None)
            if sync_tool is not None:
                sync_tool(outputs.tool, outputs.edge, int(outputs.aux.get("T", outputs.tool)))
            self.holder = auto

    def share_kept_gcodes(self, ended: Any, positions: Mapping[str, float]) -> None:
        """A program ended or was reset in interpreter ``ended``: it holds the channel's state
        now (its tool, its frames); the G groups of MD20152 = 1 go to the other interpreters
        (MDA, AUTO) too; one whose G codes change loads its frames at once (at ``positions``)."""
        modal = getattr(ended, "modal", None)  # an interpreter without G codes keeps none
        if modal is None:
            return
        keeps = kept_groups(self.plant.machine)
        codes = {group: code for group, code in modal.gcodes.items() if group in keeps}
        self.kept_gcodes = codes
        self.holder = ended
        for interp in self.by_kind.values():
            other = getattr(interp, "modal", None)
            if interp is ended or other is None or all(other.gcodes.get(g) == c for g, c in codes.items()):
                continue  # no G code changes there: its frames stay as they are (MD24006 …)
            self.take_kept_gcodes(interp)
            path = getattr(getattr(interp, "builder", None), "path", None)
            if path is not None:
                path.activate_stored_frames(other, positions)

    def take_kept_gcodes(self, interp: Any) -> None:
        """Give ``interp`` the channel's kept G codes (none before a program has ended)."""
        sync = getattr(interp, "sync_gcodes", None)
        if sync is not None:
            sync(self.kept_gcodes)
