"""ISO subprograms: ``M98 P… L…`` calls, ``M99 [P…]`` returns, ``M30`` in a subprogram.

Translation side (used by :mod:`nck.iso.translate`):

* ``M98 P<count><nnnn>`` / ``M98 P<nnnn> L<count>`` → ``CALL "O<nnnn>" P<count>``
  (L wins over the count digits of P; 1 … 9999 passes);
* ``M99`` → ``M17`` in a subprogram, ``GOTOS`` (restart) in a main program;
* ``M99 P<n>`` → ``RET("N<n>")`` in a subprogram (resume the caller at block
  N<n>), ``GOTO N<n>`` in a main program.

Interpreter side (a hook of :class:`nck.iso.dialect.IsoDialect`):

* :func:`ends_whole_program`: ``M30`` ends the whole program even in a
  subprogram while ISO mode (G291) is active; in Siemens mode it returns.

``RET("N<n>")`` itself is Siemens (the extended RET, :mod:`nck.interp.returns`).

M98 and M99 never reach the PLC: they become calls and returns, not M words.
"""

from __future__ import annotations

from nck.alarm_ids import PASS_COUNT_NOT_ALLOWED, SYNTAX_ERROR
from nck.errors import NcAlarmError
from nck.lang.dialect import InterpreterContext

MAX_PASSES = 9999
ISO_MODE_GROUP = 47  # Siemens G group of G290/G291


# ----------------------------------------------------------------------------- translation
def call_block(values: dict[str, float]) -> str:
    """The Siemens call of ``M98 P… [L…]``: ``CALL "O0021" P3`` (alarm 12080 without P)."""
    if "P" not in values:
        raise NcAlarmError(SYNTAX_ERROR, "M98")
    p_value = int(values["P"])
    count = int(values.get("L", 1))
    if p_value > 9999:  # P<count><nnnn>; an explicit L takes precedence over the count digits
        if "L" not in values:
            count = p_value // 10000
        p_value %= 10000
    if not 1 <= count <= MAX_PASSES:
        raise NcAlarmError(PASS_COUNT_NOT_ALLOWED)
    call = f'CALL "O{p_value:04d}"'
    return call if count == 1 else f"{call} P{count}"


def return_block(values: dict[str, float], main: bool) -> str:
    """The Siemens form of ``M99 [P<n>]`` in a main program or a subprogram."""
    if "P" in values:
        target = int(values["P"])
        return f"GOTO N{target}" if main else f'RET("N{target}")'
    return "GOTOS" if main else "M17"


# ----------------------------------------------------------------------------- interpreter
def ends_whole_program(interp: InterpreterContext, end_kind: str | None) -> bool:
    """True if ``M30`` in a subprogram ends the whole program.

    That is ISO mode (G291 active) in a subprogram that is not a Siemens
    ``PROC`` program (those run in Siemens mode, where M30 only returns).
    """
    if end_kind != "M30" or interp.modal.gcodes.get(ISO_MODE_GROUP) != "G291":
        return False
    frames = interp.call_stack
    return not frames or frames[-1].program.proc is None
