"""Golden: the frame chain in programs, with the MCS end point of every block worked out by hand.

Setup: G54 = (100, 50, 0); tool T1 D1 end mill with length L1 = 100 (acts on Z in G17),
so MCS = G54(programmable(WCS)) + (0, 0, 100).
"""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError
from nck.ncdata import WorkOffset

from .helpers import approx, lines, mill_data, run

C30, S30 = math.cos(math.radians(30)), math.sin(math.radians(30))

CHAIN = lines(
    "N10 G54 G17 G90 T1 M6 D1",
    "N20 G0 X0 Y0 Z10",
    "N30 TRANS X10 Y10",
    "N40 G1 X10 Y0 F500",
    "N50 AROT RPL=30",
    "N60 G1 X10 Y0",
    "N70 ASCALE X2 Y2",
    "N80 G1 X5 Y5",
    "N90 AMIRROR X0",
    "N100 G1 X5 Y5",
    "N110 G1 Z-5",
    "N120 G500 G0 X0 Y0",
    "N130 D0",
    "N140 G53 G0 Z0",
    "N150 G0 X20",
    "N160 M30",
)


def test_trans_arot_ascale_amirror_chain() -> None:
    r = run(CHAIN, mill_data({"X": 100.0, "Y": 50.0}))
    # N20: WCS (0,0,10) + G54 -> (100, 50, 10) + tool length -> Z 110.
    assert r.end_mcs(20) == approx({"X": 100.0, "Y": 50.0, "Z": 110.0})
    # N40: TRANS (10,10): (10,0) -> (20,10) -> (120, 60); Z not programmed stays 110.
    assert r.end_mcs(40) == approx({"X": 120.0, "Y": 60.0, "Z": 110.0})
    # N60: AROT RPL=30 turns (10,0) to (10cos30, 10sin30) = (8.660254, 5) -> + (110, 60).
    assert r.end_mcs(60) == approx({"X": 110.0 + 10 * C30, "Y": 65.0, "Z": 110.0})
    # N80: ASCALE 2: (5,5) -> (10,10) -> rotated (10cos30-10sin30, 10sin30+10cos30) -> + (110, 60).
    assert r.end_mcs(80) == approx({"X": 110 + 10 * C30 - 5, "Y": 60 + 5 + 10 * C30, "Z": 110.0})
    # N100: AMIRROR X: (5,5) -> (-5,5) -> (-10,10) -> (-10cos30-10sin30, -10sin30+10cos30) -> + (110, 60).
    assert r.end_mcs(100) == approx({"X": 110 - 10 * C30 - 5, "Y": 60 - 5 + 10 * C30, "Z": 110.0})
    assert r.end_wcs(100) == approx({"X": 5.0, "Y": 5.0, "Z": 10.0})
    # N110: Z-5 -> MCS Z 95 (scale acts on X/Y only).
    assert r.end_mcs(110) == approx({"X": 110 - 10 * C30 - 5, "Y": 60 - 5 + 10 * C30, "Z": 95.0})
    # N120: G500 drops G54; the programmable frame maps (0,0) to its origin (10,10).
    assert r.end_mcs(120) == approx({"X": 10.0, "Y": 10.0, "Z": 95.0})
    # N140: D0 then G53 Z0: machine Z 0; X/Y stay.
    assert r.end_mcs(140) == approx({"X": 10.0, "Y": 10.0, "Z": 0.0})
    # N150: back in the WCS (G53 was block-wise): X20 -> T R S M: (-20,0)->(-40,0)->(-40cos30,-40sin30)+(10,10).
    assert r.end_mcs(150) == approx({"X": 10 - 40 * C30, "Y": 10 - 40 * S30, "Z": 0.0})


def test_mirror_reverses_the_machine_direction_of_arcs() -> None:
    r = run(lines("N10 G0 X10 Y0", "N20 G2 X0 Y-10 I-10 J0 F100",
                  "N30 MIRROR X0", "N40 G0 X10 Y0", "N50 G2 X0 Y-10 I-10 J0", "N60 M30"))
    plain, mirrored = r.block(20)[0], r.block(50)[0]
    assert plain.kind == mirrored.kind == "G2"
    assert plain.arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": -1.0})
    assert mirrored.arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 1.0})  # runs as G3
    assert mirrored.end_mcs == approx({"X": 0.0, "Y": -10.0, "Z": 0.0})
    assert mirrored.center_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 0.0})
    assert r.block(40)[0].end_mcs == approx({"X": -10.0, "Y": 0.0, "Z": 0.0})


