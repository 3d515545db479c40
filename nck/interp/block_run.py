"""Execution of one NC block: statements, machine words, jumps, calls, program end.

:class:`BlockRun` is created by the interpreter for every block. It evaluates
the statements in source order (assignments, DEF, control structures,
builtins), collects the machine words into
:class:`~nck.interp.motion_builder.BlockWords` for the motion builder, and
finally applies jumps, subprogram calls and program/subprogram ends.
"""

from __future__ import annotations

import math
import re
from typing import Any

from nck import canon
from nck.errors import NcAlarmError
from nck.geometry.frame_vars import COMPONENTS as FRAME_COMPONENTS
from nck.alarm_ids import (
    ADDRESS_PROGRAMMED_TWICE, ARRAY_TOO_MANY_DIMENSIONS, CONTROL_STRUCTURES_NOT_NESTED,
    DEFINITION_AFTER_STATEMENT, G_GROUP_PROGRAMMED_TWICE, ILLEGAL_ARRAY_INDEX_1, JUMP_TARGET_NOT_FOUND,
    MEMORY_CAPACITY_REACHED, NAME_DEFINED_TWICE, NAME_NOT_DEFINED, OPERATION_DOES_NOT_FIT_TYPE,
    PARAMETER_NOT_A_VARIABLE, PASS_COUNT_NOT_ALLOWED, PROGRAM_NOT_FOUND, STOCK_REMOVAL_CONTOUR_ERROR,
    SUBPROGRAM_LEVEL_EXCEEDED, SYNTAX_ERROR, TOO_MANY_CALL_PARAMETERS, TOO_MANY_INITIAL_VALUES,
    VALUE_RANGE_EXCEEDED, WRONG_AXIS_TYPE, WRONG_CALL_ARGUMENTS,
)
from nck.interp import sysvars
from nck.interp.contour_table import ROW_WIDTH, contour_rows
from nck.interp.evaluator import equal, evaluate
from nck.interp.call_stack import Binding, ElemRef, Frame, RRef, VariableScope, journal_cell, write_binding
from nck.interp.host import InterpreterHost
from nck.interp.motion_builder import BlockWords
from nck.interp.program import Program, load_program
from nck.interp.returns import prepare_return, resume_caller, return_target
from nck.lang.values import (GUD_VALUES_MEM_KB, LUD_VALUES_MEM_KB, Axis, Cell, convert, memory_bytes,
                               stored_bytes, to_bool, to_number, to_string)
from nck.lang import ast
from nck.lang.parser import RESERVED, VALUE_ADDRESSES
from nck.resources import load_toml


MAX_PROGRAM_LEVELS = 16  # main program + 15 subprogram levels (alarm 14012 beyond)
MAX_PASSES = 9999
MAX_ARRAY_ELEMENTS = 1_000_000  # one array's elements (each dimension <= 65535); 17020 beyond
PROGRAM_CONTROL_M = {0: "M0", 1: "M1", 2: "M2", 17: "M17", 30: "M30"}
MODE_WORDS = frozenset(("I", "J", "K", "RP", "AP"))  # non-axis words that take AC()/IC()
SPINDLE_NAME = re.compile(r"S[1-9][0-9]?")  # S<n>: spindle n as the index of FA[…]
SPINDLE_POSITION_WORDS = frozenset(("SPOS", "SPOSA"))  # also DC()/ACP()/ACN() (002 L51117-51160)

