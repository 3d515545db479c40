"""Hardware limit switches, alarm 21614 (digest 828d-1 rank 9; 002 L2340-2375).

The switches belong to the simulated mechanics (mill3: X at +520 mm, beyond the software limit
MD36110 = 500 mm). Before referencing the software limits are not active (002 L2392-2394), so a
JOG motion reaches the switch: alarm 21614, the axis is braked as MD36600 says (0: with the
axial acceleration MD32300; 1: setpoint velocity zero), and the traversing keys of that
direction are blocked (002 L2366-2372).
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.kernel import Nck
from nck.resources import alarm_catalog
from tests.motion.helpers import machine, motion

SWITCH_X_MM = 520.0  # data/machines/mill3.toml [sim] hw_limit_plus_mm
JOG_RAPID_MM_S = 10000.0 / 60.0
ACCEL_X_MM_S2 = 2.5 * 1000.0  # MD32300 X = 2.5 m/s²


def _alarms(m) -> list[tuple[int, tuple]]:
    return [(a.number, tuple(a.params)) for a in m.drain_alarms()]


def test_jog_unreferenced_reaches_the_switch_and_brakes_with_md32300() -> None:
    """MD36600 = 0: braked from 166.7 mm/s with 2500 mm/s² after the switch, the axis stops
    v²/2a = 5.556 mm beyond it; 21614 X + is raised."""
    m = motion(referenced=False)
    m.jog_continuous("X", 1, 10000.0)
    m.advance(5.0)
    overrun = JOG_RAPID_MM_S ** 2 / (2.0 * ACCEL_X_MM_S2)
    assert m.positions_mcs()["X"] == pytest.approx(SWITCH_X_MM + overrun, abs=1e-6)
    assert not m.jog_active()
    assert _alarms(m) == [(21614, ("X", "+"))]


def test_traversing_key_of_the_switch_direction_is_blocked() -> None:
    """002 L2372: X+ again moves nothing and raises 21614 again; X- moves the axis off."""
    m = motion(referenced=False)
    m.jog_continuous("X", 1, 10000.0)
    m.advance(5.0)
    _alarms(m)
    x = m.positions_mcs()["X"]
    m.jog_continuous("X", 1, 2000.0)
    m.advance(1.0)
    assert m.positions_mcs()["X"] == pytest.approx(x, abs=1e-9)
    assert _alarms(m) == [(21614, ("X", "+"))]
    m.jog_continuous("X", -1, 2000.0)
    m.advance(1.0)
    assert m.positions_mcs()["X"] < x - 10.0
    assert _alarms(m) == []


def test_md36600_1_stops_the_setpoint_at_the_switch() -> None:
    """MD36600 = 1 (002 L2353-2356): setpoint velocity zero at the switch, no braking path."""
    m = motion(referenced=False, MD36600={"X": 1, "Y": 0, "Z": 0})
    m.jog_continuous("X", 1, 10000.0)
    m.advance(5.0)
    assert m.positions_mcs()["X"] == pytest.approx(SWITCH_X_MM, abs=1e-6)
    assert _alarms(m) == [(21614, ("X", "+"))]


def test_jog_before_the_switch_raises_nothing() -> None:
    """An increment that ends before the switch moves without 21614."""
    m = motion(referenced=False)
    m.jog_increment("X", 100.0, 10000.0)
    m.advance(3.0)
    assert m.positions_mcs()["X"] == pytest.approx(100.0, abs=1e-6)
    assert _alarms(m) == []


def test_21614_in_the_kernel_is_cleared_by_reset() -> None:
    """The alarm reaches the alarm list with its text; RESET clears it."""
    assert "hardware limit switch" in alarm_catalog()[21614].text
    nck = Nck(machine=machine(), referenced=False)
    assert nck.submit(c.SelectMode("JOG")) == c.Accepted()
    assert nck.submit(c.Jog("X", 1, rapid=True)) == c.Accepted()
    nck.run_until(lambda k: 21614 in [a.number for a in k.status().alarms], 40.0)
    assert [a.number for a in nck.status().alarms] == [21614]
    nck.submit(c.Jog("X", 0))
    nck.submit(c.Reset())
    nck.step(1)
    assert [a.number for a in nck.status().alarms] == []
