"""Golden: G58/G59, AMIRROR toggling, ROT about several axes, CT after an arc, RPL in G18,
G110 in polar form. Hand computations in the comments."""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError

from .helpers import approx, lines, run


def test_g58_g59_bookkeeping_in_a_program() -> None:
    """Digest 828d-2 rank 21, in a program (002 L28592-28598)."""
    # Digest K2 test 21: TRANS (10,10,10) -> ATRANS X5 Y5 -> G58 X20 -> G59 X10 Y10
    # (002 L28586-28598), with MD24000 FRAME_ADD_COMPONENTS set as G58/G59 require (002 L28600).
    r = run(lines("N10 TRANS X10 Y10 Z10", "N20 ATRANS X5 Y5", "N30 G0 X0 Y0 Z0",
                  "N40 G58 X20", "N50 G0 X0 Y0 Z0", "N60 G59 X10 Y10", "N70 G0 X0 Y0 Z0", "N80 M30"),
            md={"MD24000": True})
    assert r.end_mcs(30) == approx({"X": 15.0, "Y": 15.0, "Z": 10.0})
    assert r.end_mcs(50) == approx({"X": 25.0, "Y": 15.0, "Z": 10.0})
    assert r.end_mcs(70) == approx({"X": 30.0, "Y": 20.0, "Z": 10.0})


@pytest.mark.parametrize("code", ["G58 X20", "G59 X10"])
def test_g58_g59_without_md24000_raise_18311(code: str) -> None:
    """Digest 828d-2 rank 21 (alarm part)."""
    # 002 L28600-28603: G58/G59 only with MD24000 FRAME_ADD_COMPONENTS TRUE, else alarm 18311.
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 TRANS X10", f"N20 {code}", "N30 M30"), md={"MD24000": False})
    assert info.value.number == 18311


def test_g58_without_a_fine_offset_raises_18312() -> None:
    # 002 L28604-28606: without a configured fine offset (MD18600 MM_FRAME_FINE_TRANS) alarm 18312.
    with pytest.raises(NcAlarmError) as info:
        run(lines("N10 TRANS X10", "N20 G58 X20", "N30 M30"), md={"MD24000": True, "MD18600": 0})
    assert info.value.number == 18312


def test_amirror_toggles_and_mirror_of_two_axes() -> None:
    r = run(lines("N10 AMIRROR X0", "N20 G0 X10 Y10", "N30 AMIRROR X0", "N40 G0 X10 Y10",
                  "N50 MIRROR X0 Y0", "N60 G0 X10 Y10", "N70 G2 X20 Y0 I5 J-5 F100", "N80 M30"))
    assert r.end_mcs(20) == approx({"X": -10.0, "Y": 10.0, "Z": 0.0})
    assert r.end_mcs(40) == approx({"X": 10.0, "Y": 10.0, "Z": 0.0})  # toggled back off
    assert r.end_mcs(60) == approx({"X": -10.0, "Y": -10.0, "Z": 0.0})
    # Two mirrored plane axes keep the turning direction: still clockwise in the machine.
    assert r.block(70)[0].arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": -1.0})


def test_rot_about_several_axes_in_rpy_order() -> None:
    # ROT X90 Z90: R = Rz(90)·Rx(90); WCS +Y -> +Z -> +Z; WCS +Z -> -Y -> +X.
    r = run(lines("N10 ROT X90 Z90", "N20 G0 X0 Y10 Z0", "N30 G0 X0 Y0 Z10", "N40 M30"))
    assert r.end_mcs(20) == approx({"X": 0.0, "Y": 0.0, "Z": 10.0})
    assert r.end_mcs(30) == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})


def test_ct_after_an_arc_keeps_the_tangent() -> None:
    # G3 quarter from (10,0) about the origin to (0,10): the tangent at the end is -X.
    # CT to (-10,20): centre on the left normal of -X (i.e. -Y) … k = |d|²/(2 n·d) with
    # d = (-10,10), n = (0,-1): k = 200 / -20 = -10 -> centre (0,20), clockwise.
    r = run(lines("N10 G0 X10 Y0", "N20 G3 X0 Y10 I-10 J0 F100", "N30 CT X-10 Y20", "N40 M30"))
    ct = r.block(30)[0]
    assert ct.center_wcs == approx({"X": 0.0, "Y": 20.0, "Z": 0.0})
    assert ct.arc_normal_mcs == approx({"X": 0.0, "Y": 0.0, "Z": -1.0})


def test_rpl_in_g18_rotates_about_y() -> None:
    # G18: RPL=90 turns the abscissa Z onto the ordinate X. WCS Z10 -> machine X10.
    r = run(lines("N10 G18 ROT RPL=90", "N20 G0 X0 Y0 Z10", "N30 M30"))
    assert r.end_mcs(20) == approx({"X": 10.0, "Y": 0.0, "Z": 0.0})


def test_g110_in_polar_form() -> None:
    """Digest programming-840c rank 16."""
    # From (10,0): G110 RP=5 AP=90 puts the pole at (10,5); RP=5 AP=0 -> (15,5).
    r = run(lines("N10 G0 X10 Y0", "N20 G110 RP=5 AP=90", "N30 G1 RP=5 AP=0 F100", "N40 M30"))
    assert r.end_wcs(30) == approx({"X": 15.0, "Y": 5.0, "Z": 0.0})


def test_helix_with_cr_and_inch() -> None:
    """Digest programming-840c rank 17 (helix: F on the arc, linear axis synchronised)."""
    # G70: CR=1 inch = 25.4 mm; half circle from (0,0) to (2 inch, 0) with Z-0.5 inch.
    r = run(lines("N10 G70 G0 X0 Y0 Z0", "N20 G2 X2 Y0 Z-0.5 CR=1 F10", "N30 M30"))
    m = r.block(20)[0]
    assert m.end_mcs == approx({"X": 50.8, "Y": 0.0, "Z": -12.7})
    assert m.center_wcs == approx({"X": 1.0, "Y": 0.0, "Z": 0.0})
    assert m.center_mcs == approx({"X": 25.4, "Y": 0.0, "Z": 0.0})
    assert math.isclose(m.feed_mm_min, 10.0)
    assert m.end_wcs["Z"] == pytest.approx(-0.5)


def test_polar_in_g18_measures_the_angle_from_z_towards_x() -> None:
    # G18: abscissa Z, ordinate X. Pole (Z=10, X=0); RP=5 AP=90 -> Z 10, X 5.
    r = run(lines("N10 G18 G111 Z10 X0", "N20 G0 RP=5 AP=90", "N30 AP=0", "N40 M30"))
    assert r.end_wcs(20) == approx({"X": 5.0, "Y": 0.0, "Z": 10.0})
    assert r.end_wcs(30) == approx({"X": 0.0, "Y": 0.0, "Z": 15.0})
