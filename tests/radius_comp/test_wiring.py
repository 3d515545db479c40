"""Radius compensation through the interpreter: programs in, compensated motions out."""

from __future__ import annotations

import pytest

from dataclasses import dataclass

from nck import canon
from nck.errors import NcAlarmError
from nck.headless import interpret_only
from nck.interp.interpreter import Interpreter
from nck.interp.sources import MemorySource
from nck.machine import MachineConfig, load_machine
from nck.ncdata import NcData, ToolEdge


@dataclass
class Interpreted:
    """The motions a program's interpretation released and the alarm that stopped it."""

    motions: list[canon.Motion]
    alarms: list[NcAlarmError]


def run_text(name: str, text: str, machine: MachineConfig, data: NcData) -> Interpreted:
    run = interpret_only(machine, MemorySource({}), data, name, text=text)
    return Interpreted([c for c in run.commands if isinstance(c, canon.Motion)], run.alarms)


def mill(text: str, radius: float = 5.0, length: float = 0.0):
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120, 3: length, 6: radius})
    data.tools[(1, 2)] = ToolEdge({1: 120, 3: length, 6: 0.0})
    return run_text("TRC.MPF", text, machine=load_machine("mill3"), data=data)


def plane_path(result):
    return [(m.source.n, m.kind, round(m.end_wcs["X"], 4) + 0.0, round(m.end_wcs["Y"], 4) + 0.0)
            for m in result.motions]


RECTANGLE = """N5 G17 G90 G0 X-20 Y-20 Z5 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N30 X50
N40 Y0
N50 X0
N60 G40 X-20 Y-20
N70 M30
"""


def test_rectangle_program_is_compensated():
    result = mill(RECTANGLE)
    assert result.alarms == []
    assert plane_path(result) == [
        (5, "G0", -20.0, -20.0),
        (10, "G1", -5.0, 0.0),
        (20, "G1", -5.0, 30.0),
        (30, "G2", 0.0, 35.0),
        (30, "G1", 50.0, 35.0),
        (40, "G2", 55.0, 30.0),
        (40, "G1", 55.0, 0.0),
        (50, "G2", 50.0, -5.0),
        (50, "G1", 0.0, -5.0),
        (60, "G1", -20.0, -20.0),
    ]
    corner = result.motions[3]
    assert corner.inserted and corner.center_wcs["X"] == pytest.approx(0.0)
    assert corner.center_wcs["Y"] == pytest.approx(30.0)
    # Each segment starts where the previous one ended, in the MCS.
    for a, b in zip(result.motions, result.motions[1:]):
        assert all(b.start_mcs[axis] == pytest.approx(a.end_mcs[axis]) for axis in ("X", "Y", "Z"))


def test_tool_length_still_applies_with_compensation():
    result = mill(RECTANGLE, length=100.0)
    assert result.motions[2].end_mcs["Z"] == pytest.approx(105.0)
    assert result.motions[2].end_mcs["X"] == pytest.approx(-5.0)


def test_program_without_compensation_is_unchanged():
    text = RECTANGLE.replace("G41 ", "").replace("G40 ", "")
    result = mill(text)
    assert [p[2:] for p in plane_path(result)] == [
        (-20.0, -20.0), (0.0, 0.0), (0.0, 30.0), (50.0, 30.0), (50.0, 0.0), (0.0, 0.0), (-20.0, -20.0)]


def test_selection_in_a_circle_block_is_alarm_10753():
    result = mill("""N5 G17 G90 G0 X0 Y0 T1 D1 M6
N10 G2 G41 X20 Y0 I10 J0 F500
N20 M30
""")
    assert [a.number for a in result.alarms] == [10753]
    assert [m.source.n for m in result.motions] == [5]


def test_d0_while_compensating_is_alarm_10750():
    result = mill("""N5 G17 G90 G0 X-10 Y0 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 X20
N30 D0 X30
N40 M30
""")
    assert [a.number for a in result.alarms] == [10750]


def test_pocket_too_tight_stops_with_10751():
    result = mill("""N5 G17 G90 G0 X4 Y20 T1 D1 M6
N10 G1 G41 X0 Y20 F500
N20 Y0
N30 X8
N40 Y40
N50 X0
N60 Y20
N70 G40 X4
N80 M30
""")
    assert [a.number for a in result.alarms] == [10751]
    # Nothing at or after the corner that cannot be machined was released.
    assert {m.source.n for m in result.motions} <= {5, 10, 20}


def test_turning_profile_with_cutting_edge_position_3():
    # G18, DIAMON. The nose centre runs 0.8 outside the contour; the tool tip P
    # (what the length measures to) runs on the diameters and faces exactly.
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 500, 2: 3, 6: 0.8})
    result = run_text("TURN.MPF", """N5 G18 G90 DIAMON T1 D1
N10 G0 X24 Z5
N20 G1 G42 X20 Z0 F0.2
N30 Z-20
N40 X30 Z-30
N50 X40
N60 G40 X50 Z-25
N70 M30
""", machine=load_machine("lathe2"), data=data)
    assert result.alarms == []
    by_block = {m.source.n: m for m in result.motions}
    assert by_block[30].end_wcs["X"] == pytest.approx(20.0)  # Ø20 cylinder
    assert by_block[30].end_mcs["X"] == pytest.approx(10.0)
    assert by_block[50].end_wcs["Z"] == pytest.approx(-30.0)  # shoulder face
    assert by_block[50].end_wcs["X"] == pytest.approx(2 * (20 - 0.8))
    assert by_block[60].end_wcs["X"] == pytest.approx(50.0)  # retract ends on the programmed point


