"""Block search, a part of :class:`nck.kernel.Nck`: the four search types of 002 L18283-18309.

Types 1, 2 and 4 interpret (or skip) up to the target at once (:meth:`ProgramRun.search`);
NC START outputs the action blocks, 10208 follows, the next NC START continues.

Type 5, SERUPRO (search run by program test, 002 L18994-19027): the selected program runs
in program test — the machine stands, the simulated axes move, the channel is active and
may be stopped and started — up to the beginning of the target block. There the NC stops
with "search target found" and program test is deselected; selecting program test or dry
run meanwhile is refused with 16935. NC START switches the collected spindle state on and
repositions (REPOS) from where the axes stand to the start of the target block, then the
program continues. RESET aborts it. (One channel, no synchronized actions, no ASUB.)
"""

from __future__ import annotations

from typing import Any, Callable

from nck.channel_state import ChannelState, ControlSwitches, MachinePlant
from nck import commands as cmd
from nck.block_search import SEARCH_TYPES, SERUPRO
from nck.canon import Source, SpindleCommand
from nck.channel import RESET
from nck.commands import Accepted, Rejected, SubmitResult
from nck.counters import RuntimeTimer
from nck.interp.api import Interpreter
from nck.kernel_interpreters import ChannelInterpreters
from nck.errors import NcAlarmError
from nck.program_control import SEARCH_ACTIONS_DONE, SEARCH_FOUND, SEARCH_TARGET_FOUND, ProgramRun
from nck.refusals import refuse

ALARM_SELECTION_IN_SERUPRO = 16935  # program test or dry run selected during SERUPRO


class BlockSearchControl:
    """Block search of every type on the parts it is given; the kernel's steps it needs
    (a new run, starting it, the program-test motion off, outputs, alarms) are handed in."""

    def __init__(self, plant: MachinePlant, channel: ChannelState, switches: ControlSwitches,
                 runtime: RuntimeTimer, interpreters: ChannelInterpreters, *,
                 new_run: Callable[[str, str, Interpreter], ProgramRun],
                 begin_run: Callable[[ProgramRun], None], path_motion: Callable[[], Any],
                 program_test_ended: Callable[[], None], output: Callable[[object], None],
                 raise_number: Callable[..., None]) -> None:
        self.plant = plant  # the machine's axes: where a search starts from
        self.channel = channel  # the run, REPOS point, SERUPRO
        self.switches = switches  # program test is switched on and off for SERUPRO
        self.runtime = runtime
        self.interpreters = interpreters
        self.new_run = new_run  # a program run of the kernel (its tool, position, spindle synchronised)
        self.begin_run = begin_run  # the run starts from reset
        self.path_motion = path_motion  # the motion system programs run on (the simulated one in program test)
        self.program_test_ended = program_test_ended  # the simulated axes go; overrides and dry run to the machine's
        self.output = output  # a spindle command to the machine
        self.raise_number = raise_number  # an alarm by number with its parameters

    def start_block_search(self, command: cmd.StartBlockSearch) -> SubmitResult:
        """Search the target in the selected program (AUTOMATIC, channel reset or cascaded)."""
        if self.channel.situation.mode != "AUTO":
            return refuse("search_auto_only")
        if self.channel.selected is None:
            return refuse("no_program_selected")
        if command.search_type not in SEARCH_TYPES:
            return refuse("unknown_search_type", search_type=command.search_type)
        if command.search_type == SERUPRO:
            return self._start_serupro(command.target)
        cascaded = self.channel.run is not None and self.channel.run.phase in (SEARCH_FOUND, SEARCH_ACTIONS_DONE)
        if self.channel.situation.channel != RESET and not cascaded:
            return refuse("search_needs_reset")
        interp = self.interpreters.get("AUTO")
        interp.reset()
        interp.start(self.channel.selected)
        run = self.new_run("AUTO", self.channel.selected, interp)
        try:
            result = run.search(command.target, self.plant.positions(),
                                command.search_type)
        except NcAlarmError:
            interp.reset()
            raise
        if not result.found:
            interp.reset()
            return refuse("search_target_not_found", target=command.target)
        self.channel.adopt_searched_run(run)
        self.runtime.start_from_reset()
        self.channel.transition("search_found")
        return Accepted()

    # ------------------------------------------------------------------ SERUPRO
    def _start_serupro(self, target: str) -> SubmitResult:
        """Run the selected program in program test up to ``target`` (only from RESET: it
        cannot follow another search, 002 L19035-19037)."""
        if self.channel.situation.channel != RESET:
            return refuse("serupro_needs_reset")
        assert self.channel.selected is not None
        self.switches.program_control["program_test"] = True
        self.channel.serupro = True
        interp = self.interpreters.get("AUTO")
        interp.reset()
        interp.start(self.channel.selected)
        run = self.new_run("AUTO", self.channel.selected, interp)
        run.stop_before(target)
        self.begin_run(run)
        self.channel.transition("program_start")
        return Accepted()

    def serupro_target_found(self, run: ProgramRun) -> None:
        """The program stands before the target block: program test off; the next NC START
        repositions from the real axes to where the simulated ones stand."""
        simulated = self.plant.positions(self.path_motion())
        self.end_serupro()
        self.channel.repos_point = simulated
        self.channel.parked = []
        view = getattr(run.interp, "modal_view", None)
        modal = view() if view is not None else None
        if modal is not None and modal.spindle_state in ("M3", "M4"):
            self.channel.serupro_spindle = SpindleCommand(Source(run.name, 0), 1, state=modal.spindle_state,
                                                   speed_rpm=modal.spindle_speed_rpm)

    def end_serupro(self) -> None:
        """Program test off again (target found, program end or RESET)."""
        if not self.channel.serupro:
            return
        self.channel.serupro = False
        self.switches.program_control["program_test"] = False
        for interp in self.interpreters.all():
            flags = getattr(interp, "flags", None)
            if isinstance(flags, dict):
                flags["test"] = False
        self.program_test_ended()

    def start_serupro_spindles(self) -> None:
        """NC START after SERUPRO: the spindles start before the axes reposition."""
        command, self.channel.serupro_spindle = self.channel.serupro_spindle, None
        if command is not None:
            self.output(command)

    def refuse_selection_in_serupro(self, name: str) -> SubmitResult | None:
        """Program test and dry run cannot be selected while SERUPRO runs (16935)."""
        if self.channel.serupro and name in ("program_test", "dry_run"):
            self.raise_number(ALARM_SELECTION_IN_SERUPRO)
            return refuse("selection_in_serupro", alarm=ALARM_SELECTION_IN_SERUPRO)
        return None
