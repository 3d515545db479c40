"""Headless program run: the loop behind ``nck run`` and ``nck check``.

``nck run`` goes through the kernel (:func:`run_on_kernel`): the program is
selected in AUTOMATIC with every axis referenced, started with NC START, and
simulated time advances until program end, an alarm or the timeout, so
``machine_time_s`` is the kernel's simulated time. ``nck check`` (a block
budget) interprets without the kernel (:func:`interpret_only`): each segment
is placed at its end point and ``machine_time_s`` is the blocks' cost plus a
feed-based estimate (rapid traverse at the slowest axis' MD32000).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from nck.alarm_ids import INTERNAL_ERROR, PROGRAM_NOT_FOUND
from nck import canon
from nck.errors import NcAlarmError
from nck.interp.api import BLOCK_COST_S, ProgramSource
from nck.interp.interpreter import Interpreter
from nck.interp.program import load_program
from nck.iso.dialect import dialect_for
from nck.machine import MachineConfig
from nck.motion.system import PlannedMotion
from nck.ncdata import NcData
from nck.resources import alarm_catalog
from nck.translations import SOURCE_LANGUAGE, alarm_text_in

DEFAULT_RAPID_MM_MIN = 10000.0


@dataclass
class HeadlessRun:
    """A headless run of a program (``nck run`` on the kernel, ``nck check`` on the
    interpreter alone): how it ended, its alarms and canonical commands, its counters.

    ``status`` is ``ended`` (M2/M30/M17/end of file), ``alarm`` or ``timeout`` (a time or
    block budget ran out, or the caller asked the run to stop);
    ``exit_code`` follows the CLI contract (0, 1, 3). ``position_mcs`` /
    ``position_wcs`` are where the path axes stand at the end of a kernel run
    (None for ``nck check``, which moves nothing: the interpreter's end point).
    """

    status: str
    alarms: list[NcAlarmError] = field(default_factory=list)
    commands: list[canon.CanonCommand] = field(default_factory=list)
    blocks: int = 0
    machine_time_s: float = 0.0
    interpreter: Interpreter | None = None
    position_mcs: dict[str, float] | None = None
    position_wcs: dict[str, float] | None = None

    @property
    def exit_code(self) -> int:
        """0 ended without alarm, 1 alarm, 3 timeout."""
        return {"ended": 0, "alarm": 1, "timeout": 3}[self.status]

    @property
    def segments(self) -> list[canon.Motion]:
        """The motion segments in order."""
        return [c for c in self.commands if isinstance(c, canon.Motion)]


def run_program(
    machine: MachineConfig,
    programs: ProgramSource,
    data: NcData,
    program_name: str,
    *,
    timeout_s: float | None = None,
    max_blocks: int | None = None,
    on_command: Callable[[canon.CanonCommand], None] | None = None,
    dialect: str | None = None,
    text: str | None = None,
    skip_levels: frozenset[int] = frozenset(),
    on_motion: Callable[[Any], None] | None = None,
    keep_commands: bool = True,
    on_block: Callable[[Any], None] | None = None,
    give_up: Callable[[int], bool] | None = None,
) -> HeadlessRun:
    """Run ``program_name`` from channel reset to its end, an alarm or the timeout.

    ``text`` runs the given text under ``program_name`` instead of reading it.
    ``dialect``: the language mode (``siemens``, ``iso-m``, ``iso-t``); None: the machine
    data's mode after power on and RESET (:func:`nck.iso.dialect.language_mode`).
    ``on_command`` sees every canonical command as it is produced;
    ``keep_commands=False`` does not collect them in ``HeadlessRun.commands``
    (long programs: memory stays flat).

    With ``max_blocks`` (``nck check``) the interpreter is driven directly and
    no time is simulated; otherwise the run goes through the kernel
    (:func:`run_on_kernel`): AUTOMATIC, axes referenced, select, NC START,
    ticks until program end, an alarm or ``timeout_s`` of simulated time, or until
    ``give_up`` says so (see :func:`run_on_kernel`).
    """
    if max_blocks is None:
        return run_on_kernel(machine, programs, data, program_name, timeout_s=timeout_s,
                             on_command=on_command, dialect=dialect, text=text,
                             skip_levels=skip_levels, on_motion=on_motion,
                             keep_commands=keep_commands, on_block=on_block, give_up=give_up)
    return interpret_only(machine, programs, data, program_name, timeout_s=timeout_s,
                          max_blocks=max_blocks, on_command=on_command, dialect=dialect,
                          text=text, skip_levels=skip_levels, keep_commands=keep_commands)


class _TextOverlay:
    """A program source that answers ``name`` with ``text`` and delegates the rest."""

    def __init__(self, base: ProgramSource, name: str, text: str) -> None:
        self.base, self.name, self.text = base, name, text

    def read_program(self, name: str) -> tuple[str, str] | None:
        if name.upper() == self.name.upper():
            return self.name, self.text
        return self.base.read_program(name)


KERNEL_CHUNK_S = 10.0  # simulated seconds between timeout checks


def run_on_kernel(
    machine: MachineConfig,
    programs: ProgramSource,
    data: NcData,
    program_name: str,
    *,
    timeout_s: float | None = None,
    on_command: Callable[[canon.CanonCommand], None] | None = None,
    dialect: str | None = None,
    text: str | None = None,
    skip_levels: frozenset[int] = frozenset(),
    on_motion: Callable[[Any], None] | None = None,
    keep_commands: bool = True,
    on_block: Callable[[Any], None] | None = None,
    give_up: Callable[[int], bool] | None = None,
) -> HeadlessRun:
    """The headless run through :class:`nck.kernel.Nck` (see :func:`run_program`).

    ``on_motion`` receives the kernel's motion system before the start (e.g. to trace it);
    ``on_block`` every block the interpreter hands over, before its commands.
    ``give_up`` is asked with the number of blocks run so far before every
    ``KERNEL_CHUNK_S`` of simulated time; True ends the run there (status ``timeout``):
    how a caller in another thread shows progress and drops a run nobody waits for.

    M0/M1 stops are continued with NC START at once (nobody is at the machine).
    """
    from nck import commands as cmd  # here, not at the top: `nck check` builds no kernel and starts faster
    from nck.build import build_nck

    source: ProgramSource = programs if text is None else _TextOverlay(programs, program_name, text)
    interpreters: list[Interpreter] = []
    nck = build_nck(machine, data, source, dialect=dialect, referenced=True, on_interpreter=interpreters.append)
    if on_motion is not None:
        on_motion(nck.motion)
    result = HeadlessRun(status="ended")
    executed = ExecutedCommands(result, on_command, keep_commands)

    def block_done(block: object) -> None:
        result.blocks += 1
        if on_block is not None:
            on_block(block)
        executed.interpreted(getattr(block, "commands", ()), nck.motion.current_source())

    nck.block_listener = block_done
    nck.alarm_listener = result.alarms.append
    nck.submit(cmd.SetProgramControl("skip_levels", frozenset(skip_levels)))
    nck.submit(cmd.SelectMode("AUTO"))
    if isinstance(nck.submit(cmd.SelectProgram(program_name)), cmd.Rejected):
        result.status = "alarm"
        result.alarms.append(NcAlarmError(PROGRAM_NOT_FOUND, program_name).located(program_name, None, None))
        return result
    started = nck.submit(cmd.CycleStart())
    result.interpreter = interpreters[0] if interpreters else None
    if isinstance(started, cmd.Rejected):
        result.status = "alarm"
        if not result.alarms:
            result.alarms.append(NcAlarmError(INTERNAL_ERROR, started.reason))
        return result
    while True:
        if give_up is not None and give_up(result.blocks):
            result.status = "timeout"
            break
        elapsed = nck.time_s
        budget = KERNEL_CHUNK_S if timeout_s is None else min(KERNEL_CHUNK_S, timeout_s - elapsed)
        if budget <= 0.0 or not nck.run_until(lambda k: k.situation.channel != "active", budget,
                                              max_batch_cycles=nck.batch_cycles):
            if timeout_s is not None and nck.time_s >= timeout_s - 1e-9:
                result.status = "timeout"
                break
            continue
        status = nck.status()
        if status.channel.channel_state == "reset":
            break
        if status.channel.stop_reason in ("M0", "M1") and not status.alarms:
            nck.submit(cmd.CycleStart())
            continue
        break
    if nck.internal_errors and not any(a.number == INTERNAL_ERROR for a in result.alarms):
        result.alarms.append(NcAlarmError(INTERNAL_ERROR, "internal error"))
    if result.status != "timeout" and (result.alarms or nck.situation.channel != "reset"):
        result.status = "alarm"
    result.machine_time_s = nck.time_s
    path_axes = [a for a in nck.status().axes if a.kind != "spindle"]
    result.position_mcs = {a.name: a.position_mcs for a in path_axes}
    result.position_wcs = {a.name: a.position_wcs for a in path_axes}
    if result.status == "ended":
        executed.finish(None, result.position_mcs, result.position_wcs)
    else:
        motion = nck.motion
        stop = getattr(motion, "stop_source", None) if getattr(motion, "faulted", False) else None
        executed.finish(stop or motion.current_source(), result.position_mcs, result.position_wcs)
    return result


class ExecutedCommands:
    """Hands on the canonical commands of a kernel run as far as the machine executed them.

    The interpreter runs ahead of the motion; its commands are held back until
    execution has reached the next block. When the run stops early (a block the
    motion refused, a tripped monitor, the timeout) the blocks after the stop
    are never reported, and the block it stopped in ends where the axes stand
    (002 L2397-2416: a block that would pass a software limit is not started).
    """

    def __init__(self, result: HeadlessRun, on_command: Callable[[canon.CanonCommand], None] | None,
                 keep_commands: bool) -> None:
        self.result, self.on_command, self.keep = result, on_command, keep_commands
        self.pending: list[canon.CanonCommand] = []

    def interpreted(self, commands: Any, executing: canon.Source | None) -> None:
        """New commands of the interpreter; those before the ``executing`` block are done.

        ``executing`` None: the machine is idle, so every block before this one has run
        (a loop of messages or dwells must not pile its commands up until the run ends).
        """
        if not self.keep and self.on_command is None:
            return
        if executing is None:
            self._release(self.pending)
            self.pending.clear()
        self.pending.extend(commands)
        index = self._index_of(executing, (canon.Motion, canon.Dwell))
        if index:
            self._release(self.pending[:index])
            del self.pending[:index]

    def finish(self, stop: canon.Source | None, position_mcs: dict[str, float],
               position_wcs: dict[str, float]) -> None:
        """End of run: release what ran; the ``stop`` block (None: all ran) ends at the position
        (a dwell it stopped in had begun: released; nothing after it ran)."""
        index = self._index_of(stop, (canon.Motion, canon.Dwell))
        if index is None:
            self._release(self.pending)
        elif isinstance(self.pending[index], canon.Dwell):
            self._release(self.pending[:index + 1])
        else:
            self._release(self.pending[:index])
            stopped = self.pending[index]
            assert isinstance(stopped, canon.Motion)
            moved = any(abs(position_mcs.get(a, v) - v) > 1e-6 for a, v in stopped.start_mcs.items())
            if moved:
                self._release([dataclasses.replace(
                    stopped,
                    end_mcs={a: position_mcs.get(a, v) for a, v in stopped.end_mcs.items()},
                    end_wcs={a: position_wcs.get(a, v) for a, v in stopped.end_wcs.items()})])
        self.pending.clear()

    def _index_of(self, source: canon.Source | None,
                  kinds: tuple[type, ...] = (canon.Motion,)) -> int | None:
        """Index of the first pending command of ``kinds`` of block ``source`` (None: not pending)."""
        if source is None:
            return None
        for index, command in enumerate(self.pending):
            if isinstance(command, kinds) and command.source is source:
                return index
        return None

    def _release(self, commands: list[canon.CanonCommand]) -> None:
        for command in commands:
            if self.keep:
                self.result.commands.append(command)
            if self.on_command is not None:
                self.on_command(command)


def interpret_only(
    machine: MachineConfig,
    programs: ProgramSource,
    data: NcData,
    program_name: str,
    *,
    timeout_s: float | None = None,
    max_blocks: int | None = None,
    on_command: Callable[[canon.CanonCommand], None] | None = None,
    dialect: str | None = None,
    text: str | None = None,
    skip_levels: frozenset[int] = frozenset(),
    keep_commands: bool = True,
    refusals: Any = None,
    should_stop: Callable[[], bool] | None = None,
) -> HeadlessRun:
    """Interpret ``program_name`` without the kernel (``nck check``): each segment is
    placed at its end point; ``machine_time_s`` is the blocks' cost plus a
    feed-based estimate of each segment.

    ``refusals`` (a ``PlannedMotion``, axes referenced) is asked about every motion: one it
    would refuse (software limit, working area) ends the run with that alarm, as the
    kernel's run would end there.

    When nobody consumes the canonical commands (``keep_commands=False`` and no
    ``on_command``), runs of plain motion blocks are interpreted as batches
    (:meth:`Interpreter.plain_batch`, :func:`batch_clock`) with the same result.

    ``should_stop`` is polled before every block or batch; True ends the run (``timeout``).
    """
    interp = Interpreter(machine, programs, data, dialect=dialect_for(dialect, machine))
    interp.skip_levels = frozenset(skip_levels)
    result = HeadlessRun(status="ended", interpreter=interp)
    try:
        if text is not None:
            interp.start_text(program_name, text)
        else:
            interp.start(program_name)
    except NcAlarmError as alarm:
        result.status = "alarm"
        result.alarms.append(alarm.located(program_name, None, None))
        return result
    clock = 0.0
    batches = not keep_commands and on_command is None  # nobody needs the motions: plain runs in one go
    while not interp.finished:
        if (timeout_s is not None and clock >= timeout_s) or (
                max_blocks is not None and result.blocks >= max_blocks) or (
                should_stop is not None and should_stop()):
            result.status = "timeout"
            break
        if batches:
            left = max_blocks - result.blocks if max_blocks is not None else PLAIN_BATCH_ANY
            batch = interp.plain_batch(left)
            if batch is not None and refusals is not None and refusals.first_refused_end(
                    batch.axes, batch.mcs_mm[:batch.motions_before(batch.blocks)]) is not None:
                batches = False  # find the refused block one by one, with its source
                continue
            if batch is not None:
                count, clock = batch_clock(machine, batch, clock, timeout_s)
                batch.commit(count)
                result.blocks += count
                continue
        try:
            block = interp.step()
        except NcAlarmError as alarm:
            result.status = "alarm"
            result.alarms.append(alarm)
            break
        result.blocks += 1
        clock += block.cost_s
        stop = False
        for command in block.commands:
            if keep_commands:
                result.commands.append(command)
            if on_command is not None:
                on_command(command)
            if isinstance(command, canon.Motion):
                clock += segment_time_s(machine, command)
                refused = refusals.refusal_of(command) if refusals is not None else None
                if refused is not None:
                    result.alarms.append(refused)
                    stop = True
                    break
            elif isinstance(command, canon.Dwell) and command.seconds:
                clock += command.seconds
            elif isinstance(command, canon.UserAlarm):
                set_alarm = NcAlarmError(command.number, *command.params, file=command.source.file,
                                         line=command.source.line, n=command.source.n)
                result.alarms.append(set_alarm)
                stop = True
        if stop:
            result.status = "alarm"
            break
    result.machine_time_s = clock
    return result


PLAIN_BATCH_ANY = 1 << 62  # no block budget


def batch_clock(machine: MachineConfig, batch: Any, clock: float,
                timeout_s: float | None) -> tuple[int, float]:
    """How many blocks of a plain batch run before ``timeout_s``, and the clock after them.

    The same sums as the block-by-block loop, in the same order: per block its
    cost, then its segment's time (:func:`segment_time_s`).
    """
    steps = np.zeros((batch.blocks, 2))
    steps[:, 0] = BLOCK_COST_S
    steps[batch.motion_line, 1] = segment_times_s(machine, batch.axes, batch.deltas_mm, batch.feed_mm_min)
    running = np.cumsum(np.concatenate(([clock], steps.ravel())))
    count = batch.blocks
    if timeout_s is not None:
        before = running[0:-1:2]  # the clock before each block
        late = np.flatnonzero(before >= timeout_s)
        if late.size:
            count = int(late[0])
    return count, float(running[2 * count])


def segment_times_s(machine: MachineConfig, axes: tuple[str, ...], deltas_mm: Any, feed_mm_min: Any) -> Any:
    """:func:`segment_time_s` of many segments (rows of ``deltas_mm``; NaN feed = rapid)."""
    squares = deltas_mm[:, 0] * deltas_mm[:, 0] if len(axes) else np.zeros(len(feed_mm_min))
    for i in range(1, len(axes)):
        squares = squares + deltas_mm[:, i] * deltas_mm[:, i]
    rapid = np.isnan(feed_mm_min)
    with np.errstate(divide="ignore", invalid="ignore"):
        times = np.sqrt(squares) / feed_mm_min * 60.0
    if rapid.any():
        slowest = np.zeros(len(feed_mm_min))
        for i, axis in enumerate(axes):
            velocity = machine.md_value("MD32000", axis, DEFAULT_RAPID_MM_MIN) or DEFAULT_RAPID_MM_MIN
            slowest = np.maximum(slowest, np.abs(deltas_mm[:, i]) / float(velocity) * 60.0)
        times = np.where(rapid, slowest, times)
    return times


CHECK_BLOCK_BUDGET = 200_000  # blocks a check may interpret before it stops quietly


def check_program(machine: MachineConfig, programs: ProgramSource, name: str, text: str,
                  data: NcData | None = None, max_blocks: int = CHECK_BLOCK_BUDGET,
                  dialect: str | None = None) -> list[NcAlarmError]:
    """Every problem of a program: static ones (all lines), else the first run-time alarm.

    Static problems are syntax errors and control-structure errors of every
    line; when there are none, the program is interpreted (without moving
    anything) up to its end or ``max_blocks`` blocks to find run-time alarms.
    """
    return check_outcome(machine, programs, name, text, data, max_blocks, dialect).alarms


@dataclass(frozen=True)
class CheckOutcome:
    """What ``nck check`` found: the alarms, and whether the run reached the program end."""

    alarms: list[NcAlarmError]
    ended: bool  # False: the block budget ran out first (an endless loop, or a longer program)
    blocks: int


def check_outcome(machine: MachineConfig, programs: ProgramSource, name: str, text: str,
                  data: NcData | None = None, max_blocks: int = CHECK_BLOCK_BUDGET,
                  dialect: str | None = None) -> CheckOutcome:
    """As :func:`check_program`, and say whether the program ended within ``max_blocks``."""
    found = load_program(name, text, dialect_for(dialect, machine)).problems()
    if found:
        return CheckOutcome(found, True, 0)
    data = data or NcData()
    refusals = PlannedMotion(machine, referenced=True, setting_data=data.setting_data)
    outcome = interpret_only(machine, programs, data, name, text=text, max_blocks=max_blocks,
                             dialect=dialect, keep_commands=False, refusals=refusals)
    return CheckOutcome(list(outcome.alarms), outcome.status != "timeout", outcome.blocks)


def segment_time_s(machine: MachineConfig, motion: canon.Motion) -> float:
    """Estimated traverse time of one segment (no acceleration)."""
    deltas = {a: motion.end_mcs.get(a, 0.0) - motion.start_mcs.get(a, motion.end_mcs.get(a, 0.0))
              for a in motion.end_mcs}
    if motion.feed_mm_min:
        length = math.sqrt(sum(d * d for d in deltas.values()))
        return length / motion.feed_mm_min * 60.0
    slowest = 0.0
    for axis, delta in deltas.items():
        velocity = machine.md_value("MD32000", axis, DEFAULT_RAPID_MM_MIN) or DEFAULT_RAPID_MM_MIN
        slowest = max(slowest, abs(delta) / float(velocity) * 60.0)
    return slowest


def format_alarm(alarm: NcAlarmError, language: str = SOURCE_LANGUAGE) -> str:
    """``ALARM 12080 PART1.MPF:17 N170 <text>`` (the CLI's stderr line; the text in ``language``)."""
    where = f"{alarm.file or '-'}:{alarm.line if alarm.line is not None else '-'}"
    block = f"N{alarm.n}" if alarm.n is not None else "-"
    return f"ALARM {alarm.number} {where} {block} {alarm_message(alarm, language)}"


def alarm_message(alarm: NcAlarmError, language: str = SOURCE_LANGUAGE) -> str:
    """The alarm text with channel and block filled in, in ``language`` (``nck --lang``)."""
    block = f"N{alarm.n}" if alarm.n is not None else (str(alarm.line) if alarm.line else "-")
    if alarm.number not in alarm_catalog():
        kind = "cycle/user alarm" if 60000 <= alarm.number <= 69999 else "alarm"
        return " ".join([f"Channel 1 block {block}: {kind} {alarm.number}", *alarm.params])
    definition = alarm_catalog()[alarm.number]
    params = definition.with_channel(alarm.params, "1", block)
    return alarm_text_in(language, alarm.number, params, definition.format(params))
