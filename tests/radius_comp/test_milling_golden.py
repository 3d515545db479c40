"""Golden offset paths for milling contours, computed by hand (G17: plane = X, Y).

Conventions used in the hand computations: the offset of a line lies r to the
left (G41) or right (G42) of the direction of travel; "left" of direction
(dx, dy) is (−dy, dx). Outside corners under G450 get an arc of radius r round
the programmed corner point, from the normal point at the end of the first
block to the normal point at the start of the next; inside corners are cut at
the intersection of the two offset lines.
"""

from __future__ import annotations

import math

import pytest

from nck.errors import NcAlarmError
from nck.geometry.radius_comp import TrcSettings, compensate
from tests.radius_comp.helpers import assert_continuous, assert_path, chain, circ, lin

R = 5.0
START = (-20.0, -20.0)


def rectangle(points, side):
    """Approach from START to the first corner, the contour, G40 back to START."""
    blocks = [lin(START, points[0], "N10", side=side, radius=R)]
    for index, (a, b) in enumerate(zip(points, points[1:])):
        blocks.append(lin(a, b, f"N{20 + 10 * index}", side=side, radius=R))
    blocks.append(lin(points[-1], START, "N99", side="G40", radius=R))
    return blocks


CW = [(0, 0), (0, 30), (50, 30), (50, 0), (0, 0)]
CCW = [(0, 0), (50, 0), (50, 30), (0, 30), (0, 0)]


def test_rectangle_clockwise_g41_outside():
    # Travelling clockwise, left is outside. First block goes +Y: left normal (−1, 0)
    # → normal point (−5, 0). Corner arcs (G2, the turn is to the right) round every
    # corner, each belonging to the block after the corner. Last block goes −X: its
    # end normal point is (0, −5); NORM retracts from there to the start point.
    out = compensate(rectangle(CW, "G41"))
    assert_path(out, [
        ("N10", "G1", START, (-5, 0)),
        ("N20", "G1", (-5, 0), (-5, 30)),
        ("N30", "G2", (-5, 30), (0, 35), (0, 30)),
        ("N30", "G1", (0, 35), (50, 35)),
        ("N40", "G2", (50, 35), (55, 30), (50, 30)),
        ("N40", "G1", (55, 30), (55, 0)),
        ("N50", "G2", (55, 0), (50, -5), (50, 0)),
        ("N50", "G1", (50, -5), (0, -5)),
        ("N99", "G1", (0, -5), START),
    ])
    assert [o.inserted for o in out] == [False, False, True, False, True, False, True, False, False]
    assert_continuous(out)


def test_rectangle_clockwise_g42_inside():
    # Right of a clockwise contour is inside: offset lines x = 5, y = 25, x = 45,
    # y = 5, cut at their intersections. Start normal (+5, 0); end normal of the
    # last block (direction −X, right normal (0, +1)) is (0, 5).
    out = compensate(rectangle(CW, "G42"))
    assert_path(out, [
        ("N10", "G1", START, (5, 0)),
        ("N20", "G1", (5, 0), (5, 25)),
        ("N30", "G1", (5, 25), (45, 25)),
        ("N40", "G1", (45, 25), (45, 5)),
        ("N50", "G1", (45, 5), (0, 5)),
        ("N99", "G1", (0, 5), START),
    ])


def test_rectangle_counter_clockwise_g42_outside():
    # Counter-clockwise, right is outside; the corner arcs turn left (G3).
    out = compensate(rectangle(CCW, "G42"))
    assert_path(out, [
        ("N10", "G1", START, (0, -5)),
        ("N20", "G1", (0, -5), (50, -5)),
        ("N30", "G3", (50, -5), (55, 0), (50, 0)),
        ("N30", "G1", (55, 0), (55, 30)),
        ("N40", "G3", (55, 30), (50, 35), (50, 30)),
        ("N40", "G1", (50, 35), (0, 35)),
        ("N50", "G3", (0, 35), (-5, 30), (0, 30)),
        ("N50", "G1", (-5, 30), (-5, 0)),
        ("N99", "G1", (-5, 0), START),
    ])


