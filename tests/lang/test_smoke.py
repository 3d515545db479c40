"""First end-to-end checks of the interpreter API."""

from __future__ import annotations

from nck import canon
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def test_g0_g1_program_runs_and_reaches_end(run) -> None:
    result = run("G0 X10 Y5\nG1 Z-2 F100\nG91 X5\nM30\n")
    assert result.status == "ended"
    ends = [dict(m.end_wcs) for m in result.segments]
    assert ends == [
        {"X": 10.0, "Y": 5.0, "Z": 0.0},
        {"X": 10.0, "Y": 5.0, "Z": -2.0},
        {"X": 15.0, "Y": 5.0, "Z": -2.0},
    ]
    assert isinstance(result.commands[-1], canon.ProgramEnd)


def test_interpreter_api_step_modal_view_reset() -> None:
    interp = Interpreter(load_machine(), MemorySource(), NcData())
    interp.start_text("MDA", "G91 G1 X1 F50\nX1\n")
    first = interp.step()
    assert first.action_block and not first.finished
    assert interp.modal_view().gcodes[14] == "G91"
    interp.reset()
    assert interp.finished
    assert interp.modal_view().gcodes[14] == "G90"
    assert interp.modal_view().feed == 0.0
