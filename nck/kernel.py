"""The NC kernel: ``Nck``, the one mutable root of the simulated control.

Three meeting points with the outside world (HMI, headless CLI, tests):

* ``submit(command)`` — an operator command from :mod:`nck.commands`,
  answered at once with :class:`Accepted` or :class:`Rejected`;
* ``tick(dt_s)`` / ``step(n_ipo_cycles)`` — simulated time advances only here;
* ``status()`` — an immutable :class:`nck.status.NckStatus` whose ``seq``
  increases whenever anything in it changed; ``alarm_log_since(seq)`` — the
  append-only, sequenced alarm/message log.

One mode group with one channel. The channel's states follow the transition
table of :mod:`nck.channel`; a running program is a
:class:`nck.program_control.ProgramRun`; alarms live in
:class:`nck.alarms.AlarmServer`. Motion is reached only through the
protocols of :mod:`nck.motion.api` (plus optional extensions found with
``getattr``); ``motion_factory`` defaults to the planned motion system of
:mod:`nck.motion.system`; :mod:`nck.motion.instant` is a simple stand-in
(straight lines at constant speed) used by tests and for program test.

Any exception other than :class:`NcAlarmError` inside ``submit``/``tick``
becomes alarm 1 "internal error"; its traceback is kept in
``Nck.internal_errors`` (tests fail on it) and never propagates.
"""

from __future__ import annotations

import math
import traceback
from dataclasses import replace
from typing import Any, Callable, Collection

from nck.alarm_ids import INTERNAL_ERROR
from nck import commands as cmd
from nck.access import AccessControl, AccessState, Action
from nck.alarms import AlarmServer
from nck.block_search import circle_tolerance
from nck.channel_state import ChannelState, ControlSwitches, MachineOutputs, MachinePlant
from nck.canon import (END_COMMANDS, AuxFunction, EdgeSelect, Motion, Source, SpindleCommand,
                       ToolSelect, UserAlarm)
from nck.channel import (
    ABORTED, ACTIVE, INTERRUPTED, RESET, RUNNING, ChannelSituation, mode_change_allowed,
    next_state, situation_after_mode_change,
)
from nck.command_table import CommandTable
from nck.commands import Accepted, Rejected, SubmitResult
from nck.counters import DEFAULT_PART_COUNTER, PartCounters, RuntimeTimer
from nck.errors import NcAlarmError
from nck.interp.api import Interpreter, ProgramSource
from nck.interp.interpreter import Interpreter as RealInterpreter
from nck.iso.dialect import dialect_for
from nck.kernel_access import Protection
from nck.phrase import Phrase
from nck.kernel_contact import ContactEvent, ContactWatch
from nck.kernel_data import DataWrites
from nck.kernel_manual import ManualControl
from nck.kernel_search import BlockSearchControl
from nck.kernel_settings import ControlSettings
from nck.kernel_interpreters import ChannelInterpreters
from nck.kernel_setup import JobSetup
from nck.machine import MachineConfig, load_machine
from nck.machine_data import MachineDataStore
from nck.motion.instant import InstantMotion, instant_motion_factory
from nck.motion.system import planned_motion_factory
from nck.ncdata import NcData
from nck.program_control import (
    SEARCH_ACTIONS_DONE, SEARCH_FOUND, SEARCH_TARGET_FOUND, ProgramRun, RunEvent, RunOptions,
)
from nck.refusals import refuse
from nck.snapshot import StatusSources, build_status
from nck.status import AlarmEntry, AlarmEvent, LogbookEntry, NckStatus

DEFAULT_IPO_S = 0.004
DEFAULT_BATCH_CYCLES = 2500  # IPO cycles per motion step at most (10 s at 4 ms)
LEGACY_BATCH_CYCLES = 16  # per step for motion systems without block events (stand-in, JOG)
ALARM_EMERGENCY_STOP = 3000
ALARM_START_WITH_ALARM = 10200
ALARM_START_UNREFERENCED = 10203
ALARM_CONTINUE_WITH_START = 10208
MDA_NAME = "MDA"
_LOGBOOK_COMMANDS = (cmd.WriteData, cmd.SetKeyswitch, cmd.EnterPassword, cmd.DeletePassword,
                     cmd.ChangePassword, cmd.ActivateMachineData, cmd.WriteMachineSetup)


class _NoPrograms:
    """Program source used when none is given: no programs at all."""

    def read_program(self, name: str) -> tuple[str, str] | None:
        return None


def _default_interpreter_factory(
    machine: MachineConfig, programs: ProgramSource, data: NcData
) -> Interpreter:
    return RealInterpreter(machine, programs, data, dialect=dialect_for(None, machine))


