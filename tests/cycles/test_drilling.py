"""CYCLE81, CYCLE82, CYCLE83: motion worked out by hand from the cycles' documented sequence
(data/cycles/README.md, "Drilling"; programming guide cycles, chapter 2.1) and alarms 61101,
61107 (000 L5890-5892) and 61002.

Every program starts at X0 Y0 Z50 with F100 and S1000 M3 under G17 (tool axis Z)."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import run


# -- CYCLE81 -------------------------------------------------------------------------------
def test_cycle81_absolute_depth() -> None:
    """Rapid to RFP+SDIS = 0+2, drill at F100 to DP = -10, rapid to RTP = 50."""
    assert run("CYCLE81(50, 0, 2, -10)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -10, 100), ("G0", 0, 0, 50)]


def test_cycle81_relative_depth_wins() -> None:
    """DPR = 20 below RFP = 100: depth 100-20 = 80 (DP = -99 is ignored); safety 100+3 = 103."""
    assert run("CYCLE81(110, 100, 3, -99, 20)").ended().steps() == [
        ("G0", 0, 0, 103), ("G1", 0, 0, 80, 100), ("G0", 0, 0, 110)]


def test_cycle81_drills_upwards_when_the_retraction_plane_is_below() -> None:
    """RTP -50 below RFP 0: the safety plane is 0-2 = -2 and the depth DPR 10 is 0+10 = 10."""
    assert run("G0 Z-50\nCYCLE81(-50, 0, 2, 0, 10)").ended().steps() == [
        ("G0", 0, 0, -50), ("G0", 0, 0, -2), ("G1", 0, 0, 10, 100), ("G0", 0, 0, -50)]


def test_cycle81_tool_axis_follows_the_plane() -> None:
    """G18: the tool axis is Y (the axis perpendicular to Z/X)."""
    assert run("G18 G0 Y50\nCYCLE81(50, 0, 2, -10)").ended().steps() == [
        ("G0", 0, 50, 50), ("G0", 0, 2, 50), ("G1", 0, -10, 50, 100), ("G0", 0, 50, 50)]


@pytest.mark.parametrize("call", [
    "CYCLE81(0, 0, 2, 0, 5)",     # RTP = RFP and only a relative depth: no drilling direction
    "CYCLE81(50, 0, 2, 5)",       # depth above the reference plane
    "CYCLE81(50, 0, 2, 0)",       # depth on the reference plane
    "CYCLE82(50, 0, 2, 3, 0, 1)",
])
def test_reference_plane_alarm(call: str) -> None:
    """61101 before any motion of the cycle (000 L5890)."""
    case = run(call)
    assert case.alarms == [61101]
    assert case.steps() == []


# -- CYCLE82 -------------------------------------------------------------------------------
def test_cycle82_dwells_at_depth() -> None:
    """As CYCLE81 to DP = -4, then DTB = 0.5 s at the depth before the rapid retraction."""
    assert run("CYCLE82(50, 0, 2, -4, 0, 0.5)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -4, 100), ("DWELL", 0.5), ("G0", 0, 0, 50)]


# -- CYCLE83 -------------------------------------------------------------------------------
def test_cycle83_swarf_removal_with_degression() -> None:
    """VARI=1, FDEP -5, DAM 2, DP -12: infeeds 5, 5-2 = 3, 3-2 = 1 < DAM so 2, then the 2 mm
    left: depths -5, -8, -10, -12. After each infeed rapid to RFP+SDIS = 2, then rapid back to
    the last depth less the anticipation distance 0.6 mm (drilling depth 12 <= 30 mm):
    -5+0.6 = -4.4, -8+0.6 = -7.4, -10+0.6 = -9.4."""
    assert run("CYCLE83(50, 0, 2, -12, 0, -5, 0, 2, 0, 0, 1, 1)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -5, 100), ("G0", 0, 0, 2),
        ("G0", 0, 0, -4.4), ("G1", 0, 0, -8, 100), ("G0", 0, 0, 2),
        ("G0", 0, 0, -7.4), ("G1", 0, 0, -10, 100), ("G0", 0, 0, 2),
        ("G0", 0, 0, -9.4), ("G1", 0, 0, -12, 100), ("G0", 0, 0, 50)]


def test_cycle83_swarf_removal_dwells_and_first_feed_factor() -> None:
    """FRF 0.5: the first infeed at 100*0.5 = 50 mm/min, the others at 100. DTB 0.5 s after
    every infeed, DTS 1 s at the safety plane after each of the two intermediate infeeds
    (FDPR 4 of DPR 8: depths -4, -8; DAM 0 keeps the infeed)."""
    assert run("CYCLE83(50, 0, 2, 0, 8, 0, 4, 0, 0.5, 1, 0.5, 1)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -4, 50), ("DWELL", 0.5), ("G0", 0, 0, 2), ("DWELL", 1),
        ("G0", 0, 0, -3.4), ("G1", 0, 0, -8, 100), ("DWELL", 0.5), ("G0", 0, 0, 50)]


def test_cycle83_anticipation_distance_of_deep_holes() -> None:
    """Depth 100 > 30 mm: anticipation 100/50 = 2 mm. FDPR 40, DAM 0: depths -40, -80, -100;
    rapid back to -40+2 = -38 and -80+2 = -78. With _DIS1 = 1.5 the distance is 1.5."""
    assert run("CYCLE83(50, 0, 2, -100, 0, 0, 40, 0, 0, 0, 1, 1)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -40, 100), ("G0", 0, 0, 2), ("G0", 0, 0, -38),
        ("G1", 0, 0, -80, 100), ("G0", 0, 0, 2), ("G0", 0, 0, -78), ("G1", 0, 0, -100, 100),
        ("G0", 0, 0, 50)]
    rapids = [s[3] for s in run("CYCLE83(50, 0, 2, -100, 0, 0, 40, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1.5)").ended().steps()
              if s[0] == "G0"]
    assert rapids == [2, 2, -38.5, 2, -78.5, 50]


def test_cycle83_anticipation_distance_is_at_most_7_mm() -> None:
    """Depth 500: 500/50 = 10 mm, limited to 7 mm; first depth 400 gives the rapid to -393."""
    rapids = [s[3] for s in run("CYCLE83(50, 0, 2, -500, 0, 0, 400, 0, 0, 0, 1, 1)").ended().steps()
              if s[0] == "G0"]
    assert rapids == [2, 2, -393, 50]


def test_cycle83_chip_breaking() -> None:
    """VARI=0, FDPR 4, DAM 1, DP -10: infeeds 4, 3, 2, 1 (depths -4, -7, -9, -10); after each
    intermediate depth the drill retracts 1 mm (_VRT 0) at the feed and drills on; dwell DTB
    0.5 s at every depth, at the final depth _DTD = 2 s instead."""
    assert run("CYCLE83(50, 0, 2, -10, 0, 0, 4, 1, 0.5, 0, 1, 0, 0, 0, 0, 2)").ended().steps() == [
        ("G0", 0, 0, 2),
        ("G1", 0, 0, -4, 100), ("DWELL", 0.5), ("G1", 0, 0, -3, 100),
        ("G1", 0, 0, -7, 100), ("DWELL", 0.5), ("G1", 0, 0, -6, 100),
        ("G1", 0, 0, -9, 100), ("DWELL", 0.5), ("G1", 0, 0, -8, 100),
        ("G1", 0, 0, -10, 100), ("DWELL", 2), ("G0", 0, 0, 50)]


def test_cycle83_retraction_distance_and_minimum_infeed() -> None:
    """_VRT 0.5: chip-breaking retraction 0.5 mm. FDPR 6, DAM 3, _MDEP 4, DP -16: infeeds 6,
    max(6-3, 3, 4) = 4, 4, then the 2 mm left: depths -6, -10, -14, -16."""
    steps = run("CYCLE83(50, 0, 2, -16, 0, 0, 6, 3, 0, 0, 1, 0, 0, 4, 0.5)").ended().steps()
    assert [s[3] for s in steps if s[0] == "G1"] == [-6, -5.5, -10, -9.5, -14, -13.5, -16]


def test_cycle83_first_depth_beyond_the_final_depth_drills_in_one_infeed() -> None:
    assert run("CYCLE83(50, 0, 2, -12, 0, 0, 20, 2, 0, 0, 1, 1)").ended().steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -12, 100), ("G0", 0, 0, 50)]


@pytest.mark.parametrize("call", [
    "CYCLE83(50, 0, 2, -12, 0, 5, 0, 2, 0, 0, 1, 1)",   # FDEP above RFP: against the depth
    "CYCLE83(50, 0, 2, -12, 0, 0, 0, 2, 0, 0, 1, 1)",   # no first depth (FDEP = RFP, FDPR 0)
])
def test_cycle83_first_depth_alarm(call: str) -> None:
    """61107 first drilling depth incorrectly defined (000 L5892)."""
    case = run(call)
    assert case.alarms == [61107]
    assert case.steps() == []


def test_cycle83_machining_type_alarm() -> None:
    """VARI only knows 0 and 1: 61002."""
    case = run("CYCLE83(50, 0, 2, -12, 0, -5, 0, 2, 0, 0, 1, 2)")
    assert case.alarms == [61002]
    assert case.steps() == []


def test_cycle83_reference_plane_alarm() -> None:
    assert run("CYCLE83(50, 0, 2, 4, 0, -5, 0, 2, 0, 0, 1, 1)").alarms == [61101]


def test_modal_call_drills_every_position() -> None:
    """MCALL CYCLE82: each following position block drills (X10, X20); MCALL alone ends it."""
    steps = run("MCALL CYCLE82(50, 0, 2, -4, 0, 1)\nX10\nX20\nMCALL\nX30").ended().steps()
    assert steps == [
        ("G0", 10, 0, 50), ("G0", 10, 0, 2), ("G1", 10, 0, -4, 100), ("DWELL", 1), ("G0", 10, 0, 50),
        ("G0", 20, 0, 50), ("G0", 20, 0, 2), ("G1", 20, 0, -4, 100), ("DWELL", 1), ("G0", 20, 0, 50),
        ("G0", 30, 0, 50)]
