"""A loaded program: its lines, labels, block numbers, control-structure matching.

A Siemens program is scanned once at load time: every line is checked (plain and
simple motion blocks by patterns, :mod:`nck.lang.plain`; the rest by the parser),
but only what the run needs is kept — the text, a line-start checkpoint every
64 lines (:class:`~nck.lang.lines.TextLines`), the alarms of lines
that do not parse, labels, control-structure partners and the runs of plain
lines. Lines are parsed again when execution reaches them (bounded cache), so
the memory of a program does not grow with its length beyond its text. A line
that fails to parse keeps its alarm, raised only when execution reaches the
line (and reported by ``nck check``). Control structures (IF/ELSE/ENDIF,
WHILE, FOR, LOOP, REPEAT) are matched statically; a mismatch is an alarm
attached to the offending line.
"""

from __future__ import annotations

import bisect
from array import array
from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np

from nck.alarm_ids import (
    CONTROL_STRUCTURES_NOT_NESTED, CONTROL_STRUCTURES_TOO_DEEP, DEFINITION_AFTER_STATEMENT,
    G_FUNCTION_UNKNOWN, G_GROUP_PROGRAMMED_TWICE, JUMP_TARGET_NOT_FOUND, LABEL_DEFINED_TWICE,
)
from nck.errors import NcAlarmError
from nck.lang.lines import CACHE_LINES, CHECKPOINT_LINES, Line, LineSequence, TextLines, remember_bounded
from nck.lang import ast
from nck.lang.dialect import SIEMENS, Dialect
from nck.lang.gcodes import gtable
from nck.lang.parser import parse_block
from nck.lang.plain import NOT_PLAIN_LINE, SIMPLE_LINE, has_statements, match_plain

MAX_STRUCTURE_DEPTH = 16  # nesting depth of control structures per program level

_OPENERS = {"IF": "ENDIF", "WHILE": "ENDWHILE", "FOR": "ENDFOR", "LOOP": "ENDLOOP", "REPEAT": "UNTIL"}
_CLOSERS = {closer: opener for opener, closer in _OPENERS.items()}


