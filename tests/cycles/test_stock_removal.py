"""CYCLE95 stock removal on a contour subprogram: motion worked out by hand from the cycle's
documented sequence (data/cycles/README.md, "Turning"): equal infeeds of at most MID down to
the contour shifted by the allowances, each cut from the approach line (contour start + _VRT)
to the contour, 45° lift-off by _VRT, back to the approach line; finishing along the contour.

Every program runs on the lathe at X70 Z5 under DIAMON with 1000 rpm and feeds per revolution
(FF1 0.3 = 300 mm/min, FF3 0.1 = 100 mm/min). X values below are diameters."""

from __future__ import annotations

import pytest

from tests.cycles.lathe import run_lathe

SHAFT = """PROC SHAFT_A
G1 X20 Z0
Z-20
X40 Z-30
Z-45
G2 X50 Z-50 CR=5
G1 X60
M17
"""
FILES = {"SHAFT_A.SPF": SHAFT}


def test_roughing_and_finishing_longitudinal_outside() -> None:
    """VARI 9, MID 5, no allowances: the contour spans radius 10 … 30, depth 20 = 4 cuts of 5 at
    radius 25, 20, 15, 10 (X50, X40, X30, X20). Approach line Z0+1. Crossings: X50 the arc's end
    Z-50; X40 the end of the taper Z-30; X30 half-way along the taper Z-25; X20 the contour start
    Z0. Finishing: Z1, X20, then the contour at F0.1; lift X62, back to X70, Z5."""
    steps = run_lathe('CYCLE95("SHAFT_A", 5, 0, 0, 0, 0.3, 0.1, 0.1, 9, 0, 0, 1)', FILES).ended().steps()
    rough = [("G0", 62, 1)]
    for x, z in ((50, -50), (40, -30), (30, -25), (20, 0)):
        rough += [("G0", x, 1), ("G1", x, z, 300), ("G0", x + 2, z + 1), ("G0", x + 2, 1)]
    finish = [("G0", 22, 1), ("G0", 20, 1), ("G1", 20, 0, 100), ("G1", 20, -20, 100), ("G1", 40, -30, 100),
              ("G1", 40, -45, 100), ("G2", 50, -50, 100), ("G1", 60, -50, 100),
              ("G0", 62, -50), ("G0", 70, -50), ("G0", 70, 5)]
    assert steps == rough + finish


def test_roughing_leaves_the_allowances() -> None:
    """VARI 1, FALZ 0.5, FALX 0.25 (radius): the contour moves by Z+0.5 and radius +0.25, so it
    spans radius 10.25 … 30.25: depth 20, MID 4 gives 5 cuts at radius 26.25, 22.25, 18.25,
    14.25, 10.25. Crossings: 26.25 the shoulder Z-49.5; 22.25 the arc (centre Z-44.5 radius
    25.25, R5): Z = -44.5 - sqrt(25 - 3²) = -48.5; 18.25 and 14.25 the 45° taper from Z-19.5:
    Z-27.5, Z-23.5; 10.25 the start Z0.5. Approach line Z1.5; no finishing; back X first."""
    steps = run_lathe('CYCLE95("SHAFT_A", 4, 0.5, 0.25, 0, 0.3, 0.1, 0.1, 1, 0, 0, 1)', FILES).ended().steps()
    expected = [("G0", 62.5, 1.5)]
    for x, z in ((52.5, -49.5), (44.5, -48.5), (36.5, -27.5), (28.5, -23.5), (20.5, 0.5)):
        expected += [("G0", x, 1.5), ("G1", x, z, 300), ("G0", x + 2, z + 1), ("G0", x + 2, 1.5)]
    expected += [("G0", 70, 1.5), ("G0", 70, 5)]
    assert steps == expected


