"""A block that raises an alarm leaves the interpreter as it was (``Interpreter.step``: "state
unchanged"), also when the snapshot before it skips the copy of the modal state because the block
only assigns to variables (their writes are journaled): the variables, the G codes, the position
and the next block are those before the block."""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

SUB = ("PROC SUB(VAR REAL OUT)\n"
       "DEF REAL AA, BB\n"
       "AA=1 OUT=1\n"
       "G1 X10 F100\n"
       "{failing}\n"
       "RET\n")


def _run_to_alarm(failing: str) -> tuple[Interpreter, dict, NcAlarmError]:
    interp = Interpreter(load_machine(None), MemorySource({"SUB.SPF": SUB.format(failing=failing)}), NcData())
    interp.start_text("MAIN.MPF", "DEF REAL KEPT\nG0 X0 Y0 Z0\nSUB(KEPT)\nM30\n")
    while (interp.current_source().file, interp.current_source().line) != ("SUB.SPF", 5):
        interp.step()
    before = _state(interp)
    with pytest.raises(NcAlarmError) as raised:
        interp.step()
    return interp, before, raised.value


def _state(interp: Interpreter) -> dict:
    view = interp.modal_view()
    return {"AA": interp.variable("AA"), "BB": interp.variable("BB"), "OUT": interp.variable("OUT"),
            "gcodes": view.gcodes, "feed": view.feed, "position": dict(interp.modal.position_mcs),
            "next": interp.current_source(), "level": interp.level()}


@pytest.mark.parametrize("failing", [
    "AA=2 OUT=2 BB=1/0",  # only variables: no copy of the modal state before it
    "AA=2 BB=SQRT(-1)",
    "AA=2 OUT=3 X=1/0",  # X is an axis, not a variable: the modal state is copied
    "AA=2 X=5 Y=7 F=300 BB=1/0",
    "F=300 BB=1/0",
    "G2 AA=2 OUT=2 BB=1/0",
    "AA=2 X=20 F=300 CHF=-1",  # the feed is taken before the motion builder refuses CHF: only the copy undoes it
    'AA=2 OUT=2 RET("NOWHERE")',  # leaves the level, then the caller has no such block (14080): back in SUB
])
def test_a_failing_block_changes_nothing(failing):
    interp, before, alarm = _run_to_alarm(failing)
    assert _state(interp) == before
    assert (alarm.file, alarm.line) == ("SUB.SPF", 5)