@dataclass
class Program:
    """A program ready for execution.

    Attributes:
        name: display name (``PART1.MPF``).
        lines: every source line in order (a Siemens text: :class:`TextLines`, parsed on
            demand; an ISO text: the list of translated lines).
        labels: label → line index (first definition).
        numbers: block number → line indices (ISO lists; a scanned text indexes its
            numbers on the first :meth:`find_number`).
        partner: for control-structure lines: the index of the matching line
            (IF → ENDIF, ELSE → ENDIF, WHILE ↔ ENDWHILE, FOR ↔ ENDFOR,
            LOOP ↔ ENDLOOP, REPEAT ↔ UNTIL, ENDIF → IF).
        else_of: IF line index → its ELSE line index.
        structure_errors: line index → alarm (mismatched or too deep structures,
            duplicate labels).
        proc: the PROC statement of the first block, if any.
        plain_starts, plain_stops: the runs of plain lines of a scanned text.
        without_dollar: a scanned text without any ``$``: none of its lines reads main-run
            data (one scan of the text at load time instead of a look at every line as it
            comes, :meth:`Interpreter.needs_preprocessing_stop`).
    """

    name: str
    lines: LineSequence
    labels: dict[str, int] = field(default_factory=dict)
    numbers: dict[int, list[int]] = field(default_factory=dict)
    partner: dict[int, int] = field(default_factory=dict)
    else_of: dict[int, int] = field(default_factory=dict)
    structure_errors: dict[int, NcAlarmError] = field(default_factory=dict)
    jump_warnings: dict[int, NcAlarmError] = field(default_factory=dict)
    proc: ast.Proc | None = None
    plain_starts: array | None = None  # scanned programs: first line of every run of plain lines
    plain_stops: array | None = None  # … and the line after its last one
    without_dollar: bool = False

    def __deepcopy__(self, memo: dict) -> "Program":
        """Programs are immutable once loaded: snapshots share them."""
        return self

    def problems(self) -> list[NcAlarmError]:
        """Every static problem (parse errors and structure errors), in line order."""
        if isinstance(self.lines, TextLines):
            found = dict(self.jump_warnings)
            found.update(self.structure_errors)
            found.update(self.lines.errors)
            return [found[index] for index in sorted(found)]
        result: list[tuple[int, NcAlarmError]] = []
        for index, line in enumerate(self.lines):
            if line.error is not None:
                result.append((index, line.error))
            elif index in self.structure_errors:
                result.append((index, self.structure_errors[index]))
            elif index in self.jump_warnings:
                result.append((index, self.jump_warnings[index]))
        return [alarm for _, alarm in result]

    def plain_run_end(self, index: int) -> int:
        """End (exclusive) of the run of plain lines that contains line ``index``; ``index`` if none."""
        starts, stops = self.plain_starts, self.plain_stops
        if not starts or stops is None:
            return index
        position = bisect.bisect_right(starts, index) - 1
        if position >= 0 and index < stops[position]:
            return stops[position]
        return index

    def find_label(self, label: str, start: int, direction: str) -> int | None:
        """Index of the line carrying ``label`` searched from ``start``.

        ``direction``: ``F`` forward (after start), ``B`` backward (start and
        before), ``FB`` forward first, then backward.
        """
        target = self.labels_all.get(label, ())
        return _search(target, start, direction)

    def find_number(self, number: int, start: int, direction: str) -> int | None:
        """Index of the line with block number ``number`` searched like find_label."""
        if isinstance(self.lines, TextLines):
            return _search(self._numbered().get(number, ()), start, direction)
        return _search(self.numbers.get(number, ()), start, direction)

    def find_text(self, text: str) -> int | None:
        """Index of the first line whose text contains ``text`` (any case), or None."""
        lines = self.lines
        wanted = text.upper()
        for index in range(len(lines)):
            raw = lines.raw(index) if isinstance(lines, TextLines) else lines[index].text
            if wanted in raw.upper():
                return index
        return None

    def _numbered(self) -> dict[int, list[int]]:
        """Block number → line indices of a scanned program (built on the first jump to a number)."""
        cache = self.__dict__.get("_numbers_all")
        if cache is None:
            cache = {}
            lines = self.lines
            assert isinstance(lines, TextLines)
            for index in range(len(lines)):
                if index in lines.errors:
                    continue
                raw = lines.raw(index)
                found = match_plain(raw)
                if found is not None:
                    number = int(found.group(1)) if found.group(1) is not None else None
                else:
                    number = parse_block(raw, index + 1).number
                if number is not None:
                    cache.setdefault(number, []).append(index)
            self.__dict__["_numbers_all"] = cache
        return cache

    @property
    def labels_all(self) -> dict[str, list[int]]:
        """Label → every line index defining it."""
        cache = getattr(self, "_labels_all", None)
        if cache is None:
            cache = {}
            for index, line in enumerate(self.lines):
                if line.block is not None and line.block.label:
                    cache.setdefault(line.block.label, []).append(index)
            object.__setattr__(self, "_labels_all", cache)
        return cache


def _search(indices: list[int] | tuple[int, ...], start: int, direction: str) -> int | None:
    if direction in ("F", "FB"):
        for index in indices:
            if index > start:
                return index
    if direction in ("B", "FB"):
        for index in reversed(indices):
            if index <= start:
                return index
    return None


def _located(alarm: NcAlarmError, name: str, line: int, n: int | None) -> NcAlarmError:
    return alarm.located(name, line, n)


def load_program(name: str, text: str, dialect: Dialect = SIEMENS, main: bool = False) -> Program:
    """Scan ``text`` into a :class:`Program` called ``name`` (never raises).

    A text the ``dialect`` translates (ISO, or a Siemens text that switches with
    G291) becomes the translated lines (kept parsed).
    """
    key = (name, dialect.program_key(), text)
    cached = _RECENT.get(key)
    if cached is not None:
        return cached
    translated = dialect.translated_lines(name, text, _located, _guess_n, main)
    if translated is not None:
        program = Program(name=name, lines=translated)
        indexer = _Indexer(program)
        for index, line in enumerate(program.lines):
            indexer.add(index, line.number, line.block)
        indexer.finish()
        return program
    program = _load_siemens(name, text)
    remember_bounded(_RECENT, key, program, _RECENT_SIZE)
    return program


_RECENT: dict[tuple[str, object, str], Program] = {}
_RECENT_SIZE = 4
"""Programs loaded last, by (name, dialect, text): a check followed by its run, or a
subprogram called again, is scanned once. Loaded programs are immutable (the
per-line caches are derived from the parsed block), so sharing them is safe."""


