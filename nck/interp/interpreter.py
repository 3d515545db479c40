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

Simple motion blocks (G0–G3 with X Y Z, I J K, ``CR=``, F, :mod:`nck.lang.plain`) take
a fast step with the same result: their precompiled words go to the same motion builder
without the tree walk and the snapshot (:mod:`nck.interp.simple_step`); :meth:`plain_batch`
plans a whole run of plain ``G0``/``G1`` blocks for ``nck check``; :attr:`fast_path`
switches both off.

Program-control hooks for the channel: :attr:`skip_levels` (active ``/n``
levels), :attr:`position_source` (actual positions for ``$AA_IM``), :attr:`access_level`
(the protection level setting-data writes are checked against),
:attr:`flags` (``search``, ``test``, ``dry_run`` for ``$P_…``) and
:meth:`skip_to` (block search without calculation; the channel's block search with
calculation steps the interpreter itself, :mod:`nck.program_control`).

``BlockResult.extras`` carries ``level`` (program level after the block, 0 at
the end), ``skipped`` (a ``/`` block that was skipped), ``single_block_off``
(SBLOF active: single block must not stop after this block),
``display_off`` (DISPLOF: do not show this block) and ``preprocessing_stop``
(the block read main-run data; see :meth:`Interpreter.needs_preprocessing_stop`).
"""

from __future__ import annotations

import copy
from typing import Any, Callable, Mapping

from nck import canon
from nck.alarm_ids import BLOCK_TOO_COMPLEX, ILLEGAL_ARRAY_INDEX_1, MEMORY_CAPACITY_REACHED, PROGRAM_NOT_FOUND
from nck.errors import NcAlarmError
from nck.access import LEVEL_FEWEST_RIGHTS
from nck.interp import data_writes
from nck.interp.api import BLOCK_COST_S, BlockResult, ProgramSource
from nck.interp.block_run import (  # noqa: F401 - re-exported language limits
    MAX_PASSES, MAX_PROGRAM_LEVELS, PROGRAM_CONTROL_M, BlockRun,
)
from nck.interp.evaluator import evaluate
from nck.interp.call_stack import Binding, Frame, GudRef, VariableScope
from nck.interp.host import RunState
from nck.interp.modal import ModalState
from nck.interp.motion_builder import MotionBuilder
from nck.interp.plain_run import plan
from nck.interp.simple_step import SimpleStep
from nck.interp.program import load_program
from nck.lang.values import Cell, convert, to_number
from nck.lang import ast
from nck.lang.dialect import SIEMENS, Dialect
from nck.lang.gcodes import gtable
from nck.machine import MachineConfig
from nck.ncdata import TOOL_EDGE_COUNT, NcData, ToolEdge
from nck.status import ModalView
from nck.writes import ValueOutOfLimits, check_tool_value
from nck.interp.sources import DirectorySource
from nck.lang.lexer import tokenize
from nck.lang.lines import TextLines
from nck.lang.parser import BlockParser
from nck.resources import data_path


class Interpreter:
    """Interprets Siemens-mode part programs block by block (see module docstring)."""

    fast_path = True
    """Plain motion blocks take the fast path (:mod:`nck.interp.plain_run`); False: general path only."""

    def __init__(self, machine: MachineConfig, programs: ProgramSource, data: NcData,
                 dialect: Dialect = SIEMENS) -> None:
        self.machine = machine
        self.programs = programs
        self.data = data
        self.dialect = dialect  # the language mode in front (ISO: nck.iso.dialect)
        self.table = gtable(dialect.gcode_table)
        self.builder = MotionBuilder(machine, data)
        self.simple_step = SimpleStep()  # the fast step of simple motion blocks
        self.cycles = DirectorySource(data_path("cycles"))  # keeps the cycles' texts while unchanged
        self.skip_levels: frozenset[int] = frozenset()  # active /n levels (0 = plain "/")
        self.flags: dict[str, bool] = {"search": False, "test": False, "dry_run": False}
        self.position_source: Callable[[str], float] | None = None
        # The kernel's probe results for $AA_MM/$AA_MW/$AC_MEA: (name, axis) -> value.
        self.measurement_source: Callable[[str, str], float] | None = None
        # protection level the program runs with (setting-data writes); the kernel installs its own
        self.access_level: Callable[[], int] = lambda: LEVEL_FEWEST_RIGHTS
        self._axis_names = frozenset(a.name for a in machine.axes)
        self.run_state = RunState(modal=ModalState.initial(machine, self.table))
        self.undo_journal: list[tuple[str, Any, Any]] = []
        self.skip_run: tuple[int, bool] | None = None

    # ================================================================== public API
    @property
    def finished(self) -> bool:
        """True when the program has ended or none is loaded."""
        return self.run_state.finished

    @property
    def modal(self) -> ModalState:
        """The live modal state (read-only use outside the interpreter)."""
        return self.run_state.modal

    @property
    def call_stack(self) -> list[Frame]:
        """The program levels, main program first (for the dialect's hooks)."""
        return self.run_state.frames

    def journal_undo(self, undo: Callable[[], None]) -> None:
        """Run ``undo`` if the current block is taken back (preprocessing repeats it)."""
        self.undo_journal.append(("undo", undo, None))

    def start(self, program_name: str) -> None:
        """Load main program ``program_name`` (alarm 14011 if it does not exist)."""
        found = self.programs.read_program(program_name)
        if found is None:
            raise NcAlarmError(PROGRAM_NOT_FOUND, program_name)
        name, text = found
        self.start_text(name, text)

    def start_text(self, name: str, text: str) -> None:
        """Load a program given as text (MDA buffer) under ``name``."""
        program = load_program(name, text, self.dialect, main=True)
        main = Frame(program=program, is_main=True)
        self.run_state.frames = [main]
        self.run_state.finished = False
        self.run_state.blocks = 0
        self.skip_run = None

    def reset(self) -> None:
        """Abort the program; G groups and modal values back to their reset state."""
        self.run_state.frames = []
        self.run_state.finished = True
        self.run_state.modal.reset(self.machine, self.table)
        self.skip_run = None

    def modal_view(self) -> ModalView:
        """The modal state a display needs."""
        modal = self.run_state.modal
        iso = self.dialect.gcode_display(modal, self.run_state.frames)
        return ModalView(
            gcodes=dict(modal.gcodes),
            tool=modal.tool,
            edge=modal.edge,
            feed=modal.feed,
            spindle_speed_rpm=modal.spindle_speed_rpm,
            spindle_state=modal.spindle_state,
            aux=dict(modal.aux),
            iso_gcodes=iso,
        )

    def r(self, index: int) -> float:
        """Value of R parameter ``index``."""
        return self.data.r[index]

    def variable(self, name: str) -> Any:
        """Value of a variable visible at the current level (``R5``, ``COUNT``, ``ARR[1]``)."""

        expr = BlockParser(tokenize(name)).expression()
        return evaluate(expr, VariableScope(self))

    def sync_position(self, position_mcs: Mapping[str, float]) -> None:
        """Take over actual machine positions (after JOG, before a start or REPOS)."""
        modal = self.run_state.modal
        known = {a: float(v) for a, v in position_mcs.items() if a in modal.position_mcs}
        self.builder.sync_position(modal, known)  # WCS via frames and tool offset

    def read_cycle(self, name: str) -> tuple[str, str] | None:
        """A standard cycle shipped as an NC program in ``data/cycles`` (CYCLE81 …, HOLES2,
        WORKPIECE, and the cycles' own helpers such as CYC_DRILL), or None.

        Programs of the program source with the same name win (a user's own cycle).
        """

        return self.cycles.read_program(name)

    def needs_preprocessing_stop(self) -> bool:
        """True if the next block reads main-run data (``$A…``, ``$V…``, ``$$…``).

        Such a block may only be interpreted once every block before it has
        been executed (implicit STOPRE): the channel should wait until motion
        is idle, update :attr:`position_source`, then call :meth:`step`.
        """
        if self.run_state.finished or not self.run_state.frames:
            return False
        frame = self.run_state.frames[-1]
        if frame.program.without_dollar:
            return False  # no line of the program reads variables
        if frame.pc >= len(frame.program.lines) or frame.program.plain_run_end(frame.pc) > frame.pc:
            return False  # (a plain block reads no variables: no need to parse it here)
        lines = frame.program.lines
        if isinstance(lines, TextLines) and "$" not in lines.raw(frame.pc):
            return False  # nor does a line without "$" (the simple-step path never parses it)
        line = lines[frame.pc]
        if line.block is None:
            return False
        if line.main_run_read is None:
            line.main_run_read = "$" in line.text and _reads_main_run_data(line.block)
        return line.main_run_read

    def current_source(self) -> canon.Source | None:
        """File, line and block number of the next block (None when finished)."""
        if self.run_state.finished or not self.run_state.frames:
            return None
        frame = self.run_state.frames[-1]
        if frame.pc >= len(frame.program.lines):
            return canon.Source(frame.program.name, len(frame.program.lines), None)
        line = frame.program.lines[frame.pc]
        return canon.Source(frame.program.name, line.number, line.block.number if line.block else None)

    def level(self) -> int:
        """Current program level (1 = main program, 0 = none)."""
        return len(self.run_state.frames)

    def step(self) -> BlockResult:
        """Interpret the next block; raise NcAlarmError on failure (state unchanged)."""
        if self.run_state.finished:
            return BlockResult(source=canon.Source("", 0, None), text="", finished=True)
        if self.fast_path and self.run_state.frames:
            fast = self.simple_step.step(self)  # a simple motion block: the same builder, no tree walk or snapshot
            if fast is not None:
                self.undo_journal = []
                self.run_state.blocks += 1
                return fast
        saved = self._snapshot()
        self.undo_journal = []
        try:
            result = self._step()
        except NcAlarmError as alarm:
            self._rollback(saved)
            raise self._locate(alarm)
        except RecursionError:
            self._rollback(saved)
            raise self._locate(NcAlarmError(BLOCK_TOO_COMPLEX)) from None
        self.run_state.blocks += 1
        return result

    def skip_to(self, number: int | None, text: str) -> bool:
        """Block search without calculation: place the main program before its first block
        numbered ``number`` (or, with ``number`` None, the first block whose text contains
        ``text``) without interpreting a block before it, so the modal state stays what it
        was (002 L18284-18288). False (nothing changed) when no such block exists."""
        if self.run_state.finished or not self.run_state.frames:
            return False
        main = self.run_state.frames[0]
        program = main.program
        if number is not None:
            index = program.find_number(number, -1, "F")
        else:
            index = program.find_text(text)
        if index is None:
            return False
        del self.run_state.frames[1:]
        main.pc = index
        self.skip_run = None
        return True

    def plain_batch(self, max_blocks: int) -> Any:
        """The next run of plain blocks planned as one batch (:mod:`nck.interp.plain_run`), or None.

        Nothing changes until the caller commits the first *k* blocks
        (``batch.commit(k)``); None means: interpret the next block with :meth:`step`.
        """
        if not self.fast_path:
            return None

        return plan(self, max_blocks)

    # ================================================================== internals
    def _snapshot(self) -> tuple:
        """What a failing block must restore.

        The current level's frame is saved shallowly (program counter, loop ends, the
        variable table): a block changes only that frame until it leaves its level, and
        :meth:`return_from` journals the caller's frame before the block can touch it (RET
        to a target). Writes into existing variables and NC data are journaled; the modal
        state is copied only when the next block can change it.
        """
        state = self.run_state
        frames = state.frames
        top = (frames[-1], _frame_copy(frames[-1])) if frames else None
        modal = copy.deepcopy(state.modal) if self._next_block_touches_modal() else None
        return (list(frames), top, modal, state.finished, state.message, self.skip_run)

    def _next_block_touches_modal(self) -> bool:
        frame = self.run_state.frames[-1] if self.run_state.frames else None
        if frame is None or frame.pc >= len(frame.program.lines):
            return True
        line = frame.program.lines[frame.pc]
        if line.block is None:
            return False
        touches = line.touches_modal
        if touches is None:
            touches = line.touches_modal = _touches_modal(line.block)
        # Assignments to names: safe when each is a variable (journaled). This also relies on the
        # step's work after the statements (releasing held motions) never raising an alarm, as
        # blocks that only write R parameters always have.
        if type(touches) is tuple:
            return not all(type(self.lookup(name)) is Cell for name in touches)
        return bool(touches)

    def _rollback(self, saved: tuple) -> None:
        frame_list, top, modal, finished, message, skip_run = saved
        for kind, key, old in reversed(self.undo_journal):
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
            elif kind == "undo":  # key is a callable that restores what it saved (frame writes)
                key()
        self.undo_journal = []
        state = self.run_state
        if top is not None:
            top[0].__dict__.update(top[1].__dict__)
        state.frames = frame_list
        if modal is not None:
            state.modal = modal
        state.finished, state.message = finished, message
        self.skip_run = skip_run

    def _locate(self, alarm: NcAlarmError) -> NcAlarmError:
        source = self.current_source()
        if source is not None:
            alarm.located(source.file, source.line, source.n)
        return alarm

    # ---------------------------------------------------------------- one block
    def _step(self) -> BlockResult:
        state = self.run_state
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
        if line.main_run_read is None:
            line.main_run_read = "$" in line.text and _reads_main_run_data(block)
        run = BlockRun(self, frame, index, source)
        commands = run.execute(block)
        geo = getattr(state.modal, "geometry", None)
        if geo is not None and geo.pending is not None and self.needs_preprocessing_stop():
            # The next block reads main-run data ($AA_IM …): the channel waits for the motion
            # to end there, so an element held back for a corner must go out now, unrounded.
            commands.extend(self.builder.release_held(state.modal))
        return BlockResult(
            source=source,
            text=line.text,
            commands=tuple(commands),
            action_block=bool(commands),
            finished=state.finished,
            cost_s=BLOCK_COST_S,
            extras={"level": len(state.frames) if not state.finished else 0,
                    "preprocessing_stop": bool(line.main_run_read),
                    "single_block_off": frame.single_block_off,
                    "display_off": frame.display_off},
        )

    def _skipped(self, block: ast.Block) -> bool:
        """Skip levels; ``/n`` runs sample the switch once per run of equal marks."""
        level = block.skip_level
        if level is None:
            self.skip_run = None
            return False
        if self.skip_run is not None and self.skip_run[0] == level:
            return self.skip_run[1]
        active = level in self.skip_levels
        self.skip_run = (level, active)
        return active

    def _end_of_file(self, frame: Frame) -> BlockResult:
        program = frame.program
        source = canon.Source(program.name, len(program.lines), None)
        commands: list[canon.CanonCommand] = []
        if frame.is_main:
            commands.extend(self.builder.flush(self.run_state.modal))  # held-back chamfer/rounding
            commands.append(canon.ProgramEnd(source, "EOF"))
            self.end_program("EOF")
        else:
            self.return_from(frame)
        return BlockResult(source, "", tuple(commands), action_block=bool(commands),
                           finished=self.run_state.finished, cost_s=BLOCK_COST_S)

    def end_program(self, kind: str) -> None:
        self.run_state.finished = True
        self.run_state.frames = []
        modal = self.run_state.modal
        modal.reset(self.machine, self.table)
        spindles = self.machine.spindles
        if kind in canon.END_COMMANDS and spindles and not self.machine.spindle_kept_after_reset(spindles[0]):
            self.sync_spindle("M5", 0.0)
        self.skip_run = None

    def sync_spindle(self, state: str, speed_rpm: float) -> None:
        """Take over the master spindle's direction and programmed S (the channel deletes
        them at RESET, keeps them over a mode change): G95, G96 and $P_S go on from there."""
        self.run_state.modal.spindle_state = state
        self.run_state.modal.spindle_speed_rpm = float(speed_rpm)

    def sync_gcodes(self, codes: Mapping[int, str]) -> None:
        """Take over G codes the channel keeps over RESET (MD20152 = 1): ``{group: code}``;
        the frames follow when the kernel activates them."""
        self.run_state.modal.gcodes.update(codes)

    def sync_tool(self, tool: int, edge: int, preselected: int) -> None:
        """Take over the tool in the spindle, its active edge and the preselected tool (MDA
        and AUTO have interpreters of their own; the machine has one spindle): before
        :meth:`sync_position`, so that the WCS follows with the tool length."""
        modal = self.run_state.modal
        modal.tool, modal.edge, modal.tool_selected = int(tool), int(edge), int(preselected)

    def return_from(self, frame: Frame) -> None:
        """Subprogram end: repeat while passes are left, else back to the caller."""
        if frame.passes_left > 0:
            frame.passes_left -= 1
            frame.pc = 0
            frame.locals = dict(frame.params)
            frame.def_open = True
            frame.for_ends = {}
            frame.repeats = []
            return
        frames = self.run_state.frames
        frames.pop()
        if frames:  # the caller becomes the current level: saved for a rollback of this block
            self._journal_frame(frames[-1])
        if frame.saved_gcodes is not None:
            self.run_state.modal.gcodes = dict(frame.saved_gcodes)
        if frame.saved_pframe is not None:  # SAVE also restores the programmable frame
            geo = self.builder.path.state(self.run_state.modal)
            geo.frames = geo.frames.with_programmable(frame.saved_pframe)
        self.dialect.after_return(self.run_state.modal, frame)  # ISO: G291 again after a PROC program

    def _journal_frame(self, frame: Frame) -> None:
        """Restore ``frame``'s own state as it is now if the current block is taken back."""
        saved = _frame_copy(frame)
        self.journal_undo(lambda: frame.__dict__.update(saved.__dict__))

    # ---------------------------------------------------------------- data writes
    def write_r(self, index: Any, value: Any) -> None:
        """Write R parameter (journaled); alarm 17020 for a bad index."""
        i = self.r_index(index)
        self.undo_journal.append(("r", i, self.data.r[i]))
        self.data.r[i] = convert(value, "REAL", f"R{i}")

    def r_index(self, index: Any) -> int:
        """Validate an R index (0 … MD28050 − 1)."""
        number = to_number(index, "R")
        i = int(number)
        if i != number or not 0 <= i < len(self.data.r):
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, f"R{number}")
        return i

    def write_tool(self, tool: int, edge: int, param: int, value: float) -> None:
        """Write ``$TC_DP<param>[tool, edge]`` (creates the edge; journaled).

        The value obeys the one write path's rule (:func:`nck.writes.check_tool_value`, as on
        the panel): outside the limits alarm 17080/17090 and nothing is written. Tool type and
        edge position are INT data: a REAL is rounded as on every INT assignment.
        """
        name = f"$TC_DP{param}"
        if param in (1, 2):
            value = float(convert(value, "INT", name))
        try:
            check_tool_value(param, value)
        except ValueOutOfLimits as exc:
            raise NcAlarmError(exc.alarm, name) from None
        key = (tool, edge)
        edge_count = int(self.machine.md_value("MD18100", default=TOOL_EDGE_COUNT))
        if not self.data.has_room_for_edge(tool, edge, edge_count):
            raise NcAlarmError(MEMORY_CAPACITY_REACHED,
                               f"MD18100 tool offset memory {edge_count} cutting edges: T{tool} D{edge}")
        if key not in self.data.tools:
            self.undo_journal.append(("tool", (tool, edge, param), _MISSING_EDGE))
            self.data.tools[key] = ToolEdge()
        else:
            self.undo_journal.append(("tool", (tool, edge, param), self.data.tools[key].params.get(param)))
        self.data.tools[key].params[param] = value

    def write_setting_data(self, name: str, indices: tuple[Any, ...], value: Any) -> None:
        """Write setting datum ``$<name>`` at the current protection level (journaled)."""
        data_writes.write_setting_data(self, "$" + name, indices, value,
                                       lambda undo: self.undo_journal.append(("undo", undo, None)))

    def write_gud(self, name: str, value: Any) -> None:
        """Write a global user variable (journaled)."""
        self.undo_journal.append(("gud", name, self.data.gud.get(name, _MISSING_EDGE)))
        self.data.gud[name] = value

    # ---------------------------------------------------------------- sysvar context
    def measurement(self, name: str, axis: str) -> float:
        """``$AA_MM[axis]``, ``$AA_MW[axis]`` or ``$AC_MEA[1]`` of the last measuring block
        (from :attr:`measurement_source`; 0 without one)."""
        if self.measurement_source is not None:
            return float(self.measurement_source(name, axis))
        return 0.0

    def actual_position(self, axis: str) -> float:
        """Actual machine position of an axis (position source, else programmed)."""
        if self.position_source is not None:
            return float(self.position_source(axis))
        return float(self.run_state.modal.position_mcs.get(axis, 0.0))

    def program_level(self) -> int:
        """Program level for ``$P_STACK`` (main = 1)."""
        return len(self.run_state.frames)

    def program_name(self) -> str:
        """Program name of the current level."""
        return self.run_state.frames[-1].program.name if self.run_state.frames else ""

    def parameter_given(self, number: int) -> bool | None:
        """``$P_SUBPAR[n]``: whether the call of the current level programmed parameter ``n``
        (1 = first); None when the level has no parameter ``n``."""
        given = self.run_state.frames[-1].given_params if self.run_state.frames else ()
        return given[number - 1] if 1 <= number <= len(given) else None

    def flag(self, name: str) -> bool:
        """Program-control flags for ``$P_SEARCH``, ``$P_ISTEST``, ``$P_DRYRUN``."""
        return bool(self.flags.get(name, False))

    def is_axis(self, name: str) -> bool:
        """True for axis and spindle names of the machine."""
        return name in self._axis_names

    def lookup(self, name: str) -> Binding | None:
        """The binding of a user variable visible at the current level."""
        frames = self.run_state.frames
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
            return GudRef(name)
        return None

    def _pud_visible(self) -> bool:
        value = self.machine.md_value("MD11120", default=0)
        return bool(value)


