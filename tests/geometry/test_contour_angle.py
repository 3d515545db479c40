"""Contour definitions with ANG= in Siemens mode (000 L4027, L4105-4210): one straight line
with angle, two straight lines meeting at the corner their angles give, three lines with
chamfer and rounding; the forms the manual forbids are refused by check and run alike
(issue 20)."""

from __future__ import annotations

import math

import pytest

from nck.check import check_text
from tests.lang.conftest import run_text


def test_straight_line_with_angle_and_the_ordinate() -> None:
    # 000 L4150-4160: N10 X5. Z70. G18, N20 X88.8 ANG=110 (or Z39.5 ANG=110): from (Z70, X5)
    # along 110° to the abscissa Z until X = 88.8: Z = 70 + 83.8 / tan(110°) = 39.4994
    # (the manual prints it rounded to 39.5).
    result = run_text("N10 G1 G18 X5 Z70 F1000\nN20 X88.8 ANG=110\nM30\n")
    assert result.status == "ended", result.alarms
    end = result.segments[-1].end_wcs
    assert end["X"] == pytest.approx(88.8)
    assert end["Z"] == pytest.approx(70 + 83.8 / math.tan(math.radians(110)), abs=1e-6)
    assert end["Z"] == pytest.approx(39.5, abs=1e-3)


def test_straight_line_with_angle_and_the_abscissa() -> None:
    # The same line given by its Z (000 L4158): X = 5 + (39.5 - 70) * tan(110°) = 88.798.
    result = run_text("N10 G1 G18 X5 Z70 F1000\nN20 Z39.5 ANG=110\nM30\n")
    assert result.status == "ended", result.alarms
    end = result.segments[-1].end_wcs
    assert end["Z"] == pytest.approx(39.5)
    assert end["X"] == pytest.approx(5 + (39.5 - 70) * math.tan(math.radians(110)), abs=1e-6)


def test_angle_in_g17_incremental() -> None:
    # G17: the angle is measured from X; G91 X10 ANG=30 from (2, 1) ends at (12, 1 + 10 tan 30°).
    result = run_text("G1 G17 X2 Y1 F100\nG91 X10 ANG=30\nM30\n")
    end = result.segments[-1].end_wcs
    assert (end["X"], end["Y"]) == pytest.approx((12.0, 1 + 10 * math.tan(math.radians(30))))


@pytest.mark.parametrize("text, line, alarm", [
    # 000 L4093-4095: the angle and the coordinate are incompatible (Z100 lies behind 110°)
    ("N10 G1 G18 X5 Z70 F1000\nN20 Z100 ANG=110\nM30\n", 2, 12560),
    # parallel: ANG=0 runs along Z, so X cannot change
    ("N10 G1 G18 X5 Z70 F1000\nN20 X20 ANG=0\nM30\n", 2, 12560),
    # 000 L4066, L4080: both plane axes with ANG but no first block of a two-line contour before
    ("N10 G1 G17 X0 Y0 F100\nN20 X10 Y5 ANG=30\nM30\n", 2, 12550),
    # 000 L4075: the first block of two lines not followed by the block that ends the contour
    ("N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65\nM30\n", 3, 12550),
    # 000 L4079: no angle in the second block of a two-line contour
    ("N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65\nN30 X85 Z40\nM30\n", 3, 12550),
    # 000 L4073: the two lines give no corner (parallel)
    ("N10 G1 G18 X10 Z80 F1000\nN20 ANG=120\nN30 X85 Z40 ANG=120\nM30\n", 3, 12560),
    # 000 L4084: the angle only with linear interpolation
    ("N10 G2 G17 X10 Y0 CR=20 ANG=30 F100\nM30\n", 1, 12550),
])
def test_forms_not_modelled_or_wrong_are_refused_by_run_and_check(text: str, line: int, alarm: int) -> None:
    result = run_text(text)
    assert [(a.number, a.line) for a in result.alarms] == [(alarm, line)]
    assert [(a.number, a.line) for a in check_text("TEST.MPF", text)] == [(alarm, line)]


def _corner(start: tuple[float, float], angle1: float, end: tuple[float, float], angle2: float):
    """The corner of two lines (abscissa, ordinate): from ``start`` at ``angle1``, into ``end``
    at ``angle2`` — Cramer's rule on start + t·d1 = end - s·d2."""
    d1 = (math.cos(math.radians(angle1)), math.sin(math.radians(angle1)))
    d2 = (math.cos(math.radians(angle2)), math.sin(math.radians(angle2)))
    det = d1[0] * d2[1] - d2[0] * d1[1]
    t = ((end[0] - start[0]) * d2[1] - d2[0] * (end[1] - start[1])) / det
    return (start[0] + t * d1[0], start[1] + t * d1[1]), d1, d2