def _load_siemens(name: str, text: str) -> Program:
    """One pass over the text: plain lines by pattern, the others parsed and indexed."""
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    count = text.count("\n") + (0 if not text or text.endswith("\n") else 1)
    lines = TextLines(text, count, line_checkpoints(text), {})
    program = Program(name=name, lines=lines, plain_starts=array("q"), plain_stops=array("q"),
                      without_dollar="$" not in text)
    indexer = _Indexer(program)
    errors = lines.errors
    starts, stops = program.plain_starts, program.plain_stops
    assert starts is not None and stops is not None
    index = 0  # line index of the current match
    counted_to = 0
    next_plain = 0  # first line after the last non-plain line
    for found in NOT_PLAIN_LINE.finditer(text):
        raw = found.group(1)
        if not raw:
            break  # the end of the text (a non-plain line is never empty)
        begin = found.start(1)
        index += text.count("\n", counted_to, begin)
        counted_to = begin
        if index > next_plain:
            starts.append(next_plain)
            stops.append(index)
        next_plain = index + 1
        if SIMPLE_LINE.fullmatch(raw) is not None:
            indexer.add_simple(index)  # valid without the parser; parsed when it runs
            continue
        try:
            block = parse_block(raw, index + 1)
        except NcAlarmError as alarm:
            errors[index] = _located(alarm, name, index + 1, _guess_n(raw))
            indexer.add(index, index + 1, None)
        else:
            indexer.add(index, index + 1, block)
            if index < CACHE_LINES:
                lines.remember(index, Line(index + 1, raw, block))
    if count > next_plain:
        starts.append(next_plain)
        stops.append(count)
    indexer.finish()
    return program




def line_checkpoints(text: str) -> array:
    """Offsets of the starts of lines 0, 64, 128, … of ``text``."""
    step = CHECKPOINT_LINES
    if text.isascii() and len(text) > 4096:
        found = array("q", [0])
        seen = 0  # line ends before the window
        window = 1 << 20
        for begin in range(0, len(text), window):
            ends = np.flatnonzero(np.frombuffer(text[begin:begin + window].encode("ascii"), dtype=np.uint8) == 10)
            first = (-seen - 1) % step  # index in ``ends`` of the end of line 64k - 1
            found.extend((ends[first::step] + (begin + 1)).tolist())
            seen += ends.size
        if found[-1] >= len(text) and len(found) > 1:  # a start after the final line end: no line
            found.pop()
        return found
    found = array("q")
    position, index, size = 0, 0, len(text)
    while True:
        if not index % step:
            found.append(position)
        end = text.find("\n", position)
        if end < 0 or end + 1 >= size:
            break
        position = end + 1
        index += 1
    return found


def _guess_n(raw: str) -> int | None:
    """Block number of a line that failed to parse (for the alarm location)."""
    text = raw.strip().lstrip("/").lstrip("0123456789").strip().upper()
    if text.startswith("N"):
        digits = ""
        for ch in text[1:]:
            if ch.isdigit() and ch.isascii():
                digits += ch
            else:
                break
        if digits and len(digits) < 10:
            return int(digits)
    return None