def test_blocks_without_plane_motion_run_at_the_offset_point():
    result = mill("""N5 G17 G90 G0 X-20 Y-20 Z5 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N25 Z-2
N30 X50
N40 G40 X60 Y40
N50 M30
""")
    assert result.alarms == []
    infeed = [m for m in result.motions if m.source.n == 25]
    assert len(infeed) == 1
    # The Z move happens at the end normal point of N20, before N30's corner circle.
    assert (infeed[0].end_wcs["X"], infeed[0].end_wcs["Y"], infeed[0].end_wcs["Z"]) == \
        pytest.approx((-5.0, 30.0, -2.0))
    order = [m.source.n for m in result.motions]
    assert order.index(20) < order.index(25) < order.index(30)


def test_too_many_blocks_without_plane_motion_is_alarm_10762():
    result = mill("""N5 G17 G90 G0 X-20 Y-20 Z5 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N21 M8
N22 Z4
N23 Z3
N24 Z2
N30 X50
N40 M30
""")
    assert [a.number for a in result.alarms] == [10762]


def test_plane_change_while_compensating_is_alarm_10757():
    result = mill("""N5 G17 G90 G0 X-20 Y-20 Z5 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N30 G18 X50
N40 M30
""")
    assert [a.number for a in result.alarms] == [10757]
    assert result.alarms[0].line == 4


def test_programmed_contour_stays_available():
    result = mill(RECTANGLE)
    by_block = {}
    for motion in result.motions:
        if motion.contour_end_wcs is not None:
            by_block[motion.source.n] = motion.contour_end_wcs
    assert (by_block[20]["X"], by_block[20]["Y"]) == (0.0, 30.0)
    assert (by_block[30]["X"], by_block[30]["Y"]) == (50.0, 30.0)
    assert (by_block[60]["X"], by_block[60]["Y"]) == (-20.0, -20.0)
    inserted = [m for m in result.motions if m.inserted]
    assert inserted and all(m.contour_end_wcs is None for m in inserted)
    # Without compensation nothing is set.
    plain = mill(RECTANGLE.replace("G41 ", "").replace("G40 ", ""))
    assert all(m.contour_end_wcs is None for m in plain.motions)


def test_mirror_gives_the_mirror_image_of_the_compensated_path():
    # MIRROR X0 swaps G41/G42 in the machine: the MCS path is the exact mirror image,
    # the WCS path (and the displayed G2 of the corner circle) stay as without mirror.
    body = """G0 X-20 Y-20 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N30 X50
N40 G40 X70 Y50
M30
"""
    plain = mill("G17 G90\n" + body)
    mirrored = mill("G17 G90 MIRROR X0\n" + body)
    assert plain.alarms == [] and mirrored.alarms == []
    assert len(plain.motions) == len(mirrored.motions)
    for a, b in zip(plain.motions, mirrored.motions):
        assert b.end_mcs["X"] == pytest.approx(-a.end_mcs["X"])
        assert b.end_mcs["Y"] == pytest.approx(a.end_mcs["Y"])
        assert b.end_wcs["X"] == pytest.approx(a.end_wcs["X"])
        assert b.kind == a.kind
    arc = next(m for m in mirrored.motions if m.inserted)
    assert arc.kind == "G2" and arc.arc_normal_mcs["Z"] == 1.0


def test_dwell_inside_the_contour_does_not_break_the_compensation():
    with_dwell = mill(RECTANGLE.replace("N30 X50", "N25 G4 F1\nN30 X50"))
    assert with_dwell.alarms == []
    assert [p[1:] for p in plane_path(with_dwell)] == [p[1:] for p in plane_path(mill(RECTANGLE))]


def test_alarm_in_a_block_leaves_the_compensation_state_untouched():
    # The compensation state lives in the geometry state; an alarm rolls the block
    # back, so the stage must not be changed in place (copy on write).
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120, 6: 5.0})
    text = """N5 G17 G90 G0 X-20 Y-20 T1 D1 M6
N10 G1 G41 X0 Y0 F500
N20 Y30
N30 G2 G40 X40 Y30 CR=20
N40 M30
"""
    interp = Interpreter(load_machine("mill3"), MemorySource({}), data)
    interp.start_text("ROLL.MPF", text)
    interp.step()
    interp.step()
    selecting = interp.run_state.modal.geometry.trc_stage
    assert selecting.compensator._state == "selecting"
    interp.step()  # N20: the compensation is now on, in a new stage object
    assert interp.run_state.modal.geometry.trc_stage.compensator._state == "on"
    assert selecting.compensator._state == "selecting"  # a snapshot holding it is intact
    stage_before = interp.run_state.modal.geometry.trc_stage
    pieces_before = len(stage_before.compensator._pieces)
    with pytest.raises(NcAlarmError) as info:
        interp.step()
    assert info.value.number == 10754
    stage_after = interp.run_state.modal.geometry.trc_stage
    assert len(stage_after.compensator._pieces) == pieces_before
    assert stage_after.compensator.active