def test_face_roughing_outside() -> None:
    """VARI 2 (face, outside), MID 2.5, _VRT 0 (1 mm): the contour X60 Z-10 → X40 → Z0 → X0
    spans Z-10 … 0: 4 cuts at Z-2.5, -5, -7.5, -10 from the approach line radius 30+1 (X62)
    inwards: the first three end on the shoulder X40, the last on the contour start X60.
    Lift-off 1 mm in radius and Z; back Z first, then X."""
    face = "PROC FACE_A\nG1 X60 Z-10\nX40\nZ0\nX0\nM17\n"
    steps = run_lathe('CYCLE95("FACE_A", 2.5, 0, 0, 0, 0.3, 0.1, 0.1, 2, 0, 0, 0)',
                      {"FACE_A.SPF": face}).ended().steps()
    expected = [("G0", 62, 1)]
    for z, x in ((-2.5, 40), (-5, 40), (-7.5, 40), (-10, 60)):
        expected += [("G0", 62, z), ("G1", x, z, 300), ("G0", x + 2, z + 1), ("G0", 62, z + 1)]
    expected += [("G0", 62, 5), ("G0", 70, 5)]
    assert steps == expected


def test_contour_programmed_from_the_other_end_is_machined_from_the_approach_side() -> None:
    """The same shaft written from X60 Z-50 back to X20 Z0 gives the same roughing."""
    reverse = "PROC SHAFT_B\nG1 X60 Z-50\nX50\nG3 X40 Z-45 CR=5\nG1 Z-30\nX20 Z-20\nZ0\nM17\n"
    forward = run_lathe('CYCLE95("SHAFT_A", 5, 0, 0, 0, 0.3, 0.1, 0.1, 1, 0, 0, 1)', FILES).ended().steps()
    backward = run_lathe('CYCLE95("SHAFT_B", 5, 0, 0, 0, 0.3, 0.1, 0.1, 1, 0, 0, 1)',
                         {"SHAFT_B.SPF": reverse}).ended().steps()
    assert backward == forward


def test_chip_breaking_splits_the_cut() -> None:
    """DAM 20, DT 0.5: the cut at X40 from Z1 to Z-30 stops after 20 mm (Z-19) with a dwell,
    then goes on to Z-30; the shorter cuts run through."""
    steps = run_lathe('CYCLE95("SHAFT_A", 10, 0, 0, 0, 0.3, 0.1, 0.1, 1, 0.5, 20, 1)', FILES).ended().steps()
    assert steps[:9] == [("G0", 62, 1), ("G0", 40, 1), ("G1", 40, -19, 300), ("DWELL", 0.5), ("G1", 40, -30, 300),
                         ("G0", 42, -29), ("G0", 42, 1), ("G0", 20, 1), ("G1", 20, 0, 300)]


@pytest.mark.parametrize("call, alarm", [
    ('CYCLE95("SHAFT_A", 5, 0, 0, 0, 0.3, 0.1, 0.1, 0)', 61002),   # VARI outside 1 … 12
    ('CYCLE95("SHAFT_A", 5, 0, 0, 0, 0.3, 0.1, 0.1, 13)', 61002),
    ('CYCLE95("SHAFT_A", 0, 0, 0, 0, 0.3, 0.1, 0.1, 1)', 61610),   # roughing without infeed depth
    ('CYCLE95("SHAFT_A", -2, 0, 0, 0, 0.3, 0.1, 0.1, 9)', 61610),
    ('CYCLE95("NO_SUCH", 5, 0, 0, 0, 0.3, 0.1, 0.1, 9)', 14011),  # no contour program
    ('CYCLE95("ROUNDED", 5, 0, 0, 0, 0.3, 0.1, 0.1, 9)', 10931),  # RND: not a contour it can read
    ('CYCLE95("EMPTY_C", 5, 0, 0, 0, 0.3, 0.1, 0.1, 9)', 10931),  # no element at all
])
def test_bad_parameters_raise_the_alarm_before_any_motion(call: str, alarm: int) -> None:
    files = {**FILES, "ROUNDED.SPF": "PROC ROUNDED\nG1 X20 Z0\nZ-20 RND=2\nX40\nM17\n",
             "EMPTY_C.SPF": "PROC EMPTY_C\nG1 X20 Z0\nM17\n"}
    case = run_lathe(call, files)
    assert case.alarms == [alarm]
    assert case.steps() == []


