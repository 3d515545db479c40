"""SLOT2 (circumferential slots): the tool centre path worked out by hand from the documented
sequence (data/cycles/README.md, "Slots") with the end mill T1 D1 of radius 5 mm; the points
on the circles are computed with cos/sin here; one test per alarm."""

from __future__ import annotations

import math

import pytest

from tests.cycles.helpers import TOOL, run_with_tool, tool_path


def _p(r: float, deg: float, cx: float = 0, cy: float = 0) -> tuple[float, float]:
    return round(cx + r * math.cos(math.radians(deg)), 3), round(cy + r * math.sin(math.radians(deg)), 3)


def _level(z: float, w0: float, w1: float, h: float, ccw: bool = True) -> list[tuple]:
    """One level of a slot on the circle R 30 about (0, 0) from w0 to w1 with one contour at
    offset h: centre arc, out to the contour, contour, back to the centre arc, back along it."""
    a, b = _p(30, w0), _p(30, w1)
    r1, r2 = (30 + h, 30 - h) if ccw else (30 - h, 30 + h)
    g = "G3" if ccw else "G2"
    return [("G1", *a, z), ("G3", *b, z, (0, 0)), ("G1", *_p(r1, w1), z), (g, *_p(r2, w1), z, b),
            ("G2", *_p(r2, w0), z, (0, 0)), (g, *_p(r1, w0), z, a), ("G3", *_p(r1, w1), z, (0, 0)),
            ("G1", *b, z), ("G2", *a, z, (0, 0))]


def test_slot2_two_slots_complete_machining() -> None:
    """Two slots 12 wide over 60° of the circle R 30 about (0, 0), the first from 0°, the
    second 180° further; depth 4 below RFP 0: roughing in ceil(4/2.5) = 2 levels of 2 (MID
    2.5), finishing in one level at -4 (MIDF 0). Roughing contour 6 - 5 - 0.5 = 0.5 from the
    centre arc (one: 0.5 < 8), finishing contour 6 - 5 = 1; CDIR 3 counterclockwise. From slot
    to slot in rapid at RTP 10 (VARI tens 0)."""
    case = run_with_tool("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 0, 0, 200, 3000)")
    expected = [("G0", 0, 0, 10)]
    for w0 in (0, 180):
        a = _p(30, w0)
        expected += [("G0", *a, 10), ("G0", *a, 2)]
        expected += _level(-2, w0, w0 + 60, 0.5) + _level(-4, w0, w0 + 60, 0.5) + _level(-4, w0, w0 + 60, 1)
        expected.append(("G0", *a, 10))
    assert tool_path(case.ended()) == expected
    assert [s for s in case.steps() if s[0] == "S"] == [("S", 3000), ("S", 3000), ("S", 1000)]


def test_slot2_finishing_clockwise_and_along_the_circle_between_slots() -> None:
    """VARI 12: finishing only, from slot to slot along the circle at the safety plane with
    _FFCP 500; CDIR 2: the contour clockwise (inside first). Three slots over 30° from 90°,
    INDA 0 → 120° apart: 90, 210, 330. One level at -3 (DPR 3)."""
    case = run_with_tool("SLOT2(10, 0, 2, 0, 3, 3, 30, 12, 0, 0, 30, 90, 0, 80, 300, 0, 2, 0.5, 12, 0, 0, 0, 500)")
    expected = [("G0", 0, 0, 10), ("G0", *_p(30, 90), 10), ("G0", *_p(30, 90), 2)]
    for k, w0 in enumerate((90, 210, 330)):
        if k:
            expected.append(("G3", *_p(30, w0), 2, (0, 0)))
        expected += _level(-3, w0, w0 + 30, 1, ccw=False) + [("G0", *_p(30, w0), 2)]
    expected.append(("G0", *_p(30, 330), 10))
    assert tool_path(case.ended()) == expected
    arcs_between = [m.feed_mm_min for m in case.result.segments if m.kind == "G3" and round(m.end_wcs["Z"], 3) == 2]
    assert arcs_between == [500, 500]


@pytest.mark.parametrize("body, tool, alarm", [
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 0)", "T1 M6 D0\n", 61000),
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 3)", TOOL, 61002),
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 20)", TOOL, 61002),
    ("SLOT2(10, 0, 2, 4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 0)", TOOL, 61101),
    ("SLOT2(10, 0, 2, -4, 0, 0, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 0)", TOOL, 61103),
    # 60° slots 70° apart: 10° between the ends, 2 × 30 × sin 5° = 5.2 < 12
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 70, 80, 300, 2.5, 3, 0.5, 0)", TOOL, 61104),
    ("SLOT2(10, 0, 2, -4, 0, 1, 350, 12, 0, 0, 30, 0, 0, 80, 300, 2.5, 3, 0.5, 0)", TOOL, 61104),  # meets itself
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 8, 0, 0, 30, 0, 180, 80, 300, 2.5, 3, 0.5, 0)", TOOL, 61105),
    ("SLOT2(10, 0, 2, -4, 0, 2, 60, 12, 0, 0, 30, 0, 180, 80, 300, 2.5, 4, 0.5, 0)", TOOL, 61109),
])
def test_slot2_alarms(body: str, tool: str, alarm: int) -> None:
    case = run_with_tool(body, tool)
    assert case.alarms == [alarm]
    assert [s for s in case.steps() if s[0] in ("G0", "G1", "G2", "G3")] == []
