"""Issue 22: measuring arithmetic (scratching, 002 L31279-31290) against hand-computed values
to 1 µm: edge, corner, rotated corner, hole and spigot, Z surface, tool length and radius."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, strategies as st

from nck.queries import (circle, corner, edge_position, offset_for, rotated_corner, tool_length, tool_radius,
                         z_surface)

UM = 0.001  # 1 µm


def test_edge_accounts_for_radius_and_direction() -> None:
    # Cutter Ø10 (r 5) moving +X stops with its centre at X -55: the face is at -50.
    assert edge_position(-55.0, +1, 5.0) == pytest.approx(-50.0, abs=UM)
    # Probe ball r 2.5 moving -X touches the right face X 50 at centre 52.5.
    assert edge_position(52.5, -1, 2.5) == pytest.approx(50.0, abs=UM)
    with pytest.raises(ValueError):
        edge_position(0.0, 0, 5.0)


def test_same_zero_from_either_side_of_a_100_mm_block() -> None:
    # Block X -50 … 50; the zero at its left face. Left face touched moving +X with r 4:
    # centre -54 -> face -50, set X=0; right face touched moving -X: centre 54 -> face 50, set X=100.
    left = offset_for(edge_position(-54.0, +1, 4.0), 0.0)
    right = offset_for(edge_position(54.0, -1, 4.0), 100.0)
    assert left == pytest.approx(-50.0, abs=UM) and right == pytest.approx(-50.0, abs=UM)


@given(face=st.floats(-400, 400), radius=st.floats(0.5, 20), width=st.floats(1, 300))
def test_edge_from_each_direction_gives_the_same_zero(face: float, radius: float, width: float) -> None:
    # Faces `face` and `face + width`; touching each from outside, each with its WCS value.
    from_left = offset_for(edge_position(face - radius, +1, radius), 0.0)
    from_right = offset_for(edge_position(face + width + radius, -1, radius), width)
    assert from_left == pytest.approx(from_right, abs=UM)


def test_corner_parallel_to_the_axes() -> None:
    # Corner (-50, -40) touched moving +X (centre X -56) and +Y (centre Y -46) with r 6.
    assert corner(-56.0, +1, -46.0, +1, 6.0) == pytest.approx((-50.0, -40.0), abs=UM)


def test_rotated_corner_by_hand() -> None:
    # A corner at (10, 20) whose first edge runs at 30° (direction (cos30, sin30)),
    # material on the left of it (normal (-sin30, cos30)); the second edge runs along that
    # normal from the corner. Tool r 5 touches edge 1 from outside (moving along +n) at
    # distances 20 and 60 from the corner, edge 2 from outside (moving along +u) at 15.
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    u, n = (c, s), (-s, c)

    def at(along: float, off_n: float, off_u: float = 0.0) -> tuple[float, float]:
        return (10 + along * u[0] + off_n * n[0] + off_u * u[0], 20 + along * u[1] + off_n * n[1] + off_u * u[1])

    first, second = at(20, -5), at(60, -5)  # centres one radius outside edge 1
    third = (10 + 15 * n[0] - 5 * u[0], 20 + 15 * n[1] - 5 * u[1])  # one radius before edge 2
    result = rotated_corner(first, second, n, third, u, 5.0)
    assert (result.x_mm, result.y_mm) == pytest.approx((10.0, 20.0), abs=UM)
    assert result.angle_deg == pytest.approx(30.0, abs=1e-6)
    # The same corner touched along the axes (motion +Y on edge 1) gives the same point.
    assert rotated_corner(first, second, (0.0, 1.0), third, (1.0, 0.0), 5.0).x_mm == pytest.approx(10.0, abs=UM)


def test_hole_and_spigot_centre_from_three_and_four_touches() -> None:
    # Hole Ø40 at (100, -30), probe r 3: centres on a circle of radius 17.
    three = [(100 + 17.0, -30.0), (100.0, -30 + 17.0), (100 - 17 * math.cos(0.3), -30 - 17 * math.sin(0.3))]
    hole = circle(three, 3.0, hole=True)
    assert (hole.x_mm, hole.y_mm, hole.diameter_mm) == pytest.approx((100.0, -30.0, 40.0), abs=UM)
    # Spigot Ø60 at (0, 0), cutter r 5: centres on radius 35, four touches.
    four = [(35.0, 0.0), (0.0, 35.0), (-35.0, 0.0), (0.0, -35.0)]
    spigot = circle(four, 5.0, hole=False)
    assert (spigot.x_mm, spigot.y_mm, spigot.diameter_mm) == pytest.approx((0.0, 0.0, 60.0), abs=UM)


def test_z_surface_tool_length_and_radius() -> None:
    # Cutter L 100 touching the top of the blank at machine Z -120: top at -220.
    assert z_surface(-120.0, 100.0) == pytest.approx(-220.0, abs=UM)
    # Probe L 150 to the ball centre, ball r 2: lowest point 2 below the centre.
    assert z_surface(-68.0, 150.0, 2.0) == pytest.approx(-220.0, abs=UM)
    # Unknown tool touching the blank top (-220) at machine Z -95.5: length 124.5;
    # on the reference block (top -200) at machine Z -75.5: the same 124.5.
    assert tool_length(-95.5, -220.0) == pytest.approx(124.5, abs=UM)
    assert tool_length(-75.5, -200.0) == pytest.approx(124.5, abs=UM)
    # Known face X -50 touched moving +X with the centre at -58: radius 8.
    assert tool_radius(-58.0, +1, -50.0) == pytest.approx(8.0, abs=UM)
    assert tool_radius(58.0, -1, 50.0) == pytest.approx(8.0, abs=UM)