class Nck:
    """The simulated NCK; see the module docstring."""

    def __init__(
        self,
        machine: MachineConfig | None = None,
        data: NcData | None = None,
        programs: ProgramSource | None = None,
        motion_factory: Callable[[MachineConfig], Any] | None = None,
        referenced: bool = False,
        interpreter_factory: Callable[[MachineConfig, ProgramSource, NcData], Interpreter] | None = None,
        access: AccessControl | None = None,
        batch_cycles: int = DEFAULT_BATCH_CYCLES,
    ) -> None:
        config = machine or load_machine()
        self.data = data if data is not None else NcData()
        self.programs: ProgramSource = programs if programs is not None else _NoPrograms()
        self.batch_cycles = max(1, int(batch_cycles))  # see step()
        self._cycles_in_step = 1
        self._prefed: tuple[ProgramRun, list[RunEvent]] | None = None  # see _feed_between_cycles
        self._options = RunOptions()  # see _run_options
        # The machine and its motion system (both replaced when stored machine data come into effect).
        self.plant = MachinePlant(config, (motion_factory or planned_motion_factory)(config))
        getattr(self.motion, "attach_setting_data", lambda _data: None)(self.data.setting_data)
        for axis in self.machine.path_axes:
            # MD34210 ENC_REFP_STATE = 2: absolute encoder adjusted (or buffered
            # position) -> referenced at power on without any motion.
            adjusted = self.machine.md_value("MD34210", axis, 0) == 2
            self.motion.set_referenced(axis, referenced or adjusted)
        self.alarms = AlarmServer()
        self.internal_errors: list[str] = []
        self._time_s = 0.0
        self._tick_rest_s = 0.0
        self._ipo_s = self._ipo_cycle_s()
        self.channel = ChannelState()  # mode, channel and program state (nck.channel_state)
        self.switches = ControlSwitches()  # program control and overrides
        self.outputs = MachineOutputs()  # active T/D, spindle, aux functions of the main run
        # The channel's interpreters by mode, the one holding the channel's state, the kept G codes
        self.interpreters = ChannelInterpreters(self.plant, self.programs, self.data,
                                                interpreter_factory or _default_interpreter_factory,
                                                self._wire_interpreter)
        md27880 = self.machine.md_value("MD27880", None, DEFAULT_PART_COUNTER)
        md27882 = self.machine.md_value("MD27882", None, None)
        self.counters = PartCounters(mode_bits=int(md27880 if isinstance(md27880, int) else DEFAULT_PART_COUNTER))
        if isinstance(md27882, list) and len(md27882) == 3:
            self.counters.m_codes = tuple(int(v) for v in md27882)  # type: ignore[assignment]
        self.runtime = RuntimeTimer()
        self._seq = 0
        self._last_body: NckStatus | None = None
        self._snapshot: NckStatus | None = None  # the last built snapshot; None: something changed since
        self._snapshot_outside: tuple[int, ...] = ()  # the outside change counters it was built at
        # Optional observers for headless runs and tools (not for the HMI, which
        # reads status() and the alarm log): every interpreted block, every alarm raised.
        self.block_listener: Callable[[Any], None] | None = None
        self.alarm_listener: Callable[[NcAlarmError], None] | None = None
        # Simultaneous recording (installed by nck.queries.record_cuts): called with (program,
        # T, D) at each AUTO program start; the object it returns is handed every block of that
        # run with the block executing now (``interpreted(block, source)``).
        self.run_recorder_factory: Callable[[str, int, int], Any] | None = None
        self.run_recording: Any = None
        # Called at the end of every IPO cycle (the trace recorder of nck.trace).
        self.cycle_listeners: list[Callable[["Nck"], None]] = []
        self.cycles_done = 0  # IPO cycles since power on (system utilisation)
        self.blocks_interpreted = 0  # blocks the interpreter handed over since power on
        self.logbook: list[LogbookEntry] = []  # access-level and MD/SD changes since power on
        # Keyswitch and passwords (nck.kernel_access); without an access control: unprotected
        self.protection = Protection(access, self.logbook, self.alarms, clock=lambda: self._time_s,
                                     raise_number=self._raise_number)
        # Contacts with the blank / reference block (nck.kernel_contact)
        self.contact_watch = ContactWatch(
            self.plant, self.data, self.channel, self.switches, self.outputs, self.alarms, self._ipo_s,
            path_motion=self._path_motion, clock=lambda: self._time_s, motion_alarm=self._motion_alarm)
        self.manual = ManualControl(self.plant, self.data, self.channel, self.contact_watch.state, self._park)  # JOG, INC, REF
        self.setup = JobSetup(self.plant, self.data, self.channel, self.interpreters, self.protection.require)  # Set WO, set-up
        self.search = BlockSearchControl(  # block search, SERUPRO
            self.plant, self.channel, self.switches, self.runtime, self.interpreters, new_run=self._new_run,
            begin_run=self._begin_run, path_motion=self._path_motion, program_test_ended=self._program_test_ended,
            output=self._output, raise_number=self._raise_number)
        self.settings = ControlSettings(  # program control, overrides
            self.plant, self.data, self.channel, self.switches, self.interpreters, self.search)
        self.data_writes = DataWrites(  # WriteData and the other data commands, MD activation
            self.plant, self.data, self.channel, self.outputs, self.interpreters, self.protection,
            self.counters, self.setup, motion_renewed=self.settings.apply_overrides)
        self.settings.apply_overrides()
        self.interpreters.get("AUTO")  # its reset G codes are shown from power on

    @property
    def machine(self) -> MachineConfig:
        """The active machine (replaced when stored machine data come into effect)."""
        return self.plant.machine

    @machine.setter
    def machine(self, machine: MachineConfig) -> None:
        self.plant.machine = machine

    @property
    def motion(self) -> Any:
        """The machine's motion system (rebuilt for a new machine)."""
        return self.plant.motion

    @motion.setter
    def motion(self, motion: Any) -> None:
        self.plant.motion = motion

    @property
    def access(self) -> AccessControl:
        """Keyswitch and passwords (protection levels 0 … 7); created on first use."""
        return self.protection.access

    @property
    def access_state(self) -> AccessState | None:
        """Keyswitch position and password state, None when unprotected."""
        return self.protection.state()

    def action_level(self, action: Action | str) -> int:
        """The protection level ``action`` (an Action or its name, ``"READ_TOOL"``) needs;
        7 when unprotected. Creates nothing."""
        return self.protection.action_level(action)

    @property
    def md_store(self) -> MachineDataStore | None:
        """The machine/setting data store given to the kernel (the session's); None: a store of
        the machine's own values is created on first use."""
        return self.data_writes.md_store

    @md_store.setter
    def md_store(self, store: MachineDataStore | None) -> None:
        self.data_writes.md_store = store

    @property
    def machine_data(self) -> MachineDataStore:
        """The MD/SD store of this kernel (read it for the MD lists; write via ``WriteData``)."""
        return self.data_writes.machine_data

    def required_level(self, name: str) -> int:
        """The protection level writing the datum ``name`` needs (7 when unprotected)."""
        return self.data_writes.required_level(name)

    # ------------------------------------------------------------------ API
    def submit(self, command: object) -> SubmitResult:
        """Carry out one operator command; never raises."""
        handler = COMMANDS.handler(type(command))
        if handler is None:
            return refuse("unknown_command", command=type(command).__name__)
        try:
            logged = isinstance(command, _LOGBOOK_COMMANDS)
            level_before = self._access_level() if logged else 7
            result = handler(self, command)
            if logged and isinstance(result, Accepted):
                self._note_in_logbook(command, level_before)
            return result
        except NcAlarmError as error:
            entry = self._raise(error)
            return Rejected(entry.text, alarm=error.number, alarm_params=tuple(entry.params))
        except Exception as exc:  # noqa: BLE001 - every bug becomes alarm 1
            self._internal_error(exc)
            return refuse("internal_error", alarm=INTERNAL_ERROR)
        finally:
            self._snapshot = None

    def tick(self, dt_s: float) -> None:
        """Advance simulated time by ``dt_s`` seconds (whole IPO cycles; the rest is kept)."""
        try:
            dt = float(dt_s)
        except (TypeError, ValueError):
            return
        if not math.isfinite(dt) or dt <= 0.0:
            return
        self._tick_rest_s += dt
        cycles = int((self._tick_rest_s + 1e-9) // self._ipo_s)
        self._tick_rest_s = max(0.0, self._tick_rest_s - cycles * self._ipo_s)
        self.step(cycles)

    def step(self, n_ipo_cycles: int = 1) -> None:
        """Advance simulated time by ``n_ipo_cycles`` IPO cycles.

        While nothing in the channel needs attention every cycle (buffer full,
        waiting for the motion to finish, nothing running) up to
        ``batch_cycles`` cycles are handed to the motion system at once. The
        planned motion ends such a batch with the cycle of the next block
        event (segment end, dwell end, alarm, axes at rest), so a batched run
        is the same as a cycle-by-cycle one; cycle listeners (traces) always
        get every cycle.
        """
        remaining = max(0, int(n_ipo_cycles))
        while remaining > 0:
            remaining -= self._guarded_cycle(remaining)

    def run_until(self, predicate: Callable[["Nck"], bool], max_s: float,
                  max_batch_cycles: int = LEGACY_BATCH_CYCLES) -> bool:
        """Advance until ``predicate(self)`` holds (checked between steps); False on timeout.

        Steps are at most ``max_batch_cycles`` cycles long (a predicate on
        positions sees them that finely); a predicate on the channel state may
        pass ``batch_cycles``: state changes always end a step.
        """
        cycles = int(max_s / self._ipo_s + 0.5)
        step = max(1, int(max_batch_cycles))
        done = 0
        while done < cycles:
            if predicate(self):
                return True
            done += self._guarded_cycle(min(cycles - done, step))
        return predicate(self)

    def _guarded_cycle(self, limit: int) -> int:
        """One kernel step of 1 … ``limit`` IPO cycles; returns the cycles run (never raises)."""
        done = 0
        self._snapshot = None
        while True:
            self._cycles_in_step = 1
            try:
                self._cycle(limit - done)
            except NcAlarmError as error:
                self._prefed = None
                self._raise(error)
            except Exception as exc:  # noqa: BLE001
                self._prefed = None
                self._internal_error(exc)
                self._internal_reset()
            done += max(1, min(self._cycles_in_step, limit - done))
            # A feed done inside the motion step belongs to the next cycle: run that
            # cycle now, so nobody sees the kernel between the feed and its cycle.
            if self._prefed is None or done >= limit:
                return done

    @property
    def ipo_cycle_s(self) -> float:
        """The interpolation cycle in seconds."""
        return self._ipo_s

    @property
    def time_s(self) -> float:
        """Simulated control time since power on."""
        return self._time_s

    @property
    def situation(self) -> ChannelSituation:
        """Mode, channel status and program status (cheap; no snapshot)."""
        return self.channel.situation

    def alarm_log_since(self, seq: int) -> tuple[AlarmEvent, ...]:
        """Alarm/message log events newer than ``seq`` (bounded log)."""
        return self.alarms.log_since(seq)

    def _note_in_logbook(self, command: object, level_before: int) -> None:
        """Logbook (diagnosis): access-level changes and machine/setting data writes."""
        level = self._access_level()
        if isinstance(command, cmd.WriteData):
            name = command.name.upper()
            if name.startswith(("MD", "SD", "$M", "$S")):
                self.logbook.append(LogbookEntry(self._time_s, "data", f"{command.name} = {command.value}"))
            return
        if isinstance(command, cmd.ActivateMachineData):
            self.logbook.append(LogbookEntry(self._time_s, "data", Phrase("machine data activated (NEW CONFIG)")))
            return
        if isinstance(command, cmd.WriteMachineSetup):
            self.logbook.append(LogbookEntry(self._time_s, "data", Phrase("machine set-up changed")))
            return
        if isinstance(command, cmd.ChangePassword):
            self.logbook.append(LogbookEntry(self._time_s, "access",
                                             Phrase("password of access level {level} changed", level=command.level)))
            return
        if isinstance(command, cmd.SetKeyswitch):
            what = Phrase("keyswitch position {position}", position=command.position)
        elif isinstance(command, cmd.EnterPassword):
            what = Phrase("password entered")
        elif isinstance(command, cmd.DeletePassword):
            what = Phrase("password deleted")
        else:
            what = Phrase("access")
        if level != level_before or not isinstance(command, cmd.SetKeyswitch):
            self.logbook.append(LogbookEntry(self._time_s, "access", Phrase(
                "{what}: access level {before} -> {after}", what=what, before=level_before, after=level)))

    def buffer_fill(self) -> tuple[int, int]:
        """Read-only: (items in the motion system's block buffer, its capacity) for the diagnosis."""
        return self._path_motion().buffer_fill()

    def contact_events(self, since_seq: int = 0) -> tuple[ContactEvent, ...]:
        """The contacts with the blank or the reference block after ``since_seq`` (oldest first, bounded)."""
        return self.contact_watch.events(since_seq)

    def probe_deflected(self) -> bool:
        """True while the active tool is a 3D probe in contact with a solid."""
        return self.contact_watch.probe_deflected()

    def alarm_history(self) -> tuple[AlarmEntry, ...]:
        """The alarm log with come/go times, oldest first (bounded)."""
        return self.alarms.history()

    def load_alarm_history(self, entries: list[AlarmEntry]) -> None:
        """Put retained alarm-log entries (from before this power on) in front of the log."""
        self.alarms.load_history(entries)
        self._snapshot = None

    def raise_alarm(self, error: NcAlarmError) -> None:
        """Raise an alarm from outside the channel (power-on checks, data loading)."""
        self._raise(error)
        self._snapshot = None

    def positions_mcs(self) -> dict[str, float]:
        """Displayed machine positions (program test: the simulated ones)."""
        return dict(self._display_motion().positions_mcs())

    def axis_states(self) -> dict[str, Any]:
        """Read-only: the drives' service values per path axis of the displayed motion
        (``nck.motion.servo.AxisState``; program test: the simulated one), empty when the
        motion system has none (the stand-in)."""
        getter = getattr(self._display_motion(), "axis_states", None)
        return dict(getter()) if getter is not None else {}

    def status(self) -> NckStatus:
        """The immutable snapshot, built once after each command or kernel step (not once per
        call) and when state shared with other doors changed (:meth:`_outside_revisions`);
        ``seq`` grows when anything in it changed. Reading it changes nothing."""
        outside = self._outside_revisions()
        if self._snapshot is None or outside != self._snapshot_outside:
            body = build_status(self._status_sources())
            if body != self._last_body:
                self._seq += 1
                self._last_body = body
            self._snapshot = replace(body, seq=self._seq, time_s=self._time_s)
            self._snapshot_outside = outside
        return self._snapshot

    def _outside_revisions(self) -> tuple[int, ...]:
        """The change counters of what the kernel shares with other doors (the session's access
        control, turned by its command line or an exercise set-up): the kept snapshot is
        stale when one of them moved."""
        return (self.protection.revision(),)

    def _status_sources(self) -> StatusSources:
        run = self.channel.active_run()
        # The G codes shown: the run's, else AUTOMATIC's (from power on its reset G codes).
        # The frames that give the WCS while nothing executes: the run's, else those of the
        # interpreter that holds the channel's state (the one that ran last); None until a
        # program has run: the power-on state, read from the stored frames.
        modal = run.interp if run is not None else self.interpreters.existing("AUTO")
        frames = run.interp if run is not None else self.interpreters.holder
        return StatusSources(
            machine=self.machine, data=self.data, channel=self.channel, switches=self.switches,
            outputs=self.outputs, motion=self.motion, shown_motion=self._display_motion(),
            path_motion=self._path_motion(), modal_interpreter=modal, frame_interpreter=frames,
            alarms=self.alarms, runtime=self.runtime, counters=self.counters,
            access_level=self._access_level(), keyswitch_position=self.protection.keyswitch_position(),
            internal_errors=len(self.internal_errors),
        )

    def _access_level(self) -> int:
        return self.protection.level()

    # ------------------------------------------------------------ commands
    def _select_mode(self, command: cmd.SelectMode) -> SubmitResult:
        mode = command.mode.upper()
        mode = {"AUTOMATIC": "AUTO", "MDI": "MDA"}.get(mode, mode)
        if mode == self.channel.situation.mode:
            return Accepted()
        refusal = mode_change_allowed(self.channel.situation, mode, self.channel.owner)
        if refusal is None and mode == "AUTO" and self.channel.overlay is not None:
            refusal = refuse("mda_interrupted")
        if refusal is not None:
            return refusal
        new = situation_after_mode_change(self.channel.situation, mode, self.channel.owner)
        self._park()
        if self.channel.situation.channel == INTERRUPTED and self.channel.situation.program == ABORTED:
            self.channel.jog_rest.clear()
        self.channel.situation = new
        if mode == "AUTO":
            # Selecting AUTOMATIC disables the INC keys (002 L17738-17739).
            self.channel.machine_function = None
            self.channel.inc_waiting_for_jog = False
        elif mode == "MDA" and self.channel.machine_function == "INC":
            # MDA has no INC (002 L17597-17601); the selection waits for JOG (our choice).
            self.channel.machine_function = None
            self.channel.inc_waiting_for_jog = True
        elif mode == "JOG" and self.channel.inc_waiting_for_jog:
            if self.channel.machine_function is None:
                self.channel.machine_function = "INC"
            self.channel.inc_waiting_for_jog = False
        return Accepted()

    def _cycle_start(self, command: cmd.CycleStart) -> SubmitResult:
        mode = self.channel.situation.mode
        if self.channel.estop_active:
            return refuse("emergency_stop_active")
        if mode == "JOG" or (self.channel.situation.channel == INTERRUPTED and self.channel.situation.program == ABORTED):
            return self.manual.continue_jog()
        if self.channel.situation.channel == ACTIVE:
            return refuse("channel_already_active")
        self.alarms.clear("nc_start", self._time_s)
        if self.alarms.has_reaction("nc_start_disable"):
            self._raise_number(ALARM_START_WITH_ALARM)
            return refuse("start_with_alarm", alarm=ALARM_START_WITH_ALARM)
        unreferenced = self._unreferenced_axes()
        if unreferenced:
            self._raise_number(ALARM_START_UNREFERENCED, unreferenced[0])
            return refuse("axes_not_referenced", alarm=ALARM_START_UNREFERENCED, axes=" ".join(unreferenced))
        self.settings.apply_dry_run()  # SD42100/SD42101 written during the interruption
        self.data_writes.apply_offset_edits()  # MD9440: work offsets edited during the interruption
        if mode == "AUTO":
            return self._start_auto()
        return self._start_mda()

    def _start_auto(self) -> SubmitResult:
        run = self.channel.run
        if next_state(self.channel.situation, "program_start") is None:
            return refuse("start_not_possible")
        if self.channel.situation.program == ABORTED:
            if self.channel.selected is None:
                return refuse("no_program_selected")
            interp = self._interpreter("AUTO")
            interp.reset()
            interp.start(self.channel.selected)
            self._begin_run(self._new_run("AUTO", self.channel.selected, interp))
            self.runtime.start_from_reset()
            self.channel.transition("program_start")
            return Accepted()
        if run is None or self.channel.owner != "AUTO":
            return refuse("nothing_to_continue")
        if run.phase == SEARCH_FOUND:
            self._handle_events(run, run.output_search_actions())
            self.channel.transition("program_start")
            self.channel.transition("block_stop")
            self._raise_number(ALARM_CONTINUE_WITH_START)
            return Accepted()
        if run.phase == SEARCH_ACTIONS_DONE:
            approach = run.search_approach(self._path_positions(self._path_motion()),
                                           circle_tolerance(self.machine))
            self._path_motion().resume()
            if approach is not None:
                run.requeue([], replace(approach, start_mcs=self._path_positions(self._path_motion())))
            self.channel.transition("program_start")
            return Accepted()
        self.search.start_serupro_spindles()
        self._resume_motion(run)
        run.continue_after_stop()
        self.channel.transition("program_start")
        return Accepted()

    def _start_mda(self) -> SubmitResult:
        if next_state(self.channel.situation, "program_start") is None:
            return refuse("start_not_possible")
        if self.channel.owner == "AUTO":
            overlay = self.channel.overlay
            if overlay is not None and overlay.phase != "ended":
                self._path_motion().resume()
                overlay.continue_after_stop()
            else:
                if not self.channel.mda_text.strip():
                    return refuse("mda_buffer_empty")
                interp = self._interpreter("MDA")
                interp.reset()
                interp.start_text(MDA_NAME, self.channel.mda_text)
                self.channel.overlay = self._new_run("MDA", MDA_NAME, interp)
            self.channel.transition("overlay_start")
            return Accepted()
        if self.channel.owner == "MDA" and self.channel.run is not None:
            self._resume_motion(self.channel.run)
            self.channel.run.continue_after_stop()
            self.channel.transition("program_start")
            return Accepted()
        if not self.channel.mda_text.strip():
            return refuse("mda_buffer_empty")
        interp = self._interpreter("MDA")
        interp.reset()
        interp.start_text(MDA_NAME, self.channel.mda_text)
        self._begin_run(self._new_run("MDA", MDA_NAME, interp))
        self.channel.transition("program_start")
        return Accepted()

    def _new_run(self, kind: str, name: str, interp: Interpreter) -> ProgramRun:
        sync_tool = getattr(interp, "sync_tool", None)
        if sync_tool is not None:
            sync_tool(self.outputs.tool, self.outputs.edge, int(self.outputs.aux.get("T", self.outputs.tool)))
        sync = getattr(interp, "sync_position", None)
        if sync is not None:
            sync(self._path_motion().positions_mcs())
        sync_spindle = getattr(interp, "sync_spindle", None)
        if sync_spindle is not None:
            sync_spindle(self.outputs.spindle_state, self.outputs.spindle_rpm)  # what RESET or M30 left
        flags = getattr(interp, "flags", None)
        if isinstance(flags, dict):
            flags["test"] = bool(self.switches.program_control["program_test"])
            flags["dry_run"] = bool(self.switches.program_control["dry_run"])
        run = ProgramRun(kind, name, interp, self._adjust_motion)
        run.listener = self._count_block
        self.channel.basic_blocks = run.basic_blocks
        return run

    def _adjust_motion(self, motion: Motion) -> Motion:
        """The WCS offset bookkeeping of every segment handed to the motion."""
        end_wcs, offsets = motion.end_wcs, self.outputs.wcs_offset  # (every motion block)
        for axis, mcs in motion.end_mcs.items():
            if axis in end_wcs:
                offsets[axis] = float(mcs) - float(end_wcs[axis])
        return motion

    def _begin_run(self, run: ProgramRun) -> None:
        self.channel.begin_run(run)
        if run.kind == "AUTO" and self.run_recorder_factory is not None:
            recording = self.run_recorder_factory(run.name, self.outputs.tool, self.outputs.edge)
            self.run_recording = recording
            run.listener = lambda block: self._record_block(recording, block)
        self.motion.resume()
        if self.switches.program_control["program_test"]:
            self.plant.test_motion = InstantMotion(self.machine, self.motion.positions_mcs())
            self.settings.apply_overrides()  # the simulated axes run with the override switches too
        self.settings.apply_dry_run()

    def _cycle_stop(self, command: cmd.CycleStop) -> SubmitResult:
        if self.channel.situation.channel != ACTIVE:
            return refuse("stop_not_active")
        if self.channel.jogging:
            self.manual.stop_jog(keep_rest=True)
            self.channel.transition("nc_stop")
            return Accepted()
        self._path_motion().hold()
        run = self.channel.active_run()
        if run is not None:
            run.stop_reason = "NC STOP"
        self._mark_interrupted(run)
        self.channel.transition("nc_stop")
        return Accepted()

    def _reset(self, command: cmd.Reset) -> SubmitResult:
        kept = self._spindles_kept_after_reset()
        self.motion.abort(keep_spindles=kept)
        self._spindle_display_after_reset(kept)
        self.outputs.aux.pop("T", None)  # no preselection beyond RESET (the interpreter's too)
        if self.plant.test_motion is not None:
            self.plant.test_motion.abort()
        for interp in self.interpreters.all():
            try:
                interp.reset()
            except NcAlarmError as error:
                self._raise(error)
        if self.channel.run is not None:
            self.interpreters.share_kept_gcodes(self.channel.run.interp, self.plant.positions())
        self.channel.clear_programs()
        keep = frozenset({ALARM_EMERGENCY_STOP}) if self.channel.estop_pressed else frozenset()
        self.alarms.clear("reset", self._time_s, keep=keep)
        if self.channel.estop_active and not self.channel.estop_pressed:
            self.channel.estop_active = False
        self.alarms.set_message("", self._time_s)
        self.channel.situation = next_state(self.channel.situation, "reset") or self.channel.situation
        self.search.end_serupro()
        if not self.switches.program_control["program_test"]:
            self.plant.test_motion = None
        self.data_writes.activate_data("reset")  # stored MD of activation re/cf take effect
        self.setup.reset_system_frames()
        return Accepted()

    def _emergency_stop(self, command: cmd.EmergencyStop) -> SubmitResult:
        if not command.pressed:
            self.channel.estop_pressed = False
            return Accepted()
        self.channel.estop_pressed = True
        if not self.channel.estop_active:
            self.channel.estop_active = True
            self.motion.abort()
            self._spindle_display_after_reset(())  # every spindle brakes and loses its S
            if self.plant.test_motion is not None:
                self.plant.test_motion.abort()
            self.channel.stop_manual_motion()
            run = self.channel.active_run()
            self._mark_interrupted(run)
            self.channel.transition("emergency_stop")
            if self.channel.situation.program == ABORTED:
                self.channel.run = None
                self.channel.owner = None
            self._raise_number(ALARM_EMERGENCY_STOP)
        return Accepted()

    def _select_program(self, command: cmd.SelectProgram) -> SubmitResult:
        if self.channel.situation.channel != RESET:
            return refuse("select_needs_reset")
        if self.programs.read_program(command.name) is None:
            return refuse("program_not_found", program=command.name)
        self.channel.selected = command.name
        return Accepted()

    def _set_mda(self, command: cmd.SetMdaProgram) -> SubmitResult:
        mda_busy = (self.channel.run is not None and self.channel.run.kind == "MDA") or self.channel.overlay is not None
        if mda_busy and self.channel.situation.channel != RESET:
            return refuse("mda_in_progress")
        self.channel.mda_text = command.text
        return Accepted()

    def _cancel_alarms(self, command: cmd.CancelAlarms) -> SubmitResult:
        self.alarms.clear("cancel", self._time_s)
        return Accepted()

    # ------------------------------------------------------------- cycle
    def _batch_size(self, limit: int, fed: bool) -> int:
        """How many IPO cycles may run as one motion step now (1 = cycle by cycle).

        Called after the run was fed for the first cycle; ``fed`` is False when
        that feed produced events (the channel reacts at once, as cycle by cycle).
        """
        if self.batch_cycles <= 1 or self.cycle_listeners or limit <= 1 or not fed:
            return 1
        run = self.channel.active_run()
        if run is not None and self.channel.situation.channel == ACTIVE and not self.channel.jogging:
            if run.wants_every_cycle(self._path_motion()):
                return 1
        cycles = min(limit, self.batch_cycles)
        if not self._event_batching():
            # Motion without block events: batches stay short (noticed up to a batch late).
            cycles = min(cycles, LEGACY_BATCH_CYCLES)
        return cycles

    def _event_batching(self) -> bool:
        """True when the motion ends its batches at block events (planned motion, no JOG)."""
        return (
            self.plant.test_motion is None and not self.channel.jogging
            and getattr(self.motion, "advance_cycles", None) is not None
            and not self.motion.jog_active()
        )

    def _cycle(self, limit: int = 1) -> None:
        """One kernel step: feed the run for the first cycle, then move 1 … ``limit`` cycles."""
        self._time_s += self._ipo_s
        run = self.channel.active_run()
        fed = True
        prefed, self._prefed = self._prefed, None
        if prefed is not None:
            # The run was already fed for this cycle inside the last motion step.
            fed = False
            self._handle_events(prefed[0], prefed[1])
        elif run is not None and self.channel.situation.channel == ACTIVE and not self.channel.jogging:
            events = run.feed(self._path_motion(), self._run_options(), self._ipo_s)
            if events:
                fed = False
                self._handle_events(run, events)
        cycles = self.contact_watch.cycle_limit(self._batch_size(limit, fed))
        before = self.contact_watch.positions_before()
        if cycles > 1 and self._event_batching():
            cycles = self.motion.advance_cycles(cycles, self._feed_between_cycles)
        else:
            self.motion.advance(self._ipo_s * cycles)
        self._cycles_in_step = cycles
        dt_s = self._ipo_s * cycles
        self._time_s += dt_s - self._ipo_s
        if self.plant.test_motion is not None:
            self.plant.test_motion.advance(dt_s)
        for error in self.motion.drain_alarms():
            self._motion_alarm(error)
        self.contact_watch.watch(before)
        cleared = getattr(self.motion, "drain_cleared_alarms", None)
        if cleared is not None:
            for number in cleared():
                self.alarms.clear_number(number, self._time_s)
        if self.channel.jogging and not self.motion.jog_active():
            self.channel.jogging = False
            self.channel.jog_targets.clear()
            if self.channel.situation.channel == ACTIVE:
                self.channel.transition("jog_end")
        if (
            self.channel.situation.mode == "AUTO" and self.channel.situation.channel == ACTIVE
            and self.channel.situation.program == RUNNING and self.channel.run is not None and self.channel.run.kind == "AUTO"
        ):
            self.runtime.run(dt_s)
        self.cycles_done += cycles
        for listener in tuple(self.cycle_listeners):  # a listener may remove itself
            listener(self)

    def _feed_between_cycles(self, cycles_done: int) -> int:
        """Called by the motion at a block event inside a step: the per-cycle work of the
        next cycle that must happen before its motion (feeding the run).

        Returns how many more cycles the step may run (0: end the step here).
        Events of the feed are kept for the next step, which handles them
        first, as the cycle-by-cycle kernel does before that cycle's motion.
        """
        run = self.channel.active_run()
        if self.channel.jogging or self.plant.test_motion is not None:
            return 0
        if run is None or self.channel.situation.channel != ACTIVE:
            return self._contact_allows(cycles_done, self.batch_cycles)  # nothing is fed
        motion = self._path_motion()
        events = run.feed(motion, self._run_options(), self._ipo_s)
        if events:
            self._prefed = (run, events)
            return 0
        allowed = self._contact_allows(cycles_done, 1 if run.wants_every_cycle(motion) else self.batch_cycles)
        if allowed == 0:
            self._prefed = (run, [])  # fed for the next cycle, which a new step runs
        return allowed

    def _contact_allows(self, cycles_done: int, cycles: int) -> int:
        """``cycles``, fewer when the tool could reach a solid sooner (nck.kernel_contact)."""
        left = self.contact_watch.cycles_left(cycles_done)
        return cycles if left is None else min(cycles, left)

    def _record_block(self, recording: Any, block: Any) -> None:
        """A block of a recorded AUTO run: count it, then hand it to the recording."""
        self._count_block(block)
        recording.interpreted(block, self.current_source())

    def _count_block(self, block: Any) -> None:
        """Every interpreted block: count it, then tell the optional block listener."""
        self.blocks_interpreted += 1
        if self.block_listener is not None:
            self.block_listener(block)

    def _handle_events(self, run: ProgramRun, events: list[RunEvent]) -> None:
        for event in events:
            if event.kind == "alarm" and event.alarm is not None:
                self._raise(event.alarm)
            elif event.kind == "user_alarm":
                alarm = event.command
                assert isinstance(alarm, UserAlarm)
                self._raise(NcAlarmError(alarm.number, *alarm.params, file=alarm.source.file,
                                         line=alarm.source.line, n=alarm.source.n))
            elif event.kind == "message":
                self.alarms.set_message(event.text, self._time_s)
            elif event.kind == "output":
                self._output(event.command)
            elif event.kind == "stop":
                self._path_motion().hold()
                self._mark_interrupted(run)
                self.channel.transition("block_stop")
                if event.text == SEARCH_TARGET_FOUND:
                    self.search.serupro_target_found(run)
            elif event.kind == "end":
                self._program_end(run, event.text)

    def _program_end(self, run: ProgramRun, kind: str) -> None:
        if run is self.channel.overlay:
            self.channel.overlay = None
            self.channel.transition("program_end")
            return
        try:
            run.interp.reset()
        except NcAlarmError as error:
            self._raise(error)
        self.interpreters.share_kept_gcodes(run.interp, self.plant.positions())
        if run.kind == "AUTO":
            self.counters.on_program_end(bool(self.switches.program_control["program_test"]))
            self.runtime.program_end()
            self.search.end_serupro()  # the target was not found
        if kind in END_COMMANDS:
            self.outputs.aux.pop("T", None)  # no preselection beyond M2 / M30
            self._reset_spindles_at_program_end(run.name)
        self.alarms.set_message("", self._time_s)
        self.channel.run = None
        self.channel.owner = None
        self.channel.transition("program_end")

    def _reset_spindles_at_program_end(self, program: str) -> None:
        """M2 / M30: brake the spindles that MD35040 does not keep, and delete their S."""
        kept = self._spindles_kept_after_reset()
        spindle_command = getattr(self.motion, "spindle_command", None)
        for number, name in enumerate(self.machine.spindles, start=1):
            if name not in kept and spindle_command is not None and not self.switches.program_control["program_test"]:
                spindle_command(SpindleCommand(Source(program, 0), number, state="M5", speed_rpm=0.0))
        self._spindle_display_after_reset(kept)

    def _output(self, command: object) -> None:
        if isinstance(command, AuxFunction):
            address = command.address.upper()
            key = address if command.extension is None else f"{address}{command.extension}"
            value = command.value
            self.outputs.aux[key] = f"{value:g}"
            if address == "M":
                self.counters.on_m_function(int(value), bool(self.switches.program_control["program_test"]))
        elif isinstance(command, ToolSelect):
            self.outputs.aux["T"] = str(command.tool)  # the programmed (preselected) tool
            if command.change:
                self.outputs.tool = command.tool  # the active tool after the change
        elif isinstance(command, EdgeSelect):
            self.outputs.edge = command.edge
        elif isinstance(command, SpindleCommand):
            if command.state:
                self.outputs.spindle_state = command.state
            if command.speed_rpm is not None:
                self.outputs.spindle_rpm = float(command.speed_rpm)
            spindle = getattr(self.motion, "spindle_command", None)
            if spindle is not None and not self.switches.program_control["program_test"]:
                spindle(command)

    def _motion_alarm(self, error: NcAlarmError) -> None:
        self._raise(error)
        reactions = self.alarms.reactions_of(error.number)
        run = self.channel.active_run()
        if "emergency_stop" in reactions:
            self._emergency_stop(cmd.EmergencyStop(True))
            self.channel.estop_pressed = False
            return
        if run is not None and self.channel.situation.channel == ACTIVE and not self.channel.jogging:
            # A block the motion refused when execution reached it (10720, 12160 …)
            # faults the path: the blocks buffered behind it can never run, so the
            # channel is interrupted there, as if braked (RESET is needed anyway).
            faulted = bool(getattr(self._path_motion(), "faulted", False))
            if "braking" in reactions or "feed_stop" in reactions or faulted:
                self._path_motion().hold()
                run.stop_reason = "alarm"
                self._mark_interrupted(run)
                self.channel.transition("nc_stop")
            elif "interpreter_stop" in reactions:
                run.interpreter_stop("alarm")

    # ------------------------------------------------------------- helpers
    def _spindles_kept_after_reset(self) -> frozenset[str]:
        """The spindles whose MD35040 SPIND_ACTIVE_AFTER_RESET is set: they keep turning with
        their S and direction at RESET and program end; the others (0, the default) brake
        and lose them (002 L51017-51038)."""
        return frozenset(name for name in self.machine.spindles if self.machine.spindle_kept_after_reset(name))

    def _spindle_display_after_reset(self, kept: Collection[str]) -> None:
        """The displayed S and direction of the master spindle follow it: deleted unless
        the spindle is kept (002 L51032-51038)."""
        spindles = self.machine.spindles
        if not spindles or spindles[0] not in kept:
            self.outputs.spindle_state = "M5"
            self.outputs.spindle_rpm = 0.0

    def _mark_interrupted(self, run: ProgramRun | None) -> None:
        """Remember which program is stopped (the owner of the interruption)."""
        if run is not None and run is not self.channel.overlay:
            self.channel.owner = run.kind

    def _park(self) -> None:
        """Before JOG or another mode touches the axes: keep the interrupted program's
        unexecuted motion and the interruption point, and empty the motion buffer."""
        run = self.channel.run
        if run is None or self.channel.owner is None or self.channel.parked is not None or self.channel.overlay is not None:
            return
        motion = self._path_motion()
        position = self._path_positions(motion)
        self.channel.parked = run.park(motion.current_source(), position)
        self.channel.repos_point = position
        motion.abort(keep_spindles=self.machine.spindles)  # a mode change stops no spindle

    def _resume_motion(self, run: ProgramRun) -> None:
        """NC START of an interrupted program: REPOS (RMI) back, then the remainder."""
        motion = self._path_motion()
        motion.resume()
        if self.channel.parked is None:
            return
        approach: Motion | None = None
        here = self._path_positions(motion)
        point = self.channel.repos_point or {}
        if any(abs(here.get(axis, 0.0) - value) > 1e-6 for axis, value in point.items()):
            first = next((i for i in self.channel.parked if isinstance(i, Motion)), None) or run.last_motion
            feed = first.feed_mm_min if first is not None and first.kind != "G0" else None
            source = first.source if first is not None else Source(run.name, 0)
            approach = Motion(
                kind="G0" if feed is None else "G1", source=source, plane="G17",
                end_wcs={a: v - self.outputs.wcs_offset.get(a, 0.0) for a, v in point.items()},
                end_mcs=dict(point), start_mcs=here, feed_mm_min=feed, exact_stop=True, inserted=True,
            )
        run.requeue(list(self.channel.parked), approach)
        self.channel.parked = None

    def _interpreter(self, kind: str) -> Interpreter:
        """The interpreter of mode ``kind`` (created on first use)."""
        return self.interpreters.get(kind)

    def _wire_interpreter(self, interp: Interpreter) -> None:
        """Connect a new interpreter to the kernel: positions, probe results, access level, skip levels."""
        if hasattr(interp, "position_source"):
            # Read only after the implicit STOPRE of needs_preprocessing_stop().
            interp.position_source = self._actual_position  # type: ignore[attr-defined]
        if hasattr(interp, "measurement_source"):  # MEAS/MEAW results (nck.kernel_contact)
            interp.measurement_source = self.contact_watch.measurement  # type: ignore[attr-defined]
        if hasattr(interp, "access_level"):  # setting-data writes of part programs
            interp.access_level = self._access_level  # type: ignore[attr-defined]
        self.settings.apply_skip_levels(interp)

    def _path_positions(self, motion: Any) -> dict[str, float]:
        """Actual MCS positions of the path axes (no spindles) of ``motion``."""
        return self.plant.positions(motion)

    def _actual_position(self, axis: str) -> float:
        """Actual MCS position of ``axis`` (for ``$AA_IM`` and friends)."""
        return float(self._path_motion().positions_mcs().get(axis, 0.0))

    def current_source(self) -> Any:
        """The block the program's motion executes now (None: idle)."""
        return self._path_motion().current_source()

    def _path_motion(self) -> Any:
        """The motion system programs run on: the simulated one under program test."""
        test_motion = self.plant.test_motion
        return test_motion if self.switches.program_control["program_test"] and test_motion else self.motion

    def _display_motion(self) -> Any:
        return self.plant.test_motion if self.plant.test_motion is not None else self.motion

    def _run_options(self) -> RunOptions:
        """The program-control switches the run reads; the same object while they stay (asked
        before every block)."""
        control = self.switches.program_control
        single_block, m01 = control["single_block"], bool(control["m01"])
        options = self._options
        if options.single_block != single_block or options.m01 != m01:
            options = self._options = RunOptions(single_block=single_block, m01=m01)  # type: ignore[arg-type]
        return options

    def _unreferenced_axes(self) -> list[str]:
        if int(self.machine.md_value("MD20700", None, 1) or 0) == 0:
            return []
        missing = []
        for axis in self.machine.path_axes:
            if int(self.machine.md_value("MD34110", axis, 1) or 0) == -1:
                continue
            if not self.motion.is_referenced(axis):
                missing.append(axis)
        return missing

    def _ipo_cycle_s(self) -> float:
        sysclock = self.machine.md_value("MD10050", None, None)
        ratio = self.machine.md_value("MD10070", None, None)
        if isinstance(sysclock, (int, float)) and isinstance(ratio, (int, float)) and sysclock * ratio > 0:
            return float(sysclock) * float(ratio)
        return DEFAULT_IPO_S

    def _raise(self, error: NcAlarmError) -> AlarmEntry:
        if self.alarm_listener is not None:
            self.alarm_listener(error)
        block = f"N{error.n}" if error.n is not None else (str(error.line) if error.line else "")
        return self.alarms.raise_alarm(error.number, error.params, now_s=self._time_s, block=block,
                                       file=error.file, line=error.line, n=error.n)

    def _raise_number(self, number: int, *params: object) -> None:
        if self.alarm_listener is not None:
            self.alarm_listener(NcAlarmError(number, *params))
        self.alarms.raise_alarm(number, tuple(str(p) for p in params), now_s=self._time_s)

    def _internal_error(self, exc: BaseException) -> None:
        self.internal_errors.append(traceback.format_exc())
        text = f"{type(exc).__name__}: {exc}"[:120]
        try:
            self.alarms.raise_alarm(INTERNAL_ERROR, (text,), now_s=self._time_s)
        except Exception:  # noqa: BLE001 - the alarm server itself failed
            pass

    def _program_test_ended(self) -> None:
        """Program test was switched off by SERUPRO: the simulated axes go, the machine's get
        the override and dry-run switches."""
        self.plant.test_motion = None
        self.settings.apply_overrides()
        self.settings.apply_dry_run()

    def _internal_reset(self) -> None:
        """After an internal error in a cycle: stop everything, keep the alarms."""
        try:
            self.motion.abort()
        except Exception:  # noqa: BLE001
            pass
        self.channel.clear_programs()
        if not self.switches.program_control["program_test"]:
            self.plant.test_motion = None
        self.channel.situation = ChannelSituation(self.channel.situation.mode, RESET, ABORTED)

    # ------------------------------------------------------------- status


COMMANDS: CommandTable[Nck] = CommandTable()
"""Where each command is carried out: command class -> the ``Nck`` method (the channel's
commands: modes, NC START/STOP, RESET, program selection) or the method of one of its parts
(``Nck.manual`` of nck.kernel_manual, ``Nck.settings`` of nck.kernel_settings,
``Nck.protection`` of nck.kernel_access, ``Nck.data_writes`` of nck.kernel_data, ``Nck.setup``
of nck.kernel_setup, ``Nck.search`` of nck.kernel_search). Typed: mypy checks that a handler
takes its command."""
COMMANDS.register(cmd.SelectMode, Nck._select_mode)
COMMANDS.register_part(cmd.SelectMachineFunction, lambda nck: nck.manual, ManualControl.select_machine_function)
COMMANDS.register_part(cmd.SelectIncrement, lambda nck: nck.manual, ManualControl.select_increment)
COMMANDS.register(cmd.CycleStart, Nck._cycle_start)
COMMANDS.register(cmd.CycleStop, Nck._cycle_stop)
COMMANDS.register(cmd.Reset, Nck._reset)
COMMANDS.register(cmd.EmergencyStop, Nck._emergency_stop)
COMMANDS.register(cmd.SelectProgram, Nck._select_program)
COMMANDS.register(cmd.SetMdaProgram, Nck._set_mda)
COMMANDS.register_part(cmd.SetProgramControl, lambda nck: nck.settings, ControlSettings.set_program_control)
COMMANDS.register_part(cmd.SetOverride, lambda nck: nck.settings, ControlSettings.set_override)
COMMANDS.register(cmd.CancelAlarms, Nck._cancel_alarms)
COMMANDS.register_part(cmd.Jog, lambda nck: nck.manual, ManualControl.jog)
COMMANDS.register_part(cmd.SetControllerEnable, lambda nck: nck.settings, ControlSettings.set_controller_enable)
COMMANDS.register_part(cmd.SetSpindleDriveFault, lambda nck: nck.settings, ControlSettings.set_spindle_drive_fault)
COMMANDS.register_part(cmd.StartBlockSearch, lambda nck: nck.search, BlockSearchControl.start_block_search)
COMMANDS.register_part(cmd.WriteData, lambda nck: nck.data_writes, DataWrites.write_data)
COMMANDS.register_part(cmd.SetKeyswitch, lambda nck: nck.protection, Protection.set_keyswitch)
COMMANDS.register_part(cmd.EnterPassword, lambda nck: nck.protection, Protection.enter_password)
COMMANDS.register_part(cmd.DeletePassword, lambda nck: nck.protection, Protection.delete_password)
COMMANDS.register_part(cmd.ChangePassword, lambda nck: nck.protection, Protection.change_password)
COMMANDS.register_part(cmd.DeleteToolEdge, lambda nck: nck.data_writes, DataWrites.delete_tool_edge)
COMMANDS.register_part(cmd.ClearRParameters, lambda nck: nck.data_writes, DataWrites.clear_r_parameters)
COMMANDS.register_part(cmd.ActivateMachineData, lambda nck: nck.data_writes, DataWrites.activate_machine_data)
COMMANDS.register_part(cmd.WriteMachineSetup, lambda nck: nck.setup, JobSetup.write_machine_setup)
COMMANDS.register_part(cmd.WriteManualSettings, lambda nck: nck.setup, JobSetup.write_manual_settings)
COMMANDS.register_part(cmd.SetActualValue, lambda nck: nck.setup, JobSetup.set_actual_value)
COMMANDS.register_part(cmd.SetWorkOffsetRotation, lambda nck: nck.setup, JobSetup.set_work_offset_rotation)
COMMANDS.register_part(cmd.DeleteActiveWorkOffset, lambda nck: nck.setup, JobSetup.delete_active_work_offset)
