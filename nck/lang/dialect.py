"""The language dialect in front of the interpreter.

The interpreter runs Siemens-mode blocks. A :class:`Dialect` is what it is given to
(a) turn a program text into Siemens lines when the text is not Siemens (the ISO
front end, :mod:`nck.iso.dialect`), and (b) answer the few run-time questions that
depend on the language mode: its system variables, the extra G-group display, what a
call hands to the called level and whether ``M30`` in a subprogram ends the program.

:class:`SiemensDialect` is the identity: every text is parsed as Siemens, no own
variables, no hooks. The interpreter imports no dialect but this protocol; the code
that builds an interpreter (kernel, headless runs, the checker) chooses the dialect.
"""

from __future__ import annotations

from typing import Any, Callable, Protocol, Sequence

from nck.errors import NcAlarmError
from nck.lang.lines import Line

Located = Callable[[NcAlarmError, str, int, "int | None"], NcAlarmError]
"""``located(alarm, program name, line, block number)``: the alarm with its place."""

GuessN = Callable[[str], "int | None"]
"""The block number written at the start of a raw line (None: none)."""


class CallLevel(Protocol):
    """One program level of the interpreter's call stack, as a dialect sees it."""

    program: Any
    pc: int
    passes_left: int
    modal_call: Any
    iso_macro: Any


class InterpreterContext(Protocol):
    """What a dialect's run-time hooks may use of the interpreter."""

    machine: Any
    data: Any
    builder: Any

    @property
    def modal(self) -> Any:
        """The live modal state (G codes, tool, feed …)."""

    @property
    def call_stack(self) -> Sequence[CallLevel]:
        """The program levels, main program first."""

    def write_tool(self, tool: int, edge: int, param: int, value: float) -> None:
        """Write one tool edge parameter (journaled)."""

    def journal_undo(self, undo: Callable[[], None]) -> None:
        """Remember ``undo`` to take back a change if the block is repeated (preprocessing)."""


class Dialect(Protocol):
    """A language mode as the interpreter sees it (see the module docstring)."""

    @property
    def name(self) -> str:
        """``siemens``, ``iso-m`` or ``iso-t`` (the language mode the display shows)."""

    @property
    def gcode_table(self) -> str:
        """The G-code table the interpreter runs with (Siemens: ISO is translated)."""

    def program_key(self) -> object:
        """What loaded programs are cached by besides name and text."""

    def translated_lines(self, name: str, text: str, located: Located, guess_n: GuessN,
                         main: bool) -> list[Line] | None:
        """The Siemens lines of a text this dialect translates; None: parse it as Siemens."""

    def gcode_display(self, modal: Any, levels: Sequence[CallLevel]) -> dict[int, str]:
        """Codes of the dialect's own G groups for the display (empty: none)."""

    def reads_variable(self, name: str) -> bool:
        """True if system variable ``name`` is the dialect's to read."""

    def read_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...]) -> Any:
        """Value of the dialect's system variable ``name``."""

    def writes_variable(self, name: str) -> bool:
        """True if system variable ``name`` is the dialect's to write."""

    def write_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...],
                       value: Any) -> None:
        """Write the dialect's system variable ``name``."""

    def bind_call(self, caller: CallLevel, callee: CallLevel, call: Any, modal: Any) -> None:
        """A subprogram call: hand the called level what the dialect gives it."""

    def after_return(self, modal: Any, level: CallLevel) -> None:
        """A subprogram level ended and was left."""

    def ends_whole_program(self, ctx: InterpreterContext, end_kind: str | None) -> bool:
        """True if the end ``end_kind`` in a subprogram ends the whole program."""


class SiemensDialect:
    """Siemens mode alone: the identity dialect (no translation, no own variables)."""

    name = "siemens"
    gcode_table = "siemens"

    def program_key(self) -> object:
        """Siemens texts are scanned alike everywhere."""
        return self.name

    def translated_lines(self, name: str, text: str, located: Located, guess_n: GuessN,
                         main: bool) -> list[Line] | None:
        """Nothing is translated."""
        return None

    def gcode_display(self, modal: Any, levels: Sequence[CallLevel]) -> dict[int, str]:
        """No G groups of its own."""
        return {}

    def reads_variable(self, name: str) -> bool:
        """No system variables of its own."""
        return False

    def read_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...]) -> Any:
        """Never asked (:meth:`reads_variable` is False)."""
        raise LookupError(name)

    def writes_variable(self, name: str) -> bool:
        """No system variables of its own."""
        return False

    def write_variable(self, ctx: InterpreterContext, name: str, indices: tuple[Any, ...],
                       value: Any) -> None:
        """Never asked (:meth:`writes_variable` is False)."""
        raise LookupError(name)

    def bind_call(self, caller: CallLevel, callee: CallLevel, call: Any, modal: Any) -> None:
        """Nothing to hand over."""

    def after_return(self, modal: Any, level: CallLevel) -> None:
        """Nothing to restore."""

    def ends_whole_program(self, ctx: InterpreterContext, end_kind: str | None) -> bool:
        """Never: an end in a subprogram returns to the caller."""
        return False


SIEMENS = SiemensDialect()
"""The identity dialect, the interpreter's default."""