def test_rot_absolute_replaces_and_scale_zero_is_an_alarm() -> None:
    r = run(lines("N10 TRANS X50", "N20 ROT Z90", "N30 G0 X10 Y0", "N40 M30"))
    # ROT replaces the whole programmable frame: the TRANS is gone. (10,0) -> (0,10).
    assert r.end_mcs(30) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 SCALE X0", "N20 M30"))
    assert info.value.number == 18309


def test_settable_frame_with_rotation_and_base_frame() -> None:
    data = mill_data()
    data.settable_frames["G55"] = WorkOffset(trans={"X": 200.0}, rot={"Z": 90.0})
    data.base_frame = WorkOffset(trans={"Z": -20.0})
    r = run(lines("N10 G55 G0 X10 Y0 Z0", "N20 G153 G0 Z0", "N30 G0 Z5", "N40 M30"), data)
    # G55: (10,0) rotated 90 -> (0,10) + (200,0); base frame Z -20.
    assert r.end_mcs(10) == approx({"X": 200.0, "Y": 10.0, "Z": -20.0})
    # G153 also suppresses the basic frame: machine Z 0.
    assert r.end_mcs(20) == approx({"X": 200.0, "Y": 10.0, "Z": 0.0})
    assert r.end_mcs(30) == approx({"X": 200.0, "Y": 10.0, "Z": -15.0})


def test_g53_keeps_the_basic_frame_and_supa_does_not() -> None:
    data = mill_data({"X": 100.0})
    data.base_frame = WorkOffset(trans={"X": 5.0})
    r = run(lines("N10 G54 G0 X0", "N20 G53 X0", "N30 SUPA X0", "N40 M30"), data)
    assert r.end_mcs(10)["X"] == pytest.approx(105.0)
    assert r.end_mcs(20)["X"] == pytest.approx(5.0)
    assert r.end_mcs(30)["X"] == pytest.approx(0.0)


def test_offset_is_taken_up_when_the_axis_is_next_programmed() -> None:
    r = run(lines("N10 G0 X0 Y0 Z0", "N20 T1 M6 D1", "N30 G0 X10 Y10", "N40 G0 Z5",
                  "N50 G91 G54 G0 X1", "N60 M30"), mill_data({"X": 100.0, "Y": 50.0}))
    # N30: the tool length acts on Z, which is not programmed: Z stays at machine 0.
    assert r.end_mcs(30) == approx({"X": 10.0, "Y": 10.0, "Z": 0.0})
    # N40: Z programmed: 5 + 100.
    assert r.end_mcs(40) == approx({"X": 10.0, "Y": 10.0, "Z": 105.0})
    # N50: G54 selected with G91 X1: X travels the increment plus the new offset
    # (SD42440 = 1, 002 L26937-26942); Y is not programmed and keeps its machine position,
    # so in the new system it stands at 10 - 50 = -40 (issue 20: the actual position is reported).
    assert r.end_mcs(50) == approx({"X": 111.0, "Y": 10.0, "Z": 105.0})
    assert r.end_wcs(50) == approx({"X": 11.0, "Y": -40.0, "Z": 5.0})


def test_missing_edge_of_a_known_tool_is_17180() -> None:
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 T1 M6", "N20 D2", "N30 M30"), mill_data())
    assert info.value.number == 17180


def test_mcs_plane_and_direction_helper() -> None:
    from nck.geometry.arc_mcs import mcs_plane_and_direction

    r = run(lines("N10 G0 X10 Y0", "N20 G2 X0 Y-10 I-10 F100", "N30 MIRROR X0",
                  "N40 G0 X10 Y0", "N50 G2 X0 Y-10 I-10", "N60 ROT X90", "N70 G0 X10 Y0",
                  "N80 G3 X0 Y10 I-10", "N90 ROT X45", "N100 G0 X10 Y0", "N110 G3 X0 Y10 I-10",
                  "N120 M30"))
    assert mcs_plane_and_direction(r.block(20)[0]) == ("G17", True)
    assert mcs_plane_and_direction(r.block(50)[0]) == ("G17", False)  # mirrored: runs as G3
    # ROT X90: the WCS X-Y plane lies in the machine X-Z plane (WCS Y -> machine Z); a G3 about
    # WCS +Z turns about machine -Y: in G18 (Z,X) that is clockwise.
    assert mcs_plane_and_direction(r.block(80)[0]) == ("G18", True)
    assert r.block(80)[0].end_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 10.0})
    assert mcs_plane_and_direction(r.block(110)[0]) is None  # tilted plane
    assert mcs_plane_and_direction(r.block(10)[0]) is None  # a line


