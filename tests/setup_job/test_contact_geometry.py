"""Issue 22: contact geometry is exact per segment — a step never jumps over a surface.

The oracle is independent of the search: the distance of a point to a box or a cylinder
computed by brute force (nearest point by clamping), sampled densely along the segment."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from nck.contact import BALL, CUTTER, ToolBody, clearance, first_contact, point_along
from nck.workpiece import Box, Cylinder

coord = st.floats(-200, 200, allow_nan=False)
size = st.floats(1, 120)


def inside_ball_box(box: Box, radius: float, p: tuple[float, float, float]) -> bool:
    nearest = [min(max(p[i], box.low_mcs[i]), box.high_mcs[i]) for i in range(3)]
    return math.dist(nearest, p) < radius


def inside_cutter_box(box: Box, body: ToolBody, p: tuple[float, float, float]) -> bool:
    nx = min(max(p[0], box.low_mcs[0]), box.high_mcs[0])
    ny = min(max(p[1], box.low_mcs[1]), box.high_mcs[1])
    z_overlap = p[2] < box.high_mcs[2] and p[2] + body.length_mm > box.low_mcs[2]
    return math.hypot(nx - p[0], ny - p[1]) < body.radius_mm and z_overlap


@settings(max_examples=150, deadline=None)
@given(x=coord, y=coord, z=coord, sx=size, sy=size, sz=size, start=st.tuples(coord, coord, coord),
       end=st.tuples(coord, coord, coord), radius=st.floats(0.5, 10), length=st.floats(0, 80),
       probe=st.booleans())
def test_first_contact_on_a_box_is_never_jumped_over(x, y, z, sx, sy, sz, start, end, radius, length, probe):
    box = Box((x, y, z), (x + sx, y + sy, z + sz))
    body = ToolBody(BALL, radius) if probe else ToolBody(CUTTER, radius, length)
    inside = (lambda p: inside_ball_box(box, radius, p)) if probe else (lambda p: inside_cutter_box(box, body, p))
    t = first_contact(body, box, start, end)
    samples = [i / 800 for i in range(801)]
    first_inside = next((s for s in samples if inside(point_along(start, end, s))), None)
    if first_inside is not None:
        assert t is not None and t <= first_inside + 1e-12
    if t is not None:
        assert clearance(body, box, point_along(start, end, t)) <= 1e-9
        if t > 0.0:  # just before it the tool was still apart: the entry itself
            assert clearance(body, box, point_along(start, end, max(t - 1e-9, 0.0))) > -1e-6


@settings(max_examples=100, deadline=None)
@given(cx=coord, cy=coord, bottom=coord, diameter=size, height=size, start=st.tuples(coord, coord, coord),
       end=st.tuples(coord, coord, coord), radius=st.floats(0.5, 10))
def test_first_contact_of_a_probe_on_a_bar_is_never_jumped_over(cx, cy, bottom, diameter, height, start, end,
                                                                 radius):
    bar = Cylinder((cx, cy, bottom), diameter, height)
    body = ToolBody(BALL, radius)

    def inside(p: tuple[float, float, float]) -> bool:
        rho = math.hypot(p[0] - cx, p[1] - cy)
        radial = max(rho - diameter / 2, 0.0)
        axial = max(bottom - p[2], 0.0, p[2] - bottom - height)
        return math.hypot(radial, axial) < radius

    t = first_contact(body, bar, start, end)
    first_inside = next((i / 800 for i in range(801) if inside(point_along(start, end, i / 800))), None)
    if first_inside is not None:
        assert t is not None and t <= first_inside + 1e-12
    if t is not None:
        assert clearance(body, bar, point_along(start, end, t)) <= 1e-9


def test_a_whole_blank_inside_one_step_is_found() -> None:
    # One step of 400 mm crosses a 10 mm block completely: the contact is at its face.
    box = Box((0.0, -5.0, -5.0), (10.0, 5.0, 5.0))
    t = first_contact(ToolBody(BALL, 2.0), box, (-200.0, 0.0, 0.0), (200.0, 0.0, 0.0))
    assert t is not None
    assert point_along((-200.0, 0.0, 0.0), (200.0, 0.0, 0.0), t)[0] == pytest.approx(-2.0, abs=1e-9)


def test_cutter_body_touches_with_its_side_and_its_face() -> None:
    box = Box((-50.0, -40.0, -250.0), (50.0, 40.0, -220.0))
    cutter = ToolBody(CUTTER, 5.0, 30.0)
    assert clearance(cutter, box, (-55.0, 0.0, -240.0)) == 0.0  # side on the left face
    assert clearance(cutter, box, (0.0, 0.0, -220.0)) == 0.0  # tip on the top
    assert clearance(cutter, box, (0.0, 0.0, -219.0)) == 1.0
    # The shank (tip below the top, above the blank's side) still touches: tip -245, reaching -215.
    assert clearance(cutter, box, (-55.0, 0.0, -245.0)) == 0.0
