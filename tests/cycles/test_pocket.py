"""POCKET4 (circular pocket): tool centre path worked out by hand from the documented sequence
(data/cycles/README.md, "Milling") with the tool T1 D1 of radius 5 mm; alarms 61000, 61002,
61101, 61105, 61109."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def test_pocket4_roughing_in_two_levels() -> None:
    """Radius 20 about (50, 40), depth 6 below RFP 0, bottom allowance 0.2: rough to -5.8 in
    ceil(5.8/3) = 2 equal infeeds of 2.9 (at FFD 80); wall allowance 0.5: the widest circle of
    the tool centre is 20-5-0.5 = 14.5; circles 4 apart (_MIDA): radii 4, 8, 12, 14.5, climb
    milling = G3, at FFP1 300; back to the centre after each level; RTP 10 at the end."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 0, 1, 4)")
    assert case.ended().alarms == []
    level = []
    for z in (-2.9, -5.8):
        level.append(("G1", 50, 40, z))
        for r in (4, 8, 12, 14.5):
            level += [("G1", 50 + r, 40, z), ("G3", 50 + r, 40, z, (50, 40))]
        level.append(("G1", 50, 40, z))
    assert tool_path(case) == [("G0", 0, 0, 10), ("G0", 50, 40, 10), ("G0", 50, 40, 2), *level, ("G0", 50, 40, 10)]
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind != "G0"]
    assert feeds[0] == 80 and feeds[1] == 300


def test_pocket4_finishing_pass_and_conventional_direction() -> None:
    """_VARI 2: one pass at the depth -6 on the radius 20-5 = 15 (allowances removed); _CDIR 1:
    G2. Default circle step (_MIDA 0) does not matter for one circle."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 1, 2)").ended()
    assert tool_path(case)[3:] == [("G1", 50, 40, -6), ("G1", 65, 40, -6), ("G2", 65, 40, -6, (50, 40)),
                               ("G1", 50, 40, -6), ("G0", 50, 40, 10)]


def test_pocket4_default_circle_step_is_80_percent_of_the_diameter() -> None:
    """_MIDA 0: 0.8 x 10 = 8 mm: radii 8 and then 14.5 (one level, _MID 0)."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 0, 0, 0, 0.5, 0, 300, 80, 3, 1)").ended()
    assert [p[1] for p in tool_path(case) if p[0] == "G3"] == [8, 14.5]


@pytest.mark.parametrize("body, tool, alarm", [
    ("POCKET4(10, 0, 2, -6, 20, 0, 0, 3, 0, 0, 300, 80, 0, 1)", "T1 M6 D0\n", 61000),   # no offset
    ("POCKET4(10, 0, 2, -6, 20, 0, 0, 3, 0, 0, 300, 80, 0, 11)", TOOL, 61002),          # helical
    ("POCKET4(10, 0, 2, -6, 20, 0, 0, 3, 0, 0, 300, 80, 0, 3)", TOOL, 61002),
    ("POCKET4(10, 0, 2, 6, 20, 0, 0, 3, 0, 0, 300, 80, 0, 1)", TOOL, 61101),            # depth above
    ("POCKET4(10, 0, 2, -6, 4, 0, 0, 3, 0, 0, 300, 80, 0, 1)", TOOL, 61105),            # radius 4 < 5
    ("POCKET4(10, 0, 2, -6, 20, 0, 0, 3, 0, 0, 300, 80, 4, 1)", TOOL, 61109),           # _CDIR 4
])
def test_pocket4_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []


def _rounded_rectangle_ccw(cx: float, cy: float, a: float, b: float, r: float, z: float) -> list[tuple]:
    """The counterclockwise tool centre rectangle from the middle of its +X side, by hand."""
    if r == 0:
        return [("G1", cx + a, cy + b, z), ("G1", cx - a, cy + b, z), ("G1", cx - a, cy - b, z),
                ("G1", cx + a, cy - b, z), ("G1", cx + a, cy, z)]
    return [("G1", cx + a, cy + b - r, z), ("G3", cx + a - r, cy + b, z, (cx + a - r, cy + b - r)),
            ("G1", cx - a + r, cy + b, z), ("G3", cx - a, cy + b - r, z, (cx - a + r, cy + b - r)),
            ("G1", cx - a, cy - b + r, z), ("G3", cx - a + r, cy - b, z, (cx - a + r, cy - b + r)),
            ("G1", cx + a - r, cy - b, z), ("G3", cx + a, cy - b + r, z, (cx + a - r, cy - b + r)),
            ("G1", cx + a, cy, z)]


