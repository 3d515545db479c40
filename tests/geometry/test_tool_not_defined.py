"""A T number without a tool data set is alarm 17191 (002 L58140-58219; issue 20).

Without tool management the T number names a data set of the tool offset memory. With
MD22550 = 0 the tool changes with T, and the program stops at the T block (002 L58150-58153);
with MD22550 = 1 the error is noted at T and the program stops at the tool change M06
(002 L58171-58190). T0 (no tool) needs no data set. The operator loads the data set and NC START
runs the block again ("compensation block", 002 L58150-58160), as with a missing D (17180).
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.check import check_text
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.ncdata import NcData, ToolEdge
from tests.lang.conftest import run_text


def with_tool_1() -> NcData:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0})
    return data


def alarms(result) -> list[tuple[int, int | None]]:
    return [(a.number, a.line) for a in result.alarms]


def test_mill_md22550_1_stops_at_the_m6_of_a_missing_tool() -> None:
    # The default mill changes with M6 (MD22550 = 1): T5 is accepted, M06 stops (002 L58171-58190).
    text = "N10 T5\nN20 G0 X10\nN30 M6\nN40 M30\n"
    result = run_text(text, data=with_tool_1())
    assert alarms(result) == [(17191, 3)]
    assert [(a.number, a.line) for a in check_text("TEST.MPF", text, data=with_tool_1())] == [(17191, 3)]


def test_mill_tool_with_data_changes_without_alarm() -> None:
    result = run_text("N10 T1\nN20 M6\nN30 G0 Z0\nN40 M30\n", data=with_tool_1())
    assert result.status == "ended", result.alarms
    assert result.segments[-1].end_mcs["Z"] == pytest.approx(100.0)  # L1 = 100 on Z (G17)


def test_lathe_md22550_0_stops_at_the_t_block() -> None:
    # The lathe changes with T (MD22550 = 0): the program stops at the T block (002 L58150-58153).
    text = "N10 G0 X10 Z10\nN20 T7\nN30 M30\n"
    result = run_text(text, data=with_tool_1(), machine="lathe2")
    assert alarms(result) == [(17191, 2)]


def test_t0_needs_no_data_set() -> None:
    result = run_text("N10 T0\nN20 M6\nN30 M30\n")
    assert result.status == "ended", result.alarms


def test_tool_loaded_after_the_alarm_and_nc_start_runs_the_block_again() -> None:
    # 002 L58154-58160: the operator loads the data set, NC START executes the block again.
    nck = Nck(programs=MemorySource({"P.MPF": "N10 T2 M6\nN20 G0 Z0\nN30 M30"}), referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0})
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel != "active", 10.0)
    assert [a.number for a in nck.status().alarms] == [17191]
    assert nck.submit(c.WriteData("$TC_DP1[2,1]", 120)) == c.Accepted()
    assert nck.submit(c.WriteData("$TC_DP3[2,1]", 30)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert [a.number for a in nck.status().alarms] == []
    assert nck.positions_mcs()["Z"] == pytest.approx(30.0, abs=1e-3)
