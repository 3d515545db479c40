"""Chamfers, roundings and contour angles in ISO Dialect (issue 20): the comma forms ``,R``,
``,C`` and ``,A`` of ISO M and T (000 L4034-4041, L4884-4888; 003 L962-1000) and the forms
without comma of ISO T (``R``, ``C``, ``I``, ``K`` in a straight-line block, 000 L4893-4900).
They are mapped onto the Siemens functions (000 L4870): ``,R`` is RND, ``,C`` the chamfer
along the direction of motion, Siemens CHR (the chamfer name of MD10656, 000 L5251-5256),
``,A`` the contour angle ANG. Expected points worked out by hand on the default mill
(pocket-calculator notation, values in mm)."""

from __future__ import annotations

import math

import pytest

from tests.iso.conftest import run_iso


def ends(text: str, dialect: str = "iso-m") -> list[tuple[int, float, float]]:
    """(line, first plane axis, second plane axis) at the end of every segment after the first."""
    result = run_iso(text, dialect=dialect)
    assert result.status == "ended", result.alarms
    plane = ("Z", "X") if "G18" in text else ("X", "Y")
    return [(m.source.line, round(m.end_wcs[plane[0]], 4), round(m.end_wcs[plane[1]], 4))
            for m in result.segments[1:]]


def test_comma_r_rounds_the_corner() -> None:
    # 000 L4884: ,R inserts a radius. X line into a Y line, radius 2: the line ends 2 mm
    # before the corner (10, 0), the arc 2 mm up the Y line.
    assert ends("G17 G90 G0 X0 Y0\nG1 X10. ,R2. F100\nY10.\nM30\n") == [
        (2, 8.0, 0.0), (2, 10.0, 2.0), (3, 10.0, 10.0)]


def test_comma_c_is_the_chamfer_along_the_direction_of_motion() -> None:
    # 000 L5251-5256: the chamfer C is programmed as in Siemens mode, whose chamfer name means
    # the chamfer in the direction of motion (CHR): 2 mm back from the corner on each line,
    # (8, 0) to (10, 2). Before, ,C was the chord length (CHF): (8.586, 0) to (10, 1.414).
    assert ends("G17 G90 G0 X0 Y0\nG1 X10. ,C2. F100\nY10.\nM30\n") == [
        (2, 8.0, 0.0), (2, 10.0, 2.0), (3, 10.0, 10.0)]


def test_radius_and_chamfer_together_insert_the_radius() -> None:
    # 000 L4039: a radius and a chamfer in one block: the radius is inserted, the chamfer ignored.
    assert ends("G17 G90 G0 X0 Y0\nG1 X10. ,C1. ,R2. F100\nY10.\nM30\n") == [
        (2, 8.0, 0.0), (2, 10.0, 2.0), (3, 10.0, 10.0)]


def test_comma_a_gives_the_angle_of_a_straight_line() -> None:
    # 000 L4058-4060: one plane axis and the angle: from (0, 0) at 30° until X = 10,
    # Y = 10 tan 30° = 5.7735.
    assert ends("G17 G90 G0 X0 Y0\nG1 X10. ,A30. F100\nM30\n") == [(2, 10.0, round(10 * math.tan(math.radians(30)), 4))]


def test_comma_a_in_two_blocks_meets_at_the_corner() -> None:
    # 000 L4133-4155 in ISO form: ,A45 without plane axis, then X20 with ,A-45: the lines
    # from (0, 0) at 45° and into (20, 0) at -45° meet at (10, 10).
    text = "G17 G90 G0 X0 Y0\nG1 ,A45. F100\nX20. ,A-45.\nM30\n"
    assert ends(text) == [(2, 10.0, 10.0), (3, 20.0, 0.0)]


@pytest.mark.parametrize("word", ["R2.", "C2.", "I2.", "K-2."])
def test_iso_t_radius_and_chamfer_without_comma(word: str) -> None:
    # 000 L4893-4900: ISO T marks no comma; R is the radius, C, I or K the chamfer (its sign
    # means nothing). Z line to Z-10, then an X line: radius or chamfer 2 at the corner
    # (Z-10, X0): from (Z-8, X0) to (Z-10, X2) either way (a 90° corner).
    text = f"G18 G90 G0 X0 Z0\nG1 Z-10. {word} F100\nX20.\nM30\n"
    assert ends(text, "iso-t") == [(2, -8.0, 0.0), (2, -10.0, 2.0), (3, -10.0, 20.0)]
