"""CYCLE93 groove: plunges and finishing worked out by hand from the documented sequence
(data/cycles/README.md, "CYCLE93"). The grooving tool T3 has two edges 3 mm apart (D1 the
reference on the start side of the groove, D2): along Z for a longitudinal groove (length 2:
45 and 42), along X for a face groove (length 1: 25 and 22). X values are diameters."""

from __future__ import annotations

import pytest

from tests.cycles.lathe import run_lathe

TOOLS = {(3, 1): {1: 520, 3: 25.0, 4: 45.0}, (3, 2): {1: 520, 3: 22.0, 4: 42.0}}


def _groove(call: str, tools: dict | None = None, select: str = "T3 D1\n"):
    return run_lathe(select + call, tools=TOOLS if tools is None else tools)


def test_longitudinal_outside_groove_with_pecks_and_allowances() -> None:
    """SPD 40, SPL -20, width 10 on the +Z side, depth 5 (to X30), FAL1 0.2, FAL2 0.3, IDEP 2,
    DTB 0.5, F0.2 at 1000 rpm = 200 mm/min. Plunges: span 10 - 2·0.3 - 3 = 6.4 needs
    ceil(6.4/3) + 1 = 4 plunges 6.4/3 apart from Z-19.7: -19.7, -17.5667, -15.4333, -13.3.
    Each from the safety plane radius 20+1 (X42): pecks to depth 2 (X36) and 4 (X32) with 1 mm
    back (X38, X34), then the base less FAL1: radius 15.2 (X30.4), dwell, out. Finishing: the
    start flank down to X30, the base to Z-20+10-3 = -13, the other flank up to X42."""
    steps = _groove("CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.3, 2, 0.5, 1, 0)").ended().steps()
    expected = []
    for z in (-19.7, -17.5667, -15.4333, -13.3):
        expected += [("G0", 42, z), ("G1", 36, z, 200), ("G0", 38, z), ("G1", 32, z, 200), ("G0", 34, z),
                     ("G1", 30.4, z, 200), ("DWELL", 0.5), ("G0", 42, z)]
    expected += [("G0", 42, -20), ("G1", 30, -20, 200), ("G1", 30, -13, 200), ("G1", 42, -13, 200),
                 ("G0", 42, -20)]
    assert steps == expected


def test_face_groove() -> None:
    """VARI 2: face groove at Z0 from diameter 20 outwards, 4 wide (radius 10 … 14), 3 deep (Z-3),
    safety plane Z1. Span 4 - 3 = 1: 2 plunges at radius 10 and 11 (X20, X22)."""
    steps = _groove("CYCLE93(20, 0, 4, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0)").ended().steps()
    assert steps == [("G0", 20, 1), ("G1", 20, -3, 200), ("G0", 20, 1), ("G0", 22, 1), ("G1", 22, -3, 200),
                     ("G0", 22, 1), ("G0", 20, 1), ("G1", 20, -3, 200), ("G1", 22, -3, 200), ("G1", 22, 1, 200),
                     ("G0", 20, 1)]


def test_inside_groove_on_the_minus_side_as_wide_as_the_tool() -> None:
    """VARI 7: bore 30, groove on the -Z side of Z-10, 3 wide (one plunge), 2 deep (X34),
    safety plane radius 15-1 (X28)."""
    steps = _groove("CYCLE93(30, -10, 3, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7, 0)").ended().steps()
    assert steps == [("G0", 28, -10), ("G1", 34, -10, 200), ("G0", 28, -10), ("G0", 28, -10),
                     ("G1", 34, -10, 200), ("G1", 34, -10, 200), ("G1", 28, -10, 200), ("G0", 28, -10)]


@pytest.mark.parametrize("call, alarm", [
    ("CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0)", 61002),    # VARI 0
    ("CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 9, 0)", 61002),    # units 9
    ("CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 21, 0)", 61002),   # tens 2
    ("CYCLE93(40, -20, 10, 25, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61601),   # deeper than the radius
    ("CYCLE93(40, -20, 2, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61602),     # narrower than the tool
    ("CYCLE93(40, -20, 3.4, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0.3, 0, 0, 1, 0)", 61602), # no room for FAL2
    ("CYCLE93(40, -20, 10, 5, 0, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61603),   # flank angle
    ("CYCLE93(40, -20, 10, 5, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61603),    # outer radius
    ("CYCLE93(40, -20, 10, 5, 30, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61603),   # inclined contour
    ("CYCLE93(40, -20, 0, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)", 61603),     # no width
])
def test_bad_parameters_raise_the_alarm_before_any_motion(call: str, alarm: int) -> None:
    case = _groove(call)
    assert case.alarms == [alarm]
    assert case.steps() == []


def test_without_a_tool_offset_or_a_second_edge() -> None:
    """D0: 61000; a tool with one edge has no width: 61602."""
    call = "CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0)"
    assert _groove(call, select="").alarms == [61000]
    assert _groove(call, tools={(3, 1): TOOLS[(3, 1)]}).alarms == [61602]


def test_the_second_edge_given_by_dn() -> None:
    """_DN (18th parameter, "D number for the 2nd edge of the tool"): T3 with edges D1 (length 2
    45) and D3 (41): tool width 4. SPD 40, SPL -20, width 10, depth 5 (X30), no allowances: span
    10 - 4 = 6 needs ceil(6/4) + 1 = 3 plunges 3 apart at Z-20, -17, -14 from the safety plane
    X42; finishing down at Z-20, along the base to Z-20+10-4 = -14, up to X42."""
    tools = {(3, 1): {1: 520, 3: 25.0, 4: 45.0}, (3, 3): {1: 520, 3: 25.0, 4: 41.0}}
    steps = _groove("CYCLE93(40, -20, 10, 5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 3)", tools=tools).ended().steps()
    expected = []
    for z in (-20, -17, -14):
        expected += [("G0", 42, z), ("G1", 30, z, 200), ("G0", 42, z)]
    expected += [("G0", 42, -20), ("G1", 30, -20, 200), ("G1", 30, -14, 200), ("G1", 42, -14, 200),
                 ("G0", 42, -20)]
    assert steps == expected