def test_two_straight_lines_meet_at_the_corner_the_angles_give() -> None:
    # 000 L4133-4155: N10 X10 Z80, N20 ANG=148.65, N30 X85 Z40 ANG=100 (G18: abscissa Z).
    corner, _, _ = _corner((80, 10), 148.65, (40, 85), 100)
    assert corner == pytest.approx((50.002, 28.275), abs=1e-3)  # by hand: Z 50.002, X 28.275
    result = run_text("N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65\nN30 X85 Z40 ANG=100\nM30\n")
    assert result.status == "ended", result.alarms
    ends = [(m.source.n, m.end_wcs["Z"], m.end_wcs["X"]) for m in result.segments]
    assert ends[1:] == [(20, pytest.approx(corner[0]), pytest.approx(corner[1])),
                        (30, pytest.approx(40.0), pytest.approx(85.0))]


def test_two_straight_lines_with_the_chamfer_of_the_first_block() -> None:
    # 000 L4154: N20 ANG=148.65 CHR=5.5 — the chamfer cuts the corner 5.5 mm along each line.
    corner, d1, d2 = _corner((80, 10), 148.65, (40, 85), 100)
    text = "N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65 CHR=5.5\nN30 X85 Z40 ANG=100\nM30\n"
    result = run_text(text)
    assert result.status == "ended", result.alarms
    points = [(m.end_wcs["Z"], m.end_wcs["X"]) for m in result.segments[1:]]
    assert points == [pytest.approx((corner[0] - 5.5 * d1[0], corner[1] - 5.5 * d1[1])),
                      pytest.approx((corner[0] + 5.5 * d2[0], corner[1] + 5.5 * d2[1])),
                      pytest.approx((40.0, 85.0))]
    assert check_text("TEST.MPF", text) == []


def test_three_straight_lines_round_the_second_corner() -> None:
    # 000 L4196-4203: N10 X10 Z100, N20 ANG=140 CHR=7.5, N30 X80 Z70 ANG=95.824 RND=10; the third
    # line (N40 Z20, ours) leaves (Z70, X80) along -Z, rounded with R10 at (Z70, X80).
    corner, _, _ = _corner((100, 10), 140, (70, 80), 95.824)
    text = ("N10 G1 G18 X10 Z100 F1000\nN20 ANG=140 CHR=7.5\nN30 X80 Z70 ANG=95.824 RND=10\n"
            "N40 Z20\nM30\n")
    result = run_text(text)
    assert result.status == "ended", result.alarms
    assert (result.segments[-1].end_wcs["Z"], result.segments[-1].end_wcs["X"]) == pytest.approx((20.0, 80.0))
    arcs = [m for m in result.segments if m.kind in ("G2", "G3")]
    assert len(arcs) == 1  # the rounding R10 between the second and third line
    first = result.segments[1]
    # the first line runs from (100, 10) at 140° towards the corner (chamfer leg 7.5 before it)
    d1 = (math.cos(math.radians(140)), math.sin(math.radians(140)))
    assert (first.end_wcs["Z"], first.end_wcs["X"]) == pytest.approx(
        (corner[0] - 7.5 * d1[0], corner[1] - 7.5 * d1[1]))
    assert check_text("TEST.MPF", text) == []


@pytest.mark.parametrize("text, end", [
    # 000 L4059-4060: the abscissa only; the ordinate Y keeps the position reached before, 0
    ("N10 G1 G17 X0 Y0 F1000\nN20 ANG=45\nN30 X20 ANG=-45\nM30\n", (20.0, 0.0)),
    # the ordinate only; X keeps 0
    ("N10 G1 G17 X0 Y0 F1000\nN20 ANG=30\nN30 Y10 ANG=135\nM30\n", (0.0, 10.0)),
])
def test_second_block_of_two_lines_with_one_plane_axis(text: str, end: tuple[float, float]) -> None:
    """Issue 20 (000 L4059-4063): the block that ends a two-line contour may name one axis of
    the plane; the missing coordinate is the last position reached. Corner by Cramer's rule
    from the start (0, 0) and the completed end point (by hand: (10, 10) for 45°/-45° to
    (20, 0); 10 / (0.5 + cos 30°) = 7.3205 along 30°, (6.340, 3.660), for 30°/135° to (0, 10)).
    Before, check and run refused the block with 12550."""
    angles = [float(part.split("ANG=")[1].split()[0]) for part in text.splitlines() if "ANG=" in part]
    corner, _, _ = _corner((0.0, 0.0), angles[0], end, angles[1])
    assert corner == pytest.approx((10.0, 10.0) if end == (20.0, 0.0) else (6.340, 3.660), abs=1e-3)
    result = run_text(text)
    assert result.status == "ended", result.alarms
    points = [(m.source.n, m.end_wcs["X"], m.end_wcs["Y"]) for m in result.segments[1:]]
    assert points == [(20, pytest.approx(corner[0]), pytest.approx(corner[1])),
                      (30, pytest.approx(end[0]), pytest.approx(end[1]))]
    assert check_text("TEST.MPF", text) == []
