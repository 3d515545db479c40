"""CYCLE97 thread cutting: passes worked out by hand from the documented sequence
(data/cycles/README.md, "CYCLE97"): the thread from SPL to FPL lengthened by the run-in APP and
the run-out ROP, the lift-off plane _VRT (0: 1 mm) outside the thread diameter, TDEP - FAL in
NRC roughing cuts, FAL in one cut, NID idle passes.

Every program runs on the lathe at X70 Z5 under DIAMON; X values are diameters."""

from __future__ import annotations

import math

import pytest

from tests.cycles.lathe import run_lathe


def _passes(diameters: list[float], z_start: float, z_end: float, lift: float, lead: float,
            angle: float = 0.0) -> list[tuple]:
    out: list[tuple] = []
    for x in diameters:
        out += [("G0", lift, z_start), ("G0", x, z_start), ("G33", x, z_end, lead, angle), ("G0", lift, z_end)]
    return out


def test_outside_thread_with_equal_infeeds() -> None:
    """M40x1.5 from Z0 to Z-30, APP 3, ROP 2: the cut runs from Z3 to Z-32. TDEP 0.92, FAL 0.02:
    0.9 in 3 cuts of 0.3 (X39.4, 38.8, 38.2), the allowance to 0.92 (X38.16), one idle pass at
    X38.16. Lift-off plane radius 20+1 (X42); at the end back to Z3."""
    steps = run_lathe("CYCLE97(1.5, 0, 0, -30, 40, 40, 3, 2, 0.92, 0.02, 0, 0, 3, 1, 1, 1, 0)").ended().steps()
    assert steps == [("G0", 42, 5)] + _passes([39.4, 38.8, 38.2, 38.16, 38.16], 3, -32, 42, 1.5) + [("G0", 42, 3)]


def test_outside_thread_with_equal_cross_sections() -> None:
    """VARI 3, TDEP 1.6, FAL 0, NRC 4, no idle pass: depths 1.6*sqrt(n/4) = 0.8, 1.1314, 1.3856,
    1.6; MPIT 10 gives the lead 1.5 (ISO coarse series)."""
    steps = run_lathe("CYCLE97(0, 10, 0, -20, 40, 40, 2, 2, 1.6, 0, 0, 0, 4, 0, 3, 1, 0)").ended().steps()
    diameters = [round(40 - 2 * 1.6 * math.sqrt(n / 4), 4) for n in range(1, 5)]
    assert steps == [("G0", 42, 5)] + _passes(diameters, 2, -22, 42, 1.5) + [("G0", 42, 2)]


def test_inside_thread_cuts_outwards() -> None:
    """VARI 2: core diameter 30, TDEP 1, NRC 2: X31, X32; the lift-off plane inside, radius
    15-0.5 (_VRT 0.5): X29."""
    steps = run_lathe("CYCLE97(2, 0, -5, -25, 30, 30, 1, 1, 1, 0, 0, 0, 2, 0, 2, 1, 0.5)").ended().steps()
    assert steps == [("G0", 29, 5)] + _passes([31, 32], -4, -26, 29, 2) + [("G0", 29, -4)]


def test_two_start_thread_and_start_angle() -> None:
    """NUMT 2, NSP 90: the first start at 90°, the second at 90 + 180 = 270°, each cut fully."""
    steps = run_lathe("CYCLE97(3, 0, 0, -10, 20, 20, 2, 2, 0.5, 0, 0, 90, 1, 0, 1, 2, 0)").ended().steps()
    assert steps == ([("G0", 22, 5)] + _passes([19], 2, -12, 22, 3, 90) + _passes([19], 2, -12, 22, 3, 270)
                     + [("G0", 22, 2)])


def test_flank_infeed_moves_start_and_end_back() -> None:
    """IANG 30: at the depth 0.5 the cut starts and ends 0.5*tan 30° = 0.2887 mm towards the run-in."""
    steps = run_lathe("CYCLE97(1, 0, 0, -10, 20, 20, 1, 1, 0.5, 0, 30, 0, 1, 0, 1, 1, 0)").ended().steps()
    shift = round(0.5 * math.tan(math.radians(30)), 4)
    assert steps == [("G0", 22, 5)] + _passes([19], 1 + shift, -11 + shift, 22, 1) + [("G0", 22, 1)]


def test_taper_thread_follows_the_line_through_both_diameters() -> None:
    """DM1 20 at Z0, DM2 30 at Z-20: radius grows 0.25 per mm; run-in 2 and run-out 2 give radius
    9.5 at Z2 and 15.5 at Z-22; depth 0.5 (one cut): X18 → X30; lift-off radius 15+1 (X32)."""
    steps = run_lathe("CYCLE97(1, 0, 0, -20, 20, 30, 2, 2, 0.5, 0, 0, 0, 1, 0, 1, 1, 0)").ended().steps()
    assert steps == [("G0", 32, 5), ("G0", 32, 2), ("G0", 18, 2), ("G33", 30, -22, 1, 0), ("G0", 32, -22),
                     ("G0", 32, 2)]


@pytest.mark.parametrize("call, alarm", [
    ("CYCLE97(1.5, 0, 0, -30, 40, 40, 3, 2, 0.92, 0, 0, 0, 3, 1, 0, 1)", 61002),   # VARI outside 1 … 4
    ("CYCLE97(1.5, 0, 0, -30, 40, 40, 3, 2, 0.92, 0, 0, 0, 3, 1, 5, 1)", 61002),
    ("CYCLE97(0, 0, 0, -30, 40, 40, 3, 2, 0.92, 0, 0, 0, 3, 1, 1, 1)", 61001),     # no lead
    ("CYCLE97(0, 11, 0, -30, 40, 40, 3, 2, 0.92, 0, 0, 0, 3, 1, 1, 1)", 61001),    # M11 not in the series
    ("CYCLE97(1.5, 0, 0, -5, 40, 60, 3, 2, 0.92, 0, 0, 0, 3, 1, 1, 1)", 61001),    # steeper than 45°
    ("CYCLE97(1.5, 0, 0, -30, 40, 40, 3, 2, 0, 0, 0, 0, 3, 1, 1, 1)", 61610),      # no thread depth
])
def test_bad_parameters_raise_the_alarm_before_any_motion(call: str, alarm: int) -> None:
    case = run_lathe(call)
    assert case.alarms == [alarm]
    assert case.steps() == []