def test_finishing_only_needs_no_infeed_depth() -> None:
    """VARI 5: MID 0 is fine; the tool goes to Z1, X20 and along the contour."""
    steps = run_lathe('CYCLE95("SHAFT_A", 0, 0, 0, 0, 0.3, 0.1, 0.1, 5)', FILES).ended().steps()
    assert steps[:3] == [("G0", 70, 1), ("G0", 20, 1), ("G1", 20, 0, 100)]


def test_longitudinal_inside_roughing_cuts_outwards() -> None:
    """VARI 3 (longitudinal, inside), MID 5, called in the bore at X18 Z5: the bore contour X40 Z0
    → Z-10 → X30 Z-20 → Z-30 → X20 spans radius 10 … 20, material inside it: 2 cuts of 5 at
    radius 15 (X30, ending on the taper at Z-20) and 20 (X40, ending at the start Z0), each from
    the approach line Z1; lift-off 1 mm towards the axis and +Z; back X first, then Z."""
    bore = "PROC BORE_A\nG1 X40 Z0\nZ-10\nX30 Z-20\nZ-30\nX20\nM17\n"
    steps = run_lathe('G0 X18 Z5\nCYCLE95("BORE_A", 5, 0, 0, 0, 0.3, 0.1, 0.1, 3, 0, 0, 1)',
                      {"BORE_A.SPF": bore}).ended().steps()
    assert steps == [("G0", 18, 5), ("G0", 18, 1),
                     ("G0", 30, 1), ("G1", 30, -20, 300), ("G0", 28, -19), ("G0", 28, 1),
                     ("G0", 40, 1), ("G1", 40, 0, 300), ("G0", 38, 1), ("G0", 38, 1),
                     ("G0", 18, 1), ("G0", 18, 5)]


def test_relief_cut_is_not_roughed_and_never_cut_into() -> None:
    """A contour with a relief cut: X20 Z0 → Z-10 → X16 Z-14 → Z-20 → X40 Z-25 → X50. The
    roughing reaches down to the start radius 10 only (depth 15, MID 4: 4 cuts of 3.75 at radius
    21.25, 17.5, 13.75, 10); each cut ends where the contour first rises to its level: X42.5 on
    the shoulder X50 at Z-25, the others on the taper X16 Z-20 → X40 Z-25 (radius 8 + 12/5 per
    mm of Z): Z = -20 - (r - 8)·5/12, i.e. -23.9583 and -22.3958; the cut at radius 10 ends at
    the start Z0 (the contour there is already at the level). The relief X16 is left to the
    finishing pass, which follows the whole contour."""
    relief = "PROC RELIEF_A\nG1 X20 Z0\nZ-10\nX16 Z-14\nZ-20\nX40 Z-25\nX50\nM17\n"
    steps = run_lathe('CYCLE95("RELIEF_A", 4, 0, 0, 0, 0.3, 0.1, 0.1, 9)', {"RELIEF_A.SPF": relief}).ended().steps()
    rough = [("G0", 52, 1)]
    for x, z in ((42.5, -25), (35, -23.9583), (27.5, -22.3958), (20, 0)):
        rough += [("G0", x, 1), ("G1", x, z, 300), ("G0", x + 2, round(z + 1, 4)), ("G0", x + 2, 1)]
    finish = [("G0", 22, 1), ("G0", 20, 1), ("G1", 20, 0, 100), ("G1", 20, -10, 100), ("G1", 16, -14, 100),
              ("G1", 16, -20, 100), ("G1", 40, -25, 100), ("G1", 50, -25, 100),
              ("G0", 52, -25), ("G0", 70, -25), ("G0", 70, 5)]
    assert steps == rough + finish
