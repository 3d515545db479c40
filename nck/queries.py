"""Read-only questions to the kernel, for clients that must not hold it (the HMI's screens).

A screen asks the HMI bridge, ``bridge.query(AlarmHistory())``; the bridge, the only
holder of the kernel, answers with :func:`answer`. Each question is a small frozen
class; its docstring says what the answer is. Writes are never answered here: they
are commands (``nck.commands``) submitted through the bridge.

The answers are the kernel's own read accessors. :class:`DataView` hands out the live
configuration and NC data objects for reading (the tables of the Parameter and Setup
areas are built from them); they are read only, changed only by ``WriteData`` commands.
A kernel stand-in that lacks an accessor answers "nothing" (an empty tuple, ``None``,
level 7), as the screens always treated such kernels.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass
from typing import Any, Callable

from nck.check import CheckContext
from nck.ncdata import NcData
from nck.simulation.live import LiveRecording
from nck.simulation.run import Simulation
# Scrubbing through a finished simulation (the editor's Block ◀/▶, playing, the cursor's cut).
from nck.simulation.scrub import Scrubber as Scrubber
# The measuring screens' arithmetic (pure functions on touch positions, nck.measuring),
# re-exported here so that screens reach it through the façade.
from nck.measuring import (Circle as Circle, Corner as Corner, circle as circle, corner as corner,
                           edge_position as edge_position, offset_for as offset_for,
                           rotated_corner as rotated_corner, tool_length as tool_length,
                           tool_radius as tool_radius, z_surface as z_surface)
from nck.status import AlarmEntry, AlarmEvent, LogbookEntry
# The machine set-up as named fields (the Setup area edits it as nck setup does).
from nck.setup_fields import (SetupField as SetupField, SetupFieldError as SetupFieldError,
                              setup_fields as setup_fields, with_field as with_field)
from nck.refusals import rejected_by as rejected_by  # a data layer's refusal (SetupFieldError …) as the panel says it
# The data tables (data/*.toml) the HMI shows as they are, e.g. the cycle forms of the editor.
from nck.resources import load_toml as load_toml
# The alarm catalogue with its help texts (the alarm help of the Diagnostics area).
from nck.resources import AlarmDefinition as AlarmDefinition, alarm_catalog as alarm_catalog
# The classroom (issue 26): exercises as data, their checks, set-up and report files, for
# the panel's Exercises view; pure or writing only the exercise's own directories.
from nck.exercise import Exercise as Exercise, ExerciseError as ExerciseError, load_exercises as load_exercises
from nck.exercise import available_exercises as available_exercises
from nck.paths import default_data_dir as default_data_dir  # where reports go by default (outside a copy)
from nck.class_pack import PackError as PackError, install_pack as install_pack, read_pack as read_pack
from nck.exercise_checks import ExerciseProgress as ExerciseProgress, report_text as report_text
from nck.exercise_files import save_report as save_report
from nck.exercise_setup import prepare_data_dir as prepare_data_dir, start_commands as start_commands

UNPROTECTED_LEVEL = 7
"""The level a kernel without access control asks for (every function is free)."""


@dataclass(frozen=True)
class AlarmHistory:
    """The alarm log (raised and cleared alarms, oldest first): ``tuple[AlarmEntry, ...]``."""


@dataclass(frozen=True)
class AlarmLogSince:
    """The alarm events logged after sequence number ``seq``: ``tuple[AlarmEvent, ...]``."""

    seq: int = 0


@dataclass(frozen=True)
class Logbook:
    """Access-level and machine-data changes since power on: ``tuple[LogbookEntry, ...]``."""


@dataclass(frozen=True)
class BufferFill:
    """(blocks in the motion system's look-ahead buffer, its capacity); (0, 0) when unknown."""


@dataclass(frozen=True)
class Counters:
    """The kernel's IPO cycle and its counters since power on: :class:`KernelCounters`."""


@dataclass(frozen=True)
class KernelCounters:
    """IPO cycle time and what the kernel has done since power on."""

    ipo_cycle_s: float
    cycles_done: int
    blocks_interpreted: int


@dataclass(frozen=True)
class ReadData:
    """The machine configuration, NC data and machine/setting data, for reading: :class:`DataView`."""


@dataclass(frozen=True)
class DataView:
    """What the data tables read: ``machine`` (MachineConfig), ``data`` (NcData), ``machine_data``.

    A field is ``None`` when the kernel does not have that part (a stand-in kernel).
    """

    machine: Any
    data: Any
    machine_data: Any


@dataclass(frozen=True)
class ManualSettingsData:
    """Retraction plane, safety distance, measuring feed of manual mode
    (``nck.commands.ManualSettings``); ``None`` for a kernel without NC data."""


@dataclass(frozen=True)
class AccessStatus:
    """Keyswitch position and password state (``nck.access.AccessState``); ``None`` when unprotected."""


@dataclass(frozen=True)
class RequiredLevel:
    """The protection level writing the datum ``name`` needs (7 when unprotected): ``int``."""

    name: str


@dataclass(frozen=True)
class ActionLevel:
    """The protection level the protected function ``action`` (``"EDIT_PROGRAM"``) needs: ``int``."""

    action: str


@dataclass(frozen=True)
class RecordedCut:
    """Simultaneous recording: the cut of the last AUTO program run as far as it executed
    (:class:`nck.simulation.run.Simulation`, status ``running`` or ``ended``); ``None`` before a
    program was started with recording on (:func:`record_cuts`)."""


@dataclass(frozen=True)
class CheckSetting:
    """What the editor's check and simulation run on: :class:`nck.check.CheckContext`.

    The session's machine and a copy of its NC data (tool table, work offsets, R
    parameters, setting data) taken now; the check and the simulation may then run
    in a worker thread without touching the kernel.
    """


@dataclass(frozen=True)
class ProgramSource:
    """The kernel's program source (``read_program``, ``all_programs`` …); ``None`` without one."""


@dataclass(frozen=True)
class ProgramNames:
    """The part programs the kernel can select: ``list[str]``.

    The main-program paths of its NC file system (``MPF/PART1.MPF``, as the Program
    manager selects them), else the names its program source lists.
    """


@dataclass(frozen=True)
class MachineSetupData:
    """What is clamped on the machine: ``nck.commands.MachineSetup`` (blank, reference block,
    ``hidden``), positions in the MCS; ``None`` for a kernel without NC data.

    A trainee's screen must not show the blank's position when ``hidden`` is set.
    """


@dataclass(frozen=True)
class ContactEvents:
    """Contacts of the tool with the blank or the reference block after ``seq`` (oldest first,
    bounded): ``tuple[nck.kernel_contact.ContactEvent, ...]`` — each with ``kind`` ``"probe"``
    (a 3D probe switched: ``position_mcs`` is its trigger position, the touch for the
    measuring arithmetic), ``"scratch"`` (a turning cutter touched: no alarm) or ``"crash"``
    (alarm 90001-90003, trainer numbers), ``solid``, ``position_mcs`` (machine positions at
    the exact point of contact), ``tool``, ``edge``, ``seq``, ``time_s``."""

    seq: int = 0


@dataclass(frozen=True)
class ProbeDeflected:
    """True while the active tool is a 3D probe (type 710) touching the blank or the reference."""


def _reader(nck: Any, name: str) -> Callable[..., Any] | None:
    reader = getattr(nck, name, None)
    return reader if callable(reader) else None


def _alarm_history(nck: Any, query: AlarmHistory) -> tuple[AlarmEntry, ...]:
    reader = _reader(nck, "alarm_history")
    return tuple(reader()) if reader else ()


def _alarm_log_since(nck: Any, query: AlarmLogSince) -> tuple[AlarmEvent, ...]:
    reader = _reader(nck, "alarm_log_since")
    return tuple(reader(query.seq)) if reader else ()


def _logbook(nck: Any, query: Logbook) -> tuple[LogbookEntry, ...]:
    return tuple(getattr(nck, "logbook", ()) or ())


def _buffer_fill(nck: Any, query: BufferFill) -> tuple[int, int]:
    reader = _reader(nck, "buffer_fill")
    return reader() if reader else (0, 0)


def _counters(nck: Any, query: Counters) -> KernelCounters:
    return KernelCounters(float(getattr(nck, "ipo_cycle_s", 0.0) or 0.0), int(getattr(nck, "cycles_done", 0)),
                          int(getattr(nck, "blocks_interpreted", 0)))


def _read_data(nck: Any, query: ReadData) -> DataView:
    return DataView(getattr(nck, "machine", None), getattr(nck, "data", None), getattr(nck, "machine_data", None))


def _access_status(nck: Any, query: AccessStatus) -> Any:
    return getattr(nck, "access_state", None)


def _required_level(nck: Any, query: RequiredLevel) -> int:
    reader = _reader(nck, "required_level")
    return int(reader(query.name)) if reader else UNPROTECTED_LEVEL


def _action_level(nck: Any, query: ActionLevel) -> int:
    reader = _reader(nck, "action_level")
    return int(reader(query.action)) if reader else UNPROTECTED_LEVEL


def record_cuts(nck: Any) -> None:
    """Switch simultaneous recording on: every following AUTO program start of ``nck`` records
    its cut (:class:`nck.simulation.live.LiveRecording`); ``RecordedCut`` answers it."""
    programs = getattr(nck, "programs", None)

    def text_of(name: str) -> str:
        found = programs.read_program(name) if programs is not None else None
        return found[1] if found else ""

    def start(name: str, tool: int, edge: int) -> LiveRecording:
        return LiveRecording(nck.machine, nck.data, name, text_of(name), tool, edge)

    nck.run_recorder_factory = start


def _recorded_cut(nck: Any, query: RecordedCut) -> Simulation | None:
    recording = getattr(nck, "run_recording", None)
    if recording is None:
        return None
    status = nck.status()
    ended = status.channel.channel_state == "reset"
    return recording.snapshot(nck.current_source(), ended, getattr(nck, "time_s", 0.0))


def _check_setting(nck: Any, query: CheckSetting) -> CheckContext:
    data = getattr(nck, "data", None)
    return CheckContext(getattr(nck, "machine", None), copy.deepcopy(data) if isinstance(data, NcData) else None)


def _program_source(nck: Any, query: ProgramSource) -> Any:
    return getattr(nck, "programs", None)


def _program_names(nck: Any, query: ProgramNames) -> list[str]:
    source = getattr(nck, "programs", None)
    lister = _reader(source, "all_programs")
    if lister:
        return [entry.path for entry in lister() if entry.kind == "MPF"]
    for holder in (nck, source):
        lister = _reader(holder, "list_programs")
        if lister:
            return [str(name) for name in lister()]
    return []


def _manual_settings(nck: Any, query: ManualSettingsData) -> Any:
    return getattr(getattr(nck, "data", None), "manual_settings", None)


def _machine_setup(nck: Any, query: MachineSetupData) -> Any:
    return getattr(getattr(nck, "data", None), "machine_setup", None)


def _contact_events(nck: Any, query: ContactEvents) -> tuple[Any, ...]:
    reader = _reader(nck, "contact_events")
    return tuple(reader(query.seq)) if reader else ()


def _probe_deflected(nck: Any, query: ProbeDeflected) -> bool:
    reader = _reader(nck, "probe_deflected")
    return bool(reader()) if reader else False


ANSWERS: dict[type, Callable[[Any, Any], Any]] = {
    AlarmHistory: _alarm_history,
    AlarmLogSince: _alarm_log_since,
    Logbook: _logbook,
    BufferFill: _buffer_fill,
    Counters: _counters,
    ReadData: _read_data,
    AccessStatus: _access_status,
    RequiredLevel: _required_level,
    ActionLevel: _action_level,
    CheckSetting: _check_setting,
    RecordedCut: _recorded_cut,
    ProgramSource: _program_source,
    ProgramNames: _program_names,
    MachineSetupData: _machine_setup,
    ManualSettingsData: _manual_settings,
    ContactEvents: _contact_events,
    ProbeDeflected: _probe_deflected,
}
"""Question type -> the function that answers it from a kernel."""


def answer(nck: Any, query: object) -> Any:
    """Answer ``query`` (one of the question classes above) from the kernel ``nck``."""
    try:
        handler = ANSWERS[type(query)]
    except KeyError:
        raise TypeError(f"not a kernel query: {query!r}") from None
    return handler(nck, query)