def test_pocket3_roughing_rectangles() -> None:
    """60 x 40 pocket, corner radius 10, centre (50, 40), one level to -4 (no allowances),
    tool radius 5: final tool centre rectangle half 30-5 = 25 by 20-5 = 15 with corner radius
    10-5 = 5. First the centre line (length 25-15 = 10 each side: X 40 … 60), then
    ceil(15/8) = 2 rectangles 7.5 apart: inset 7.5 → half 17.5 x 7.5, corner 5-7.5 < 0 → sharp;
    inset 0 → the final one. Each is entered straight from the centre line along +X."""
    case = run_with_tool("POCKET3(10, 0, 2, -4, 60, 40, 10, 50, 40, 0, 0, 0, 0, 300, 80, 0, 1, 8)").ended()
    z = -4
    expected = [("G0", 0, 0, 10), ("G0", 50, 40, 10), ("G0", 50, 40, 2), ("G1", 50, 40, z),
                ("G1", 40, 40, z), ("G1", 60, 40, z),
                ("G1", 67.5, 40, z), *_rounded_rectangle_ccw(50, 40, 17.5, 7.5, 0, z),
                ("G1", 75, 40, z), *_rounded_rectangle_ccw(50, 40, 25, 15, 5, z),
                ("G1", 50, 40, z), ("G0", 50, 40, 10)]
    got = tool_path(case)
    # zero-length moves (a rectangle starts where the step out ended) are not motion
    assert [p for p in got] == [p for i, p in enumerate(expected) if i == 0 or p[:4] != expected[i - 1][:4]]


def test_pocket3_finishing_turned_by_90_degrees_clockwise() -> None:
    """40 x 30 pocket turned by 90° (its length along Y), corner radius 8, finishing at -4:
    half 20-5 = 15 along Y, 15-5 = 10 along X, corner 8-5 = 3. _CDIR 1: clockwise (G2) from
    the middle of the +length side (0, 15): to (7, 15), arc to (10, 12) about (7, 12), down to
    (10, -12), arc to (7, -15) …"""
    got = tool_path(run_with_tool("POCKET3(10, 0, 2, -4, 40, 30, 8, 0, 0, 90, 0, 0, 0, 300, 80, 1, 2)").ended())
    assert got[3:] == [
        ("G1", 0, 0, -4), ("G1", 0, 15, -4), ("G1", 7, 15, -4), ("G2", 10, 12, -4, (7, 12)),
        ("G1", 10, -12, -4), ("G2", 7, -15, -4, (7, -12)), ("G1", -7, -15, -4), ("G2", -10, -12, -4, (-7, -12)),
        ("G1", -10, 12, -4), ("G2", -7, 15, -4, (-7, 12)), ("G1", 0, 15, -4), ("G1", 0, 0, -4), ("G0", 0, 0, 10)]


@pytest.mark.parametrize("body, tool, alarm", [
    ("POCKET3(10, 0, 2, -4, 60, 40, 10, 0, 0, 0, 0, 0, 0, 300, 80, 0, 1)", "T1 M6 D0\n", 61000),
    ("POCKET3(10, 0, 2, -4, 60, 40, 10, 0, 0, 0, 0, 0, 0, 300, 80, 0, 21)", TOOL, 61002),
    ("POCKET3(10, 0, 2, 4, 60, 40, 10, 0, 0, 0, 0, 0, 0, 300, 80, 0, 1)", TOOL, 61101),
    ("POCKET3(10, 0, 2, -4, 60, 8, 2, 0, 0, 0, 0, 0, 0, 300, 80, 0, 1)", TOOL, 61105),   # width 8 < 10
    ("POCKET3(10, 0, 2, -4, 60, 40, 10, 0, 0, 0, 0, 0, 0, 300, 80, 5, 1)", TOOL, 61109),
])
def test_pocket3_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []


def _helix_level(cx: float, cy: float, rad1: float, z_from: float, zs: list[float]) -> list[tuple]:
    """Helical insertion by hand: out to the helix start, full turns down to each of zs, a
    flat circle at the last, back to the centre (G3, climb milling)."""
    z = zs[-1]
    return [("G1", cx + rad1, cy, z_from), *[("G3", cx + rad1, cy, zi, (cx, cy)) for zi in zs],
            ("G3", cx + rad1, cy, z, (cx, cy)), ("G1", cx, cy, z)]


def _circles(z: float) -> list[tuple]:
    """The roughing circles of the first POCKET4 test at the level z: radii 4, 8, 12, 14.5."""
    return [p for r in (4, 8, 12, 14.5) for p in (("G1", 50 + r, 40, z), ("G3", 50 + r, 40, z, (50, 40)))]


