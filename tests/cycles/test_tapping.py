"""CYCLE84 (rigid tapping) and CYCLE840 (tapping with compensating chuck): motion worked out by
hand from the documented sequence (data/cycles/README.md, "Tapping"), alarms 61001 (lead),
61101 (reference plane) and 61102 (spindle direction, 000 L5891).

Every program starts at X0 Y0 Z50 with F100 and S1000 M3 under G17 (tool axis Z, lead K)."""

from __future__ import annotations

import pytest

from nck.resources import alarm_text
from tests.cycles.helpers import run


def test_cycle84_rigid_tapping_sequence() -> None:
    """M8 has the lead 1.25 mm (right hand). Rapid to RFP+SDIS = 2, SPOS to POSS = 30°, G331 to
    DP -10 at SST 200 rpm, dwell DTB 1 s, G332 back to 2 at SST1 400 rpm, rapid to RTP 50, then
    the spindle turns again with SDAC = 3 (M3) at the speed before the call, 1000 rpm."""
    assert run("CYCLE84(50, 0, 2, -10, 0, 1, 3, 8, 0, 30, 200, 400)").ended().steps() == [
        ("G0", 0, 0, 2), ("SPOS", 30), ("S", 200), ("G331", 0, 0, -10, 1.25), ("DWELL", 1),
        ("S", 400), ("G332", 0, 0, 2, 1.25), ("G0", 0, 0, 50), ("S", 1000), ("M3",)]


def test_cycle84_path_feed_is_speed_times_lead() -> None:
    """G331 at 200 rpm x 1.25 mm = 250 mm/min, G332 at 400 rpm x 1.25 mm = 500 mm/min."""
    case = run("CYCLE84(50, 0, 2, -10, 0, 1, 3, 8, 0, 30, 200, 400)").ended()
    feeds = [m.feed_mm_min for m in case.result.segments if m.kind in ("G331", "G332")]
    assert feeds == [250, 500]


def test_cycle84_lead_value_left_hand_and_spindle_stop_after() -> None:
    """PIT -1.5 (left-hand thread, lead 1.5 mm), SST1 0 = retraction at SST 300 rpm, DPR 12
    below RFP 5 = -7, SDAC 5: the spindle stays stopped (M5) after the cycle."""
    assert run("CYCLE84(50, 5, 1, 0, 12, 0, 5, 0, -1.5, 0, 300, 0)").ended().steps() == [
        ("G0", 0, 0, 6), ("SPOS", 0), ("S", 300), ("G331", 0, 0, -7, 1.5),
        ("S", 300), ("G332", 0, 0, 6, 1.5), ("G0", 0, 0, 50), ("M5",)]


@pytest.mark.parametrize("call, alarm", [
    ("CYCLE84(50, 0, 2, -10, 0, 0, 0, 8, 0, 0, 200)", 61102),    # SDAC 0
    ("CYCLE84(50, 0, 2, -10, 0, 0, 6, 8, 0, 0, 200)", 61102),    # SDAC 6
    ("CYCLE84(50, 0, 2, -10, 0, 0, 3, 7, 0, 0, 200)", 61001),    # M7 is not a metric size
    ("CYCLE84(50, 0, 2, -10, 0, 0, 3, 8, 1, 0, 200)", 61001),    # M8 (1.25) and PIT 1 disagree
    ("CYCLE84(50, 0, 2, -10, 0, 0, 3, 0, 0, 0, 200)", 61001),    # no lead at all
    ("CYCLE84(50, 0, 2, 3, 0, 0, 3, 8, 0, 0, 200)", 61101),      # depth above RFP
])
def test_cycle84_alarms(call: str, alarm: int) -> None:
    case = run(call)
    assert case.alarms == [alarm]
    assert case.steps() == []


def test_cycle840_without_encoder_feeds_lead_times_speed() -> None:
    """ENC 1 (G63): M6 has the lead 1 mm, so F = 1 mm x 1000 rpm = 1000 mm/min; to DP -10,
    dwell 0.5 s, spindle reversed to SDR 4 (M4), back to RFP+SDIS = 2, rapid to 50, spindle
    SDAC 3 (M3); afterwards the feed programmed before the call (100) is active again."""
    case = run("CYCLE840(50, 0, 2, -10, 0, 0.5, 4, 3, 1, 6)\nG1 X5").ended()
    assert case.steps() == [
        ("G0", 0, 0, 2), ("G1", 0, 0, -10, 1000), ("DWELL", 0.5), ("M4",), ("G1", 0, 0, 2, 1000),
        ("G0", 0, 0, 50), ("M3",), ("G1", 5, 0, 50, 100)]


def test_cycle840_without_lead_taps_at_the_programmed_feed() -> None:
    steps = run("CYCLE840(50, 0, 2, -10, 0, 0, 4, 3, 1)").ended().steps()
    assert steps[1] == ("G1", 0, 0, -10, 100) and steps[3] == ("G1", 0, 0, 2, 100)


def test_cycle840_with_encoder_cuts_the_thread_with_g33() -> None:
    """ENC 0, PIT 1.5: G33 to -10 and back with the lead 1.5; SDR 0 reverses automatically to
    the opposite of SDAC 3, i.e. M4; SDAC 3 (M3) at the end."""
    assert run("CYCLE840(50, 0, 2, -10, 0, 0, 0, 3, 0, 0, 1.5)").ended().steps() == [
        ("G0", 0, 0, 2), ("G33", 0, 0, -10, 1.5), ("M4",), ("G33", 0, 0, 2, 1.5),
        ("G0", 0, 0, 50), ("M3",)]


@pytest.mark.parametrize("call, alarm", [
    ("CYCLE840(50, 0, 2, -10, 0, 0, 0, 3, 1)", 61102),       # no encoder, nothing reverses
    ("CYCLE840(50, 0, 2, -10, 0, 0, 4, 6, 1)", 61102),       # SDAC 6
    ("CYCLE840(50, 0, 2, -10, 0, 0, 5, 3, 1)", 61102),       # SDR 5
    ("CYCLE840(50, 0, 2, -10, 0, 0, 4, 3, 0)", 61001),       # encoder, but no lead
    ("CYCLE840(50, 50, 2, 0, 10, 0, 4, 3, 1)", 61101),       # RTP = RFP, only a relative depth
])
def test_cycle840_alarms(call: str, alarm: int) -> None:
    case = run(call)
    assert case.alarms == [alarm]
    assert case.steps() == []


def test_no_spindle_direction_alarm_text() -> None:
    """The alarm reaches the operator with the cycles' text, not a generic one."""
    alarm = run("CYCLE84(50, 0, 2, -10, 0, 0, 0, 8)").result.alarms[0]
    assert alarm.number == 61102
    assert "no spindle direction programmed" in alarm_text(alarm.number, ("1", "N1"))
