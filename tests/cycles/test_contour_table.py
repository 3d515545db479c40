"""CONTOURTAB's reading of a contour subprogram (nck/interp/contour_table.py): rows
(type, start Z, R, end Z, R, centre Z, R) worked out by hand; X is a diameter under DIAMON."""

from __future__ import annotations

import pytest

from nck.errors import NcAlarmError
from nck.interp.contour_table import contour_rows
from nck.lang import ast


def _value(expr: ast.Expr) -> float:
    assert isinstance(expr, ast.Num)
    return float(expr.value)


def test_lines_arcs_and_incremental_values() -> None:
    """Start X20 Z0 (radius 10); G91 Z-10 to Z-10; X=AC(30) under G91: absolute diameter 30;
    G90 G2 to X50 Z-20 with I10 K0: centre 10 above the start (Z-10, radius 25), the end (Z-20,
    radius 25) 10 from it; G1 Z=IC(-5) to Z-25. The reading ends at M17."""
    text = "PROC CT\nG1 X20 Z0\nG91 Z-10\nX=AC(30)\nG90 G2 X50 Z-20 I10 K0\nG1 Z=IC(-5) F0.2\nM17\nG1 X99\n"
    rows = contour_rows(text, "CT", _value, diameter=True)
    assert rows == [(1, 0, 10, -10, 10, 0, 0), (1, -10, 10, -10, 15, 0, 0), (2, -10, 15, -20, 25, -10, 25),
                    (1, -20, 25, -25, 25, 0, 0)]


def test_radius_programming_and_cr() -> None:
    """Under DIAMOF X is a radius; G3 CR=5 from (Z0, 10) to (Z-5, 15): centre (Z-5, 10)."""
    rows = contour_rows("G1 X10 Z0\nG3 X15 Z-5 CR=5\n", "CT", _value, diameter=False)
    assert rows == [(3, 0, 10, -5, 15, -5, 10)]


@pytest.mark.parametrize("text", [
    "G1 X20 Z0\nZ-10 RND=1\n",        # rounding
    "G1 X20 Z0\nR1=5\n",              # an assignment
    "G1 X20 Z0\nG2 X30 Z-5\n",        # an arc without CR or I/K
    "G1 X20 Z0\nG2 X30 Z-5 CR=1\n",   # radius too small for the chord
    "G1 X20 Z0\nG2 X30 Z-5 I3 K0\n",  # end not on the circle
])
def test_what_the_contour_cannot_hold_is_10931(text: str) -> None:
    with pytest.raises(NcAlarmError) as raised:
        contour_rows(text, "CT", _value, diameter=True)
    assert raised.value.number == 10931
