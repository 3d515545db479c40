"""CYCLE85 ... CYCLE89 (boring 1-5): motion worked out by hand from the documented sequences
(data/cycles/README.md, "Boring") and alarms 61101 / 61102 (000 L5890-5891).

Every program starts at X0 Y0 Z50 with F100 and S1000 M3 under G17 (plane X/Y, tool axis Z)."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import run


def test_cycle85_feeds_in_and_out() -> None:
    """In at FFR 80 to -8, dwell 1 s, out to RFP+SDIS = 2 at RFF 200, rapid to 50; the next G1
    runs at the feed of before, 100."""
    assert run("CYCLE85(50, 0, 2, -8, 0, 1, 80, 200)\nG1 X5").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -8, 80), ("DWELL", 1), ("G1", 0, 0, 2, 200), ("G0", 0, 0, 50),
        ("G1", 5, 0, 50, 100)]


def test_cycle86_oriented_stop_and_lift_off() -> None:
    """At X10 Y20: spindle SDIR 3 (M3), in to -8 at F100, dwell 1 s, SPOS to POSS 45°, lift off
    in rapid by RPA -1 (X), RPO 0.5 (Y), RPAP 1 (Z): to X9 Y20.5 Z-7; out to Z2; back to the
    hole centre X10 Y20; up to RTP 50."""
    assert run("X10 Y20\nCYCLE86(50, 0, 2, -8, 0, 1, 3, -1, 0.5, 1, 45)").ended().steps() == [
        ("G0", 10, 20, 50), ("G0", 10, 20, 2), ("M3",), ("G1", 10, 20, -8, 100), ("DWELL", 1),
        ("SPOS", 45), ("G0", 9, 20.5, -7), ("G0", 9, 20.5, 2), ("G0", 10, 20, 2), ("G0", 10, 20, 50)]


def test_cycle86_lift_off_in_the_g18_plane() -> None:
    """G18: abscissa Z, ordinate X, tool axis Y. RPA 1 moves Z, RPO -2 moves X, RPAP 0.5 moves Y."""
    steps = run("G18 G0 Y50\nCYCLE86(50, 0, 2, -8, 0, 0, 4, 1, -2, 0.5, 90)").ended().steps()
    assert steps == [
        ("G0", 0, 50, 50), ("G0", 0, 2, 50), ("M4",), ("G1", 0, -8, 50, 100), ("SPOS", 90),
        ("G0", -2, -7.5, 51), ("G0", -2, 2, 51), ("G0", 0, 2, 50), ("G0", 0, 50, 50)]


def test_cycle87_stops_for_the_operator() -> None:
    """Spindle SDIR 4, in to -8, M5, M0 (the operator retracts or not; NC START goes on), rapid
    to 50."""
    assert run("CYCLE87(50, 0, 2, -8, 0, 4)").ended().steps() == [
        ("G0", 0, 0, 2), ("M4",), ("G1", 0, 0, -8, 100), ("M5",), ("M0",), ("G0", 0, 0, 50)]


def test_cycle88_dwells_then_stops() -> None:
    assert run("CYCLE88(50, 0, 2, -8, 0, 1.5, 3)").ended().steps() == [
        ("G0", 0, 0, 2), ("M3",), ("G1", 0, 0, -8, 100), ("DWELL", 1.5), ("M5",), ("M0",),
        ("G0", 0, 0, 50)]


def test_cycle89_feeds_out_at_the_same_feed() -> None:
    assert run("CYCLE89(50, 0, 2, -8, 0, 2)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -8, 100), ("DWELL", 2), ("G1", 0, 0, 2, 100), ("G0", 0, 0, 50)]


@pytest.mark.parametrize("call", [
    "CYCLE86(50, 0, 2, -8, 0, 1, 5, 0, 0, 0, 0)",
    "CYCLE86(50, 0, 2, -8, 0, 1, 0, 0, 0, 0, 0)",
    "CYCLE87(50, 0, 2, -8, 0, 2)",
    "CYCLE88(50, 0, 2, -8, 0, 1, 0)",
])
def test_spindle_direction_alarm(call: str) -> None:
    """SDIR must be 3 or 4: 61102 before any motion."""
    case = run(call)
    assert case.alarms == [61102]
    assert case.steps() == []


@pytest.mark.parametrize("call", [
    "CYCLE85(50, 0, 2, 1, 0, 0, 80, 200)",
    "CYCLE86(50, 0, 2, 1, 0, 1, 3, 0, 0, 0, 0)",
    "CYCLE87(50, 50, 2, 0, 5, 3)",
    "CYCLE88(50, 0, 2, 0, 0, 1, 3)",
    "CYCLE89(50, 0, 2, 2, 0, 1)",
])
def test_reference_plane_alarm(call: str) -> None:
    case = run(call)
    assert case.alarms == [61101]
    assert case.steps() == []
