"""Digest 828d-3 (002, spindle, feed, tool offsets, protection): ranked items not proved
elsewhere, on the real interpreter and motion where they interact.

``tests/README.md`` lists where the other items are proved. Expected values are worked out by
hand from the manual lines cited.
"""

from __future__ import annotations

import math

import pytest

from nck import commands as c
from nck.errors import NcAlarmError
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from tests.geometry.golden.helpers import lines, run


def start(program: str, machine: str | None = None) -> Nck:
    nck = Nck(machine=load_machine(machine), programs=MemorySource({"P.MPF": program}), referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck


def spindle(nck: Nck):
    return next(a for a in nck.status().axes if a.kind == "spindle")


def until_stop(nck: Nck) -> str:
    assert nck.run_until(lambda k: k.situation.program in ("stopped", "aborted"), 120.0)
    block = nck.status().channel.current_block
    return block.text if block else ""


def test_digest_828d_3_rank_04_nc_stop_brakes_the_axes_not_the_spindle() -> None:
    """Digest 828d-3 rank 4: NC STOP brings the axes (not spindles) to a standstill, program
    stopped, channel interrupted (002 L70669-70673); NC START resumes to the end point."""
    nck = start("N10 M3 S1000\nN20 G1 X100 F1000\nN30 M30")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 20.0, 30.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(1.0)
    x = nck.positions_mcs()["X"]
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(x)
    assert (nck.situation.channel, nck.situation.program) == ("interrupted", "stopped")
    assert spindle(nck).speed_rpm == pytest.approx(1000.0)  # still turning
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_stop(nck) == ""
    assert nck.positions_mcs()["X"] == pytest.approx(100.0, abs=1e-3)


def test_digest_828d_3_rank_12_g0_after_the_feed_type_switch_needs_no_f() -> None:
    """Digest 828d-3 rank 12: after G94 -> G95 a G1 without F raises 10860 (002 L56880-56882,
    tested in ``test_feed_type_change_deletes_f``); a G0 block needs no F (002 L55649-55651)."""
    r = run(lines("N10 G94 G1 X10 F500", "N20 G95 S100 M3", "N30 G0 X20", "N40 M30"))
    assert r.end_mcs(30)["X"] == pytest.approx(20.0)
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 G94 G1 X10 F500", "N20 G95 S100 M3", "N30 G1 X20", "N40 M30"))
    assert info.value.number == 10860


def test_digest_828d_3_rank_14_constant_cutting_rate_on_the_lathe() -> None:
    """Digest 828d-3 rank 14: G96 S230 (002 L55549-55552): n = 230 000 / (2π r). The manual
    prints 183.12 / 366.24 rpm for r = 0.2 / 0.1 m (computed with π = 3.14); with π exact,
    r = 100 mm gives 366.056 rpm. At r = 10 mm, 3660.6 rpm is clamped to LIMS = 3000.
    G97 keeps the last speed (002 L55563-55565). Diameter programming: X200 is r = 100."""
    nck = start("N10 DIAMON G0 X300 Z10\nN20 G96 S230 LIMS=3000 M3\nN30 G1 X200 F2\nN40 M0\n"
                "N50 G1 X20\nN60 M0\nN70 G97\nN80 G1 X100\nN90 M0\nN100 M30", machine="lathe2")
    assert until_stop(nck).startswith("N40")
    nck.tick(3.0)
    assert spindle(nck).speed_rpm == pytest.approx(230_000 / (2 * math.pi * 100), rel=1e-6)
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N60")
    nck.tick(3.0)
    assert 230_000 / (2 * math.pi * 10) > 3000.0
    assert spindle(nck).speed_rpm == pytest.approx(3000.0)
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N90")
    assert spindle(nck).speed_rpm == pytest.approx(3000.0)  # frozen under G97 at r = 50


def test_digest_828d_3_rank_14_g96_alarms() -> None:
    """Digest 828d-3 rank 14: 10870 without a transverse axis, 14820 for LIMS < 0, 10900 for
    the first G96 without S (002 L55654-55665)."""
    for program, machine, number in (("N10 G96 S200 M3", None, 10870),
                                     ("N10 G96 S100 LIMS=-1", "lathe2", 14820),
                                     ("N10 G0 X20\nN20 G96 M3", "lathe2", 10900)):
        with pytest.raises(NcAlarmError) as info:
            run(program + "\nM30\n", None, machine or "mill3")
        assert info.value.number == number


def test_digest_828d_3_rank_21_effective_length_is_geometry_plus_wear_plus_base() -> None:
    """Digest 828d-3 rank 21: type 120, L1 = 100 ($TC_DP3), wear -0.2 ($TC_DP12), base 5
    ($TC_DP21) (002 L58637, L58804-58825): G17 G0 Z10 ends at machine Z 10 + 104.8 = 114.8;
    under G18 L1 acts on Y."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0, 12: -0.2, 21: 5.0})
    r = run(lines("N10 T1 M6 D1", "N20 G17 G0 X0 Y0 Z10", "N30 G18 X0 Y0 Z0", "N40 M30"), data)
    assert r.end_mcs(20)["Z"] == pytest.approx(114.8)
    assert r.end_mcs(30)["Y"] == pytest.approx(104.8)


def test_digest_828d_3_rank_20_missing_edge_is_corrected_and_the_block_runs_again() -> None:
    """Digest 828d-3 rank 20: a D that does not exist interrupts the program at that block
    (17180, with T and D); the operator loads the missing data set and NC START executes the
    block again ("compensation block", 002 L58140-58170); still missing, the alarm comes again;
    corrected, the program continues: D3 with L1 = 50 puts G0 Z0 at machine Z50."""
    nck = Nck(programs=MemorySource({"P.MPF": "N10 T1 M6\nN20 D3\nN30 G0 Z0\nN40 M30"}),
              referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0})
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel != "active", 10.0)
    assert [a.number for a in nck.status().alarms] == [17180]
    assert (nck.situation.channel, nck.situation.program) == ("interrupted", "stopped")
    assert nck.submit(c.CycleStart()) == c.Accepted()  # not corrected: the alarm again
    assert nck.run_until(lambda k: k.situation.channel != "active", 10.0)
    assert [a.number for a in nck.status().alarms] == [17180]
    assert nck.submit(c.WriteData("$TC_DP1[1,3]", 120)) == c.Accepted()
    assert nck.submit(c.WriteData("$TC_DP3[1,3]", 50)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert [a.number for a in nck.status().alarms] == []
    assert nck.positions_mcs()["Z"] == pytest.approx(50.0, abs=1e-3)
