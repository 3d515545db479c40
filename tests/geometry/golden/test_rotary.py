"""Golden: a rotary axis with DC / ACP / ACN, and frames on a special axis.

Machine: X, Y, Z and a rotary table A (built in the test, no machine file).
"""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import AxisConfig, MachineConfig
from nck.ncdata import NcData

from .helpers import Run, lines

MILL4 = MachineConfig(
    name="mill4", title="mill with rotary table A", kind="mill",
    axes=(AxisConfig("X", "linear", 0), AxisConfig("Y", "linear", 1), AxisConfig("Z", "linear", 2),
          AxisConfig("A", "rotary", 3), AxisConfig("SP", "spindle", 4)),
)


def run4(text: str) -> Run:
    interp = Interpreter(MILL4, MemorySource({}), NcData())
    interp.start_text("R.MPF", text)
    result = Run(interp)
    while not interp.finished:
        result.commands.extend(interp.step().commands)
    return result


def test_dc_acp_acn() -> None:
    r = run4(lines(
        "N10 G0 A350",
        "N20 A=DC(10)",    # shortest way from 350 to 10: +20 -> 370
        "N30 A=ACN(350)",  # negative direction from 370 (10°) to 350°: -20 -> 350
        "N40 A=ACP(340)",  # positive direction from 350 to 340: +350 -> 700
        "N50 A=DC(340)",   # already there: stays 700
        "N60 A=ACP(340)",  # same position: no motion
        "N70 M30",
    ))
    assert [r.end_mcs(n)["A"] for n in (20, 30, 40, 50, 60)] == pytest.approx([370, 350, 700, 700, 700])
    # A is not converted by G70 (degrees), X is.
    r = run4(lines("N10 G70 G0 X1 A90", "N20 M30"))
    assert r.end_mcs(10)["X"] == pytest.approx(25.4) and r.end_mcs(10)["A"] == pytest.approx(90.0)


def test_dc_on_a_linear_axis_and_acp_out_of_range() -> None:
    with pytest.raises(NcAlarmError) as info:
        run4(lines("N10 G0 X=DC(10)", "N20 M30"))
    assert info.value.number == 16800
    with pytest.raises(NcAlarmError) as info:
        run4(lines("N10 G0 X=ACP(10)", "N20 M30"))
    assert info.value.number == 16810
    with pytest.raises(NcAlarmError) as info:
        run4(lines("N10 G0 A=ACP(400)", "N20 M30"))
    assert info.value.number == 16830


def test_frames_translate_and_mirror_a_special_axis() -> None:
    r = run4(lines("N10 TRANS A30", "N20 G0 A10", "N30 AMIRROR A0", "N40 G0 A10", "N50 M30"))
    assert r.end_mcs(20)["A"] == pytest.approx(40.0)
    assert r.end_mcs(40)["A"] == pytest.approx(20.0)  # 30 + (-10)
