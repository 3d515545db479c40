"""The Siemens-mode interpreter: read → check → execute, one block per :meth:`step`.

Usage (the channel's view, see :mod:`nck.interp.api`)::

    interp = Interpreter(machine, programs, data)
    interp.start("PART1.MPF")          # or interp.start_text("MDA", "G1 X10 F100")
    while not interp.finished:
        result = interp.step()          # BlockResult; NcAlarmError on failure
    interp.reset()

Each block is atomic: before it runs, the interpreter state (call stack,
variables, modal state) is copied and every write into the shared
:class:`~nck.ncdata.NcData` (R parameters, tool data, GUD) is journaled; an
alarm restores both, so a failed block changes nothing.

Every interpreted block costs :data:`BLOCK_COST_S` of simulated time, so that
an endless loop without motion still advances the clock and ends at a timeout.

Program-control hooks for the channel: :attr:`skip_levels` (active ``/n``
levels), :attr:`position_source` (actual positions for ``$AA_IM``),
:attr:`flags` (``search``, ``test``, ``dry_run`` for ``$P_…``) and
:meth:`block_search` (block search with calculation).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from nck import canon
from nck.errors import NcAlarmError
from nck.interp import sysvars
from nck.interp.api import BlockResult, ProgramSource
from nck.interp.evaluator import evaluate
from nck.interp.modal import ModalState
from nck.interp.motion_builder import BlockWords, MotionBuilder
from nck.interp.program import Program, load_program
from nck.interp.values import Axis, Cell, convert, to_bool, to_number, to_string
from nck.lang import ast
from nck.lang.gcodes import gtable
from nck.lang.parser import RESERVED, VALUE_ADDRESSES
from nck.machine import MachineConfig
from nck.ncdata import NcData
from nck.status import ModalView

BLOCK_COST_S = 0.001  # simulated time one interpreted block costs (1 ms)
MAX_PROGRAM_LEVELS = 16  # main program + 15 subprogram levels (alarm 14012 beyond)
MAX_PASSES = 9999
PROGRAM_CONTROL_M = {0: "M0", 1: "M1", 2: "M2", 17: "M17", 30: "M30"}
MODE_WORDS = frozenset(("I", "J", "K", "RP", "AP"))  # non-axis words that take AC()/IC()


# ----------------------------------------------------------------------------- bindings
@dataclass
class _RRef:
    """By-reference binding to an R parameter."""

    index: int


@dataclass
class _ElemRef:
    """By-reference binding to one element of an array variable."""

    cell: Cell
    indices: tuple[Any, ...]


@dataclass
class _GudRef:
    """By-reference binding to a global user variable stored in NcData.gud."""

    name: str


Binding = Cell | _RRef | _ElemRef | _GudRef


@dataclass
class Frame:
    """One program level on the call stack."""

    program: Program
    pc: int = 0
    locals: dict[str, Binding] = field(default_factory=dict)
    params: dict[str, Binding] = field(default_factory=dict)
    passes_left: int = 0
    def_open: bool = True
    for_ends: dict[int, Any] = field(default_factory=dict)
    is_main: bool = False


@dataclass
class _State:
    """Everything the interpreter changes; copied before each block."""

    modal: ModalState
    frames: list[Frame] = field(default_factory=list)
    finished: bool = True
    blocks: int = 0
    message: str = ""


@dataclass
class SearchResult:
    """Outcome of :meth:`Interpreter.block_search`.

    ``found`` tells whether the target block was reached; the interpreter then
    stands before it. ``commands`` are the collected outputs (tool, spindle,
    aux functions, messages) of the searched blocks — no motion. ``position_wcs``
    is the calculated position the channel must approach (REPOS) before going on.
    """

    found: bool
    blocks: int
    commands: tuple[canon.CanonCommand, ...]
    position_wcs: dict[str, float]


class Interpreter:
    """Interprets Siemens-mode part programs block by block (see module docstring)."""

    def __init__(self, machine: MachineConfig, programs: ProgramSource, data: NcData,
                 dialect: str = "siemens") -> None:
        self.machine = machine
        self.programs = programs
        self.data = data
        self.dialect = dialect
        self.table = gtable(dialect)
        self.builder = MotionBuilder(machine, data)
        self.skip_levels: frozenset[int] = frozenset()  # active /n levels (0 = plain "/")
        self.flags: dict[str, bool] = {"search": False, "test": False, "dry_run": False}
        self.position_source: Callable[[str], float] | None = None
        self._axis_names = frozenset(a.name for a in machine.axes)
        self._state = _State(modal=ModalState.initial(machine, self.table))
        self._journal: list[tuple[str, Any, Any]] = []
        self._skip_run: tuple[int, bool] | None = None

    # ================================================================== public API
    @property
    def finished(self) -> bool:
        """True when the program has ended or none is loaded."""
        return self._state.finished

    @property
    def modal(self) -> ModalState:
        """The live modal state (read-only use outside the interpreter)."""
        return self._state.modal

    def start(self, program_name: str) -> None:
        """Load main program ``program_name`` (alarm 14011 if it does not exist)."""
        found = self.programs.read_program(program_name)
        if found is None:
            raise NcAlarmError(14011, program_name)
        name, text = found
        self.start_text(name, text)

    def start_text(self, name: str, text: str) -> None:
        """Load a program given as text (MDA buffer) under ``name``."""
        program = load_program(name, text)
        main = Frame(program=program, is_main=True)
        self._state.frames = [main]
        self._state.finished = False
        self._state.blocks = 0
        self._skip_run = None

    def reset(self) -> None:
        """Abort the program; G groups and modal values back to their reset state."""
        self._state.frames = []
        self._state.finished = True
        self._state.modal.reset(self.machine, self.table)
        self._skip_run = None

    def modal_view(self) -> ModalView:
        """The modal state a display needs."""
        modal = self._state.modal
        return ModalView(
            gcodes=dict(modal.gcodes),
            tool=modal.tool,
            edge=modal.edge,
            feed=modal.feed,
            spindle_speed_rpm=modal.spindle_speed_rpm,
            spindle_state=modal.spindle_state,
            aux=dict(modal.aux),
        )

    def r(self, index: int) -> float:
        """Value of R parameter ``index``."""
        return self.data.r[index]

    def variable(self, name: str) -> Any:
        """Value of a variable visible at the current level (``R5``, ``COUNT``, ``ARR[1]``)."""
        from nck.lang.lexer import tokenize
        from nck.lang.parser import _Parser

        expr = _Parser(tokenize(name)).expression()
        return evaluate(expr, _Scope(self))

    def sync_position(self, position_mcs: Mapping[str, float]) -> None:
        """Take over actual machine positions (after JOG, before a start or REPOS)."""
        modal = self._state.modal
        known = {a: float(v) for a, v in position_mcs.items() if a in modal.position_mcs}
        self.builder.sync_position(modal, known)  # WCS via frames and tool offset

    def current_source(self) -> canon.Source | None:
        """File, line and block number of the next block (None when finished)."""
        if self._state.finished or not self._state.frames:
            return None
        frame = self._state.frames[-1]
        if frame.pc >= len(frame.program.lines):
            return canon.Source(frame.program.name, len(frame.program.lines), None)
        line = frame.program.lines[frame.pc]
        return canon.Source(frame.program.name, line.number, line.block.number if line.block else None)

    def level(self) -> int:
        """Current program level (1 = main program, 0 = none)."""
        return len(self._state.frames)

    def step(self) -> BlockResult:
        """Interpret the next block; raise NcAlarmError on failure (state unchanged)."""
        if self._state.finished:
            return BlockResult(source=canon.Source("", 0, None), text="", finished=True)
        saved = self._snapshot()
        self._journal = []
        try:
            result = self._step()
        except NcAlarmError as alarm:
            self._rollback(saved)
            raise self._locate(alarm)
        except RecursionError:
            self._rollback(saved)
            raise self._locate(NcAlarmError(12540)) from None
        except (ArithmeticError, ValueError, TypeError) as exc:
            self._rollback(saved)
            raise self._locate(NcAlarmError(14051, type(exc).__name__)) from None
        self._state.blocks += 1
        return result

    def block_search(self, target: str, max_blocks: int = 1_000_000) -> SearchResult:
        """Block search with calculation up to the block ``target`` (``N100``, a label or text).

        Interprets without emitting motion, keeping modal state and positions,
        and stops *before* the target block. Alarms propagate as in :meth:`step`.
        """
        self.flags["search"] = True
        collected: list[canon.CanonCommand] = []
        blocks = 0
        try:
            while not self.finished and blocks < max_blocks:
                if self._is_search_target(target):
                    return SearchResult(True, blocks, tuple(collected),
                                        dict(self._state.modal.position_wcs))
                result = self.step()
                blocks += 1
                collected.extend(c for c in result.commands
                                 if not isinstance(c, (canon.Motion, canon.Dwell, canon.StopPoint)))
        finally:
            self.flags["search"] = False
        return SearchResult(False, blocks, tuple(collected), dict(self._state.modal.position_wcs))

    # ================================================================== internals
    def _snapshot(self) -> tuple:
        """What a failing block must restore.

        Frames are saved shallowly (program counter, loop ends, the variable
        table); writes into existing variables and NC data are journaled; the
        modal state is copied only when the next block can change it.
        """
        state = self._state
        frames = [(f, f.pc, f.passes_left, f.def_open, dict(f.for_ends), dict(f.locals))
                  for f in state.frames]
        modal = copy.deepcopy(state.modal) if self._next_block_touches_modal() else None
        return (list(state.frames), frames, modal, state.finished, state.message, self._skip_run)

    def _next_block_touches_modal(self) -> bool:
        frame = self._state.frames[-1] if self._state.frames else None
        if frame is None or frame.pc >= len(frame.program.lines):
            return True
        line = frame.program.lines[frame.pc]
        if line.block is None:
            return False
        if line.touches_modal is None:
            line.touches_modal = _touches_modal(line.block)
        return line.touches_modal

    def _rollback(self, saved: tuple) -> None:
        frame_list, frames, modal, finished, message, skip_run = saved
        for kind, key, old in reversed(self._journal):
            if kind == "cell":
                cell, offset = key
                if offset is None:
                    cell.value = old
                else:
                    cell.value[offset] = old
            elif kind == "r":
                self.data.r[key] = old
            elif kind == "tool":
                tool, edge, param = key
                if old is _MISSING_EDGE:
                    self.data.tools.pop((tool, edge), None)
                else:
                    edge_data = self.data.tools[(tool, edge)]
                    if old is None:
                        edge_data.params.pop(param, None)
                    else:
                        edge_data.params[param] = old
            elif kind == "gud":
                if old is _MISSING_EDGE:
                    self.data.gud.pop(key, None)
                else:
                    self.data.gud[key] = old
        self._journal = []
        state = self._state
        for frame, pc, passes_left, def_open, for_ends, local_vars in frames:
            frame.pc, frame.passes_left, frame.def_open = pc, passes_left, def_open
            frame.for_ends, frame.locals = for_ends, local_vars
        state.frames = frame_list
        if modal is not None:
            state.modal = modal
        state.finished, state.message = finished, message
        self._skip_run = skip_run

    def _locate(self, alarm: NcAlarmError) -> NcAlarmError:
        source = self.current_source()
        if source is not None:
            alarm.located(source.file, source.line, source.n)
        return alarm

    def _is_search_target(self, target: str) -> bool:
        frame = self._state.frames[-1]
        if frame.pc >= len(frame.program.lines):
            return False
        line = frame.program.lines[frame.pc]
        text = target.strip().upper()
        block = line.block
        if block is not None:
            if text.startswith("N") and text[1:].isdigit() and block.number == int(text[1:]):
                return True
            if block.label and block.label == text.rstrip(":"):
                return True
        return bool(text) and not (text.startswith("N") and text[1:].isdigit()) and text in line.text.upper()

    # ---------------------------------------------------------------- one block
    def _step(self) -> BlockResult:
        state = self._state
        frame = state.frames[-1]
        program = frame.program
        if frame.pc >= len(program.lines):
            return self._end_of_file(frame)
        index = frame.pc
        line = program.lines[index]
        if line.error is not None:
            raise _clone(line.error)
        block = line.block
        assert block is not None
        source = canon.Source(program.name, line.number, block.number)
        if self._skipped(block):
            frame.pc = index + 1
            return BlockResult(source, line.text, cost_s=BLOCK_COST_S, extras={"skipped": True})
        if index in program.structure_errors:
            raise _clone(program.structure_errors[index])
        run = _BlockRun(self, frame, index, source)
        commands = run.execute(block)
        return BlockResult(
            source=source,
            text=line.text,
            commands=tuple(commands),
            action_block=bool(commands),
            finished=state.finished,
            cost_s=BLOCK_COST_S,
            extras={"level": len(state.frames) if not state.finished else 0},
        )

    def _skipped(self, block: ast.Block) -> bool:
        """Skip levels; ``/n`` runs sample the switch once per run of equal marks."""
        level = block.skip_level
        if level is None:
            self._skip_run = None
            return False
        if self._skip_run is not None and self._skip_run[0] == level:
            return self._skip_run[1]
        active = level in self.skip_levels
        self._skip_run = (level, active)
        return active

    def _end_of_file(self, frame: Frame) -> BlockResult:
        program = frame.program
        source = canon.Source(program.name, len(program.lines), None)
        commands: list[canon.CanonCommand] = []
        if frame.is_main:
            commands.extend(self.builder.flush(self._state.modal))  # held-back chamfer/rounding
            commands.append(canon.ProgramEnd(source, "EOF"))
            self._program_end()
        else:
            self._return_from(frame)
        return BlockResult(source, "", tuple(commands), action_block=bool(commands),
                           finished=self._state.finished, cost_s=BLOCK_COST_S)

    def _program_end(self) -> None:
        self._state.finished = True
        self._state.frames = []
        self._state.modal.reset(self.machine, self.table)
        self._skip_run = None

    def _return_from(self, frame: Frame) -> None:
        """Subprogram end: repeat while passes are left, else back to the caller."""
        if frame.passes_left > 0:
            frame.passes_left -= 1
            frame.pc = 0
            frame.locals = dict(frame.params)
            frame.def_open = True
            frame.for_ends = {}
            return
        self._state.frames.pop()

    # ---------------------------------------------------------------- data writes
    def write_r(self, index: Any, value: Any) -> None:
        """Write R parameter (journaled); alarm 17020 for a bad index."""
        i = self.r_index(index)
        self._journal.append(("r", i, self.data.r[i]))
        self.data.r[i] = convert(value, "REAL", f"R{i}")

    def r_index(self, index: Any) -> int:
        """Validate an R index (0 … MD28050 − 1)."""
        number = to_number(index, "R")
        i = int(number)
        if i != number or not 0 <= i < len(self.data.r):
            raise NcAlarmError(17020, f"R{number}")
        return i

    def write_tool(self, tool: int, edge: int, param: int, value: float) -> None:
        """Write ``$TC_DP<param>[tool, edge]`` (creates the edge; journaled)."""
        from nck.ncdata import ToolEdge

        key = (tool, edge)
        if key not in self.data.tools:
            self._journal.append(("tool", (tool, edge, param), _MISSING_EDGE))
            self.data.tools[key] = ToolEdge()
        else:
            self._journal.append(("tool", (tool, edge, param), self.data.tools[key].params.get(param)))
        self.data.tools[key].params[param] = value

    def write_gud(self, name: str, value: Any) -> None:
        """Write a global user variable (journaled)."""
        self._journal.append(("gud", name, self.data.gud.get(name, _MISSING_EDGE)))
        self.data.gud[name] = value

    # ---------------------------------------------------------------- sysvar context
    def actual_position(self, axis: str) -> float:
        """Actual machine position of an axis (position source, else programmed)."""
        if self.position_source is not None:
            return float(self.position_source(axis))
        return float(self._state.modal.position_mcs.get(axis, 0.0))

    def program_level(self) -> int:
        """Program level for ``$P_STACK`` (main = 1)."""
        return len(self._state.frames)

    def program_name(self) -> str:
        """Program name of the current level."""
        return self._state.frames[-1].program.name if self._state.frames else ""

    def flag(self, name: str) -> bool:
        """Program-control flags for ``$P_SEARCH``, ``$P_ISTEST``, ``$P_DRYRUN``."""
        return bool(self.flags.get(name, False))

    def is_axis(self, name: str) -> bool:
        """True for axis and spindle names of the machine."""
        return name in self._axis_names

    def lookup(self, name: str) -> Binding | None:
        """The binding of a user variable visible at the current level."""
        frames = self._state.frames
        if frames:
            frame = frames[-1]
            found = frame.locals.get(name)
            if found is not None:
                return found
            main = frames[0]
            if main is not frame and self._pud_visible():
                found = main.locals.get(name)
                if found is not None:
                    return found
        if name in self.data.gud:
            return _GudRef(name)
        return None

    def _pud_visible(self) -> bool:
        value = self.machine.md_value("MD11120", default=0)
        return bool(value)


_MISSING_EDGE = object()


class _Scope:
    """Variable access for expressions (see :class:`nck.interp.evaluator.Scope`)."""

    __slots__ = ("interp",)

    def __init__(self, interp: Interpreter) -> None:
        self.interp = interp

    def read_r(self, index: Any) -> float:
        return self.interp.data.r[self.interp.r_index(index)]

    def read_name(self, name: str) -> Any:
        interp = self.interp
        binding = interp.lookup(name)
        if binding is not None:
            return read_binding(interp, binding, ())
        if name.startswith("$"):
            return sysvars.read(interp, name, ())  # type: ignore[arg-type]
        if interp.is_axis(name):
            return Axis(name)
        raise NcAlarmError(12550, name)

    def read_index(self, name: str, indices: tuple[Any, ...]) -> Any:
        interp = self.interp
        if name == "R":
            if len(indices) != 1:
                raise NcAlarmError(17020, "R")
            return self.read_r(indices[0])
        binding = interp.lookup(name)
        if binding is not None:
            return read_binding(interp, binding, indices)
        if name.startswith("$"):
            return sysvars.read(interp, name, indices)  # type: ignore[arg-type]
        raise NcAlarmError(12550, name)

    def is_axis(self, name: str) -> bool:
        return self.interp.is_axis(name)

    def has_name(self, name: str) -> bool:
        return self.interp.lookup(name) is not None


_MODAL_SAFE = (ast.Control, ast.Goto, ast.IfGoto, ast.Def, ast.Extern, ast.Proc, ast.Call)


def _touches_modal(block: ast.Block) -> bool:
    """True if a block may change the modal state (machine words, builtins, addresses)."""
    for stmt in block.statements:
        if isinstance(stmt, _MODAL_SAFE):
            continue
        if isinstance(stmt, ast.Assign) and isinstance(stmt.target, (ast.RParam, ast.Index)) \
                and not (isinstance(stmt.target, ast.Index) and stmt.target.name == "AX"):
            continue
        return True
    return False


def _journal_cell(interp: Interpreter, cell: Cell, indices: tuple[Any, ...]) -> None:
    """Record the old value of a variable (or one array element) before a write."""
    if cell.dims:
        offset = cell.offset(indices)
        interp._journal.append(("cell", (cell, offset), cell.value[offset]))
    else:
        interp._journal.append(("cell", (cell, None), cell.value))


def read_binding(interp: Interpreter, binding: Binding, indices: tuple[Any, ...]) -> Any:
    """Read through a variable binding."""
    if isinstance(binding, Cell):
        if binding.dims and not indices:
            raise NcAlarmError(12150, binding.name)
        return binding.get(indices)
    if isinstance(binding, _RRef):
        if indices:
            raise NcAlarmError(17020, f"R{binding.index}")
        return interp.data.r[binding.index]
    if isinstance(binding, _ElemRef):
        if indices:
            raise NcAlarmError(17020, binding.cell.name)
        return binding.cell.get(binding.indices)
    value = interp.data.gud[binding.name]
    if isinstance(value, list):
        if len(indices) != 1:
            raise NcAlarmError(17020, binding.name)
        i = int(to_number(indices[0], binding.name))
        if not 0 <= i < len(value):
            raise NcAlarmError(17020, binding.name)
        return value[i]
    if indices:
        raise NcAlarmError(17020, binding.name)
    return value


def write_binding(interp: Interpreter, binding: Binding, indices: tuple[Any, ...], value: Any) -> None:
    """Write through a variable binding (converted to the variable's type)."""
    if isinstance(binding, Cell):
        if binding.dims and not indices:
            raise NcAlarmError(12150, binding.name)
        _journal_cell(interp, binding, indices)
        binding.set(value, indices)
        return
    if isinstance(binding, _RRef):
        if indices:
            raise NcAlarmError(17020, f"R{binding.index}")
        interp.write_r(binding.index, value)
        return
    if isinstance(binding, _ElemRef):
        if indices:
            raise NcAlarmError(17020, binding.cell.name)
        _journal_cell(interp, binding.cell, binding.indices)
        binding.cell.set(value, binding.indices)
        return
    current = interp.data.gud[binding.name]
    if isinstance(current, list):
        if len(indices) != 1:
            raise NcAlarmError(17020, binding.name)
        i = int(to_number(indices[0], binding.name))
        if not 0 <= i < len(current):
            raise NcAlarmError(17020, binding.name)
        new = list(current)
        new[i] = _like(current[i], value, binding.name)
        interp.write_gud(binding.name, new)
    else:
        if indices:
            raise NcAlarmError(17020, binding.name)
        interp.write_gud(binding.name, _like(current, value, binding.name))


def _like(current: Any, value: Any, name: str) -> Any:
    if isinstance(current, bool):
        return convert(value, "BOOL", name)
    if isinstance(current, int):
        return convert(value, "INT", name)
    if isinstance(current, float):
        return convert(value, "REAL", name)
    if isinstance(current, str):
        return convert(value, "STRING", name)
    return value


# ----------------------------------------------------------------------------- block run
class _BlockRun:
    """Executes the statements of one block (created per block)."""

    def __init__(self, interp: Interpreter, frame: Frame, index: int, source: canon.Source) -> None:
        self.interp = interp
        self.frame = frame
        self.index = index
        self.source = source
        self.scope = _Scope(interp)
        self.next_pc = index + 1
        self.words = BlockWords(source=source)
        self.goto: ast.Goto | None = None
        self.call: ast.Call | None = None
        self.passes: int | None = None
        self.early: list[canon.CanonCommand] = []
        self.late: list[canon.CanonCommand] = []
        self.end_kind: str | None = None  # M2/M30/M17/RET
        self.executable = False

    def eval(self, expr: ast.Expr) -> Any:
        return evaluate(expr, self.scope)

    # ------------------------------------------------------------ driver
    def execute(self, block: ast.Block) -> list[canon.CanonCommand]:
        interp = self.interp
        for stmt in block.statements:
            self.statement(stmt)
        if self.executable:
            self.frame.def_open = False
        commands = list(self.early)
        m_control = [(ext, v) for ext, v in self.words.m_codes if ext in (None, 0) and v in PROGRAM_CONTROL_M]
        self.words.m_codes = [mc for mc in self.words.m_codes if mc not in m_control]
        self._apply_gcodes()
        if self.words.gcodes or self.words.axes or self.words.words or self.words.m_codes \
                or self.words.h_codes or self.words.extended:
            commands.extend(interp.builder.build(self.words, interp.modal))
        if m_control or self.end_kind is not None or any(isinstance(c, canon.StopPoint) for c in self.late):
            commands.extend(interp.builder.flush(interp.modal))  # held-back chamfer/rounding
        for _, value in m_control:
            kind = PROGRAM_CONTROL_M[value]
            if kind in ("M0", "M1"):
                commands.append(canon.StopPoint(self.source, kind))
            elif self.end_kind is None:
                self.end_kind = kind
        commands.extend(self.late)
        self.frame.pc = self.next_pc
        if self.goto is not None:
            self._jump(self.goto)
        if self.call is not None:
            self._call(self.call)
        if self.end_kind is not None:
            commands.extend(self._end())
        return commands

    def _end(self) -> list[canon.CanonCommand]:
        interp = self.interp
        if self.call is not None:
            raise NcAlarmError(12080, self.end_kind)
        if self.frame.is_main:
            interp._program_end()
            return [canon.ProgramEnd(self.source, self.end_kind or "M30")]
        interp._return_from(self.frame)
        return []

    # ------------------------------------------------------------ statements
    def statement(self, stmt: ast.Statement) -> None:
        kind = type(stmt)
        if kind is ast.AddressWord:
            self.executable = True
            self._address(stmt)  # type: ignore[arg-type]
        elif kind is ast.GWord:
            self.executable = True
            self._gword(stmt.code)  # type: ignore[union-attr]
        elif kind is ast.Assign:
            self.executable = True
            self._assign_stmt(stmt)  # type: ignore[arg-type]
        elif kind is ast.Control:
            self.executable = True
            self._control(stmt)  # type: ignore[arg-type]
        elif kind is ast.Goto:
            self.executable = True
            self.goto = stmt  # type: ignore[assignment]
        elif kind is ast.IfGoto:
            self.executable = True
            if to_bool(self.eval(stmt.cond)):  # type: ignore[union-attr]
                self.goto = stmt.goto  # type: ignore[union-attr]
        elif kind is ast.Call:
            self.executable = True
            if self.call is not None:
                raise NcAlarmError(12080, stmt.name)  # type: ignore[union-attr]
            self.call = stmt  # type: ignore[assignment]
        elif kind is ast.Builtin:
            self.executable = True
            self._builtin(stmt)  # type: ignore[arg-type]
        elif kind is ast.Def:
            self._def(stmt)  # type: ignore[arg-type]
        elif kind is ast.Proc:
            if self.index != 0 and self.frame.program.proc is not stmt:
                raise NcAlarmError(14500)
        elif kind is ast.Extern:
            pass  # declarations only; calls are resolved by name at run time

    def _address(self, word: ast.AddressWord) -> None:
        address = word.address
        interp = self.interp
        value_expr = word.value
        mode = None
        if isinstance(value_expr, ast.Func) and value_expr.name in ("AC", "IC"):
            if len(value_expr.args) != 1 or value_expr.args[0] is None:
                raise NcAlarmError(12080, value_expr.name)
            mode = value_expr.name
            value_expr = value_expr.args[0]
        value = self.eval(value_expr)
        if address in interp.machine.path_axes:
            if address in self.words.axes:
                raise NcAlarmError(12000, address)
            self.words.axes[address] = (float(to_number(value, address)), mode)
            return
        if mode is not None:
            if address not in MODE_WORDS and not (address[0] in "IJK" and address[1:].isdigit()):
                raise NcAlarmError(12080, f"{address}={mode}")
            self.words.word_modes[address] = mode  # I=AC(…), AP=IC(…): read by the motion builder
        if address == "G":
            raise NcAlarmError(12080, "G=")
        number = to_number(value, address)
        if address == "M":
            m = _whole(number, "M")
            self.words.m_codes.append((word.ext, m))
            if word.ext in (None, 0) and m == 17:
                pass
            return
        if address == "H":
            self.words.h_codes.append((word.ext, float(number)))
            return
        if address == "P":
            passes = _whole(number, "P")
            if not 1 <= passes <= MAX_PASSES:
                raise NcAlarmError(14013)
            self.passes = passes
            return
        if address in ("S", "T", "D", "F") and word.ext is not None:
            key = (address, word.ext)
            if key in self.words.extended:
                raise NcAlarmError(12000, f"{address}{word.ext}")
            self.words.extended[key] = float(number)
            if word.ext == 1 or address in ("T", "D"):
                self.words.words.setdefault(address, float(number))
            return
        if address in ("T", "D"):
            _whole(number, address)
        if len(address) == 1:
            if address not in "FSTDIJK":
                raise NcAlarmError(12550, address)
        elif address not in VALUE_ADDRESSES and not (address[0] in "IJK" and address[1:].isdigit()):
            raise NcAlarmError(12550, address)
        if word.indices and address == "FA":  # FA[X]=…: one feed per positioning axis
            address = f"FA[{to_string(self._index_value(word.indices[0]))}]"
        if address in self.words.words:
            raise NcAlarmError(12000, address)
        self.words.words[address] = float(number)

    def _gword(self, code: str) -> None:
        group = self.interp.table.lookup(code)
        present = self.words.gcodes.get(group.number)
        if present is not None and present != code:
            raise NcAlarmError(12060, group.number)
        self.words.gcodes[group.number] = code

    def _apply_gcodes(self) -> None:
        modal = self.interp.modal
        table = self.interp.table
        for number, code in self.words.gcodes.items():
            if table.groups[number].modal:
                modal.gcodes[number] = code

    # ------------------------------------------------------------ assignment
    def _assign_stmt(self, stmt: ast.Assign) -> None:
        target = stmt.target
        if isinstance(target, ast.Index) and target.name == "AX" and self.interp.lookup("AX") is None:
            # AX[<axis expression>]=value: axis word with a computed axis name
            if len(target.indices) != 1:
                raise NcAlarmError(17020, "AX")
            axis = self._index_value(target.indices[0])
            if not isinstance(axis, str) or not self.interp.is_axis(axis):
                raise NcAlarmError(14092, "AX")
            self._address(ast.AddressWord(str(axis), stmt.value))
            return
        if isinstance(target, ast.Name):
            name = target.name
            if self.interp.lookup(name) is None and not name.startswith("$") and self._is_address(name):
                self._address(ast.AddressWord(name, stmt.value))
                return
        self.assign(target, self.eval(stmt.value))

    def _is_address(self, name: str) -> bool:
        return self.interp.is_axis(name) or name in VALUE_ADDRESSES or (len(name) == 1)

    def assign(self, target: ast.Name | ast.Index | ast.RParam, value: Any) -> None:
        interp = self.interp
        if isinstance(target, ast.RParam):
            interp.write_r(target.number, value)
            return
        if isinstance(target, ast.Index):
            indices = tuple(self._index_value(i) for i in target.indices)
            if target.name == "R":
                if len(indices) != 1:
                    raise NcAlarmError(17020, "R")
                interp.write_r(indices[0], value)
                return
            binding = interp.lookup(target.name)
            if binding is not None:
                write_binding(interp, binding, indices, value)
                return
            if target.name.startswith("$"):
                sysvars.write(interp, target.name, indices, value)  # type: ignore[arg-type]
                return
            raise NcAlarmError(12550, target.name)
        binding = interp.lookup(target.name)
        if binding is not None:
            write_binding(interp, binding, (), value)
            return
        if target.name.startswith("$"):
            sysvars.write(interp, target.name, (), value)  # type: ignore[arg-type]
            return
        raise NcAlarmError(12550, target.name)

    def _index_value(self, expr: ast.Expr) -> Any:
        if isinstance(expr, ast.Name) and self.interp.is_axis(expr.name) and self.interp.lookup(expr.name) is None:
            return Axis(expr.name)
        return self.eval(expr)

    # ------------------------------------------------------------ DEF
    def _def(self, stmt: ast.Def) -> None:
        frame = self.frame
        if not frame.def_open:
            raise NcAlarmError(14500)
        lower = float(to_number(self.eval(stmt.lower))) if stmt.lower is not None else None
        upper = float(to_number(self.eval(stmt.upper))) if stmt.upper is not None else None
        for decl in stmt.names:
            name = decl.name
            if len(name) < 2 or not all(c.isalpha() or c == "_" for c in name[:2]):
                raise NcAlarmError(12080, name)
            if name in RESERVED or self.interp.is_axis(name) or self.interp.table.is_gcode(name) \
                    or name in VALUE_ADDRESSES:
                raise NcAlarmError(12170, name)
            scope_dict = frame.locals
            if stmt.scope is None and name in scope_dict:
                raise NcAlarmError(12170, name)
            dims: list[int] = []
            for dim_expr in decl.dims:
                size = to_number(self.eval(dim_expr), name)
                if size != int(size) or not 1 <= int(size) <= 65535:
                    raise NcAlarmError(17020, name)
                dims.append(int(size))
            cell = Cell.create(name, stmt.type, tuple(dims), lower, upper, stmt.string_len)
            if decl.init is not None:
                values = [self.eval(e) for e in decl.init]
                if not dims:
                    if len(values) != 1:
                        raise NcAlarmError(12260, name)
                    cell.set(values[0])
                else:
                    size = len(cell.value)
                    if decl.init_rep:
                        if len(values) != 1:
                            raise NcAlarmError(12260, name)
                        converted = convert(values[0], stmt.type, name, stmt.string_len)
                        for i in range(size):
                            cell.value[i] = converted
                        cell.set(values[0], tuple(0 for _ in dims))
                    else:
                        if len(values) > size:
                            raise NcAlarmError(12260, name)
                        for i, v in enumerate(values):
                            cell.set(v, _unflatten(i, tuple(dims)))
            if stmt.scope is not None:
                self._def_gud(cell)
            else:
                scope_dict[name] = cell

    def _def_gud(self, cell: Cell) -> None:
        """``DEF NCK/CHAN``: a global user variable kept in NcData.gud (created once)."""
        if cell.name in self.interp.data.gud:
            return
        value = list(cell.value) if cell.dims else cell.value
        if cell.dims and len(cell.dims) > 1:
            raise NcAlarmError(12190, cell.name)
        self.interp.write_gud(cell.name, value)

    # ------------------------------------------------------------ control structures
    def _control(self, stmt: ast.Control) -> None:
        program = self.frame.program
        index = self.index
        kind = stmt.kind
        if kind == "IF":
            if not to_bool(self.eval(stmt.cond)):  # type: ignore[arg-type]
                else_index = program.else_of.get(index)
                self.next_pc = (else_index if else_index is not None else program.partner[index]) + 1
        elif kind == "ELSE":
            self.next_pc = program.partner[index] + 1
        elif kind == "WHILE":
            if not to_bool(self.eval(stmt.cond)):  # type: ignore[arg-type]
                self.next_pc = program.partner[index] + 1
        elif kind == "ENDWHILE":
            self.next_pc = program.partner[index]
        elif kind == "ENDLOOP":
            self.next_pc = program.partner[index] + 1
        elif kind == "UNTIL":
            if not to_bool(self.eval(stmt.cond)):  # type: ignore[arg-type]
                self.next_pc = program.partner[index] + 1
        elif kind == "FOR":
            start = self.eval(stmt.start)  # type: ignore[arg-type]
            end = to_number(self.eval(stmt.end), "FOR")  # type: ignore[arg-type]
            self.assign(stmt.var, start)  # type: ignore[arg-type]
            self.frame.for_ends[index] = end
            if to_number(self._read_target(stmt.var), "FOR") > end:  # type: ignore[arg-type]
                self.next_pc = program.partner[index] + 1
        elif kind == "ENDFOR":
            opener = program.partner[index]
            head = program.lines[opener].block.statements[0]  # type: ignore[union-attr]
            end = self.frame.for_ends.get(opener)
            if end is None:
                raise NcAlarmError(12640)
            value = to_number(self._read_target(head.var), "FOR") + 1  # type: ignore[union-attr]
            self.assign(head.var, value)  # type: ignore[union-attr,arg-type]
            if to_number(self._read_target(head.var), "FOR") <= end:  # type: ignore[union-attr]
                self.next_pc = opener + 1
        # ENDIF, LOOP, REPEAT: fall through to the next block

    def _read_target(self, target: ast.Expr) -> Any:
        return self.eval(target)

    # ------------------------------------------------------------ jumps and calls
    def _jump(self, goto: ast.Goto) -> None:
        program = self.frame.program
        direction = {"GOTOF": "F", "GOTOB": "B", "GOTO": "FB", "GOTOC": "FB"}[goto.kind]
        label, number = goto.label, goto.number
        if goto.expr is not None:
            text = to_string(self.eval(goto.expr)).strip().upper()
            if text[:1] == "N" and text[1:].isdigit():
                number = int(text[1:])
            else:
                label = text
        if label is not None and program.find_label(label, self.index, "FB") is None \
                and self.interp.lookup(label) is not None:
            # GOTOF <variable>: the destination is the variable's (string) value
            text = to_string(self.eval(ast.Name(label))).strip().upper()
            label, number = text, None
            if text[:1] == "N" and text[1:].isdigit():
                label, number = None, int(text[1:])
        found = None
        if number is not None:
            found = program.find_number(number, self.index, direction)
        elif label is not None:
            found = program.find_label(label, self.index, direction)
            if found is None and label[:1] == "N" and label[1:].isdigit():
                found = program.find_number(int(label[1:]), self.index, direction)
        if found is None:
            if goto.kind == "GOTOC":
                return
            raise NcAlarmError(14080, label if label is not None else f"N{number}")
        self.frame.pc = found

    def _call(self, call: ast.Call) -> None:
        interp = self.interp
        state = interp._state
        found = interp.programs.read_program(call.name)
        if found is None:
            if call.args is None and not call.name[:1] == "L" and self.passes is None:
                raise NcAlarmError(12550, call.name)
            raise NcAlarmError(14011, call.name)
        if len(state.frames) >= MAX_PROGRAM_LEVELS:
            raise NcAlarmError(14012)
        name, text = found
        program = _program_cache(interp, name, text)
        frame = Frame(program=program, passes_left=(self.passes or 1) - 1)
        self._bind_parameters(program, call, frame)
        frame.locals = dict(frame.params)
        state.frames.append(frame)

    def _bind_parameters(self, program: Program, call: ast.Call, frame: Frame) -> None:
        params = program.proc.params if program.proc is not None else ()
        args = call.args or ()
        if len(args) > len(params):
            raise NcAlarmError(12340, call.name)
        for position, param in enumerate(params):
            name = param.name or f"_P{position}"
            arg = args[position] if position < len(args) else None
            if param.by_ref:
                frame.params[name] = self._reference(arg, param, call.name)
            else:
                cell = Cell.create(name, param.type)
                if arg is not None:
                    cell.set(self.eval(arg))
                frame.params[name] = cell

    def _reference(self, arg: ast.Expr | None, param: ast.ParamDecl, callee: str) -> Binding:
        interp = self.interp
        if arg is None:
            return Cell.create(param.name or "_", param.type)
        if isinstance(arg, ast.RParam):
            return _RRef(interp.r_index(arg.number))
        if isinstance(arg, ast.Name):
            binding = interp.lookup(arg.name)
            if binding is None:
                raise NcAlarmError(12320, arg.name)
            return binding
        if isinstance(arg, ast.Index):
            indices = tuple(self._index_value(i) for i in arg.indices)
            if arg.name == "R":
                if len(indices) != 1:
                    raise NcAlarmError(17020, "R")
                return _RRef(interp.r_index(indices[0]))
            binding = interp.lookup(arg.name)
            if isinstance(binding, Cell) and binding.dims:
                binding.offset(indices)  # validates
                return _ElemRef(binding, indices)
            raise NcAlarmError(12320, arg.name)
        raise NcAlarmError(12320, callee)

    # ------------------------------------------------------------ builtins
    def _builtin(self, stmt: ast.Builtin) -> None:
        name = stmt.name
        if name == "MSG":
            if len(stmt.args) > 1:
                raise NcAlarmError(14020, "MSG")
            text = to_string(self.eval(stmt.args[0])) if stmt.args and stmt.args[0] is not None else ""
            self.interp._state.message = text
            self.early.append(canon.Message(self.source, text))
        elif name == "SETAL":
            if not stmt.args or stmt.args[0] is None:
                raise NcAlarmError(14020, "SETAL")
            number = _whole(to_number(self.eval(stmt.args[0]), "SETAL"), "SETAL")
            if not 60000 <= number <= 69999:
                raise NcAlarmError(14020, "SETAL")
            params = tuple(to_string(self.eval(a)) for a in stmt.args[1:] if a is not None)
            self.late.append(canon.UserAlarm(self.source, number, params))
        elif name == "STOPRE":
            self.late.append(canon.StopPoint(self.source, "STOPRE"))
        elif name == "RET":
            self.end_kind = "RET"


def _clone(alarm: NcAlarmError) -> NcAlarmError:
    """A fresh copy of a stored alarm (stored alarms are raised again on every pass)."""
    return NcAlarmError(alarm.number, *alarm.params, file=alarm.file, line=alarm.line, n=alarm.n)


def _whole(number: Any, address: str) -> int:
    value = to_number(number, address)
    if isinstance(value, float):
        if not value.is_integer():
            raise NcAlarmError(12080, address)
        value = int(value)
    if value < 0 or value > 99_999_999:
        raise NcAlarmError(12160, address)
    return value


def _unflatten(flat: int, dims: tuple[int, ...]) -> tuple[int, ...]:
    out = []
    for size in reversed(dims):
        out.append(flat % size)
        flat //= size
    return tuple(reversed(out))


def _program_cache(interp: Interpreter, name: str, text: str) -> Program:
    cache: dict[tuple[str, str], Program] = interp.__dict__.setdefault("_programs", {})
    key = (name, text)
    program = cache.get(key)
    if program is None:
        if len(cache) > 64:
            cache.clear()
        program = load_program(name, text)
        cache[key] = program
    return program