_MISSING_EDGE = object()


_MODAL_SAFE = (ast.Control, ast.Goto, ast.IfGoto, ast.Case, ast.SectionRepeat, ast.Def, ast.Extern,
               ast.Proc, ast.Call, ast.ModalCall)


_MAIN_RUN_PREFIXES = ("$A", "$V", "$$")


def _reads_main_run_data(block: ast.Block) -> bool:
    """True if any expression of the block names a main-run variable.

    Callers skip it for lines without ``$`` (every such name starts with one).
    """
    found = False

    def visit(node: object) -> None:
        nonlocal found
        if found or node is None:
            return
        if isinstance(node, (ast.Name, ast.Index)) and node.name.startswith(_MAIN_RUN_PREFIXES):
            found = True
            return
        if isinstance(node, (list, tuple)):
            for item in node:
                visit(item)
            return
        fields = getattr(node, "__dataclass_fields__", None)
        if fields:
            for name in fields:
                visit(getattr(node, name))

    visit(block.statements)
    return found


def _frame_copy(frame: Frame) -> Frame:
    """A copy of a frame's own state (the variables themselves are journaled, not copied)."""
    saved = object.__new__(type(frame))  # copy.copy without the pickling protocol (a dataclass)
    saved.__dict__.update(frame.__dict__)
    saved.locals = dict(frame.locals)
    saved.for_ends = dict(frame.for_ends)
    saved.repeats = list(frame.repeats)
    return saved


def _touches_modal(block: ast.Block) -> bool | tuple[str, ...]:
    """True if a block may change the modal state (machine words, builtins, addresses); the
    names a block assigns to when only those assignments may (``NAME=…`` is an address word or
    system variable unless NAME is a variable: decided when the block runs); else False."""
    names: list[str] = []
    for stmt in block.statements:
        if isinstance(stmt, _MODAL_SAFE):
            continue
        if isinstance(stmt, ast.Assign) and isinstance(stmt.target, (ast.RParam, ast.Index)) \
                and not (isinstance(stmt.target, ast.Index) and stmt.target.name == "AX"):
            continue
        if isinstance(stmt, ast.Assign) and isinstance(stmt.target, ast.Name) \
                and not (isinstance(stmt.value, ast.Func) and stmt.value.name in ("SET", "REP")):
            names.append(stmt.target.name)
            continue
        return True
    return tuple(names) if names else False


def _clone(alarm: NcAlarmError) -> NcAlarmError:
    """A fresh copy of a stored alarm (stored alarms are raised again on every pass)."""
    return NcAlarmError(alarm.number, *alarm.params, file=alarm.file, line=alarm.line, n=alarm.n)
