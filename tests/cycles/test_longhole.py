"""LONGHOLE (elongated holes on a circle): the tool centre path worked out by hand from the
documented sequence (data/cycles/README.md, "Slots") with the end mill T1 D1 of radius 5 mm;
the points on the circle are computed with cos/sin here; one test per alarm."""

from __future__ import annotations

import math

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def test_longhole_three_holes_reciprocating_infeed() -> None:
    """Three holes 30 long on the circle R 20 about (50, 40) at 0°, 120°, 240°; depth 5 in
    ceil(5/2) = 3 infeeds of 5/3 (MID 2) at FFD 80. Tool centre line 15 - 5 = 10 either side
    of the middle: insertion at the end 10 nearer the centre, then infeed, pass to the far end
    (FFP1 300), infeed there, pass back, infeed, pass out; rapid to RTP 10 at the far end."""
    case = run_with_tool("LONGHOLE(10, 0, 2, -5, 0, 3, 30, 50, 40, 20, 0, 120, 80, 300, 2)")
    expected = [("G0", 0, 0, 10)]
    for deg in (0, 120, 240):
        c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
        near = (round(50 + 10 * c, 3), round(40 + 10 * s, 3))
        far = (round(50 + 30 * c, 3), round(40 + 30 * s, 3))
        expected += [("G0", *near, 10), ("G0", *near, 2)]
        for z, here, there in ((-1.667, near, far), (-3.333, far, near), (-5, near, far)):
            expected += [("G1", *here, z), ("G1", *there, z)]
        expected.append(("G0", *far, 10))
    assert tool_path(case.ended()) == expected
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind == "G1"]
    assert feeds[:6] == [80, 300, 80, 300, 80, 300]


@pytest.mark.parametrize("body, tool, alarm", [
    ("LONGHOLE(10, 0, 2, -5, 0, 3, 30, 50, 40, 20, 0, 120, 80, 300, 2)", "T1 M6 D0\n", 61000),
    ("LONGHOLE(10, 0, 2, 5, 0, 3, 30, 50, 40, 20, 0, 120, 80, 300, 2)", TOOL, 61101),
    ("LONGHOLE(10, 0, 2, -5, 0, 0, 30, 50, 40, 20, 0, 120, 80, 300, 2)", TOOL, 61103),
    # inner ends 20 - 10 = 10 from the centre, 45° apart: 2 × 10 × sin 22.5° = 7.7 < 10
    ("LONGHOLE(10, 0, 2, -5, 0, 3, 30, 50, 40, 20, 0, 45, 80, 300, 2)", TOOL, 61104),
    ("LONGHOLE(10, 0, 2, -5, 0, 3, 8, 50, 40, 20, 0, 120, 80, 300, 2)", TOOL, 61105),   # 8 < 10
])
def test_longhole_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []
