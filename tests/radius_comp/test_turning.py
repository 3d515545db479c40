"""Turning: cutting edge positions 1–9, nose radius compensation with SL3, DIAMON/DIAMOF.

Plane G18 with the tool behind the turning centre: plane coordinates are
(abscissa, ordinate) = (Z, X), X as a radius. An external profile machined
towards the chuck (−Z) has the material on the left of travel, so the tool
works with G42 and its nose centre S lies r above the contour.
"""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError
from nck.geometry import cutting_edge as ce
from nck.geometry.radius_comp import compensate
from nck.geometry.trc_geometry import plane_axes
from nck.ncdata import ToolEdge
from tests.radius_comp.helpers import assert_path, lin

NOSE = 0.8


def profile():
    """Ø20 cylinder Z0…−20, taper to Ø30 at Z−30, shoulder up to Ø40; DIAMON values → radii."""
    x = lambda diameter: ce.program_to_radius(diameter, diameter_programming=True)  # noqa: E731
    kw = dict(side="G42", radius=NOSE)
    return [
        lin((5, x(24)), (0, x(20)), "N10", **kw),
        lin((0, x(20)), (-20, x(20)), "N20", **kw),
        lin((-20, x(20)), (-30, x(30)), "N30", **kw),
        lin((-30, x(30)), (-30, x(40)), "N40", **kw),
        lin((-30, x(40)), (-25, x(50)), "N50", side="G40"),
    ]


def test_plane_g18_is_z_then_x():
    assert plane_axes("G18") == ("Z", "X", "Y")


def test_external_profile_nose_centre_path():
    # Cylinder: S on X = 10 + 0.8. Taper (direction (−2, 1)/√5) meets it at an inside
    # corner turning 26.565°: the intersection lies r·tan(13.28°) = 0.18885 before
    # Z−20. Shoulder (Z = −30 + 0.8) meets the taper r·tan(31.72°) = 0.49443 above
    # X 15. Approach: normal point of N20 at (0, 10) is (0, 10.8); retract from the
    # end normal point of N40, (−29.2, 20).
    t1 = NOSE * math.tan(math.atan(0.5) / 2)
    t2 = NOSE * math.tan((math.pi / 2 - math.atan(0.5)) / 2)
    out = compensate(profile())
    assert_path(out, [
        ("N10", "G1", (5, 12), (0, 10.8)),
        ("N20", "G1", (0, 10.8), (-20 + t1, 10.8)),
        ("N30", "G1", (-20 + t1, 10.8), (-29.2, 15 + t2)),
        ("N40", "G1", (-29.2, 15 + t2), (-29.2, 20)),
        ("N50", "G1", (-29.2, 20), (-25, 25)),
    ])


def test_edge_position_3_tip_touches_cylinder_and_face():
    """Digest 828d-3 rank 24 (edge position 3, r = 0.8)."""
    # The length refers to the tip P = S + (−r, −r) for SL3. On the cylinder P runs
    # exactly on Ø20 (X 10), on the shoulder exactly on Z −30: no dimension error on
    # faces and diameters. On the taper P is off the contour (that is what S corrects).
    out = compensate(profile())
    offset = ce.reference_offset(500, 3, NOSE)
    assert offset == (-NOSE, -NOSE)
    cylinder, taper, shoulder = out[1], out[2], out[3]
    for point in (cylinder.start, cylinder.end):
        tip = (point[0] + offset[0], point[1] + offset[1])
        assert tip[1] == pytest.approx(10.0)
    for point in (shoulder.start, shoulder.end):
        tip = (point[0] + offset[0], point[1] + offset[1])
        assert tip[0] == pytest.approx(-30.0)
    mid = ((taper.start[0] + taper.end[0]) / 2, (taper.start[1] + taper.end[1]) / 2)
    tip = ce.tip_from_centre(mid, 3, NOSE)
    # Distance of the tip from the taper line through (−20, 10), direction (−2, 1)/√5.
    gap = abs((tip[0] + 20) * 1 / math.sqrt(5) + (tip[1] - 10) * 2 / math.sqrt(5))
    assert gap > 0.1


def test_cutting_edge_position_table():
    r = 0.4
    assert ce.tip_offset(1, r) == (r, r)
    assert ce.tip_offset(2, r) == (-r, r)
    assert ce.tip_offset(3, r) == (-r, -r)
    assert ce.tip_offset(4, r) == (r, -r)
    assert ce.tip_offset(5, r) == (r, 0)
    assert ce.tip_offset(6, r) == (0, r)
    assert ce.tip_offset(7, r) == (-r, 0)
    assert ce.tip_offset(8, r) == (0, -r)
    assert ce.tip_offset(9, r) == (0, 0)
    for sl in range(1, 5):
        assert ce.tip_distance(sl, r) == pytest.approx(r * math.sqrt(2))
    for sl in range(5, 9):
        assert ce.tip_distance(sl, r) == pytest.approx(r)
    assert ce.centre_from_tip(ce.tip_from_centre((3.0, 4.0), 2, r), 2, r) == pytest.approx((3.0, 4.0))


def test_cutting_edge_position_0_is_an_alarm():
    """Digest 828d-3 rank 24 (DP2 = 0 invalid)."""
    with pytest.raises(NcAlarmError) as info:
        ce.tip_offset(0, 0.8)
    assert info.value.number == 10799


def test_cut_directions_fit_the_position():
    assert ce.cut_direction_fits(3, 1) and ce.cut_direction_fits(3, 3)
    assert not ce.cut_direction_fits(3, 2)
    assert ce.cut_direction_fits(6, 4) and not ce.cut_direction_fits(6, 1)


def test_tool_classes_and_radius():
    assert ce.tool_class(120) == "milling"
    assert ce.tool_class(200) == "drilling"
    assert ce.tool_class(500) == "turning" and ce.tool_class(599) == "turning"
    assert ce.tool_class(0) == "none"
    assert not ce.uses_radius(200) and ce.uses_radius(120) and ce.uses_radius(510)
    assert ce.has_cutting_edge_position(510) and not ce.has_cutting_edge_position(120)
    assert ce.reference_offset(120, 3, 5.0) == (0.0, 0.0)  # milling: no tip shift
    edge = ToolEdge({1: 120, 6: 10.0, 15: 0.5})
    assert ce.effective_radius(edge) == pytest.approx(10.5)
    assert ce.effective_radius(edge, wear_sign=1) == pytest.approx(9.5)
    assert ce.effective_radius(None) == 0.0


def test_diameter_programming_helpers():
    assert ce.program_to_radius(40.0, True) == 20.0
    assert ce.program_to_radius(40.0, False) == 40.0
    assert ce.radius_to_program(20.0, True) == 40.0
    assert ce.radius_to_program(20.0, False) == 20.0
