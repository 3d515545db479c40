"""ISO subprograms: ``M98 P… L…`` calls, ``M99 [P…]`` returns, ``M30`` in a subprogram.

Translation side (used by :mod:`nck.iso.translate`):

* ``M98 P<count><nnnn>`` / ``M98 P<nnnn> L<count>`` → ``CALL "O<nnnn>" P<count>``
  (L wins over the count digits of P; 1 … 9999 passes);
* ``M99`` → ``M17`` in a subprogram, ``GOTOS`` (restart) in a main program;
* ``M99 P<n>`` → ``RET("N<n>")`` in a subprogram (resume the caller at block
  N<n>), ``GOTO N<n>`` in a main program.

Interpreter side (small hooks in :mod:`nck.interp.block_run`):

* :func:`return_target` / :func:`resume_caller`: ``RET("<block number or
  label>"[, after])`` returns to the caller and continues at that block,
  searched forward from the calling block first, then backward; with
  ``after`` > 0 at the block after it (the extended RET of the manual);
* :func:`ends_whole_program`: ``M30`` ends the whole program even in a
  subprogram while ISO mode (G291) is active; in Siemens mode it returns.

M98 and M99 never reach the PLC: they become calls and returns, not M words.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from nck.errors import NcAlarmError

if TYPE_CHECKING:
    from nck.interp.frames import Frame
    from nck.interp.interpreter import Interpreter

MAX_PASSES = 9999
ISO_MODE_GROUP = 47  # Siemens G group of G290/G291


# ----------------------------------------------------------------------------- translation
def call_block(values: dict[str, float]) -> str:
    """The Siemens call of ``M98 P… [L…]``: ``CALL "O0021" P3`` (alarm 12080 without P)."""
    if "P" not in values:
        raise NcAlarmError(12080, "M98")
    p_value = int(values["P"])
    count = int(values.get("L", 1))
    if p_value > 9999:  # P<count><nnnn>; an explicit L takes precedence over the count digits
        if "L" not in values:
            count = p_value // 10000
        p_value %= 10000
    if not 1 <= count <= MAX_PASSES:
        raise NcAlarmError(14013)
    call = f'CALL "O{p_value:04d}"'
    return call if count == 1 else f"{call} P{count}"


def return_block(values: dict[str, float], main: bool) -> str:
    """The Siemens form of ``M99 [P<n>]`` in a main program or a subprogram."""
    if "P" in values:
        target = int(values["P"])
        return f"GOTO N{target}" if main else f'RET("N{target}")'
    return "GOTOS" if main else "M17"


# ----------------------------------------------------------------------------- interpreter
def return_target(evaluate: Any, args: tuple[Any, ...]) -> tuple[str, int] | None:
    """``(target text, after)`` of ``RET(target[, after])``, or None for a plain RET."""
    if not args or args[0] is None:
        return None
    from nck.interp.values import to_number, to_string

    target = to_string(evaluate(args[0])).strip().upper()
    if not target:
        raise NcAlarmError(14080, "RET")
    after = 0
    if len(args) > 1 and args[1] is not None:
        after = int(to_number(evaluate(args[1]), "RET"))
    return target, after


def resume_caller(interp: Interpreter, target: str, after: int) -> None:
    """Continue the (now current) caller at block ``target`` (after it when ``after`` > 0).

    The caller stands behind its calling block; the search starts at that
    block, forward first, then backward. Not found: alarm 14080.
    """
    frames = interp._state.frames
    if not frames:
        return
    caller = frames[-1]
    program = caller.program
    start = max(caller.pc - 1, 0)
    found = None
    if target[:1] == "N" and target[1:].isdigit():
        found = program.find_number(int(target[1:]), start, "FB")
    if found is None:
        found = program.find_label(target.rstrip(":"), start, "FB")
    if found is None:
        raise NcAlarmError(14080, target)
    if after > 0:  # behind every Siemens line of that source block
        number = program.lines[found].number
        while found < len(program.lines) and program.lines[found].number == number:
            found += 1
    caller.pc = found


def prepare_return(frame: Frame, target: tuple[str, int] | None) -> None:
    """A RET with a target ends the subprogram for good: no further passes."""
    if target is not None:
        frame.passes_left = 0


def ends_whole_program(interp: Interpreter, end_kind: str | None) -> bool:
    """True if ``M30`` in a subprogram ends the whole program.

    That is ISO mode (G291 active) in a subprogram that is not a Siemens
    ``PROC`` program (those run in Siemens mode, where M30 only returns).
    """
    if end_kind != "M30" or interp.modal.gcodes.get(ISO_MODE_GROUP) != "G291":
        return False
    frames = interp._state.frames
    return not frames or frames[-1].program.proc is None