def test_rectangle_counter_clockwise_g41_inside():
    out = compensate(rectangle(CCW, "G41"))
    assert_path(out, [
        ("N10", "G1", START, (0, 5)),
        ("N20", "G1", (0, 5), (45, 5)),
        ("N30", "G1", (45, 5), (45, 25)),
        ("N40", "G1", (45, 25), (5, 25)),
        ("N50", "G1", (5, 25), (5, 0)),
        ("N99", "G1", (5, 0), START),
    ])


def corner(direction_deg, mode, settings=None):
    """Approach (−20, 20) → (0, 0), X+ to (50, 0), then 50 mm at ``direction_deg``, G40."""
    d = math.radians(direction_deg)
    far = (50 + 50 * math.cos(d), 50 * math.sin(d))
    blocks = [
        lin((-20, 20), (0, 0), "N10", corner_mode=mode),
        lin((0, 0), (50, 0), "N20", corner_mode=mode),
        lin((50, 0), far, "N30", corner_mode=mode),
        lin(far, (far[0] + 20, far[1] - 20), "N40", side="G40"),
    ]
    return compensate(blocks, settings)


def test_90_degree_outside_corner_g450_circle():
    """Digest 828d-3 rank 23 (G450: arc round the corner point)."""
    out = corner(-90, "G450")
    assert_path(out[1:4], [
        ("N20", "G1", (0, 5), (50, 5)),
        ("N30", "G2", (50, 5), (55, 0), (50, 0)),
        ("N30", "G1", (55, 0), (55, -50)),
    ])
    assert out[2].inserted and out[2].role == "corner"


def test_90_degree_outside_corner_g451_intersection():
    """Digest 828d-3 rank 23 (G451: intersection)."""
    # The offset lines y = 5 and x = 55 meet at (55, 5): r from both edges.
    out = corner(-90, "G451")
    assert_path(out[1:3], [
        ("N20", "G1", (0, 5), (55, 5)),
        ("N30", "G1", (55, 5), (55, -50)),
    ])
    assert not any(o.inserted for o in out)


def test_45_degree_turn_135_degree_corner_g451_and_g450():
    # Direction change 45° (contour angle 135°). G451: the intersection lies on
    # y = 5 at x = 50 + r·tan(22.5°) = 52.0711. G450: arc to the start normal of
    # the next block, (50, 0) + 5·(sin 45°, cos 45°) = (53.5355, 3.5355).
    s = 5 * math.sqrt(0.5)
    out451 = corner(-45, "G451")
    assert_path(out451[1:3], [
        ("N20", "G1", (0, 5), (50 + 5 * math.tan(math.radians(22.5)), 5)),
        ("N30", "G1", (50 + 5 * math.tan(math.radians(22.5)), 5), (50 + 50 * s / 5 + s, -50 * s / 5 + s)),
    ])
    out450 = corner(-45, "G450")
    assert_path(out450[1:3], [
        ("N20", "G1", (0, 5), (50, 5)),
        ("N30", "G2", (50, 5), (50 + s, s), (50, 0)),
    ])


def test_135_degree_turn_g451_falls_back_to_circle():
    # Direction change 135° (an acute 45° corner) exceeds MD20210 = 100°: G451
    # inserts the transition circle like G450, ending at (50, 0) + 5·(sin45°, −cos45°).
    s = 5 * math.sqrt(0.5)
    for mode in ("G450", "G451"):
        out = corner(-135, mode)
        assert_path(out[1:3], [
            ("N20", "G1", (0, 5), (50, 5)),
            ("N30", "G2", (50, 5), (50 + s, -s), (50, 0)),
        ])
    # With MD20210 = 150° the intersection is kept: x = 50 + r·tan(67.5°).
    out = corner(-135, "G451", TrcSettings(corner_limit_deg=150))
    assert_path(out[1:2], [("N20", "G1", (0, 5), (50 + 5 * math.tan(math.radians(67.5)), 5))])


def test_very_flat_corner_g450_uses_intersection():
    # 5° direction change is below MD20230 = 10°: no tiny circle, the intersection
    # at x = 50 + r·tan(2.5°) instead.
    out = corner(-5, "G450")
    assert_path(out[1:2], [("N20", "G1", (0, 5), (50 + 5 * math.tan(math.radians(2.5)), 5))])
    assert len(out) == 4  # approach, N20, N30, retract: nothing inserted


