"""Circles: centre, radius, opening angle, CIP, CT, helix, end-point monitoring.

Hand computations are given next to each case (chord, half chord, centre on
the perpendicular bisector; G2 = clockwise seen from +applicate).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.errors import NcAlarmError
from nck.geometry.circles import (
    Arc,
    CircleTolerance,
    arc_from_center,
    arc_from_center_and_angle,
    arc_from_end_and_angle,
    arc_from_radius,
    arc_tangential,
    arc_through_point,
)
from nck.geometry.planes import plane

G17, G18, G19 = plane("G17"), plane("G18"), plane("G19")


def close(a, b, tol=1e-9) -> bool:
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def test_center_incremental_quarter_circle_g17() -> None:
    # G2 from (0,0) to (10,10) with centre (10,0): start at 180°, clockwise to 90°: 90° sweep.
    arc = arc_from_center(G17, (0, 0, 0), (10, 10, 0), (10.0, 0.0), clockwise=True)
    assert close(arc.center, (10, 0, 0))
    assert arc.sweep_deg == pytest.approx(90.0)
    assert arc.radius == pytest.approx(10.0)
    assert arc.axis == (-0.0, -0.0, -1.0) or close(arc.axis, (0, 0, -1))
    assert arc.clockwise_in(G17)
    # Halfway: 135° on the circle around (10,0): (10 - 7.0711, 7.0711).
    assert close(arc.point_at(0.5), (10 - 10 / math.sqrt(2), 10 / math.sqrt(2), 0), 1e-9)


def test_full_circle_with_center() -> None:
    arc = arc_from_center(G17, (10, 0, 0), (10, 0, 0), (0.0, 0.0), clockwise=False)
    assert arc.sweep_deg == pytest.approx(360.0)
    assert close(arc.point_at(0.25), (0, 10, 0))


def test_circles_in_g18_and_g19() -> None:
    # G18: abscissa Z, ordinate X. G3 from Z=10 (X=0) to X=10 (Z=0) around the origin:
    # from +abscissa counter-clockwise to +ordinate = 90°. Geometry order (X, Y, Z).
    arc = arc_from_center(G18, (0, 0, 10), (10, 0, 0), (0.0, 0.0), clockwise=False)
    assert arc.sweep_deg == pytest.approx(90.0)
    assert close(arc.axis, (0, 1, 0))  # G3 in G18 turns about +Y
    # G19: abscissa Y, ordinate Z; G2 from Y=10 to Z=-10 about the origin: clockwise 90°.
    arc = arc_from_center(G19, (0, 10, 0), (0, 0, -10), (0.0, 0.0), clockwise=True)
    assert arc.sweep_deg == pytest.approx(90.0)
    assert close(arc.axis, (-1, 0, 0))


def test_end_point_tolerance() -> None:
    # Radius 10: allowed difference max(0.01, 0.001·10) = 0.01 mm.
    ok = arc_from_center(G17, (0, 0, 0), (10, 10.005, 0), (10.0, 0.0), clockwise=True)
    # The end point is trusted: the centre moves so both radii are equal.
    rs = math.dist(ok.start[:2], ok.center[:2])
    re = math.dist(ok.end[:2], ok.center[:2])
    assert rs == pytest.approx(re, abs=1e-9)
    with pytest.raises(NcAlarmError) as info:
        arc_from_center(G17, (0, 0, 0), (10, 10.02, 0), (10.0, 0.0), clockwise=True)
    assert info.value.number == 14040
    # Radius 100: allowed 0.1 mm.
    arc_from_center(G17, (0, 0, 0), (100, 100.05, 0), (100.0, 0.0), clockwise=True)
    with pytest.raises(NcAlarmError):
        arc_from_center(G17, (0, 0, 0), (100, 100.2, 0), (100.0, 0.0), clockwise=True)
    # Machine data can tighten it.
    with pytest.raises(NcAlarmError):
        arc_from_center(G17, (0, 0, 0), (10, 10.005, 0), (10.0, 0.0), True, tolerance=CircleTolerance(0.001, 0.0))


def test_zero_radius_is_an_alarm() -> None:
    with pytest.raises(NcAlarmError) as info:
        arc_from_center(G17, (0, 0, 0), (10, 0, 0), (0.0, 0.0), clockwise=True)
    assert info.value.number == 14040


def test_radius_cr_positive_and_negative() -> None:
    # G2 CR=10 from (0,0) to (10,10): small arc, centre (10,0), 90°.
    small = arc_from_radius(G17, (0, 0, 0), (10, 10, 0), 10.0, clockwise=True)
    assert close(small.center, (10, 0, 0))
    assert small.sweep_deg == pytest.approx(90.0)
    # CR=-10: the other centre (0,10), 270°.
    large = arc_from_radius(G17, (0, 0, 0), (10, 10, 0), -10.0, clockwise=True)
    assert close(large.center, (0, 10, 0))
    assert large.sweep_deg == pytest.approx(270.0)
    # G3 CR=10: centre (0,10) for the small arc.
    ccw = arc_from_radius(G17, (0, 0, 0), (10, 10, 0), 10.0, clockwise=False)
    assert close(ccw.center, (0, 10, 0))
    assert ccw.sweep_deg == pytest.approx(90.0)


def test_radius_semicircle_and_errors() -> None:
    half = arc_from_radius(G17, (0, 0, 0), (20, 0, 0), 10.0, clockwise=True)
    assert close(half.center, (10, 0, 0))
    assert half.sweep_deg == pytest.approx(180.0)
    with pytest.raises(NcAlarmError) as info:
        arc_from_radius(G17, (0, 0, 0), (30, 0, 0), 10.0, clockwise=True)
    assert info.value.number == 14095
    with pytest.raises(NcAlarmError) as info:
        arc_from_radius(G17, (0, 0, 0), (30, 0, 0), 0.0, clockwise=True)
    assert info.value.number == 14095
    with pytest.raises(NcAlarmError) as info:  # full circle with CR: not determined
        arc_from_radius(G17, (5, 5, 0), (5, 5, 0), 10.0, clockwise=True)
    assert info.value.number == 14040


def test_opening_angle_with_end_point() -> None:
    # AR=90 from (0,0) to (10,10), G2: r = 5√2 / sin 45° = 10, centre (10,0).
    arc = arc_from_end_and_angle(G17, (0, 0, 0), (10, 10, 0), 90.0, clockwise=True)
    assert close(arc.center, (10, 0, 0))
    assert arc.radius == pytest.approx(10.0)
    # AR=270 G2: the far centre (0,10).
    arc = arc_from_end_and_angle(G17, (0, 0, 0), (10, 10, 0), 270.0, clockwise=True)
    assert close(arc.center, (0, 10, 0))
    assert arc.sweep_deg == pytest.approx(270.0)
    with pytest.raises(NcAlarmError):
        arc_from_end_and_angle(G17, (0, 0, 0), (10, 10, 0), 360.0, clockwise=True)


def test_opening_angle_with_center() -> None:
    # G3 AR=90 around (0,0) from (10,0): ends at (0,10).
    arc = arc_from_center_and_angle(G17, (10, 0, 0), (0.0, 0.0), 90.0, clockwise=False)
    assert close(arc.end, (0, 10, 0))
    # G2 AR=90: ends at (0,-10).
    arc = arc_from_center_and_angle(G17, (10, 0, 0), (0.0, 0.0), 90.0, clockwise=True)
    assert close(arc.end, (0, -10, 0))


def test_cip_through_intermediate_point() -> None:
    # (0,0) -> (10,10) -> (20,0): circle centre (10,0) r=10, clockwise over the top: 180°.
    arc = arc_through_point((0, 0, 0), (10, 10, 0), (20, 0, 0))
    assert arc is not None
    assert close(arc.center, (10, 0, 0))
    assert arc.clockwise_in(G17)
    assert arc.sweep_deg == pytest.approx(180.0)
    # Intermediate below: counter-clockwise.
    arc = arc_through_point((0, 0, 0), (10, -10, 0), (20, 0, 0))
    assert arc is not None and not arc.clockwise_in(G17)


def test_cip_in_space() -> None:
    # Points in the X-Z plane: (10,0,0) -> (0,0,10) -> (-10,0,0): half circle about Y.
    arc = arc_through_point((10, 0, 0), (0, 0, 10), (-10, 0, 0))
    assert arc is not None
    assert close(arc.center, (0, 0, 0))
    assert arc.sweep_deg == pytest.approx(180.0)
    assert close(arc.point_at(0.5), (0, 0, 10))


def test_cip_collinear() -> None:
    assert arc_through_point((0, 0, 0), (5, 0, 0), (10, 0, 0)) is None  # straight line
    with pytest.raises(NcAlarmError) as info:
        arc_through_point((0, 0, 0), (15, 0, 0), (10, 0, 0))
    assert info.value.number == 14920


def test_ct_tangential() -> None:
    # Arriving along +X at (0,0), CT to (10,10): centre on the left normal at distance
    # k = |d|²/(2 n·d) = 200/20 = 10 -> centre (0,10), counter-clockwise, 90°.
    arc = arc_tangential(G17, (0, 0, 0), (10, 10, 0), (1.0, 0.0, 0.0))
    assert close(arc.center, (0, 10, 0))
    assert not arc.clockwise_in(G17)
    assert arc.sweep_deg == pytest.approx(90.0)
    # Arriving along +X, CT to (10,-10): clockwise, centre (0,-10).
    arc = arc_tangential(G17, (0, 0, 0), (10, -10, 0), (1.0, 0.0, 0.0))
    assert close(arc.center, (0, -10, 0)) and arc.clockwise_in(G17)
    with pytest.raises(NcAlarmError) as info:
        arc_tangential(G17, (0, 0, 0), (10, 0, 0), (1.0, 0.0, 0.0))
    assert info.value.number == 14045


def test_helix_with_turns() -> None:
    # G3 from (10,0,0) around (0,0) back to (10,0,-6) with TURN=2: 3 full revolutions,
    # lead -6 over 3 revolutions: after one third of the path one turn is done at Z=-2.
    arc = arc_from_center(G17, (10, 0, 0), (10, 0, -6), (0.0, 0.0), clockwise=False, turns=2)
    assert arc.sweep_deg == pytest.approx(1080.0)
    assert arc.lead == pytest.approx(-6.0)
    assert close(arc.point_at(1 / 3), (10, 0, -2), 1e-9)
    assert close(arc.point_at(1 / 12), (0, 10, -0.5), 1e-9)
    assert arc.length() == pytest.approx(math.hypot(2 * math.pi * 10 * 3, 6))
    # Half circle plus one turn: 540°.
    arc = arc_from_center(G17, (10, 0, 0), (-10, 0, 5), (0.0, 0.0), clockwise=True, turns=1)
    assert arc.sweep_deg == pytest.approx(540.0)
    with pytest.raises(NcAlarmError) as info:
        arc_from_center(G17, (10, 0, 0), (-10, 0, 5), (0.0, 0.0), clockwise=True, turns=-1)
    assert info.value.number == 14048


def test_tangents() -> None:
    arc = arc_from_center(G17, (10, 0, 0), (0, 10, 0), (0.0, 0.0), clockwise=False)
    assert close(arc.tangent_at(0.0), (0, 1, 0))
    assert close(arc.tangent_at(1.0), (-1, 0, 0))


_UNIT_AXIS_VECTORS = [(1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, -0.0),
                      (0.0, 0.0, 1.0), (-0.0, 0.0, -1.0)]
_COORDINATES = st.one_of(st.floats(-1e6, 1e6), st.sampled_from([0.0, -0.0, 1e-300, -5e-324, 1e200]))


@settings(max_examples=3000, deadline=None)
@given(st.tuples(_COORDINATES, _COORDINATES, _COORDINATES), st.tuples(_COORDINATES, _COORDINATES, _COORDINATES),
       st.sampled_from(_UNIT_AXIS_VECTORS), st.floats(1e-6, 1e4), st.floats(1e-9, 100.0))
def test_length_about_a_coordinate_axis_is_the_dot_product_form(start: tuple[float, float, float],
                                                                end: tuple[float, float, float],
                                                                axis: tuple[float, float, float],
                                                                radius: float, sweep: float) -> None:
    """``Arc.length`` about a coordinate axis takes the end's difference along it as the lead:
    bit for bit ``hypot(radius · sweep, dot(end - start, axis))`` with numpy's ``dot``."""
    arc = Arc(start=start, end=end, center=start, axis=axis, radius=radius, sweep_rad=sweep)
    delta = np.asarray(end) - np.asarray(start)
    expected = math.hypot(radius * sweep, float(np.dot(delta, np.asarray(axis))))
    got = arc.length()
    assert (math.isnan(got) and math.isnan(expected)) or got.hex() == expected.hex(), (start, end, axis)
    assert got.hex() == math.hypot(radius * sweep, arc.lead).hex() or math.isnan(got)
