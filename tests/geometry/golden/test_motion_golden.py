"""Golden: circles in the three planes, helix with TURN, polar moves, units, chamfers.

Every expected value is worked out by hand in the comment next to it.
"""

from __future__ import annotations

import math

import pytest

from nck import canon
from nck.errors import NcAlarmError

from .helpers import approx, lines, run

SQ2 = math.sqrt(2.0)


def test_circles_in_all_three_planes() -> None:
    r = run(lines(
        "N10 G17 G0 X0 Y0 Z0",
        "N20 G2 X10 Y10 I10 J0 F100",   # centre (10,0): 90° clockwise
        "N30 G3 X0 Y0 CR=10",            # back on the same circle: centre (10,0)
        "N40 G18 G2 Z10 X10 K10 I0",     # G18 (Z,X): centre Z10 X0, end Z10 X10
        "N50 G19 G3 Y20 Z10 J10 K0",     # G19 (Y,Z): start Y0 Z10, centre Y10 Z10, half circle
        "N60 M30",
    ))
    n20, n30, n40, n50 = (r.block(n)[0] for n in (20, 30, 40, 50))
    assert n20.end_mcs == approx({"X": 10.0, "Y": 10.0, "Z": 0.0})
    assert n20.center_wcs == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})
    assert n30.center_wcs == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})
    assert n30.end_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 0.0})
    assert n40.plane == "G18"
    assert n40.center_wcs == approx({"X": 0.0, "Y": 0.0, "Z": 10.0})
    assert n40.end_mcs == approx({"X": 10.0, "Y": 0.0, "Z": 10.0})
    assert n40.arc_normal_mcs == approx({"X": 0.0, "Y": -1.0, "Z": 0.0})  # G2 in G18: about -Y
    assert n50.center_wcs == approx({"X": 10.0, "Y": 10.0, "Z": 10.0})
    assert n50.end_mcs == approx({"X": 10.0, "Y": 20.0, "Z": 10.0})
    assert n50.arc_normal_mcs == approx({"X": 1.0, "Y": 0.0, "Z": 0.0})


def test_centre_absolute_with_ac_and_radius_forms() -> None:
    r = run(lines(
        "N10 G0 X0 Y0",
        "N20 G2 X20 Y0 I=AC(10) J=AC(0) F100",  # semicircle over the top, centre (10,0)
        "N30 G2 X30 Y10 CR=-10",                # >180°: centre left of the chord for G2
        "N40 G3 X40 Y0 AR=90",                  # chord (10,-10): r = 7.071/sin45 = 10
        "N50 M30",
    ))
    assert r.block(20)[0].center_wcs == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})
    # N30: from (20,0) to (30,10); half chord 7.071, distance 7.071 to the centre; a large
    # clockwise arc has its centre on the left of the chord: (20,10).
    assert r.block(30)[0].center_wcs == approx({"X": 20.0, "Y": 10.0, "Z": 0.0})
    # N40: from (30,10) to (40,0), G3 90°: centre on the left of the chord direction (1,-1),
    # i.e. along (1,1)/√2 by 7.071 from the midpoint (35,5): (40,10); from 180° to 270° CCW.
    assert r.block(40)[0].center_wcs == approx({"X": 40.0, "Y": 10.0, "Z": 0.0})


def test_cip_and_ct() -> None:
    r = run(lines(
        "N10 G0 X0 Y0",
        "N20 G1 X10 F100",
        "N30 CT X20 Y10",               # leaves (10,0) along +X: centre (10,10), G3 quarter
        "N40 CIP X40 Y10 I1=30 J1=20",  # through (30,20): centre (30,10)
        "N50 M30",
    ))
    ct, cip = r.block(30)[0], r.block(40)[0]
    assert ct.center_wcs == approx({"X": 10.0, "Y": 10.0, "Z": 0.0})
    assert ct.arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 1.0})
    assert cip.center_wcs == approx({"X": 30.0, "Y": 10.0, "Z": 0.0})
    assert cip.arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": -1.0})  # over the top: clockwise