def test_line_arc_line_tangent():
    # (0,0)→(20,0), G3 quarter circle R10 about (20,10) to (30,10), then up to (30,30).
    # G41 r=4 lies towards the arc centre: arc radius 10 − 4 = 6, lines y = 4 and x = 26.
    blocks = [
        lin((-10, -10), (0, 0), "N10", radius=4),
        lin((0, 0), (20, 0), "N20", radius=4),
        circ((20, 0), (30, 10), (20, 10), "N30", ccw=True, radius=4),
        lin((30, 10), (30, 30), "N40", radius=4),
        lin((30, 30), (40, 40), "N50", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (-10, -10), (0, 4)),
        ("N20", "G1", (0, 4), (20, 4)),
        ("N30", "G3", (20, 4), (26, 10), (20, 10)),
        ("N40", "G1", (26, 10), (26, 30)),
        ("N50", "G1", (26, 30), (40, 40)),
    ])
    # G42 r=4: arc radius 14, lines y = −4 and x = 34.
    right = [b.__class__(**{**{f: getattr(b, f) for f in b.__dataclass_fields__},
                            "side": "G42" if b.side == "G41" else b.side}) for b in blocks]
    out = compensate(right)
    assert_path(out[1:4], [
        ("N20", "G1", (0, -4), (20, -4)),
        ("N30", "G3", (20, -4), (34, 10), (20, 10)),
        ("N40", "G1", (34, 10), (34, 30)),
    ])


def test_line_arc_line_with_inside_corners():
    # A G2 half circle R10 about (20,0) rises between two lines on y = 0. With G41
    # (left = +Y) both transitions are inside corners; the offset arc has radius
    # 10 + 4 = 14 and meets y = 4 at x = 20 ∓ √(14² − 4²) = 20 ∓ 13.41641.
    h = math.sqrt(14**2 - 4**2)
    blocks = [
        lin((-5, -5), (0, 0), "N10", radius=4),
        lin((0, 0), (10, 0), "N20", radius=4),
        circ((10, 0), (30, 0), (20, 0), "N30", ccw=False, radius=4),
        lin((30, 0), (40, 0), "N40", radius=4),
        lin((40, 0), (45, -5), "N50", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (-5, -5), (0, 4)),
        ("N20", "G1", (0, 4), (20 - h, 4)),
        ("N30", "G2", (20 - h, 4), (20 + h, 4), (20, 0)),
        ("N40", "G1", (20 + h, 4), (40, 4)),
        ("N50", "G1", (40, 4), (45, -5)),
    ])


def test_full_circle_offset():
    # Inside a full circle R20 about (0,0) with G41 (G3 travel, left = inside): R 15.
    blocks = [
        lin((0, 0), (20, 0), "N10"),
        circ((20, 0), (20, 0), (0, 0), "N20", ccw=True),
        lin((20, 0), (0, 0), "N30", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (0, 0), (15, 0)),
        ("N20", "G3", (15, 0), (15, 0), (0, 0)),
        ("N30", "G1", (15, 0), (0, 0)),
    ])


def pocket(radius):
    """A pocket 8 mm wide and 40 mm long, milled counter-clockwise inside with G41."""
    points = [(0, 20), (0, 0), (8, 0), (8, 40), (0, 40), (0, 20)]
    blocks = [lin((4, 20), (0, 20), "N10", radius=radius)]
    blocks += chain(points, radius=radius, first_n=20)
    blocks.append(lin((0, 20), (4, 20), "N99", side="G40", radius=radius))
    return blocks


def test_pocket_that_fits():
    # r = 3.9 < 4: offset lines x = 3.9, y = 3.9, x = 4.1, y = 36.1.
    out = compensate(pocket(3.9))
    corners = [o.end for o in out[1:6]]
    expected = [(3.9, 3.9), (4.1, 3.9), (4.1, 36.1), (3.9, 36.1), (3.9, 20)]
    for got, want in zip(corners, expected):
        assert math.dist(got, want) < 1e-6


