"""CYCLE61 (face milling): the tool centre paths worked out by hand from the documented
sequence (data/cycles/README.md, "Face milling") with the end mill T1 D1 of radius 5 mm; one
test per alarm."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def test_cycle61_roughing_alternating_along_x() -> None:
    """Face 100 x 60 from (0, 0), top 0, depth -3, 0.5 left for finishing: ceil(2.5/2) = 2
    levels of 1.25 (MID 2). VARI 31: roughing, paths along X alternating; MIDA 8: 60/8 → 8
    steps of 7.5, 9 paths Y 0 … 60. Each path runs 5 (tool radius) + 5 (FDP) beyond the
    face: X -10 → 110, back 110 → -10, …; the sideways steps at the feed beside the face.
    After each level up to the safety plane 2; RTP 10 at the end."""
    case = run_with_tool("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 31)")
    expected = [("G0", 0, 0, 10)]
    for z in (-1.25, -2.5):
        expected += [("G0", -10, 0, 10), ("G0", -10, 0, 2)] if z == -1.25 else [("G0", -10, 0, 2)]
        expected.append(("G1", -10, 0, z))
        for j in range(9):
            y = 7.5 * j
            if j:
                expected.append(("G1", 110 if j % 2 else -10, y, z))
            expected.append(("G1", -10 if j % 2 else 110, y, z))
        expected.append(("G0", 110, 60, 2))
    expected.append(("G0", 110, 60, 10))
    assert tool_path(case.ended()) == expected
    assert {m.feed_mm_min for m in case.result.segments if m.kind == "G1"} == {500}


def test_cycle61_finishing_one_direction_along_y() -> None:
    """VARI 22: finishing, paths along Y in one direction: one level at -3 (allowance and MID
    do not apply). Face 40 x 30 from (0, 0); MIDA 20: 40/20 = 2 steps, paths at X 0, 20, 40;
    FDP 0: each from Y -5 to 35, then up to the safety plane and back in rapid."""
    got = tool_path(run_with_tool("CYCLE61(10, 0, 2, -3, 0, 0, 40, 30, 1, 20, 0, 0.5, 400, 22)").ended())
    expected = [("G0", 0, 0, 10)]
    for x in (0, 20, 40):
        expected += [("G0", x, -5, 10), ("G0", x, -5, 2)] if x == 0 else [("G0", x, -5, 2)]
        expected += [("G1", x, -5, -3), ("G1", x, 35, -3), ("G0", x, 35, 2)]
    expected.append(("G0", 40, 35, 10))
    assert got == expected


def test_cycle61_negative_length_runs_the_other_way() -> None:
    """LENG -50 from X 100: the face is X 50 … 100; paths along X in one direction (VARI 12)
    run from 100 + 5 to 50 - 5; WID 0: one path."""
    got = tool_path(run_with_tool("CYCLE61(10, 0, 2, -1, 100, 20, -50, 0, 0, 0, 0, 0, 400, 12)").ended())
    assert got[1:5] == [("G0", 105, 20, 10), ("G0", 105, 20, 2), ("G1", 105, 20, -1), ("G1", 45, 20, -1)]


@pytest.mark.parametrize("body, tool, alarm", [
    ("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 31)", "T1 M6 D0\n", 61000),
    ("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 51)", TOOL, 61002),
    ("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 3)", TOOL, 61002),
    ("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 33)", TOOL, 61002),
    ("CYCLE61(10, 0, 2, 3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 31)", TOOL, 61101),   # depth above the top
    ("CYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 3, 500, 31)", TOOL, 61101),    # allowance ≥ depth
])
def test_cycle61_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []


def test_cycle61_tool_without_radius_is_61105() -> None:
    case = run_with_tool("$TC_DP6[1, 1]=0\nCYCLE61(10, 0, 2, -3, 0, 0, 100, 60, 2, 8, 5, 0.5, 500, 31)")
    assert case.alarms == [61105]
    assert [s for s in case.steps() if s[0] in ("G0", "G1")] == []