def test_helix_with_turn() -> None:
    r = run(lines(
        "N10 G17 G0 X10 Y0 Z0",
        "N20 G3 X10 Y0 Z-6 I-10 J0 TURN=2 F300",  # full circle + 2 turns = 3 revolutions, 2 mm each
        "N30 G2 X-10 Y0 Z-16 I-10 TURN=1",        # half circle + 1 turn = 540°
        "N40 M30",
    ))
    n20, n30 = r.block(20)[0], r.block(30)[0]
    assert n20.turns == 2
    assert n20.end_mcs == approx({"X": 10.0, "Y": 0.0, "Z": -6.0})
    assert n20.center_mcs == approx({"X": 0.0, "Y": 0.0, "Z": 0.0})
    assert n30.turns == 1
    assert n30.end_mcs == approx({"X": -10.0, "Y": 0.0, "Z": -16.0})
    assert n30.center_wcs == approx({"X": 0.0, "Y": 0.0, "Z": -6.0})
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 G0 X10 Y0", "N20 G3 X10 Y0 I-10 TURN=-1 F100", "N30 M30"))
    assert info.value.number == 14048


def test_polar_moves() -> None:
    r = run(lines(
        "N10 G17 G0 X0 Y0",
        "N20 G111 X20 Y10",          # pole (20,10) absolute
        "N30 G1 RP=50 AP=30 F100",   # (20 + 50cos30, 10 + 50sin30) = (63.30127, 35)
        "N40 AP=90",                 # RP stays 50: (20, 60)
        "N50 G110 X-10 Y20",         # pole relative to the last position: (10, 80)
        "N60 RP=10 AP=0",            # (20, 80)
        "N70 G112 X-10",             # pole relative to the last pole: (0, 80)
        "N80 G3 RP=20 AP=90",        # circle about the pole from (20,80) to (0,100)
        "N90 G1 G91 AP=-45",         # incremental angle: 45° -> (14.142136, 94.142136)
        "N100 M30",
    ))
    assert r.end_wcs(30) == approx({"X": 20 + 25 * math.sqrt(3), "Y": 35.0, "Z": 0.0})
    assert r.end_wcs(40) == approx({"X": 20.0, "Y": 60.0, "Z": 0.0})
    assert r.end_wcs(60) == approx({"X": 20.0, "Y": 80.0, "Z": 0.0})
    arc = r.block(80)[0]
    assert arc.kind == "G3"
    assert arc.center_wcs == approx({"X": 0.0, "Y": 80.0, "Z": 0.0})
    assert arc.end_wcs == approx({"X": 0.0, "Y": 100.0, "Z": 0.0})
    assert r.end_wcs(90) == approx({"X": 10 * SQ2, "Y": 80 + 10 * SQ2, "Z": 0.0})


def test_polar_without_pole_uses_the_wcs_origin() -> None:
    r = run(lines("N10 TRANS X5", "N20 G0 RP=10 AP=90", "N30 M30"))
    assert r.end_wcs(20) == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    assert r.end_mcs(20) == approx({"X": 5.0, "Y": 10.0, "Z": 0.0})


def test_inch_and_metric() -> None:
    r = run(lines(
        "N10 G71 G0 X0 Y0",
        "N20 G70 G1 X1 Y2 F10",   # positions in inch: MCS (25.4, 50.8); F stays mm/min under G70
        "N30 G700 G1 X2 F10",     # G700 also reads F in inch/min: 254 mm/min
        "N40 G71 G1 X10",         # back to mm; the F (10 inch/min as programmed) is kept as written
        "N50 M30",
    ))
    n20 = r.block(20)[0]
    assert n20.end_wcs == approx({"X": 1.0, "Y": 2.0, "Z": 0.0})
    assert n20.end_mcs == approx({"X": 25.4, "Y": 50.8, "Z": 0.0})
    assert n20.feed_mm_min == pytest.approx(10.0)
    n30 = r.block(30)[0]
    assert n30.end_mcs["X"] == pytest.approx(50.8)
    assert n30.feed_mm_min == pytest.approx(254.0)
    assert r.block(40)[0].end_mcs == approx({"X": 10.0, "Y": 50.8, "Z": 0.0})
    assert r.block(40)[0].end_wcs == approx({"X": 10.0, "Y": 50.8, "Z": 0.0})


def test_chamfer_and_rounding_segments() -> None:
    r = run(lines(
        "N10 G0 X0 Y0",
        "N20 G1 X10 Y0 RND=2 F100",
        "N30 G1 X10 Y10 CHR=3",
        "N40 G1 X0 Y10",
        "N50 M30",
    ))
    n20, n30, n40 = r.block(20), r.block(30), r.block(40)
    # N20: line to (8,0), then the rounding arc about (8,2) to (10,2) (inserted, caused by N20).
    assert [m.inserted for m in n20] == [False, True]
    assert n20[0].end_wcs == approx({"X": 8.0, "Y": 0.0, "Z": 0.0})
    assert n20[1].kind == "G3"
    assert n20[1].center_wcs == approx({"X": 8.0, "Y": 2.0, "Z": 0.0})
    assert n20[1].end_wcs == approx({"X": 10.0, "Y": 2.0, "Z": 0.0})
    # N30: line from (10,2) to (10,7), then the chamfer to (7,10).
    assert n30[0].start_mcs == approx({"X": 10.0, "Y": 2.0, "Z": 0.0})
    assert n30[0].end_wcs == approx({"X": 10.0, "Y": 7.0, "Z": 0.0})
    assert n30[1].kind == "G1" and n30[1].inserted
    assert n30[1].end_wcs == approx({"X": 7.0, "Y": 10.0, "Z": 0.0})
    assert n40[0].start_mcs == approx({"X": 7.0, "Y": 10.0, "Z": 0.0})
    assert n40[0].end_wcs == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})