# ----------------------------------------------------------------------------- block run
class BlockRun:
    """Executes the statements of one block (created per block)."""

    def __init__(self, interp: InterpreterHost, frame: Frame, index: int, source: canon.Source) -> None:
        self.interp = interp
        self.frame = frame
        self.index = index
        self.source = source
        self.scope = VariableScope(interp)
        self.next_pc = index + 1
        self.words = BlockWords(source=source)
        self.goto: ast.Goto | None = None
        self.call: ast.Call | None = None
        self.passes: int | None = None
        self.early: list[canon.CanonCommand] = []
        self.late: list[canon.CanonCommand] = []
        self.end_kind: str | None = None  # M2/M30/M17/RET
        self.executable = False
        self.repeat: ast.SectionRepeat | None = None
        self.goto_start = False
        self.mcall_set = False
        self.ret_target: tuple[str, int] | None = None  # RET("N40"[, 1]) (ISO M99 P40)

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
        if self.goto_start:  # GOTOS: a fresh pass of this program level
            self.frame.pc = 0
            self.frame.repeats = []
            self.frame.for_ends = {}
            self.frame.locals = dict(self.frame.params)
            self.frame.def_open = True
        if self.repeat is not None:
            self._start_repeat(self.repeat)
        elif self.goto is None:
            self._section_end()
        if self.call is None and self.words.axes and self.frame.modal_call is not None \
                and not self.mcall_set and self.end_kind is None:
            self.call = self.frame.modal_call  # MCALL: after every block with path motion
        if self.call is not None:
            self._call(self.call)
        if self.end_kind is not None:
            commands.extend(self._end())
        return commands

    def _end(self) -> list[canon.CanonCommand]:
        interp = self.interp
        if self.call is not None:
            raise NcAlarmError(SYNTAX_ERROR, self.end_kind)
        if self.frame.is_main or interp.dialect.ends_whole_program(interp, self.end_kind):
            interp.end_program(self.end_kind or "M30")  # (ISO mode: M30 in a subprogram ends the whole program)
            return [canon.ProgramEnd(self.source, self.end_kind or "M30")]
        prepare_return(self.frame, self.ret_target)
        interp.return_from(self.frame)
        if self.ret_target is not None:
            resume_caller(interp, *self.ret_target)
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
        elif kind is ast.ModalCall:
            self.executable = True
            self.frame.modal_call = stmt.call  # type: ignore[union-attr]
            self.mcall_set = True
        elif kind is ast.SectionRepeat:
            self.executable = True
            self.repeat = stmt  # type: ignore[assignment]
        elif kind is ast.Case:
            self.executable = True
            value = self.eval(stmt.expr)  # type: ignore[union-attr,arg-type]
            self.goto = stmt.default  # type: ignore[union-attr]
            for constant, goto in stmt.branches:  # type: ignore[union-attr]
                if equal(value, self.eval(constant)):
                    self.goto = goto
                    break
        elif kind is ast.IfGoto:
            self.executable = True
            if to_bool(self.eval(stmt.cond)):  # type: ignore[union-attr,arg-type]
                self.goto = stmt.goto  # type: ignore[union-attr]
        elif kind is ast.Call:
            self.executable = True
            if self.call is not None:
                raise NcAlarmError(SYNTAX_ERROR, stmt.name)  # type: ignore[union-attr]
            self.call = stmt  # type: ignore[assignment]
        elif kind is ast.Builtin:
            self.executable = True
            self._builtin(stmt)  # type: ignore[arg-type]
        elif kind is ast.Def:
            self._def(stmt)  # type: ignore[arg-type]
        elif kind is ast.Proc:
            if self.index != 0 and self.frame.program.proc is not stmt:
                raise NcAlarmError(DEFINITION_AFTER_STATEMENT)
        elif kind is ast.Extern:
            pass  # declarations only; calls are resolved by name at run time

    def _address(self, word: ast.AddressWord) -> None:
        address = word.address
        interp = self.interp
        value_expr = word.value
        mode = None
        if isinstance(value_expr, ast.Func) and value_expr.name in ("AC", "IC", "DC", "ACP", "ACN"):
            if len(value_expr.args) != 1 or value_expr.args[0] is None:
                raise NcAlarmError(SYNTAX_ERROR, value_expr.name)
            mode = value_expr.name
            value_expr = value_expr.args[0]
        value = self.eval(value_expr)
        if address in interp.machine.path_axes:
            if address in self.words.axes:
                raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, address)
            self.words.axes[address] = (float(to_number(value, address)), mode)
            return
        if mode is not None:
            spindle_mode = address in SPINDLE_POSITION_WORDS
            if not spindle_mode and mode in ("DC", "ACP", "ACN"):
                raise NcAlarmError(SYNTAX_ERROR, f"{address}={mode}")
            if not spindle_mode and address not in MODE_WORDS and not (
                    address[0] in "IJK" and address[1:].isdigit()):
                raise NcAlarmError(SYNTAX_ERROR, f"{address}={mode}")
            self.words.word_modes[address] = mode  # I=AC(…), AP=IC(…): read by the motion builder
        if address == "G":
            raise NcAlarmError(SYNTAX_ERROR, "G=")
        number = to_number(value, address)
        if address == "M":
            m = _whole(number, "M")
            self.words.m_codes.append((word.ext, m))
            return
        if address == "H":
            self.words.h_codes.append((word.ext, float(number)))
            return
        if address == "P":
            passes = _whole(number, "P")
            if not 1 <= passes <= MAX_PASSES:
                raise NcAlarmError(PASS_COUNT_NOT_ALLOWED)
            self.passes = passes
            return
        if address in ("S", "T", "D", "F") and word.ext is not None:
            key = (address, word.ext)
            if key in self.words.extended:
                raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, f"{address}{word.ext}")
            self.words.extended[key] = float(number)
            if word.ext == 1 or address in ("T", "D"):
                self.words.words.setdefault(address, float(number))
            return
        if address in ("T", "D"):
            _whole(number, address)
        if len(address) == 1:
            if address not in "FSTDIJK":
                raise NcAlarmError(NAME_NOT_DEFINED, address)
        elif address not in VALUE_ADDRESSES and not (address[0] in "IJK" and address[1:].isdigit()):
            raise NcAlarmError(NAME_NOT_DEFINED, address)
        if word.indices and address in ("FA", "ACC"):  # FA[X]=…, ACC[X]=…: one value per axis
            index = word.indices[0]
            if address == "FA" and isinstance(index, ast.Name) and SPINDLE_NAME.fullmatch(index.name) \
                    and self.interp.lookup(index.name) is None:
                address = f"FA[{index.name}]"  # FA[S1]: positioning speed of spindle 1 (002 L51379)
            else:
                address = f"{address}[{to_string(self._index_value(index))}]"
        if address in self.words.words:
            raise NcAlarmError(ADDRESS_PROGRAMMED_TWICE, address)
        self.words.words[address] = float(number)

    def _gword(self, code: str) -> None:
        group = self.interp.table.lookup(code)
        present = self.words.gcodes.get(group.number)
        if present is not None and present != code:
            raise NcAlarmError(G_GROUP_PROGRAMMED_TWICE, group.number)
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
        if isinstance(stmt.value, ast.Func) and stmt.value.name in ("SET", "REP"):
            self._assign_list(target, stmt.value)
            return
        if isinstance(target, ast.Index) and target.name == "AX" and self.interp.lookup("AX") is None:
            # AX[<axis expression>]=value: axis word with a computed axis name
            if len(target.indices) != 1:
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "AX")
            axis = self._index_value(target.indices[0])
            if not isinstance(axis, str) or not self.interp.is_axis(axis):
                raise NcAlarmError(WRONG_AXIS_TYPE, "AX")
            self._address(ast.AddressWord(str(axis), stmt.value))
            return
        if isinstance(target, ast.Name):
            name = target.name
            if self.interp.lookup(name) is None and not name.startswith("$") and self._is_address(name):
                self._address(ast.AddressWord(name, stmt.value))
                return
        self.assign(target, self.eval(stmt.value))

    def _assign_list(self, target: ast.Name | ast.Index | ast.RParam, func: ast.Func) -> None:
        """``ARR[i]=SET(a, b, …)`` fills from element i on; ``ARR[i]=REP(v)`` fills to the end."""
        if isinstance(target, ast.RParam) or any(a is None for a in func.args) or not func.args:
            raise NcAlarmError(SYNTAX_ERROR, func.name)
        binding = self.interp.lookup(target.name)
        if not isinstance(binding, Cell) or not binding.dims:
            raise NcAlarmError(OPERATION_DOES_NOT_FIT_TYPE, target.name)
        start = 0
        if isinstance(target, ast.Index):
            start = binding.offset(tuple(self._index_value(i) for i in target.indices))
        values = [self.eval(a) for a in func.args if a is not None]
        size = len(binding.value)
        if func.name == "REP":
            if len(values) != 1:
                raise NcAlarmError(SYNTAX_ERROR, "REP")
            values = values * (size - start)
        elif start + len(values) > size:
            raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, target.name)
        for position, value in enumerate(values, start=start):
            element = _unflatten(position, binding.dims)
            journal_cell(self.interp, binding, element)
            binding.set(value, element)

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
                    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "R")
                interp.write_r(indices[0], value)
                return
            binding = interp.lookup(target.name)
            if binding is not None:
                write_binding(interp, binding, indices, value)
                return
            if target.name.startswith("$"):
                sysvars.write(interp, target.name, indices, value)  # type: ignore[arg-type]
                return
            raise NcAlarmError(NAME_NOT_DEFINED, target.name)
        binding = interp.lookup(target.name)
        if binding is not None:
            write_binding(interp, binding, (), value)
            return
        if target.name.startswith("$"):
            sysvars.write(interp, target.name, (), value)  # type: ignore[arg-type]
            return
        raise NcAlarmError(NAME_NOT_DEFINED, target.name)

    def _index_value(self, expr: ast.Expr) -> Any:
        if isinstance(expr, ast.Name) and self.interp.is_axis(expr.name) and self.interp.lookup(expr.name) is None:
            return Axis(expr.name)
        if isinstance(expr, ast.Name) and expr.name in FRAME_COMPONENTS and self.interp.lookup(expr.name) is None:
            return expr.name  # $P_UIFR[1,X,TR]=…: frame component names
        return self.eval(expr)

    # ------------------------------------------------------------ DEF
    def _def(self, stmt: ast.Def) -> None:
        frame = self.frame
        if not frame.def_open:
            raise NcAlarmError(DEFINITION_AFTER_STATEMENT)
        lower = float(to_number(self.eval(stmt.lower))) if stmt.lower is not None else None
        upper = float(to_number(self.eval(stmt.upper))) if stmt.upper is not None else None
        for decl in stmt.names:
            name = decl.name
            if len(name) < 2 or not all(c.isalpha() or c == "_" for c in name[:2]):
                raise NcAlarmError(SYNTAX_ERROR, name)
            if name in RESERVED or self.interp.is_axis(name) or self.interp.table.is_gcode(name) \
                    or name in VALUE_ADDRESSES:
                raise NcAlarmError(NAME_DEFINED_TWICE, name)
            scope_dict = frame.locals
            if stmt.scope is None and name in scope_dict:
                raise NcAlarmError(NAME_DEFINED_TWICE, name)
            dims: list[int] = []
            for dim_expr in decl.dims:
                size = to_number(self.eval(dim_expr), name)
                if size != int(size) or not 1 <= int(size) <= 65535:
                    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
                dims.append(int(size))
            if math.prod(dims) > MAX_ARRAY_ELEMENTS:  # every dimension allowed, the whole too big
                raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, name)
            self._reserve_memory(name, stmt, math.prod(dims), global_data=stmt.scope is not None)
            cell = Cell.create(name, stmt.type, tuple(dims), lower, upper, stmt.string_len)
            if decl.init is not None:
                values = [self.eval(e) for e in decl.init]
                if not dims:
                    if len(values) != 1:
                        raise NcAlarmError(TOO_MANY_INITIAL_VALUES, name)
                    cell.set(values[0])
                else:
                    size = len(cell.value)
                    if decl.init_rep:
                        if len(values) != 1:
                            raise NcAlarmError(TOO_MANY_INITIAL_VALUES, name)
                        converted = convert(values[0], stmt.type, name, stmt.string_len)
                        for i in range(size):
                            cell.value[i] = converted
                        cell.set(values[0], tuple(0 for _ in dims))
                    else:
                        if len(values) > size:
                            raise NcAlarmError(TOO_MANY_INITIAL_VALUES, name)
                        for i, v in enumerate(values):
                            cell.set(v, _unflatten(i, tuple(dims)))
            if stmt.scope is not None:
                self._def_gud(cell, stmt)
            else:
                scope_dict[name] = cell

    def _reserve_memory(self, name: str, stmt: ast.Def, elements: int, global_data: bool) -> None:
        """Count a new variable against the variable memory: MD28040 for the local (and
        program-global) variables of every program level, MD18150 for GUD; 12380 beyond it."""
        interp = self.interp
        size = memory_bytes(stmt.type, elements, stmt.string_len)
        if global_data:
            if name in interp.data.gud:
                return  # defined once; a second DEF takes no memory
            used = sum(stored_bytes(value) for value in interp.data.gud.values())
            limit_kb = interp.machine.md_value("MD18150", default=GUD_VALUES_MEM_KB)
            what = "MD18150 GUD memory"
        else:
            used = sum(frame.lud_bytes for frame in interp.run_state.frames)
            limit_kb = interp.machine.md_value("MD28040", default=LUD_VALUES_MEM_KB)
            what = "MD28040 LUD memory"
        if used + size > int(limit_kb) * 1024:
            raise NcAlarmError(MEMORY_CAPACITY_REACHED, f"{what} {int(limit_kb)} KB: {name}")
        if not global_data:
            self.frame.lud_bytes += size

    def _def_gud(self, cell: Cell, stmt: ast.Def) -> None:
        """``DEF NCK/CHAN``: a global user variable kept in NcData.gud (created once, with the
        part-program protection levels of its APRP/APWP attributes)."""
        if cell.name in self.interp.data.gud:
            return
        value = list(cell.value) if cell.dims else cell.value
        if cell.dims and len(cell.dims) > 1:
            raise NcAlarmError(ARRAY_TOO_MANY_DIMENSIONS, cell.name)
        self.interp.write_gud(cell.name, value)
        levels = {k: v for k, v in (("read", stmt.read_level), ("write", stmt.write_level)) if v is not None}
        if levels:
            self.interp.data.gud_access[cell.name] = levels

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
            loop_end = self.frame.for_ends.get(opener)
            if loop_end is None:
                raise NcAlarmError(CONTROL_STRUCTURES_NOT_NESTED)
            value = to_number(self._read_target(head.var), "FOR") + 1  # type: ignore[union-attr,arg-type]
            self.assign(head.var, value)  # type: ignore[union-attr,arg-type]
            if to_number(self._read_target(head.var), "FOR") <= loop_end:  # type: ignore[union-attr,arg-type]
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
            raise NcAlarmError(JUMP_TARGET_NOT_FOUND, label if label is not None else f"N{number}")
        self.frame.pc = found

    def _start_repeat(self, stmt: ast.SectionRepeat) -> None:
        """REPEAT/REPEATB: find the section, remember where to come back, jump to its start."""
        program = self.frame.program
        start = program.find_label(stmt.start, self.index, "B")
        if start is None:
            start = program.find_label(stmt.start, self.index, "F")
        if start is None:
            raise NcAlarmError(JUMP_TARGET_NOT_FOUND, stmt.start)
        if stmt.single_block:
            end = start
        elif stmt.end is not None:
            end_found = program.find_label(stmt.end, start - 1, "F")
            if end_found is None:
                raise NcAlarmError(JUMP_TARGET_NOT_FOUND, stmt.end)
            end = end_found
            if start <= self.index <= end:  # REPEAT between its labels: up to the REPEAT block (002 L21385-21387)
                end = self.index - 1
        else:
            end_label = program.find_label("ENDLABEL", start, "F")
            end = end_label if end_label is not None and end_label < self.index else self.index - 1
        passes = 1
        if stmt.passes is not None:
            passes = _whole(self.eval(stmt.passes), "P")
            if not 1 <= passes <= MAX_PASSES:
                raise NcAlarmError(PASS_COUNT_NOT_ALLOWED)
        if end < start:
            raise NcAlarmError(JUMP_TARGET_NOT_FOUND, stmt.start)
        self.frame.repeats.append((end, start, passes, self.index + 1))
        self.frame.pc = start

    def _section_end(self) -> None:
        """After the last block of a REPEAT section: run it again or go back behind REPEAT."""
        repeats = self.frame.repeats
        while repeats and repeats[-1][0] == self.index:
            end, start, passes, back = repeats[-1]
            if passes > 1:
                repeats[-1] = (end, start, passes - 1, back)
                self.frame.pc = start
                return
            repeats.pop()
            self.frame.pc = back

    def _call(self, call: ast.Call) -> None:
        interp = self.interp
        state = interp.run_state
        found = interp.programs.read_program(call.name) or interp.read_cycle(call.name)
        if found is None:
            if call.args is None and not call.name[:1] == "L" and self.passes is None:
                raise NcAlarmError(NAME_NOT_DEFINED, call.name)
            raise NcAlarmError(PROGRAM_NOT_FOUND, call.name)
        if len(state.frames) >= MAX_PROGRAM_LEVELS:
            raise NcAlarmError(SUBPROGRAM_LEVEL_EXCEEDED)
        name, text = found
        program = _program_cache(interp, name, text)
        frame = Frame(program=program, passes_left=(self.passes or 1) - 1)
        interp.dialect.bind_call(self.frame, frame, call, interp.modal)  # ISO: $C_… arguments, PROC → G290
        if program.proc is not None and program.proc.save:
            frame.saved_gcodes = dict(interp.modal.gcodes)  # PROC … SAVE
            frame.saved_pframe = interp.builder.path.state(interp.modal).frames.programmable
        frame.single_block_off = self.frame.single_block_off or bool(program.proc and program.proc.sblof)
        frame.display_off = self.frame.display_off or bool(program.proc and program.proc.displof)
        self._bind_parameters(program, call, frame)
        frame.locals = dict(frame.params)
        if self.frame.modal_call is not None and call is not self.frame.modal_call \
                and call.name.upper() in load_toml("cycles", "cycles.toml")["modal_call"]["passed_into"]:
            frame.modal_call = self.frame.modal_call  # a position pattern cycle (HOLES1 …) calls it
        state.frames.append(frame)

    def _bind_parameters(self, program: Program, call: ast.Call, frame: Frame) -> None:
        params = program.proc.params if program.proc is not None else ()
        args = call.args or ()
        if len(args) > len(params):
            raise NcAlarmError(TOO_MANY_CALL_PARAMETERS, call.name)
        frame.given_params = tuple(i < len(args) and args[i] is not None for i in range(len(params)))
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
            return RRef(interp.r_index(arg.number))
        if isinstance(arg, ast.Name):
            binding = interp.lookup(arg.name)
            if binding is None:
                raise NcAlarmError(PARAMETER_NOT_A_VARIABLE, arg.name)
            return binding
        if isinstance(arg, ast.Index):
            indices = tuple(self._index_value(i) for i in arg.indices)
            if arg.name == "R":
                if len(indices) != 1:
                    raise NcAlarmError(ILLEGAL_ARRAY_INDEX_1, "R")
                return RRef(interp.r_index(indices[0]))
            binding = interp.lookup(arg.name)
            if isinstance(binding, Cell) and binding.dims:
                binding.offset(indices)  # validates
                return ElemRef(binding, indices)
            raise NcAlarmError(PARAMETER_NOT_A_VARIABLE, arg.name)
        raise NcAlarmError(PARAMETER_NOT_A_VARIABLE, callee)

    # ------------------------------------------------------------ builtins
    def _builtin(self, stmt: ast.Builtin) -> None:
        name = stmt.name
        if name == "MSG":
            if len(stmt.args) > 1:
                raise NcAlarmError(WRONG_CALL_ARGUMENTS, "MSG")
            text = to_string(self.eval(stmt.args[0])) if stmt.args and stmt.args[0] is not None else ""
            self.interp.run_state.message = text
            self.early.append(canon.Message(self.source, text))
        elif name == "SETAL":
            if not stmt.args or stmt.args[0] is None:
                raise NcAlarmError(WRONG_CALL_ARGUMENTS, "SETAL")
            number = _whole(to_number(self.eval(stmt.args[0]), "SETAL"), "SETAL")
            if not 60000 <= number <= 69999:
                raise NcAlarmError(WRONG_CALL_ARGUMENTS, "SETAL")
            params = tuple(to_string(self.eval(a)) for a in stmt.args[1:] if a is not None)
            self.late.append(canon.UserAlarm(self.source, number, params))
        elif name == "STOPRE":
            self.late.append(canon.StopPoint(self.source, "STOPRE"))
        elif name == "WAITS":
            # WAITS / WAITS(n, …): the next block waits for the spindle (002 L51302-51335).
            for arg in stmt.args:
                number = _whole(to_number(self.eval(arg), "WAITS"), "WAITS") if arg is not None else 1
                if not 1 <= number <= len(self.interp.machine.spindles):
                    raise NcAlarmError(NAME_NOT_DEFINED, f"WAITS({number})")
            modal = self.interp.modal
            self.late.append(canon.Dwell(self.source, wait_spindle=True, gcodes=dict(modal.gcodes),
                                         feed=modal.feed))
        elif name == "RET":
            self.end_kind = "RET"
            self.ret_target = return_target(self.eval, stmt.args)
        elif name == "CALL":
            # indirect call: CALL "NAME" / CALL <string variable>
            target = to_string(self.eval(stmt.args[0])).strip().upper()  # type: ignore[arg-type]
            if not target or self.call is not None:
                raise NcAlarmError(PROGRAM_NOT_FOUND, target or "CALL")
            self.call = ast.Call(target, ())
        elif name == "GOTOS":
            # back to the start of the program (of this level), with an implicit STOPRE
            self.late.append(canon.StopPoint(self.source, "STOPRE"))
            self.goto_start = True
        elif name in ("SBLOF", "SBLON"):
            self.frame.single_block_off = name == "SBLOF"
        elif name in ("DISPLOF", "DISPLON"):
            self.frame.display_off = name == "DISPLOF"
        elif name == "CONTOURTAB":
            self._contour_table(stmt.args)

    def _contour_table(self, args: tuple[ast.Expr | None, ...]) -> None:
        """``CONTOURTAB(NAME, TAB, NN)``: the contour subprogram NAME read into the REAL
        array TAB[n, 7], NN its number of rows (nck.interp.contour_table)."""
        if len(args) != 3 or args[0] is None or not all(isinstance(a, ast.Name) for a in args[1:]):
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, "CONTOURTAB")
        interp = self.interp
        name = to_string(self.eval(args[0])).strip().upper()
        table, count = (interp.lookup(a.name) for a in args[1:])  # type: ignore[union-attr]
        if not isinstance(table, Cell) or len(table.dims) != 2 or table.dims[1] != ROW_WIDTH or count is None:
            raise NcAlarmError(WRONG_CALL_ARGUMENTS, "CONTOURTAB")
        found = interp.programs.read_program(name) if name else None
        if found is None:
            raise NcAlarmError(PROGRAM_NOT_FOUND, name or "CONTOURTAB")
        diameter = interp.modal.gcodes.get(29) in ("DIAMON", "DIAM90")
        rows = contour_rows(found[1], name, lambda expr: to_number(self.eval(expr), name), diameter)
        if not rows or len(rows) > table.dims[0]:  # no element, or more than the table holds
            raise NcAlarmError(STOCK_REMOVAL_CONTOUR_ERROR, name)
        for row_index, row in enumerate(rows):
            for column, value in enumerate(row):
                write_binding(interp, table, (row_index, column), value)
        write_binding(interp, count, (), len(rows))


def _whole(number: Any, address: str) -> int:
    value = to_number(number, address)
    if isinstance(value, float):
        if not value.is_integer():
            raise NcAlarmError(SYNTAX_ERROR, address)
        value = int(value)
    if value < 0 or value > 99_999_999:
        raise NcAlarmError(VALUE_RANGE_EXCEEDED, address)
    return value


def _unflatten(flat: int, dims: tuple[int, ...]) -> tuple[int, ...]:
    out = []
    for size in reversed(dims):
        out.append(flat % size)
        flat //= size
    return tuple(reversed(out))


def _program_cache(interp: InterpreterHost, name: str, text: str) -> Program:
    cache: dict[tuple[str, str], Program] = interp.__dict__.setdefault("_programs", {})
    key = (name, text)
    program = cache.get(key)
    if program is None:
        if len(cache) > 64:
            cache.clear()
        program = load_program(name, text, interp.dialect)
        cache[key] = program
    return program