def test_jog_sync_and_reset_recompute_the_wcs_from_the_machine_position() -> None:
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine

    data = mill_data({"X": 100.0})
    machine = load_machine("mill3")
    machine.md["MD20152"] = 0  # the control's default: group 8 back to G500 (the shipped mill keeps it)
    interp = Interpreter(machine, MemorySource({}), data)
    interp.start_text("A.MPF", "N10 G54 T1 M6 D1\nN20 G0 X5 Y0 Z0\n")
    while not interp.finished:
        interp.step()
    # Program end reset G54 to G500; the WCS follows from machine (105, 0, 100): tool 100 on Z.
    assert interp.modal.position_mcs == approx({"X": 105.0, "Y": 0.0, "Z": 100.0})
    interp.start_text("B.MPF", "N10 G91 G0 X1\n")
    interp.step()
    assert interp.modal.position_wcs == approx({"X": 106.0, "Y": 0.0, "Z": 0.0})
    # JOG moved the machine to X 50: with G500 and the tool length, WCS X = 50, Z = 20 - 100.
    interp.sync_position({"X": 50.0, "Z": 20.0})
    assert interp.modal.position_wcs == approx({"X": 50.0, "Y": 0.0, "Z": -80.0})
    assert interp.builder.wcs_from_mcs(interp.modal, {"X": 50.0, "Y": 0.0, "Z": 20.0}) == approx(
        {"X": 50.0, "Y": 0.0, "Z": -80.0})


def test_save_subprogram_restores_the_programmable_frame() -> None:
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine

    sub = "PROC SHIFTED SAVE\nN10 TRANS X50\nN20 G0 X0\nN30 RET\n"
    interp = Interpreter(load_machine("mill3"), MemorySource({"SHIFTED.SPF": sub}), mill_data())
    interp.start_text("M.MPF", "N10 TRANS X5\nN20 SHIFTED\nN30 G0 X0\nN40 M30\n")
    ends = []
    while not interp.finished:
        ends += [c.end_mcs["X"] for c in interp.step().commands if hasattr(c, "end_mcs")]
    assert ends == [50.0, 5.0]  # inside: TRANS X50; back in the main program: TRANS X5 again


def test_arc_points_follow_tilted_and_mirrored_arcs() -> None:
    import math as _m

    from nck.geometry.arc_mcs import arc_points_mcs

    r = run(lines("N10 ROT X45", "N20 G0 X10 Y0 Z0", "N30 G3 X0 Y10 I-10 F100",
                  "N40 MIRROR X0", "N50 G0 X10 Y0", "N60 G2 X0 Y-10 I-10 Z-3 TURN=1", "N70 M30"))
    tilted = arc_points_mcs(r.block(30)[0], 8)
    # Every point is 10 from the centre (origin) and lies in the tilted plane y = z.
    for p in tilted:
        assert _m.sqrt(p["X"] ** 2 + p["Y"] ** 2 + p["Z"] ** 2) == pytest.approx(10.0, abs=1e-9)
        assert p["Y"] == pytest.approx(p["Z"], abs=1e-9)
    # Half way round a quarter circle: 45° -> (7.071, 7.071·cos45, 7.071·sin45).
    assert tilted[4] == approx({"X": 10 / _m.sqrt(2), "Y": 5.0, "Z": 5.0})
    helix = arc_points_mcs(r.block(60)[0], 20)
    assert helix[0] == approx(r.block(60)[0].start_mcs)
    assert helix[-1] == approx(r.block(60)[0].end_mcs)
    # A quarter plus one turn: the point at 4/5 of the sweep is back at the start angle, Z -2.4.
    start = r.block(60)[0].start_mcs
    assert helix[16]["X"] == pytest.approx(start["X"], abs=1e-9)
