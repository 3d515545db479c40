"""SLOT1 (slots on a circle): the tool centre path worked out by hand from the documented
sequence (data/cycles/README.md, "Slots") with the end mill T1 D1 of radius 5 mm; one test per
alarm."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def _oblong_ccw(x0: float, y0: float, x1: float, y1: float, h: float, z: float) -> list[tuple]:
    """The counterclockwise oblong of offset h about the centre line (x0, y0)-(x1, y1) when
    that line runs along +X (dx = 1) or +Y (dx = 0), from (x1, y1) shifted to the right."""
    if y0 == y1:  # along +X: right of the line is -Y
        return [("G1", x1, y1 - h, z), ("G3", x1, y1 + h, z, (x1, y1)), ("G1", x0, y0 + h, z),
                ("G3", x0, y0 - h, z, (x0, y0)), ("G1", x1, y1 - h, z)]
    return [("G1", x1 + h, y1, z), ("G3", x1 - h, y1, z, (x1, y1)), ("G1", x0 - h, y0, z),  # along +Y
            ("G3", x0 + h, y0, z, (x0, y0)), ("G1", x1 + h, y1, z)]


def _slot(x0: float, y0: float, x1: float, y1: float) -> list[tuple]:
    """One slot of the golden test: two roughing levels -2.4 / -4.8 with the oblong at 0.5,
    one finishing level at -5 with the oblong at 1; retraction to RTP 10."""
    out = [("G0", x0, y0, 10), ("G0", x0, y0, 2)]
    for z, h in ((-2.4, 0.5), (-4.8, 0.5), (-5, 1)):
        out += [("G1", x0, y0, z), ("G1", x1, y1, z), *_oblong_ccw(x0, y0, x1, y1, h, z), ("G1", x0, y0, z)]
    return out + [("G0", x0, y0, 10)]


def test_slot1_two_slots_complete_machining() -> None:
    """Two slots 30 long and 12 wide on the circle of radius 25 about (50, 40), at 0° and 90°;
    depth 5 below RFP 0 with 0.2 left on the bottom for finishing: roughing in ceil(4.8/3) = 2
    levels of 2.4 (MID 3), finishing in one level at -5 (MIDF 0). Centre line of the tool:
    half length 15 - 6 = 9 either side of the slot middle, from the end nearer the circle
    centre: slot 1 middle (75, 40), X 66 → 84; slot 2 middle (50, 65), Y 56 → 74. Roughing
    offset 6 - 5 - 0.5 = 0.5 (one oblong: 0.5 < 0.8 × 10), finishing offset 6 - 5 = 1. CDIR 3:
    counterclockwise. Feeds: FFD 80 down, FFP1 300 roughing, FFP2 200 finishing at SSF 3000,
    then S 1000 again."""
    case = run_with_tool("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 0, 0, 200, 3000, 0.2)")
    assert case.ended().alarms == []
    expected = [("G0", 0, 0, 10), *_slot(66, 40, 84, 40), *_slot(50, 56, 50, 74)]
    assert tool_path(case) == expected
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind != "G0"]
    # slot 1: level 1 starts with the infeed, then 8 roughing moves per level (line, oblong, back)
    assert feeds[0] == 80 and set(feeds[1:8]) == {300}
    assert feeds[16] == 80 and set(feeds[17:24]) == {200}
    assert [s for s in case.steps() if s[0] == "S"] == [("S", 3000), ("S", 3000), ("S", 1000)]


def test_slot1_roughing_only_leaves_the_allowances_and_default_angle() -> None:
    """VARI 1: only the roughing levels (to -4.8, offset 0.5); INDA 0 with NUM 4: 90° apart,
    first at STA1 90: middles (50, 65), (25, 40), (50, 15), (75, 40); the insertion points are
    9 nearer the centre: (50, 56), (34, 40), (50, 24), (66, 40)."""
    case = run_with_tool("SLOT1(10, 0, 2, -5, 0, 4, 30, 12, 50, 40, 25, 90, 0, 80, 300, 3, 3, 0.5, 1, 0, 200, 3000, 0.2)")
    path = tool_path(case.ended())
    inserts = [p[1:3] for p in path if p[0] == "G0" and p[3] == 2]
    assert inserts == [(50, 56), (34, 40), (50, 24), (66, 40)]
    assert min(p[3] for p in path) == -4.8
    assert [s for s in case.steps() if s[0] == "S"] == []


def test_slot1_conventional_milling_runs_clockwise() -> None:
    """CDIR 1 (conventional = G2), finishing only (VARI 2) at DPR 5: the oblong at offset 1
    starts on the left of the centre line (66, 40) → (84, 40): (84, 41), G2 to (84, 39)."""
    path = tool_path(run_with_tool("SLOT1(10, 0, 2, 0, 5, 1, 30, 12, 50, 40, 25, 0, 0, 80, 300, 3, 1, 0.5, 2)").ended())
    assert path[3:9] == [("G1", 66, 40, -5), ("G1", 84, 40, -5), ("G1", 84, 41, -5), ("G2", 84, 39, -5, (84, 40)),
                         ("G1", 66, 39, -5), ("G2", 66, 41, -5, (66, 40))]


@pytest.mark.parametrize("body, tool, alarm", [
    ("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 0)", "T1 M6 D0\n", 61000),
    ("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 31)", TOOL, 61002),  # oscillating
    ("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 3)", TOOL, 61002),
    ("SLOT1(10, 0, 2, 5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 0)", TOOL, 61101),   # depth above
    # bottom allowance 5 not less than the depth 5: nothing left to rough
    ("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 1, 0, 0, 0, 5)", TOOL, 61101),
    ("SLOT1(10, 0, 2, -5, 0, 0, 30, 12, 50, 40, 25, 0, 90, 80, 300, 3, 3, 0.5, 0)", TOOL, 61103),  # NUM 0
    # inner ends 25 - 9 = 16 from the centre, 30° apart: 2 × 16 × sin 15° = 8.3 < 12
    ("SLOT1(10, 0, 2, -5, 0, 2, 30, 12, 50, 40, 25, 0, 30, 80, 300, 3, 3, 0.5, 0)", TOOL, 61104),
    ("SLOT1(10, 0, 2, -5, 0, 1, 10, 12, 50, 40, 25, 0, 0, 80, 300, 3, 3, 0.5, 0)", TOOL, 61104),   # shorter than wide
    ("SLOT1(10, 0, 2, -5, 0, 1, 30, 8, 50, 40, 25, 0, 0, 80, 300, 3, 3, 0.5, 0)", TOOL, 61105),    # width 8 < 10
    ("SLOT1(10, 0, 2, -5, 0, 1, 30, 12, 50, 40, 25, 0, 0, 80, 300, 3, 5, 0.5, 0)", TOOL, 61109),
])
def test_slot1_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []
