"""POCKET4 (circular pocket): tool centre path worked out by hand from the documented sequence
(data/cycles/README.md, "Milling") with the tool T1 D1 of radius 5 mm; alarms 61000, 61002,
61101, 61105, 61109."""

from __future__ import annotations

import pytest

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from tests.cycles.helpers import PROLOGUE, Cycled

TOOL = "T1 M6 D1\n"  # end mill, radius 5 mm ($TC_DP6)


def run_with_tool(body: str, tool: str = TOOL) -> Cycled:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 50.0, 6: 5.0})
    text = PROLOGUE + tool + body + "\nM30\n"
    return Cycled(interpret_only(load_machine(None), MemorySource({"main.mpf": text}), data, "main.mpf",
                                 text=text, max_blocks=20_000))


def _path(case: Cycled) -> list[tuple]:
    out = []
    for m in case.result.segments[1:]:  # after the prologue's G0
        end = tuple(round(m.end_wcs[a], 3) for a in "XYZ")
        centre = tuple(round(m.center_wcs[a], 3) for a in "XY") if m.center_wcs else None
        out.append((m.kind, *end, centre) if centre else (m.kind, *end))
    return out


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
    assert _path(case) == [("G0", 0, 0, 10), ("G0", 50, 40, 10), ("G0", 50, 40, 2), *level, ("G0", 50, 40, 10)]
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind != "G0"]
    assert feeds[0] == 80 and feeds[1] == 300


def test_pocket4_finishing_pass_and_conventional_direction() -> None:
    """_VARI 2: one pass at the depth -6 on the radius 20-5 = 15 (allowances removed); _CDIR 1:
    G2. Default circle step (_MIDA 0) does not matter for one circle."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 50, 40, 3, 0.5, 0.2, 300, 80, 1, 2)").ended()
    assert _path(case)[3:] == [("G1", 50, 40, -6), ("G1", 65, 40, -6), ("G2", 65, 40, -6, (50, 40)),
                               ("G1", 50, 40, -6), ("G0", 50, 40, 10)]


def test_pocket4_default_circle_step_is_80_percent_of_the_diameter() -> None:
    """_MIDA 0: 0.8 x 10 = 8 mm: radii 8 and then 14.5 (one level, _MID 0)."""
    case = run_with_tool("POCKET4(10, 0, 2, -6, 20, 0, 0, 0, 0.5, 0, 300, 80, 3, 1)").ended()
    assert [p[1] for p in _path(case) if p[0] == "G3"] == [8, 14.5]


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
