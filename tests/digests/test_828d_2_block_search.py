"""Digest 828d-2 rank 25: the block search types on the real interpreter and motion.

The program is the manual's example for type 2 and type 4 (002 L18842-18880), with the tool
change routine WZW written into the main program (its N550 approach to the tool change
position X450 Y300 Z300 and the M6) and tool 1 as "CUTTER_2" (radius 5, length 0, so the
machine positions equal the programmed ones). Expected values are read off the manual's
figure 9-4 and notes (002 L18778-18795, L18836-18840) and worked out by hand.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck

WORKPIECE = """N100 G0 G40 X200 Y200
N110 Z100 D0
N200 T1
N210 G0 G40 G60 G90 X450 Y300 Z300 D0
N215 M6
N220 G0 X170 Y30 Z10 S3000 M3 D1
N230 Z-5
N240 G1 G64 G42 F500 X150 Y50
N250 Y150
N260 G2 J50 X100 Y200
N270 G1 X50
N280 Y50
N290 X150
N300 G0 G40 G60 X170 Y30
N310 Z100 D0
N320 M30
"""
TOOL_CHANGE_POINT = {"X": 450.0, "Y": 300.0, "Z": 300.0}


def machine(at: dict[str, float] | None = None) -> Nck:
    """The default mill with tool 1 (radius 5), axes referenced, standing at ``at`` (MDA G0)."""
    nck = Nck(programs=MemorySource({"WORKPIECE_1.MPF": WORKPIECE}), referenced=True)
    for name, value in (("$TC_DP1[1,1]", 120), ("$TC_DP3[1,1]", 0), ("$TC_DP6[1,1]", 5)):
        assert nck.submit(c.WriteData(name, value)) == c.Accepted()
    if at:
        assert nck.submit(c.SelectMode("MDA")) == c.Accepted()
        nck.submit(c.SetMdaProgram("G0 " + " ".join(f"{a}{v:g}" for a, v in at.items())))
        assert nck.submit(c.CycleStart()) == c.Accepted()
        assert nck.run_until(lambda k: k.situation.program == "aborted", 30.0)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("WORKPIECE_1.MPF")) == c.Accepted()
    return nck


def search(nck: Nck, target: str, search_type: str) -> None:
    """Search, then the first NC START (action blocks, 10208), then the second one."""
    assert nck.submit(c.StartBlockSearch(target, search_type)) == c.Accepted()
    status = nck.status().channel
    assert status.stop_reason == "search target found"
    assert status.current_block.text.startswith(target)
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert alarms(nck) == [10208]  # 002 L18337-18341: the sequence of types 1, 2 and 4
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert alarms(nck) == []


def alarms(nck: Nck) -> list[int]:
    return [a.number for a in nck.status().alarms]


def position(nck: Nck) -> dict[str, float]:
    return {a: v for a, v in nck.positions_mcs().items() if a in "XYZ"}


def test_digest_828d_2_rank_25_type_4_approaches_the_end_point_of_n220_in_a_straight_line() -> None:
    """Digest 828d-2 rank 25, type 4 (002 L18295-18302, figure 9-4 L18778-18790): from the tool
    change point (450, 300, 300) NC START moves straight to N220's end (170, 30, 10) with G0.
    Halfway in X (310) the straight line has Y = 300 - 270 / 2 = 165 and Z = 300 - 290 / 2 = 155."""
    nck = machine(at=TOOL_CHANGE_POINT)
    search(nck, "N220", "end_point")
    assert nck.status().channel.modal.tool == 1  # the action blocks: T1, M6 (002 L18422-18427)
    assert nck.run_until(lambda k: k.positions_mcs()["X"] <= 310.0, 30.0)
    here = position(nck)
    assert here["Y"] == pytest.approx(165.0 + (here["X"] - 310.0) * 270 / 280, abs=0.05)
    assert here["Z"] == pytest.approx(155.0 + (here["X"] - 310.0) * 290 / 280, abs=0.05)
    assert nck.run_until(lambda k: k.positions_mcs()["Z"] <= -5.0 + 1e-6, 30.0)  # N230 follows
    assert position(nck) == pytest.approx({"X": 170.0, "Y": 30.0, "Z": -5.0})


def test_digest_828d_2_rank_25_type_2_to_n220_approaches_the_tool_change_point_first() -> None:
    """Digest 828d-2 rank 25, type 2 (002 L18290-18294, note L18792-18795): the search to contour
    with target N220 approaches N220's start point, the tool change point (450, 300, 300),
    from wherever the machine stands (here 0, 0, 0), then runs N220 to (170, 30, 10)."""
    nck = machine()
    search(nck, "N220", "contour")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 450.0 - 1e-6, 30.0)
    assert position(nck) == pytest.approx(TOOL_CHANGE_POINT)
    assert nck.run_until(lambda k: k.positions_mcs()["Z"] <= 10.0 + 1e-6, 30.0)
    assert position(nck) == pytest.approx({"X": 170.0, "Y": 30.0, "Z": 10.0})


def test_digest_828d_2_rank_25_type_4_to_the_circle_n260_is_alarm_14040() -> None:
    """Digest 828d-2 rank 25, type 4 (002 L18474-18477, note L18836-18840): the search to the
    block end point with target N260 (G2 J50 X100 Y200, centre 150/200) fails with 14040:
    from the tool change point the radius is about 318, at the end point it is 50 (±5 for G42).
    The axes do not move."""
    nck = machine(at=TOOL_CHANGE_POINT)
    search(nck, "N260", "end_point")
    nck.tick(0.5)
    assert alarms(nck) == [14040]
    assert nck.status().alarms[0].n == 260
    assert position(nck) == pytest.approx(TOOL_CHANGE_POINT)
    assert isinstance(nck.submit(c.CycleStart()), c.Rejected)  # cleared by RESET only


def test_digest_828d_2_rank_25_type_4_moves_only_the_axes_of_the_target_block() -> None:
    """Digest 828d-2 rank 25, type 4 (002 L18298-18299): from the tool change point, target N300
    (G0 X170 Y30) leaves Z at 300; from there, target N250 (Y150) moves only Y."""
    nck = machine(at=TOOL_CHANGE_POINT)
    search(nck, "N300", "end_point")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] <= 170.0 + 1e-6, 30.0)
    assert position(nck) == pytest.approx({"X": 170.0, "Y": 30.0, "Z": 300.0})
    nck.submit(c.Reset())
    search(nck, "N250", "end_point")
    assert nck.run_until(lambda k: k.positions_mcs()["Y"] >= 149.0, 30.0)
    # cycle by cycle near the end (a longer step could run on into N260)
    assert nck.run_until(lambda k: k.positions_mcs()["Y"] >= 150.0 - 1e-6, 5.0, max_batch_cycles=1)
    # (G64: the next block blends in as Y reaches 150, hence the 0.01 mm)
    assert position(nck) == pytest.approx({"X": 170.0, "Y": 150.0, "Z": 300.0}, abs=0.01)


LINEAR = "N10 G0 X100\nN20 T1 M6 D1\nN30 G91 G1 X5 F600\nN40 M30"


def linear() -> Nck:
    """LINEAR selected in AUTO, tool 1 defined (length 0)."""
    nck = Nck(programs=MemorySource({"P.MPF": LINEAR}), referenced=True)
    assert nck.submit(c.WriteData("$TC_DP1[1,1]", 120)) == c.Accepted()
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    return nck


@pytest.mark.parametrize("search_type, end_x, tool", [
    ("without_calculation", 5.0, 0),  # nothing before N30 ran: X 0 + 5, no tool
    ("contour", 105.0, 1),  # approach to X100 (the end of N10), then 100 + 5
])
def test_digest_828d_2_rank_25_type_1_keeps_the_state_from_before_the_search(
        search_type: str, end_x: float, tool: int) -> None:
    """Digest 828d-2 rank 25, type 1 (002 L18284-18288): the search without calculation computes
    nothing, so the control state at the target block is the one from before the search: no
    tool, and the target block G91 X5 runs from where X stands (0). With calculation (type 2)
    the same target starts at X100 with tool 1."""
    nck = linear()
    search(nck, "N30", search_type)
    assert nck.status().channel.modal.tool == tool
    assert nck.run_until(lambda k: k.situation.program == "aborted", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(end_x)
    assert alarms(nck) == []


def test_digest_828d_2_rank_25_cascaded_search_may_change_the_type() -> None:
    """Digest 828d-2 rank 25 (002 L18329-18332, L18725-18728): from "search target found" a new
    search with another type and target may start; the last one counts."""
    nck = linear()
    assert nck.submit(c.StartBlockSearch("N20", "contour")) == c.Accepted()
    search(nck, "N30", "without_calculation")
    assert nck.run_until(lambda k: k.situation.program == "aborted", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(5.0)


def test_block_search_refuses_an_unknown_type() -> None:
    nck = linear()
    assert isinstance(nck.submit(c.StartBlockSearch("N30", "sideways")), c.Rejected)


SPINDLE_PROGRAM = "N10 G0 X10 Y10\nN20 T1 D1\nN30 S3000 M3\nN40 G1 X50 F1200\nN50 G1 Y40\nN60 G1 X0\nN70 M30"


def spindle_program() -> Nck:
    nck = Nck(programs=MemorySource({"P.MPF": SPINDLE_PROGRAM}), referenced=True)
    assert nck.submit(c.WriteData("$TC_DP1[1,1]", 120)) == c.Accepted()
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    return nck


def test_digest_828d_2_rank_25_serupro_runs_in_program_test_and_repositions_to_the_target() -> None:
    """Digest 828d-2 rank 25, type 5 (002 L18994-19027): SERUPRO to N50 runs the program in
    program test (channel active, the machine stands), stops at the beginning of N50 with
    "search target found" and program test deselected; NC START starts the spindle (M3 S3000
    of N30) and repositions to the start of N50 = the end of N40 (50, 10), then N50 and N60
    run to (0, 40)."""
    nck = spindle_program()
    assert nck.submit(c.StartBlockSearch("N50", "serupro")) == c.Accepted()
    assert (nck.situation.channel, nck.situation.program) == ("active", "running")
    assert nck.run_until(lambda k: k.situation.program != "running", 30.0)
    status = nck.status()
    assert (nck.situation.channel, nck.situation.program) == ("interrupted", "stopped")
    assert status.channel.stop_reason == "search target found"
    assert status.channel.current_block.text.startswith("N50")
    assert position(nck) == {"X": 0.0, "Y": 0.0, "Z": 0.0}  # nothing moved
    assert not status.channel.program_control.get("program_test")
    assert nck.submit(c.CycleStart()) == c.Accepted()  # one NC START: no 10208 in SERUPRO
    assert alarms(nck) == []
    assert nck.status().channel.modal.spindle_state == "M3"
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 50.0 - 1e-6, 30.0)
    assert position(nck) == pytest.approx({"X": 50.0, "Y": 10.0, "Z": 0.0})
    assert nck.run_until(lambda k: k.situation.program == "aborted", 30.0)
    assert position(nck) == pytest.approx({"X": 0.0, "Y": 40.0, "Z": 0.0})
    assert alarms(nck) == []


def test_digest_828d_2_rank_25_serupro_refuses_program_test_and_dry_run_with_16935() -> None:
    """Digest 828d-2 rank 25, type 5 (002 L19011-19012): selecting program test or dry run while
    SERUPRO runs is refused with 16935; RESET aborts SERUPRO (002 L19035-19036) and program
    test is off again."""
    nck = spindle_program()
    assert nck.submit(c.StartBlockSearch("N50", "serupro")) == c.Accepted()
    result = nck.submit(c.SetProgramControl("dry_run", True))
    assert isinstance(result, c.Rejected) and result.alarm == 16935
    assert 16935 in alarms(nck)
    assert nck.submit(c.Reset()) == c.Accepted()
    assert (nck.situation.channel, nck.situation.program) == ("reset", "aborted")
    assert not nck.status().channel.program_control.get("program_test")


def test_digest_828d_2_rank_25_serupro_is_no_cascaded_search() -> None:
    """Digest 828d-2 rank 25, type 5: SERUPRO cannot be combined with another search type
    (002 L18325-18332 lists cascading for types 1-4 only): from "search target found" it is
    refused."""
    nck = spindle_program()
    assert nck.submit(c.StartBlockSearch("N40", "contour")) == c.Accepted()
    assert isinstance(nck.submit(c.StartBlockSearch("N50", "serupro")), c.Rejected)
