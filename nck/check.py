"""Check and dry-run a program text without a channel: what the editor and its simulation use.

Two passes, both pure and deterministic (no clock, no threads; the HMI runs them
in a worker thread and shows the results as they come):

1. **Block syntax**, line by line with the language's block parser: every
   faulty line is reported, so a trainee sees all syntax errors at once.
   Then the **control structure** of the whole text (IF/ENDIF, loops) with the
   interpreter's program loader, on the lines without a syntax error.
2. **Interpretation**: the interpreter runs the whole program headless (no axis
   moves; ``nck check``'s run, :func:`nck.headless.interpret_only`). This finds what one
   line cannot show (undefined labels, nesting, unknown subprograms, values out of
   range …). The run stops at the first alarm, as the control would; that alarm
   is reported unless its line already has a syntax alarm.

The editor's simulation runs the program as AUTO runs it (:func:`nck.simulation.run.simulate`).

Both run on a machine and NC data they are given (the default mill and fresh data
when none). The HMI's editor takes the session's through :class:`CheckContext`, the
answer of the query ``nck.queries.CheckSetting``: the session's machine and a copy of
its NC data (tools, work offsets, R parameters, setting data, GUD), so a program
that is valid only with the session's data checks clean and simulates the path
the run would take.
"""

from __future__ import annotations

import copy
import functools
import re
from dataclasses import dataclass, replace
from typing import Any, Callable, Iterator

from nck.alarm_ids import BLOCK_TOO_COMPLEX
from nck.errors import NcAlarmError
from nck.headless import interpret_only
from nck.interp.program import load_program
from nck.interp.sources import program_file_key
from nck.iso.dialect import dialect_for, language_mode
from nck.iso.loader import wants_iso
from nck.lang.parser import parse_block
from nck.lang.plain import NOT_SIMPLE_LINE
from nck.machine import load_machine
from nck.motion.system import PlannedMotion
from nck.ncdata import NcData
from nck.resources import alarm_text
from nck.simulation.run import Simulation, simulate

_BLOCK_NUMBER = re.compile(r"\s*(?:/\d?\s*)?[Nn](\d+)\b")

MAX_RUN_BLOCKS = 200_000
"""A headless run stops after this many interpreted blocks (endless loops end)."""

@dataclass(frozen=True, slots=True)
class CheckAlarm:
    """One problem found in a program text.

    Attributes:
        number: SINUMERIK alarm number.
        line: 1-based source line of the checked text (None when the alarm has no line); for
            an alarm in a program it called (a cycle, a subprogram), the line of the call.
        n: block number of the block, if known.
        text: the formatted alarm text.
        params: the alarm parameters.
        text_params: every value of the text's placeholders (the channel and block first, then
            ``params``): what a panel needs to format the text in another language.
        called_file, called_line: where in the called program the alarm came (None for an
            alarm of the checked text itself).
    """

    number: int
    line: int | None
    n: int | None
    text: str
    params: tuple[str, ...] = ()
    text_params: tuple[str, ...] = ()
    called_file: str | None = None
    called_line: int | None = None


def _alarm(error: NcAlarmError, fallback_line: int | None = None) -> CheckAlarm:
    line = error.line if error.line is not None else fallback_line
    block = f"N{error.n}" if error.n is not None else (str(line) if line is not None else "")
    params = ("1", block)
    return CheckAlarm(
        number=error.number,
        line=line,
        n=error.n,
        text=alarm_text(error.number, params + error.params),
        params=error.params,
        text_params=params + error.params,
    )


@functools.lru_cache(maxsize=300_000)
def _line_problem(line: str) -> tuple[int, tuple[str, ...], int | None] | None:
    """Parse one line; return (alarm number, params, block number) or None (cached by text).

    The cache makes re-checking an edited program cost only the changed lines. The syntax pass
    asks only about lines that are not simple motion lines (those are valid without the parser).
    """
    try:
        parse_block(line, 1)
    except NcAlarmError as error:
        return error.number, error.params, error.n
    except RecursionError:
        return BLOCK_TOO_COMPLEX, (), None
    return None


SCAN_CHUNK_CHARS = 1 << 16
"""The syntax pass scans the text in pieces of about this many characters (whole lines), so that
``should_stop`` is polled between them."""


def iter_syntax_alarms(
    text: str, should_stop: Callable[[], bool] | None = None
) -> Iterator[CheckAlarm]:
    """Yield a syntax alarm for every line the block parser refuses (pass 1).

    Stretches of simple motion lines (valid without the parser) are skipped by one pattern
    scan; the other lines are parsed. ``should_stop`` is polled before every piece of the scan
    and every 16 parsed lines; True ends the pass early.
    """
    index = 0  # 0-based line of ``counted_to``
    counted_to = 0
    position, size = 0, len(text)
    parsed = 0
    while position < size:
        if should_stop is not None and should_stop():
            return
        end = text.find("\n", position + SCAN_CHUNK_CHARS)
        end = size if end < 0 else end + 1
        for found in NOT_SIMPLE_LINE.finditer(text, position, end):
            line = found.group(1)
            if not line:
                break  # the end of the piece (a line that is not simple is never empty)
            begin = found.start(1)
            index += text.count("\n", counted_to, begin)
            counted_to = begin
            parsed += 1
            if should_stop is not None and parsed % 16 == 0 and should_stop():
                return
            if not line.strip():
                continue
            problem = _line_problem(line)
            if problem is not None:
                number, params, n = problem
                if n is None:
                    block = _BLOCK_NUMBER.match(line)
                    n = int(block.group(1)) if block else None
                yield _alarm(NcAlarmError(number, *params, line=index + 1, n=n), index + 1)
        position = end


