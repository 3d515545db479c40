"""A loaded program: parsed lines, labels, block numbers, control-structure matching.

Each source line is parsed once at load time. A line that fails to parse keeps
its alarm, raised only when execution reaches the line (and reported by
``nck check``). Control structures (IF/ELSE/ENDIF, WHILE, FOR, LOOP, REPEAT)
are matched statically; a mismatch is an alarm attached to the offending line.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.gcodes import gtable
from nck.lang.parser import parse_block

MAX_STRUCTURE_DEPTH = 16  # nesting depth of control structures per program level

_OPENERS = {"IF": "ENDIF", "WHILE": "ENDWHILE", "FOR": "ENDFOR", "LOOP": "ENDLOOP", "REPEAT": "UNTIL"}
_CLOSERS = {closer: opener for opener, closer in _OPENERS.items()}


@dataclass
class Line:
    """One source line: its parsed block or the alarm its parsing raised."""

    number: int  # 1-based line
    text: str
    block: ast.Block | None
    error: NcAlarmError | None = None
    touches_modal: bool | None = None  # cache for the interpreter's block snapshot
    main_run_read: bool | None = None  # cache: the block reads $A…/$V… (preprocessing stop)


@dataclass
class Program:
    """A program ready for execution.

    Attributes:
        name: display name (``PART1.MPF``).
        lines: every source line in order.
        labels: label → line index (first definition).
        numbers: block number → line indices.
        partner: for control-structure lines: the index of the matching line
            (IF → ENDIF, ELSE → ENDIF, WHILE ↔ ENDWHILE, FOR ↔ ENDFOR,
            LOOP ↔ ENDLOOP, REPEAT ↔ UNTIL, ENDIF → IF).
        else_of: IF line index → its ELSE line index.
        structure_errors: line index → alarm (mismatched or too deep structures,
            duplicate labels).
        proc: the PROC statement of the first block, if any.
    """

    name: str
    lines: list[Line]
    labels: dict[str, int] = field(default_factory=dict)
    numbers: dict[int, list[int]] = field(default_factory=dict)
    partner: dict[int, int] = field(default_factory=dict)
    else_of: dict[int, int] = field(default_factory=dict)
    structure_errors: dict[int, NcAlarmError] = field(default_factory=dict)
    jump_warnings: dict[int, NcAlarmError] = field(default_factory=dict)
    proc: ast.Proc | None = None

    def __deepcopy__(self, memo: dict) -> "Program":
        """Programs are immutable once loaded: snapshots share them."""
        return self

    def problems(self) -> list[NcAlarmError]:
        """Every static problem (parse errors and structure errors), in line order."""
        found: list[tuple[int, NcAlarmError]] = []
        for index, line in enumerate(self.lines):
            if line.error is not None:
                found.append((index, line.error))
            elif index in self.structure_errors:
                found.append((index, self.structure_errors[index]))
            elif index in self.jump_warnings:
                found.append((index, self.jump_warnings[index]))
        return [alarm for _, alarm in found]

    def find_label(self, label: str, start: int, direction: str) -> int | None:
        """Index of the line carrying ``label`` searched from ``start``.

        ``direction``: ``F`` forward (after start), ``B`` backward (start and
        before), ``FB`` forward first, then backward.
        """
        target = self.labels_all.get(label, ())
        return _search(target, start, direction)

    def find_number(self, number: int, start: int, direction: str) -> int | None:
        """Index of the line with block number ``number`` searched like find_label."""
        return _search(self.numbers.get(number, ()), start, direction)

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


def load_program(name: str, text: str, dialect: str = "siemens", main: bool = False) -> Program:
    """Parse ``text`` into a :class:`Program` called ``name`` (never raises).

    In an ISO ``dialect`` (or a Siemens text that switches with G291) the
    lines are first translated by :mod:`nck.iso.translate`.
    """
    from nck.iso.loader import iso_lines, wants_iso
    if wants_iso(text, dialect):
        program = Program(name=name, lines=iso_lines(name, text, dialect, _located, _guess_n, main))
        _index(program)
        _check_jumps(program)
        return program
    key = (name, dialect, text)
    cached = _RECENT.get(key)
    if cached is not None:
        return cached
    program = _load_siemens(name, text)
    try:  # the HMI checks in a worker thread: tolerate a concurrent eviction
        while len(_RECENT) >= _RECENT_SIZE:
            _RECENT.pop(next(iter(_RECENT)), None)
    except (RuntimeError, StopIteration):
        pass
    _RECENT[key] = program
    return program


_RECENT: dict[tuple[str, str, str], Program] = {}
_RECENT_SIZE = 4
"""Programs loaded last, by (name, dialect, text): a check followed by its run, or a
subprogram called again, is parsed once. Loaded programs are immutable (the
per-line caches are derived from the parsed block), so sharing them is safe."""


def _load_siemens(name: str, text: str) -> Program:
    lines: list[Line] = []
    raw_lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    if raw_lines and raw_lines[-1] == "":
        raw_lines.pop()
    for number, raw in enumerate(raw_lines, start=1):
        try:
            block = parse_block(raw, number)
            lines.append(Line(number, raw, block))
        except NcAlarmError as alarm:
            lines.append(Line(number, raw, None, _located(alarm, name, number, _guess_n(raw))))
    program = Program(name=name, lines=lines)
    _index(program)
    _check_jumps(program)
    return program


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


def _index(program: Program) -> None:
    stack: list[tuple[str, int]] = []
    for index, line in enumerate(program.lines):
        block = line.block
        if block is None:
            continue
        if block.label:
            if block.label in program.labels:
                program.structure_errors[index] = NcAlarmError(12450, block.label).located(
                    program.name, line.number, block.number)
            else:
                program.labels[block.label] = index
        if block.number is not None:
            program.numbers.setdefault(block.number, []).append(index)
        gcode_problem = _check_gcodes(block)
        if gcode_problem is not None:
            program.structure_errors[index] = gcode_problem.located(program.name, line.number, block.number)
        for stmt in block.statements:
            if isinstance(stmt, ast.Proc):
                if index == _first_code_line(program, index):
                    program.proc = stmt
                else:
                    program.structure_errors[index] = NcAlarmError(14500).located(
                        program.name, line.number, block.number)
            if not isinstance(stmt, ast.Control):
                continue
            kind = stmt.kind
            if kind in _OPENERS:
                stack.append((kind, index))
                if len(stack) > MAX_STRUCTURE_DEPTH:
                    program.structure_errors[index] = NcAlarmError(12641).located(
                        program.name, line.number, block.number)
            elif kind == "ELSE":
                if not stack or stack[-1][0] != "IF" or stack[-1][1] in program.else_of:
                    program.structure_errors[index] = NcAlarmError(12640).located(
                        program.name, line.number, block.number)
                else:
                    program.else_of[stack[-1][1]] = index
            elif kind in _CLOSERS:
                if not stack or stack[-1][0] != _CLOSERS[kind]:
                    program.structure_errors[index] = NcAlarmError(12640).located(
                        program.name, line.number, block.number)
                    continue
                _, opener = stack.pop()
                program.partner[opener] = index
                program.partner[index] = opener
                if opener in program.else_of:
                    program.partner[program.else_of[opener]] = index
    for kind, index in stack:
        line = program.lines[index]
        program.structure_errors.setdefault(index, NcAlarmError(12640).located(
            program.name, line.number, line.block.number if line.block else None))


def _check_jumps(program: Program) -> None:
    """Jumps to labels or block numbers that cannot be found in their direction.

    Found for ``nck check`` only (``jump_warnings``): at run time the jump
    itself raises 14080 when it is taken. A target name that is also a
    variable DEFined in the program (``GOTOF <string variable>``) is skipped.
    """
    variables = {decl.name for line in program.lines if line.block is not None
                 for stmt in line.block.statements if isinstance(stmt, ast.Def) for decl in stmt.names}
    for index, line in enumerate(program.lines):
        if line.block is None:
            continue
        for stmt in line.block.statements:
            gotos: list[ast.Goto] = []
            if isinstance(stmt, ast.Goto):
                gotos = [stmt]
            elif isinstance(stmt, ast.IfGoto):
                gotos = [stmt.goto]
            elif isinstance(stmt, ast.Case):
                gotos = [g for _, g in stmt.branches] + ([stmt.default] if stmt.default else [])
            for goto in gotos:
                if goto.kind == "GOTOC" or goto.expr is not None or goto.label in variables:
                    continue
                direction = {"GOTOF": "F", "GOTOB": "B", "GOTO": "FB"}[goto.kind]
                if goto.number is not None:
                    found = program.find_number(goto.number, index, direction)
                else:
                    found = program.find_label(goto.label or "", index, direction)
                if found is None:
                    program.jump_warnings.setdefault(index, NcAlarmError(14080, goto.target_text).located(
                        program.name, line.number, line.block.number))


def _check_gcodes(block: ast.Block) -> NcAlarmError | None:
    """Unknown G functions (12470) and two codes of one group (12060), found statically."""
    table = gtable()
    seen: dict[int, str] = {}
    for stmt in block.statements:
        if isinstance(stmt, ast.GWord):
            number = table.group_of.get(stmt.code)
            if number is None:
                return NcAlarmError(12470, stmt.code)
            if seen.get(number, stmt.code) != stmt.code:
                return NcAlarmError(12060, number)
            seen[number] = stmt.code
    return None


def _first_code_line(program: Program, upto: int) -> int:
    """Index of the first line up to ``upto`` that has statements."""
    for index in range(upto + 1):
        block = program.lines[index].block
        if block is None or block.statements:
            return index
    return upto