def test_pocket4_helical_insertion() -> None:
    """_VARI 11: roughing with helical insertion, helix radius _RAD1 3, at most _DP1 2 per turn.
    Levels -2.9 and -5.8 as in the first test. Level 1 from the safety plane 2 down 4.9:
    ceil(4.9/2) = 3 turns of 4.9/3 (to 0.367, -1.267, -2.9); level 2 down 2.9: 2 turns of 1.45
    (-4.35, -5.8). Helix at FFD 80, the flat circle and the pocket circles at FFP1 300."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 0, 11, 4, 0, 0, 3, 2)")
    expected = [("G0", 0, 0, 10), ("G0", 50, 40, 10), ("G0", 50, 40, 2),
                *_helix_level(50, 40, 3, 2, [0.367, -1.267, -2.9]), *_circles(-2.9), ("G1", 50, 40, -2.9),
                *_helix_level(50, 40, 3, -2.9, [-4.35, -5.8]), *_circles(-5.8), ("G1", 50, 40, -5.8),
                ("G0", 50, 40, 10)]
    assert tool_path(case.ended()) == expected
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind != "G0"]
    assert feeds[:6] == [80, 80, 80, 80, 300, 300]


def test_pocket3_helical_insertion() -> None:
    """POCKET3 60 x 40 about (50, 40), one level to -4 (no allowances), _VARI 11 with _RAD1 4
    and _DP1 5: from the safety plane 2 down 6 in ceil(6/5) = 2 turns of 3 (-1, -4), flat
    circle, back to the centre; then the centre line and rectangles as in the roughing test."""
    got = tool_path(run_with_tool(
        "POCKET3(10, 0, 2, -4, 60, 40, 10, 50, 40, 0, 0, 0, 0, 300, 80, 0, 11, 8, 0, 0, 0, 4, 5)").ended())
    assert got[3:8] == _helix_level(50, 40, 4, 2, [-1, -4])
    assert got[8:10] == [("G1", 40, 40, -4), ("G1", 60, 40, -4)]


@pytest.mark.parametrize("body, alarm", [
    ("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 0, 11, 4, 0, 0, 3, 0)", 61002),     # no depth per turn
    ("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 0, 11, 4, 0, 0, 15, 2)", 61105),    # 15 > 14.5
    ("POCKET3(10, 0, 2, -4, 60, 40, 10, 50, 40, 0, 0, 0, 0, 300, 80, 0, 11, 8, 0, 0, 0, 0, 5)", 61002),
    ("POCKET3(10, 0, 2, -4, 60, 40, 10, 50, 40, 0, 0, 0, 0, 300, 80, 0, 11, 8, 0, 0, 0, 16, 5)", 61105),  # 16 > 15
])
def test_helical_insertion_alarms(body: str, alarm: int) -> None:
    case = run_with_tool(body)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []


def test_pocket4_premachined_blank_leaves_out_the_inner_circles() -> None:
    """_AP1 9 (blank radius), _AD 3 (its depth below RFP): the level -2.9 lies inside the
    blank's depth, so the circle of radius 4 (tool reaching 4 + 5 = 9, not beyond the blank)
    is left out; 8, 12, 14.5 remain. The level -5.8 is below the blank: all four circles."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 0, 1, 4, 9, 3)")
    radii = [(round(p[1] - 50, 3), p[3]) for p in tool_path(case.ended()) if p[0] == "G3"]
    assert radii == [(8, -2.9), (12, -2.9), (14.5, -2.9), (4, -5.8), (8, -5.8), (12, -5.8), (14.5, -5.8)]


def test_pocket3_premachined_blank_leaves_out_what_it_covers() -> None:
    """The roughing test's pocket with a pre-machined pocket 50 x 30, 4 deep (the whole level
    -4): the centre line (reaching 10 + 5 = 15 ≤ 25 along, 5 ≤ 15 across) and the inner
    rectangle (17.5 + 5 = 22.5 ≤ 25, 7.5 + 5 = 12.5 ≤ 15) are left out; the tool goes from
    the centre straight to the final rectangle."""
    got = tool_path(run_with_tool("POCKET3(10, 0, 2, -4, 60, 40, 10, 50, 40, 0, 0, 0, 0, 300, 80, 0, 1, 8, 50, 30, 4)").ended())
    assert got == [("G0", 0, 0, 10), ("G0", 50, 40, 10), ("G0", 50, 40, 2), ("G1", 50, 40, -4), ("G1", 75, 40, -4),
                   *_rounded_rectangle_ccw(50, 40, 25, 15, 5, -4), ("G1", 50, 40, -4), ("G0", 50, 40, 10)]