def test_rndm_is_modal_and_a_held_motion_is_flushed_at_the_end() -> None:
    r = run(lines(
        "N10 G0 X0 Y0",
        "N20 G1 X10 RNDM=1 F100",
        "N30 Y10",
        "N40 X0",        # held back for RNDM, then flushed unchanged at M30
        "N50 M30",
    ))
    assert [m.inserted for m in r.block(20)] == [False, True]
    assert [m.inserted for m in r.block(30)] == [False, True]
    assert r.block(40)[0].end_wcs == approx({"X": 0.0, "Y": 10.0, "Z": 0.0})
    assert r.block(40)[0].start_mcs == approx({"X": 9.0, "Y": 10.0, "Z": 0.0})
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 G1 X10 RND=-1 F100", "N20 X20 Y5", "N30 M30"))
    assert info.value.number == 16500


def test_thread_dwell_and_spindle() -> None:
    r = run(lines(
        "N10 S1000 M3",
        "N20 G0 X0 Z5",
        "N30 G33 Z-20 K1.5",    # lead 1.5 mm at 1000 rpm: 1500 mm/min
        "N40 G4 F2.5",
        "N50 G4 S10",
        "N60 SPOS=90",
        "N70 G95 G1 X10 F0.1",  # spindle positioned (not turning): the path waits, 0 mm/min
        "N80 M3 X20",           # 0.1 mm/rev x 1000 rpm = 100 mm/min
        "N90 M30",
    ))
    thread = r.block(30)[0]
    assert thread.kind == "G33" and thread.lead_mm == pytest.approx(1.5)
    assert thread.feed_mm_min == pytest.approx(1500.0)
    # The cuts after M3 (N30, N80) first wait for the set speed range (MD35500, 002 L54530-54536).
    assert [c.source.n for c in r.commands if isinstance(c, canon.Dwell) and c.feed_enable] == [30, 80]
    dwells = [c for c in r.commands if isinstance(c, canon.Dwell) and not c.feed_enable]
    assert [(d.seconds, d.revolutions, d.wait_spindle) for d in dwells] == [
        (2.5, None, False), (None, 10.0, False),
        (None, None, True)]  # SPOS: the block waits until the spindle is positioned (002 L51162-51165)
    spos = [c for c in r.commands if isinstance(c, canon.SpindleCommand) and c.state == "SPOS"]
    assert spos[0].position_deg == pytest.approx(90.0)
    assert r.block(70)[0].feed_mm_min == pytest.approx(0.0)
    assert r.block(80)[0].feed_mm_min == pytest.approx(100.0)


def test_feed_type_change_deletes_f() -> None:
    """Digest 828d-3 rank 12: G94 -> G95 without F gives 10860 (002 L56880-56882)."""
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 G1 X10 F100", "N20 G95 S100 M3", "N30 G1 X20", "N40 M30"))
    assert info.value.number == 10860


def test_g96_needs_a_transverse_axis_and_computes_the_speed_on_a_lathe() -> None:
    """Digest 828d-3 rank 14 (n = v / (2 pi r), 10870)."""
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 G96 S200 M3", "N20 M30"))
    assert info.value.number == 10870
    # Lathe: X is the transverse axis (DIAMOF here, so X20 is a radius of 20 mm):
    # n = 200 m/min / (2π · 20 mm) = 200000 / 125.664 = 1591.549 rpm, below LIMS=3000.
    r = run(lines("N10 G0 X20 Z5", "N20 G96 S200 LIMS=3000 M3", "N30 G95 G1 Z0 F0.2", "N40 M30"),
            machine="lathe2")
    speeds = [c.speed_rpm for c in r.commands if isinstance(c, canon.SpindleCommand) and c.speed_rpm]
    expected = 200000 / (2 * math.pi * r.interp.modal.geometry.wcs_mm["X"])
    assert speeds[0] == pytest.approx(expected, rel=1e-6)
