"""The extended return ``RET("<block number or label>"[, after])`` (Siemens; ISO ``M99 P<n>``).

``RET`` with a target returns to the caller and continues at that block, searched
from the calling block forward first, then backward; with ``after`` > 0 at the block
after it. The subprogram ends for good: no further passes. A plain ``RET`` returns
behind the calling block (:meth:`Interpreter.return_from`).
"""

from __future__ import annotations

from typing import Any, Callable

from nck.alarm_ids import JUMP_TARGET_NOT_FOUND
from nck.errors import NcAlarmError
from nck.lang.dialect import CallLevel, InterpreterContext
from nck.lang.values import to_number, to_string


def return_target(evaluate: Callable[[Any], Any], args: tuple[Any, ...]) -> tuple[str, int] | None:
    """``(target text, after)`` of ``RET(target[, after])``, or None for a plain RET."""
    if not args or args[0] is None:
        return None
    target = to_string(evaluate(args[0])).strip().upper()
    if not target:
        raise NcAlarmError(JUMP_TARGET_NOT_FOUND, "RET")
    after = 0
    if len(args) > 1 and args[1] is not None:
        after = int(to_number(evaluate(args[1]), "RET"))
    return target, after


def resume_caller(interp: InterpreterContext, target: str, after: int) -> None:
    """Continue the (now current) caller at block ``target`` (after it when ``after`` > 0).

    The caller stands behind its calling block; the search starts at that
    block, forward first, then backward. Not found: alarm 14080.
    """
    levels = interp.call_stack
    if not levels:
        return
    caller = levels[-1]
    program = caller.program
    start = max(caller.pc - 1, 0)
    found = None
    if target[:1] == "N" and target[1:].isdigit():
        found = program.find_number(int(target[1:]), start, "FB")
    if found is None:
        found = program.find_label(target.rstrip(":"), start, "FB")
    if found is None:
        raise NcAlarmError(JUMP_TARGET_NOT_FOUND, target)
    if after > 0:  # behind every Siemens line of that source block
        number = program.lines[found].number
        while found < len(program.lines) and program.lines[found].number == number:
            found += 1
    caller.pc = found


def prepare_return(level: CallLevel, target: tuple[str, int] | None) -> None:
    """A RET with a target ends the subprogram for good: no further passes."""
    if target is not None:
        level.passes_left = 0
