"""Monitoring: limits, contour, standstill, positioning, clamping, speed and velocity."""

from __future__ import annotations

import pytest

from nck.resources import alarm_catalog
from tests.motion.helpers import motion, move, run_to_idle


def numbers(m) -> list[int]:
    return [a.number for a in m.drain_alarms()]


def test_every_motion_alarm_is_in_the_catalogue() -> None:
    catalog = alarm_catalog()
    for number in (10621, 10631, 10720, 10730, 20000, 20002, 25030, 25040, 25050, 25060, 25080, 26000):
        assert number in catalog


def test_software_limit_in_auto_stops_before_the_block() -> None:
    """Digest 828d-1 rank 3 (002 L2378-2400)."""
    m = motion()
    m.push(move("G1", 2000.0, X=400.0))
    bad = move("G1", 2000.0, X=600.0)
    m.push(bad)
    for _ in range(200):
        m.advance(0.1)
    alarms = m.drain_alarms()
    assert [a.number for a in alarms] == [10720]
    assert alarms[0].params == ("X", "+")
    assert alarms[0].n == bad.source.n
    assert m.positions_mcs()["X"] == pytest.approx(400.0, abs=0.01)
    m.abort()
    assert m.is_idle() or m.jog_active() is False


def test_software_limit_not_checked_for_unreferenced_axis() -> None:
    m = motion(referenced=False)
    run_to_idle(m, feed=[move("G0", X=600.0)])
    assert numbers(m) == []
    assert m.positions_mcs()["X"] == pytest.approx(600.0, abs=0.05)


def test_arc_bulging_over_the_limit_is_refused() -> None:
    m = motion()
    m.push(move("G1", 5000.0, X=0.0, Y=390.0))
    # Half circle to the left around (0, 380) — its top reaches Y = 390 only at the start,
    # but a circle around (0, 395) with radius 5 passes Y = 400 + … no: around (0, 396).
    m.push(move("G2", 2000.0, X=0.0, Y=402.0, center={"X": 0.0, "Y": 396.0}))
    for _ in range(100):
        m.advance(0.1)
    assert numbers(m) == [10720]


def test_working_area_limit_from_setting_data() -> None:
    """Digest 828d-1 rank 14: 10730 in AUTO, 10631 in JOG, WALIMOF (002 L2456-2620)."""
    from nck.motion.system import PlannedMotion
    from tests.motion.helpers import machine

    data = {"SD43400": {"X": 1}, "SD43420": {"X": 100.0}}
    m = PlannedMotion(machine(), referenced=True, setting_data=data)
    m.push(move("G1", 2000.0, X=150.0))
    for _ in range(20):
        m.advance(0.1)
    assert numbers(m) == [10730]
    assert m.positions_mcs()["X"] == pytest.approx(0.0)
    m.abort()
    m.set_workarea_monitoring(False)  # WALIMOF
    run_to_idle(m, feed=[move("G1", 5000.0, X=150.0)])
    assert m.positions_mcs()["X"] == pytest.approx(150.0, abs=0.05)
    # JOG stops at the working-area limit; pressing on raises 10631.
    m.abort()
    m.set_workarea_monitoring(True)
    run_to_idle(m, feed=[move("G1", 5000.0, X=50.0)])
    m.jog_continuous("X", 1, 5000.0)
    while m.jog_active():
        m.advance(0.2)
    assert m.axis_states()["X"].position_setpoint_mm == pytest.approx(100.0, abs=1e-9)
    m.jog_continuous("X", 1, 5000.0)
    assert numbers(m) == [10631]


def test_jog_stops_exactly_at_software_limit_then_10621_which_clears_itself() -> None:
    """Digest 828d-1 rank 2: JOG stops at MD36110, then 10621 which clears on release (002 L2378-2400, L2453)."""
    m = motion()
    run_to_idle(m, feed=[move("G0", X=490.0)])
    m.jog_continuous("X", 1, 10000.0)
    while m.jog_active():
        m.advance(0.2)
    assert m.axis_states()["X"].position_setpoint_mm == pytest.approx(500.0, abs=1e-9)
    m.advance(1.0)
    assert m.positions_mcs()["X"] == pytest.approx(500.0, abs=1e-6)
    assert numbers(m) == []
    m.jog_continuous("X", 1, 10000.0)
    assert not m.jog_active()
    assert numbers(m) == [10621]
    m.jog_continuous("X", 0, 0.0)
    assert m.drain_cleared_alarms() == [10621]
    m.jog_continuous("X", -1, 2000.0)
    m.advance(1.0)
    assert m.positions_mcs()["X"] < 500.0


def test_jog_unreferenced_passes_the_limit() -> None:
    """Digest 828d-1 rank 2 (variant: limits act only once referenced, 002 L2392-2394)."""
    m = motion(referenced=False)
    m.jog_continuous("X", 1, 10000.0)
    m.advance(4.0)
    assert m.positions_mcs()["X"] > 500.0
    m.jog_continuous("X", 0, 0.0)
    m.advance(1.0)
    assert not m.jog_active()


def test_contour_monitoring_on_a_jam() -> None:
    """Digest 828d-1 rank 10: 25050 and follow-up on a jam (002 L1885)."""
    m = motion()
    m.push(move("G1", 5000.0, X=100.0))
    m.advance(1.0)
    m.inject_fault("X", jam_at_mm=m.positions_mcs()["X"])
    m.advance(1.0)
    assert numbers(m) == [25050]
    state = m.axis_states()["X"]
    assert state.controller_mode == 4  # follow-up
    x = m.positions_mcs()["X"]
    m.advance(1.0)
    assert m.positions_mcs()["X"] == pytest.approx(x)  # nothing moves any more
    m.abort()
    m.inject_fault("X", jam_at_mm=None)
    assert m.axis_states()["X"].controller_mode == 0


def test_zero_speed_monitoring_after_a_push() -> None:
    """Digest 828d-1 rank 11: 0.3 mm > MD36030 0.2 gives 25040 (002 L1970-2001)."""
    m = motion()
    m.advance(2.0)
    m.inject_fault("X", push_mm=0.1)
    m.advance(0.5)
    assert numbers(m) == []
    m.inject_fault("X", push_mm=0.3)
    m.advance(0.1)
    assert numbers(m) == [25040]


def test_clamping_monitoring_replaces_zero_speed_monitoring() -> None:
    """Digest 828d-1 rank 16: 0.4 mm no alarm, 0.6 mm 26000 with MD36050 = 0.5 (002 L2014)."""
    m = motion()
    m.set_clamped("X", True)
    m.advance(2.0)
    m.inject_fault("X", push_mm=0.4)
    m.advance(0.5)
    assert numbers(m) == []
    m.inject_fault("X", push_mm=0.6)
    m.advance(0.1)
    assert numbers(m) == [26000]


def test_positioning_monitoring_when_exact_stop_fine_is_never_reached() -> None:
    """Digest 828d-1 rank 12: 25080 after MD36020 (002 L1919-1943)."""
    m = motion()
    m.inject_fault("X", offset_mm=0.05)
    m.push(move("G1", 1000.0, X=10.0))
    m.advance(1.0)
    assert numbers(m) == []
    m.advance(2.0)
    assert numbers(m) == [25080]


def test_speed_setpoint_limitation_when_max_velocity_exceeds_the_motor() -> None:
    """Digest 828d-1 rank 15: 25060 above MD36210 (002 L2240)."""
    # MD32000 needs 3000 rpm at the motor, rated speed only 2000 rpm → 150 % > MD36210 110 %.
    m = motion(MD32260={"X": 2000.0})
    m.push(move("G0", X=400.0))
    m.advance(2.0)
    assert numbers(m) == [25060]


def test_actual_velocity_monitoring_on_a_runaway() -> None:
    """Digest 828d-1 rank 15: 25030 above MD36200 (002 L2285-2292)."""
    m = motion()
    m.push(move("G0", X=400.0))
    m.advance(0.4)  # at MD32000 = 30000 mm/min
    m.inject_fault("X", runaway_mm_s=100.0)  # 36000 mm/min > MD36200 34500
    m.advance(0.1)
    assert numbers(m) == [25030]
