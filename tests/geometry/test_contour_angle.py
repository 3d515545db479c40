"""Contour definition "straight line with angle" (ANG=) in Siemens mode, and the forms that are
not modelled refused in check and run alike (issue 20; 000 L4027, L4105-4160)."""

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
    # 000 L4133-4141: two straight lines (the corner needs the next block): not modelled
    ("N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65 CHR=5.5\nN30 X85 Z40 ANG=100\nM30\n", 2, 12550),
    # both plane axes with ANG: the second block of a two-line contour
    ("N10 G1 G17 X0 Y0 F100\nN20 X10 Y5 ANG=30\nM30\n", 2, 12550),
    # 000 L4084: the angle only with linear interpolation
    ("N10 G2 G17 X10 Y0 CR=20 ANG=30 F100\nM30\n", 1, 12550),
])
def test_forms_not_modelled_or_wrong_are_refused_by_run_and_check(text: str, line: int, alarm: int) -> None:
    result = run_text(text)
    assert [(a.number, a.line) for a in result.alarms] == [(alarm, line)]
    assert [(a.number, a.line) for a in check_text("TEST.MPF", text)] == [(alarm, line)]
