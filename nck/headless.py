"""Headless program run: the loop behind ``nck run`` and ``nck check``.

For now the loop drives the interpreter directly: each motion segment is
placed at its end point, and ``machine_time_s`` is the sum of the blocks'
interpretation cost plus a feed-based estimate of each segment (path length /
feed; rapid traverse at the slowest programmed axis' MD32000). The kernel will
later take over this loop; keep :func:`run_program`'s signature.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.api import ProgramSource
from nck.interp.interpreter import Interpreter
from nck.machine import MachineConfig
from nck.ncdata import NcData
from nck.resources import alarm_text

DEFAULT_RAPID_MM_MIN = 10000.0


@dataclass
class RunResult:
    """Outcome of a headless run.

    ``status`` is ``ended`` (M2/M30/M17/end of file), ``alarm`` or ``timeout``;
    ``exit_code`` follows the CLI contract (0, 1, 3).
    """

    status: str
    alarms: list[NcAlarmError] = field(default_factory=list)
    commands: list[canon.CanonCommand] = field(default_factory=list)
    blocks: int = 0
    machine_time_s: float = 0.0
    interpreter: Interpreter | None = None

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
    dialect: str = "siemens",
    text: str | None = None,
    skip_levels: frozenset[int] = frozenset(),
) -> RunResult:
    """Run ``program_name`` from channel reset to its end, an alarm or the timeout.

    ``text`` runs the given text under ``program_name`` instead of reading it.
    ``on_command`` sees every canonical command as it is produced.
    """
    interp = Interpreter(machine, programs, data, dialect=dialect)
    interp.skip_levels = frozenset(skip_levels)
    result = RunResult(status="ended", interpreter=interp)
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
    while not interp.finished:
        if (timeout_s is not None and clock >= timeout_s) or (
                max_blocks is not None and result.blocks >= max_blocks):
            result.status = "timeout"
            break
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
            result.commands.append(command)
            if on_command is not None:
                on_command(command)
            if isinstance(command, canon.Motion):
                clock += segment_time_s(machine, command)
            elif isinstance(command, canon.Dwell) and command.seconds:
                clock += command.seconds
            elif isinstance(command, canon.UserAlarm):
                alarm = NcAlarmError(command.number, *command.params, file=command.source.file,
                                     line=command.source.line, n=command.source.n)
                result.alarms.append(alarm)
                stop = True
        if stop:
            result.status = "alarm"
            break
    result.machine_time_s = clock
    return result


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


def format_alarm(alarm: NcAlarmError) -> str:
    """``ALARM 12080 PART1.MPF:17 N170 <text>`` (the CLI's stderr line)."""
    where = f"{alarm.file or '-'}:{alarm.line if alarm.line is not None else '-'}"
    block = f"N{alarm.n}" if alarm.n is not None else "-"
    return f"ALARM {alarm.number} {where} {block} {alarm_message(alarm)}"


def alarm_message(alarm: NcAlarmError) -> str:
    """The alarm text with channel and block filled in."""
    block = f"N{alarm.n}" if alarm.n is not None else (str(alarm.line) if alarm.line else "-")
    return alarm_text(alarm.number, ("1", block, *alarm.params))