def iter_structure_alarms(name: str, text: str, machine: Any = None) -> Iterator[CheckAlarm]:
    """Yield the control-structure problems of the whole text (IF without ENDIF, …) in the
    language mode of ``machine`` after RESET (the default mill's: Siemens mode).

    Uses the interpreter's program loader, which knows the nesting rules; it reports the
    lines with syntax errors again (the only report of them in a text that switches to ISO
    mode with G291, whose syntax errors only the loader can find).
    """
    try:
        problems = load_program(name, text, dialect_for(None, machine)).problems()
    except RecursionError:
        return
    for error in problems:
        yield _alarm(error)


class _OverlaySource:
    """Serves the edited text under its own name, everything else from ``fallback``."""

    def __init__(self, name: str, text: str, fallback: Any | None) -> None:
        self._name = name
        self._text = text
        self._fallback = fallback

    def read_program(self, name: str) -> tuple[str, str] | None:
        """The edited program by its name (with or without extension), else the fallback."""
        wanted = name.upper().rsplit("/", 1)[-1]
        own = self._name.upper().rsplit("/", 1)[-1]
        if wanted in (own, own.rsplit(".", 1)[0]):
            return self._name, self._text
        if self._fallback is None:
            return None
        return self._fallback.read_program(name)


def iter_check(
    name: str,
    text: str,
    *,
    machine: Any = None,
    programs: Any = None,
    data: Any = None,
    should_stop: Callable[[], bool] | None = None,
) -> Iterator[CheckAlarm]:
    """Yield every problem of a program text, syntax errors first (streamed).

    The control-structure problems follow, on lines without a syntax error (the loader
    reports those lines again), so the editor lists what ``nck check`` lists. The
    interpretation pass runs only when neither found anything (the run would stop at the
    first one anyway). A text in ISO dialect — the machine starts in ISO mode (MD20150[46]),
    or the text switches with G291 — is read as the interpreter reads it, its ISO lines
    translated (not line by line in Siemens mode: ``G81 … R2`` is an ISO drilling cycle
    there, not a syntax error).
    """
    machine = machine or load_machine()
    syntax_lines: set[int | None] = set()
    if wants_iso(text, language_mode(machine)):
        static = list(iter_structure_alarms(name, text, machine))
    else:
        for alarm in iter_syntax_alarms(text, should_stop):
            syntax_lines.add(alarm.line)
            yield alarm
        if should_stop is not None and should_stop():
            return
        static = [alarm for alarm in iter_structure_alarms(name, text, machine) if alarm.line not in syntax_lines]
    yield from static
    if static or syntax_lines:
        return
    data = data if data is not None else NcData()
    stopped_by = _run_alarm(name, text, machine, programs, data, should_stop)
    if stopped_by is not None:
        yield stopped_by


def _run_alarm(name: str, text: str, machine: Any, programs: Any, data: NcData,
               should_stop: Callable[[], bool] | None = None) -> CheckAlarm | None:
    """The alarm that ends the run of ``text`` (pass 2), or None.

    The run is ``nck check``'s (:func:`nck.headless.interpret_only`): it ends at the first
    interpreter alarm, SETAL, or motion the run's motion would refuse — software limit
    (10720), working area (10730), value range — with the axes referenced, as they must be
    for NC START. No motion is kept, so runs of plain blocks go in batches.
    """
    refusals = PlannedMotion(machine, referenced=True, setting_data=data.setting_data)
    try:
        outcome = interpret_only(machine, _OverlaySource(name, text, programs), data, name, text=text,
                                 max_blocks=MAX_RUN_BLOCKS, keep_commands=False, refusals=refusals,
                                 should_stop=should_stop)
    except RecursionError:
        return _alarm(NcAlarmError(BLOCK_TOO_COMPLEX))
    if not outcome.alarms:
        return None
    first = outcome.alarms[0]
    frames = outcome.interpreter.call_stack if outcome.interpreter is not None else []
    if (len(frames) > 1 and frames[0].is_main and first.file is not None
            and program_file_key(first.file) != program_file_key(name)):
        # the main program's level waits behind its call: its next line follows the call's
        return replace(_alarm(first), line=frames[0].pc, called_file=first.file, called_line=first.line)
    return _alarm(first)


def check_text(name: str, text: str, **options: Any) -> list[CheckAlarm]:
    """Every problem of a program text as a list (see :func:`iter_check`)."""
    return list(iter_check(name, text, **options))


@dataclass(frozen=True)
class CheckContext:
    """The machine and NC data a check or a simulation of a program text runs on.

    ``data`` is a private copy of the session's NC data, taken when the context was
    asked for (in the thread that owns the kernel); each check or run works on its own
    copy of it, so a program that writes R parameters or tool data changes neither
    the session nor the next run, and the context may be used from a worker thread.
    ``None`` means the default machine or fresh NC data.
    """

    machine: Any = None
    data: NcData | None = None

    def _fresh_data(self) -> NcData:
        return copy.deepcopy(self.data) if self.data is not None else NcData()

    def iter_check(self, name: str, text: str, *, programs: Any = None,
                   should_stop: Callable[[], bool] | None = None) -> Iterator[CheckAlarm]:
        """Every problem of ``text`` on this machine and data (see :func:`iter_check`)."""
        return iter_check(name, text, machine=self.machine, programs=programs, data=self._fresh_data(),
                          should_stop=should_stop)

    def simulate(self, name: str, text: str, *, programs: Any = None, resolution_mm: float | None = None,
                 give_up: Callable[[int], bool] | None = None) -> Simulation:
        """Run ``text`` as AUTO runs it on this machine and data and cut the blank with it
        (see :func:`nck.simulation.run.simulate`)."""
        return simulate(name, text, machine=self.machine, programs=programs, data=self._fresh_data(),
                        resolution_mm=resolution_mm, give_up=give_up)
