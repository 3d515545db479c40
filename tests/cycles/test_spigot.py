"""CYCLE76 / CYCLE77 (rectangular / circular spigot): the tool centre path worked out by hand
from the documented sequence (data/cycles/README.md, "Spigots") with the end mill T1 D1 of
radius 5 mm; one test per alarm."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def _rectangle(cx: float, cy: float, a: float, b: float, r: float, z: float, cw: bool) -> list[tuple]:
    """The tool centre's rounded rectangle (half sizes a, b, corner radius r) from the middle
    of its +X side, clockwise (G2) or counterclockwise (G3), by hand."""
    ua, vb = a - r, b - r  # corner centres at (±ua, ±vb)
    if cw:
        return [("G1", cx + a, cy - vb, z), ("G2", cx + ua, cy - b, z, (cx + ua, cy - vb)),
                ("G1", cx - ua, cy - b, z), ("G2", cx - a, cy - vb, z, (cx - ua, cy - vb)),
                ("G1", cx - a, cy + vb, z), ("G2", cx - ua, cy + b, z, (cx - ua, cy + vb)),
                ("G1", cx + ua, cy + b, z), ("G2", cx + a, cy + vb, z, (cx + ua, cy + vb)),
                ("G1", cx + a, cy, z)]
    return [("G1", cx + a, cy + vb, z), ("G3", cx + ua, cy + b, z, (cx + ua, cy + vb)),
            ("G1", cx - ua, cy + b, z), ("G3", cx - a, cy + vb, z, (cx - ua, cy + vb)),
            ("G1", cx - a, cy - vb, z), ("G3", cx - ua, cy - b, z, (cx - ua, cy - vb)),
            ("G1", cx + ua, cy - b, z), ("G3", cx + a, cy - vb, z, (cx + ua, cy - vb)),
            ("G1", cx + a, cy, z)]


def test_cycle76_roughing_from_the_blank_inwards() -> None:
    """Spigot 40 x 20, corner radius 5, about (50, 40) out of a blank 60 x 30: per side 10
    along the length, 5 across; the larger, 10, is removed in ceil(10/8) = 2 steps of 5.
    Wall allowance 0.5: contour offsets 5 + 0.5 + 5 = 10.5 and 5.5 (half sizes 30.5 x 20.5,
    corner 15.5; 25.5 x 15.5, corner 10.5; corner centres stay at (±15, ±5)). Insertion one
    tool diameter out from the first contour: X 50 + 30.5 + 10 = 90.5. Bottom allowance 0.2:
    ceil(5.8/3) = 2 levels of 2.9 (MID 3). CDIR 0: climb around a spigot = G2."""
    case = run_with_tool("CYCLE76(10, 0, 2, -6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 0, 1, 60, 30)")
    expected = [("G0", 0, 0, 10), ("G0", 90.5, 40, 10), ("G0", 90.5, 40, 2)]
    for z in (-2.9, -5.8):
        expected += [("G1", 90.5, 40, z), ("G1", 80.5, 40, z), *_rectangle(50, 40, 30.5, 20.5, 15.5, z, cw=True),
                     ("G1", 75.5, 40, z), *_rectangle(50, 40, 25.5, 15.5, 10.5, z, cw=True), ("G1", 90.5, 40, z)]
    expected.append(("G0", 90.5, 40, 10))
    assert tool_path(case.ended()) == expected
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind != "G0"]
    assert feeds[0] == 80 and set(feeds[1:20]) == {300}


def test_cycle76_finishing_counterclockwise_turned_by_90_degrees() -> None:
    """VARI 2, CDIR 3 (G3): one contour at the depth -4 (DPR 4) on the spigot plus the tool
    radius: half 20 + 5 = 25 along the length, which is turned to +Y by STA 90, and 10 + 5 = 15
    across, corner 0 + 5 = 5; insertion 25 + 10 = 35 along +Y from (0, 0)."""
    got = tool_path(run_with_tool("CYCLE76(10, 0, 2, 0, 4, 40, 20, 0, 0, 0, 90, 0, 0.5, 0.2, 300, 80, 3, 2)").ended())
    # in the spigot's own axes (u along +Y, v along -X) the contour is _rectangle about (0, 0)
    own = _rectangle(0, 0, 25, 15, 5, -4, cw=False)
    turned = [(p[0], -p[2], p[1], p[3], *([(-p[4][1], p[4][0])] if len(p) > 4 else [])) for p in own]
    assert got == [("G0", 0, 0, 10), ("G0", 0, 35, 10), ("G0", 0, 35, 2), ("G1", 0, 35, -4), ("G1", 0, 25, -4),
                   *turned, ("G1", 0, 35, -4), ("G0", 0, 35, 10)]


def test_cycle77_roughing_circles_from_the_blank_inwards() -> None:
    """Spigot of diameter 30 about (50, 40) out of a blank of diameter 50: 10 per side in
    ceil(10/8) = 2 steps of 5; wall allowance 0.5: circle radii 15 + 5.5 + 5 = 25.5 and 20.5;
    insertion at X 50 + 25.5 + 10 = 85.5. One level at -5.8 (MID 0, bottom allowance 0.2).
    CDIR 2: G2."""
    case = run_with_tool("CYCLE77(10, 0, 2, -6, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, 2, 1, 50)")
    z = -5.8
    assert tool_path(case.ended()) == [
        ("G0", 0, 0, 10), ("G0", 85.5, 40, 10), ("G0", 85.5, 40, 2), ("G1", 85.5, 40, z),
        ("G1", 75.5, 40, z), ("G2", 75.5, 40, z, (50, 40)), ("G1", 70.5, 40, z), ("G2", 70.5, 40, z, (50, 40)),
        ("G1", 85.5, 40, z), ("G0", 85.5, 40, 10)]


def test_cycle77_finishing_one_circle_per_level() -> None:
    """VARI 2, CDIR 1 (conventional = G3 around a spigot): one circle of radius 15 + 5 = 20 at
    the depth -6; insertion at 20 + 10 = 30 from the centre (0, 0)."""
    got = tool_path(run_with_tool("CYCLE77(10, 0, 2, -6, 0, 30, 0, 0, 3, 0.5, 0.2, 300, 80, 1, 2, 50)").ended())
    assert got[3:] == [("G1", 30, 0, -6), ("G1", 20, 0, -6), ("G3", 20, 0, -6, (0, 0)), ("G1", 30, 0, -6),
                       ("G0", 30, 0, 10)]


@pytest.mark.parametrize("body, tool, alarm", [
    ("CYCLE76(10, 0, 2, -6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 0, 1)", "T1 M6 D0\n", 61000),
    ("CYCLE76(10, 0, 2, -6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 0, 3)", TOOL, 61002),
    ("CYCLE76(10, 0, 2, 6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 0, 1)", TOOL, 61101),
    ("CYCLE76(10, 0, 2, -6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 7, 1)", TOOL, 61109),
    ("CYCLE77(10, 0, 2, -6, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, 2, 1)", "T1 M6 D0\n", 61000),
    ("CYCLE77(10, 0, 2, -6, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, 2, 0)", TOOL, 61002),
    ("CYCLE77(10, 0, 2, 0, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, 2, 1)", TOOL, 61101),    # no depth
    ("CYCLE77(10, 0, 2, -6, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, -1, 1)", TOOL, 61109),
])
def test_spigot_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []


@pytest.mark.parametrize("call", ["CYCLE76(10, 0, 2, -6, 0, 40, 20, 5, 50, 40, 0, 3, 0.5, 0.2, 300, 80, 0, 1)",
                                  "CYCLE77(10, 0, 2, -6, 0, 30, 50, 40, 0, 0.5, 0.2, 300, 80, 2, 1)"])
def test_spigot_tool_without_radius_is_61105(call: str) -> None:
    case = run_with_tool("$TC_DP6[1, 1]=0\n" + call)
    assert case.alarms == [61105]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []
