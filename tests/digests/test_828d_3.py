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


def test_digest_828d_3_rank_21_wear_sign_acts_from_the_next_edge_selection() -> None:
    """Digest 828d-3 rank 21: SD42930 = 1 inverts the sign of every wear value, but the tool
    components are evaluated when an edge is selected, so the change acts only after D1 is
    programmed again (002 L62074-62083, the manual's example N200/N300). L1 = 100, wear
    -0.2, base 5: Z10 at 10 + 104.8 = 114.8; after $SC_WEAR_SIGN=1 still 114.8; after D1
    again 10 + 100 + 0.2 + 5 = 115.2. The radius follows the same rule (G41 below)."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 100.0, 12: -0.2, 21: 5.0})
    r = run(lines("N10 T1 M6 D1", "N20 G17 G0 X0 Y0 Z10", "N30 $SC_WEAR_SIGN=1", "N40 Z10.5",
                  "N50 D1", "N60 Z10", "N70 M30"), data)
    assert r.end_mcs(20)["Z"] == pytest.approx(114.8)
    assert r.end_mcs(40)["Z"] == pytest.approx(115.3)  # 10.5 + 104.8: not yet inverted
    assert r.end_mcs(60)["Z"] == pytest.approx(115.2)


def test_digest_828d_3_rank_21_wear_sign_on_the_radius_after_d1_again() -> None:
    """002 L62085-62106 in small: radius 10 ($TC_DP6), wear 1 ($TC_DP15): radius 11; with
    SD42930 = 1 the radius is 9, from the next D1 on. G41 along X from the left (Y0 line,
    tool left of it): the tool centre runs at Y = radius."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 6: 10.0, 15: 1.0})
    r = run(lines("N10 T1 M6 D1", "N20 G17 G0 X-50 Y0 Z0", "N30 G41 G1 X0 Y0 F1000", "N40 X100",
                  "N50 G40 X150 Y0", "N60 $SC_WEAR_SIGN=1", "N70 G0 X-50 Y0", "N80 G41 G1 X0 Y0",
                  "N90 X100", "N100 G40 X150 Y0", "N110 D1", "N120 G0 X-50 Y0", "N130 G41 G1 X0 Y0",
                  "N140 X100", "N150 G40 X150 Y0", "N160 M30"), data)
    assert r.end_mcs(40)["Y"] == pytest.approx(11.0)
    assert r.end_mcs(90)["Y"] == pytest.approx(11.0)  # SD42930 changed, D1 not programmed again
    assert r.end_mcs(140)["Y"] == pytest.approx(9.0)


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


def _first_cycle_with(program: str, found, data: NcData | None = None) -> tuple[float, float]:
    """(X, Y) setpoint in the IPO cycle where ``found(status)`` first holds (real interpreter and motion)."""
    nck = Nck(machine=load_machine(), programs=MemorySource({"P.MPF": program}), data=data, referenced=True,
              batch_cycles=1)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    for _ in range(20000):
        nck.step(1)
        status = nck.status()
        if found(status):
            position = nck.positions_mcs()
            return round(position["X"], 3), round(position["Y"], 3)
        assert nck.situation.channel != "reset", "the program ended first"
    raise AssertionError("never found")


def test_digest_828d_3_rank_06_m8_between_rounded_blocks_goes_out_after_the_rounding() -> None:
    """Digest 828d-3 rank 6 (single block and the blocks held back): N35 M8 stands between
    N30, whose motion RND holds back, and N40. A block without path motion ends the block
    before it with exact stop and goes out there (002 L4797-4809); the rounding belongs to N30
    and blocks without motion may stand between the two rounded blocks (002 L56859-56868). So
    M8 comes when the axes stand at the end of the rounding arc: RND=2 between X and Y lines
    at the corner (10, 0) ends the arc 2 mm up the Y line, at (10, 2). Before, M8 went out
    before N30 moved. The status shows the output in the IPO cycle after it went out, when N40
    has just started from standstill (well under 0.05 mm)."""
    program = "N20 G0 X0 Y0\nN30 G1 X10 RND=2 F3000\nN35 M8\nN40 Y10\nN50 M30\n"
    assert _first_cycle_with(program, lambda s: s.channel.modal.aux.get("M") == "8") == pytest.approx(
        (10.0, 2.0), abs=0.05)


def test_digest_828d_3_rank_06_dwell_under_g41_comes_at_the_compensated_corner() -> None:
    """Digest 828d-3 rank 6: with G41 the look-ahead holds N40 back until N50 is known. The
    block outside the compensation plane (N45 G4) is output at the end of N40's compensated
    segment (001 L7752-7757: the functions of the block in between go out at point S1, the end
    of the block before it). Tool radius 2, G41 inside the square (10,10)-(30,10)-(30,30):
    N40 ends at the intersection of the offset lines Y = 12 and X = 28, (28, 12); the dwell
    is the first time the channel shows a dwell. Before, it dwelt at (10, 12), before N40."""
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 6: 2.0})
    program = ("N10 T1 M6 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 Y10 F3000\nN40 X30\nN45 G4 F0.5\nN50 Y30\n"
               "N60 X10\nN70 G40 X0 Y0\nN80 M30\n")
    assert _first_cycle_with(program, lambda s: (s.channel.current_block is not None
                                                 and s.channel.current_block.line == 5), data) == (28.0, 12.0)


def test_digest_828d_3_rank_06_single_block_stops_at_the_block_without_motion_in_its_place() -> None:
    """Digest 828d-3 rank 6: one stop per action (002 L18071-18094): the line of N30 to 2 mm
    before the corner (8, 0), the rounding arc to (10, 2), then N35 M8 there (its own stop, an
    auxiliary output is an action), then N40 to (10, 10). Before, N35 stopped at (0, 0)."""
    from tests.kernel.test_single_block_motion import stops

    text = "N20 G0 X0 Y0\nN30 G1 X10 RND=2 F1000\nN35 M8\nN40 Y10\nN50 M30\n"
    assert stops(text) == [(0.0, 0.0, 1), (8.0, 0.0, 2), (10.0, 2.0, 2), (10.0, 2.0, 3), (10.0, 10.0, 4)]
    text = ("N10 T1 M6 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 Y10 F1000\nN40 X30\nN45 M8\nN50 Y30\nN60 X10\n"
            "N70 G40 X0 Y0\nN80 M30\n")
    assert stops(text) == [(0.0, 0.0, 1), (0.0, 0.0, 2), (10.0, 12.0, 3), (28.0, 12.0, 4), (28.0, 12.0, 5),
                           (28.0, 28.0, 6), (10.0, 28.0, 7), (0.0, 0.0, 8)]


def test_digest_828d_3_rank_11_g95_with_the_spindle_at_rest_stands_without_an_alarm() -> None:
    """Digest 828d-3 rank 11: the path velocity under G95 is the actual speed of the master
    spindle times F (002 L55411-55420); with the spindle at rest it is 0, so the axes stand and
    the block does not end, as on the control, without an alarm (the manual names none; the
    digest: spindle stopped, no motion). RESET ends the program."""
    nck = start("N10 G95 G1 X10 F0.2\nN20 M30\n")
    assert not nck.run_until(lambda k: k.situation.program != "running", 2.0)
    assert nck.positions_mcs()["X"] == pytest.approx(0.0)
    assert nck.situation.program == "running"
    assert nck.status().alarms == ()
    assert nck.submit(c.Reset()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 5.0)