class _Indexer:
    """Labels, block numbers, control-structure partners and static alarms, line by line."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self.stack: list[tuple[str, int]] = []
        self.first_code: int | None = None  # first line with statements (or a parse error)
        self.variables: set[str] = set()  # names DEFined anywhere (GOTOF <variable>)
        self.gotos: list[tuple[int, int, int | None, list[ast.Goto]]] = []
        self.labels_all: dict[str, list[int]] = {}
        self.numbered = not isinstance(program.lines, TextLines)

    def add(self, index: int, line_number: int, block: ast.Block | None) -> None:
        """Index one line (``block`` None: the line did not parse)."""
        program = self.program
        if block is None:
            if self.first_code is None:
                self.first_code = index
            return
        if self.first_code is None and block.statements:
            self.first_code = index
        if block.label:
            self.labels_all.setdefault(block.label, []).append(index)
            if block.label in program.labels:
                program.structure_errors[index] = NcAlarmError(LABEL_DEFINED_TWICE, block.label).located(
                    program.name, line_number, block.number)
            else:
                program.labels[block.label] = index
        if block.number is not None and self.numbered:
            program.numbers.setdefault(block.number, []).append(index)
        gcode_problem = _check_gcodes(block)
        if gcode_problem is not None:
            program.structure_errors[index] = gcode_problem.located(program.name, line_number, block.number)
        gotos: list[ast.Goto] = []
        for stmt in block.statements:
            if isinstance(stmt, ast.Def):
                self.variables.update(decl.name for decl in stmt.names)
            elif isinstance(stmt, ast.Goto):
                gotos.append(stmt)
            elif isinstance(stmt, ast.IfGoto):
                gotos.append(stmt.goto)
            elif isinstance(stmt, ast.Case):
                gotos.extend([g for _, g in stmt.branches] + ([stmt.default] if stmt.default else []))
            if isinstance(stmt, ast.Proc):
                if self.first_code is None or index <= self.first_code:
                    self.first_code = self._first_plain_code(index)
                if self.first_code is None or index <= self.first_code:
                    program.proc = stmt
                else:
                    program.structure_errors[index] = NcAlarmError(DEFINITION_AFTER_STATEMENT).located(
                        program.name, line_number, block.number)
            if not isinstance(stmt, ast.Control):
                continue
            self._control(stmt.kind, index, line_number, block)
        if gotos:
            self.gotos.append((index, line_number, block.number, gotos))

    def add_simple(self, index: int) -> None:
        """Index a simple motion line (:data:`nck.lang.plain.SIMPLE_LINE`) that a scan did not
        parse: it has statements, and no label, control structure, jump or definition."""
        if self.first_code is None:
            self.first_code = index

    def _first_plain_code(self, upto: int) -> int | None:
        """First line before ``upto`` with statements among the plain lines a scan skipped."""
        lines = self.program.lines
        if not isinstance(lines, TextLines):
            return self.first_code
        for index in range(min(upto, self.first_code if self.first_code is not None else upto)):
            found = match_plain(lines.raw(index))
            if found is not None and has_statements(found):
                return index
        return self.first_code

    def _control(self, kind: str, index: int, line_number: int, block: ast.Block) -> None:
        program, stack = self.program, self.stack
        if kind in _OPENERS:
            stack.append((kind, index))
            if len(stack) > MAX_STRUCTURE_DEPTH:
                program.structure_errors[index] = NcAlarmError(CONTROL_STRUCTURES_TOO_DEEP).located(
                    program.name, line_number, block.number)
        elif kind == "ELSE":
            if not stack or stack[-1][0] != "IF" or stack[-1][1] in program.else_of:
                program.structure_errors[index] = NcAlarmError(CONTROL_STRUCTURES_NOT_NESTED).located(
                    program.name, line_number, block.number)
            else:
                program.else_of[stack[-1][1]] = index
        elif kind in _CLOSERS:
            if not stack or stack[-1][0] != _CLOSERS[kind]:
                program.structure_errors[index] = NcAlarmError(CONTROL_STRUCTURES_NOT_NESTED).located(
                    program.name, line_number, block.number)
                return
            _, opener = stack.pop()
            program.partner[opener] = index
            program.partner[index] = opener
            if opener in program.else_of:
                program.partner[program.else_of[opener]] = index

    def finish(self) -> None:
        """Unclosed structures, then jumps whose target cannot be found."""
        program = self.program
        for _kind, index in self.stack:
            line = program.lines[index]
            program.structure_errors.setdefault(index, NcAlarmError(CONTROL_STRUCTURES_NOT_NESTED).located(
                program.name, line.number, line.block.number if line.block else None))
        object.__setattr__(program, "_labels_all", self.labels_all)
        self._check_jumps()

    def _check_jumps(self) -> None:
        """Jumps to labels or block numbers that cannot be found in their direction.

        Found for ``nck check`` only (``jump_warnings``): at run time the jump
        itself raises 14080 when it is taken. A target name that is also a
        variable DEFined in the program (``GOTOF <string variable>``) is skipped.
        """
        program = self.program
        for index, line_number, number, gotos in self.gotos:
            for goto in gotos:
                if goto.kind == "GOTOC" or goto.expr is not None or goto.label in self.variables:
                    continue
                direction = {"GOTOF": "F", "GOTOB": "B", "GOTO": "FB"}[goto.kind]
                if goto.number is not None:
                    found = program.find_number(goto.number, index, direction)
                else:
                    found = program.find_label(goto.label or "", index, direction)
                if found is None:
                    warning = NcAlarmError(JUMP_TARGET_NOT_FOUND, goto.target_text)
                    program.jump_warnings.setdefault(index, warning.located(program.name, line_number, number))


def _check_gcodes(block: ast.Block) -> NcAlarmError | None:
    """Unknown G functions (12470) and two codes of one group (12060), found statically."""
    table = gtable()
    seen: dict[int, str] = {}
    for stmt in block.statements:
        if isinstance(stmt, ast.GWord):
            number = table.group_of.get(stmt.code)
            if number is None:
                return NcAlarmError(G_FUNCTION_UNKNOWN, stmt.code)
            if seen.get(number, stmt.code) != stmt.code:
                return NcAlarmError(G_GROUP_PROGRAMMED_TWICE, number)
            seen[number] = stmt.code
    return None