def test_pocket_corner_too_tight_raises_10751_and_nothing_passes_it():
    """Digest 828d-3 rank 23 (10751)."""
    # r = 5 needs 10 mm: the offsets of the 8 mm bottom (y = 5 from x = 5) and of the
    # far side (x = 3) cross before the bottom block starts; no later offset meets
    # it within MD20240 blocks → collision danger.
    from nck.geometry.radius_comp import RadiusCompensator

    comp = RadiusCompensator()
    emitted = []
    with pytest.raises(NcAlarmError) as info:
        for block in pocket(5.0):
            emitted += comp.feed(block)
        emitted += comp.flush()
    assert info.value.number == 10751
    assert info.value.trc_source == "N40"
    # Nothing at or beyond the faulty corner was released.
    assert {o.source for o in emitted} <= {"N10", "N20"}


def test_inside_arc_smaller_than_tool_raises_10758():
    blocks = [
        lin((-10, 10), (0, 10), "N10"),
        lin((0, 10), (0, 3), "N20"),
        circ((0, 3), (3, 0), (3, 3), "N30", ccw=True),  # R3 inside corner, tool R5
        lin((3, 0), (30, 0), "N40"),
    ]
    with pytest.raises(NcAlarmError) as info:
        compensate(blocks)
    assert info.value.number == 10758
    assert info.value.trc_source == "N30"


def test_step_shorter_than_radius_is_skipped_with_warning_10763():
    """Digest 828d-3 rank 23 (10763)."""
    # A 1 mm step up under G41 r=5: the offset of the step (x = 15, y 0…1) never
    # meets y = 5; the next piece, the transition circle R5 about (20, 1), does at
    # x = 20 − √(5² − 4²) = 17. The step block is left out (warning 10763).
    blocks = [
        lin((-10, 10), (0, 0), "N10"),
        lin((0, 0), (20, 0), "N20"),
        lin((20, 0), (20, 1), "N30"),
        lin((20, 1), (40, 1), "N40"),
        lin((40, 1), (50, 20), "N50", side="G40"),
    ]
    out = compensate(blocks)
    assert_path(out, [
        ("N10", "G1", (-10, 10), (0, 5)),
        ("N20", "G1", (0, 5), (17, 5)),
        ("N30", "dummy", (17, 5), (17, 5)),
        ("N40", "G2", (17, 5), (20, 6), (20, 1)),
        ("N40", "G1", (20, 6), (40, 6)),
        ("N50", "G1", (40, 6), (50, 20)),
    ])
    assert out[2].warning == 10763 and out[2].role == "skipped"
    assert all(o.warning is None for o in out if o.source != "N30")


def test_programming_guide_contour_11_15():
    # Complete contour of the 840C Programming Guide example 11.15 (G41 G450 D1) with
    # R = 5: outside corners get circles, inside corners are cut, arcs are offset.
    # Every compensated element stays exactly 5 mm from the programmed contour.
    from nck.geometry.trc_geometry import distance_to_curve, sample

    pts = [(30, 60), (40, 80)]
    blocks = [lin((15, 60), (30, 60), "N10"), lin((30, 60), (40, 80), "N20"),
              circ((40, 80), (65, 55), (40, 55), "N30", ccw=False),
              lin((65, 55), (95, 55), "N40"),
              circ((95, 55), (110, 70), (110, 55), "N50", ccw=False)]
    pts = [(110, 70), (105, 55), (110, 35), (90, 35), (65, 15), (40, 40), (30, 60)]
    blocks += [lin(a, b, f"N{60 + 10 * i}") for i, (a, b) in enumerate(zip(pts, pts[1:]))]
    blocks.append(lin((30, 60), (15, 60), "N120", side="G40"))
    out = compensate(blocks)
    assert_continuous(out)
    contour = [b.curve() for b in blocks[1:-1]]
    checked = 0
    for element in out:
        if element.role in ("contour", "corner") and element.kind != "dummy":
            for point in sample(element.curve(), 10):
                assert min(distance_to_curve(point, c) for c in contour) == pytest.approx(R, abs=1e-6)
                checked += 1
    assert checked > 100
    # Every block from N20 to N110 is present; the arcs keep their direction and centre.
    assert [o.source for o in out if o.role == "contour"] == [f"N{n}" for n in range(20, 120, 10)]
    arcs = {o.source: o for o in out if o.role == "contour" and o.kind == "G2"}
    assert arcs["N30"].center == (40, 55) and arcs["N50"].center == (110, 55)
