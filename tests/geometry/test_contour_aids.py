"""Chamfers and roundings between two elements.

Line-line corner at (10,0) between +X and +Y (a left turn of 90°):
CHR=2 cuts both legs at 2 mm: (8,0) and (10,2). CHF=2√2 gives the same
chamfer (hypotenuse of the isosceles right triangle). RND=2: tangent distance
r/tan(45°) = 2, centre (8,2).
"""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError
from nck.geometry.circles import Arc, arc_from_center
from nck.geometry.contour_aids import LineElement, chamfer, rounding
from nck.geometry.planes import plane

G17 = plane("G17")
A = LineElement((0.0, 0.0, 0.0), (10.0, 0.0, 0.0))
B = LineElement((10.0, 0.0, 0.0), (10.0, 10.0, 0.0))


def close(a, b, tol=1e-9) -> bool:
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def test_chr_and_chf_line_line() -> None:
    for corner in (chamfer(G17, A, B, 2.0, "CHR"), chamfer(G17, A, B, 2 * math.sqrt(2), "CHF")):
        assert close(corner.first.end, (8, 0, 0))
        assert isinstance(corner.inserted, LineElement)
        assert close(corner.inserted.start, (8, 0, 0)) and close(corner.inserted.end, (10, 2, 0))
        assert close(corner.second.start, (10, 2, 0)) and close(corner.second.end, (10, 10, 0))


def test_chf_on_an_obtuse_corner() -> None:
    # +X then 45° up-left... use +X then direction (1,1): corner angle 135°,
    # legs l with chord 2·l·sin(67.5°) = 3 -> l = 1.5 / sin(67.5°).
    second = LineElement((10.0, 0.0, 0.0), (20.0, 10.0, 0.0))
    corner = chamfer(G17, A, second, 3.0, "CHF")
    leg = 1.5 / math.sin(math.radians(67.5))
    assert close(corner.first.end, (10 - leg, 0, 0), 1e-7)
    assert math.dist(corner.inserted.start, corner.inserted.end) == pytest.approx(3.0, abs=1e-7)


def test_rnd_line_line() -> None:
    corner = rounding(G17, A, B, 2.0)
    arc = corner.inserted
    assert isinstance(arc, Arc)
    assert close(arc.center, (8, 2, 0))
    assert arc.sweep_deg == pytest.approx(90.0)
    assert not arc.clockwise_in(G17)  # left turn -> G3 rounding
    assert close(corner.first.end, (8, 0, 0)) and close(corner.second.start, (10, 2, 0))


def test_rnd_right_turn_is_clockwise() -> None:
    down = LineElement((10.0, 0.0, 0.0), (10.0, -10.0, 0.0))
    arc = rounding(G17, A, down, 2.0).inserted
    assert isinstance(arc, Arc) and arc.clockwise_in(G17)
    assert close(arc.center, (8, -2, 0))


def test_rnd_line_arc() -> None:
    # Line along +X to (10,0), then G3 around the origin to (0,10). Rounding r=2 lies
    # inside the circle: its centre is 8 from the origin and 2 above the line: (√60, 2).
    arc = arc_from_center(G17, (10, 0, 0), (0, 10, 0), (0.0, 0.0), clockwise=False)
    corner = rounding(G17, A, arc, 2.0)
    assert close(corner.inserted.center, (math.sqrt(60), 2, 0))
    # Tangent point on the arc: origin + 10·(√60, 2)/8.
    assert close(corner.second.start, (10 * math.sqrt(60) / 8, 2.5, 0))
    assert corner.second.radius == pytest.approx(10.0)
    assert close(corner.second.end, (0, 10, 0))


def test_rnd_arc_line() -> None:
    # G3 to (0,10), then +Y: a right turn outside the circle. Offset circle R=13,
    # offset line x=3: centre (3, √160); tangent point on the line (0, √160).
    arc = arc_from_center(G17, (10, 0, 0), (0, 10, 0), (0.0, 0.0), clockwise=False)
    corner = rounding(G17, arc, LineElement((0, 10, 0), (0, 20, 0)), 3.0)
    assert close(corner.inserted.center, (3, math.sqrt(160), 0))
    assert close(corner.second.start, (0, math.sqrt(160), 0))
    assert corner.inserted.clockwise_in(G17)


def test_chamfer_line_arc() -> None:
    arc = arc_from_center(G17, (10, 0, 0), (0, 10, 0), (0.0, 0.0), clockwise=False)
    corner = chamfer(G17, A, arc, 2.0, "CHR")
    # Both cut points lie 2 mm (straight) from the corner and the arc point stays on the circle.
    assert math.dist(corner.first.end, (10, 0, 0)) == pytest.approx(2.0)
    assert math.dist(corner.second.start, (10, 0, 0)) == pytest.approx(2.0)
    assert math.hypot(*corner.second.start[:2]) == pytest.approx(10.0)


def test_too_large_is_reduced_and_negative_is_an_alarm() -> None:
    short = LineElement((0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
    b = LineElement((1.0, 0.0, 0.0), (1.0, 10.0, 0.0))
    corner = rounding(G17, short, b, 5.0)
    assert corner.inserted is not None
    assert corner.inserted.radius == pytest.approx(1.0, abs=1e-6)  # reduced to what fits
    corner = chamfer(G17, short, b, 5.0, "CHR")
    assert close(corner.first.end, (0, 0, 0), 1e-9)
    with pytest.raises(NcAlarmError) as info:
        rounding(G17, A, B, -1.0)
    assert info.value.number == 16500
    with pytest.raises(NcAlarmError):
        chamfer(G17, A, B, -1.0)


def test_tangent_transition_gets_nothing() -> None:
    straight = LineElement((10.0, 0.0, 0.0), (20.0, 0.0, 0.0))
    assert rounding(G17, A, straight, 2.0).inserted is None
    assert chamfer(G17, A, straight, 2.0).inserted is None
    assert rounding(G17, A, B, 0.0).inserted is None


def test_rounding_in_g18() -> None:
    # G18: abscissa Z, ordinate X. Line along +Z to Z=10, then +X: left turn (Z -> X).
    first = LineElement((0.0, 0.0, 0.0), (0.0, 0.0, 10.0))
    second = LineElement((0.0, 0.0, 10.0), (10.0, 0.0, 10.0))
    arc = rounding(plane("G18"), first, second, 2.0).inserted
    assert close(arc.center, (2, 0, 8))
    assert not arc.clockwise_in(plane("G18"))
