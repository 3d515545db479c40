"""A machining block waits for the spindle's set speed range (MD35500, MD35150).

002 L54530-54536: with the actual speed outside the tolerance of MD35150, DB31 DBX83.5 is 0
and the next machining block is not enabled (as MD35500 says). L51282-51285: MD35500 = 1
interpolates the path only once the spindle is up to its speed within MD35150. L54545-54551:
MD35150 = 0.1 lets the actual speed deviate ±10 % from the set speed. L54555-54556: MD35150 = 0
sets the signal permanently, no path control. L54560-54562: checked only at the start of a
traversing block after a programmed speed change. WAITS ends with the same signal
(L51326-51335). The control waits without an alarm: the program status is "waiting"
(L21104-21108).

Hand figures on the default mill: MD35200 = 50 rev/s² = 3000 rpm/s, MD35150 = 0.1 (catalogue
default). S1000 from standstill is in range at 900 rpm: 900 / 3000 = 0.3 s. Times are whole
IPO cycles (4 ms): each figure is checked to within one cycle.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine

CYCLE_S = 0.004
ACCEL_RPM_S = 50.0 * 60.0  # MD35200 of the mill: 50 rev/s²


def make(program: str, **md: object) -> Nck:
    machine = load_machine()
    for key, value in md.items():
        machine.md[key] = value
    return Nck(programs=MemorySource({"P.MPF": program}), referenced=True, machine=machine)


def start(nck: Nck) -> float:
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck.time_s


def run_time_s(program: str, **md: object) -> float:
    nck = make(program, **md)
    began = start(nck)
    assert nck.run_until(lambda k: k.situation.channel == "reset", 120.0)
    assert nck.status().alarms == ()
    return nck.time_s - began


CUT = "N30 G1 X10 F600\nN40 M30"


def test_the_cut_after_m3_waits_until_the_speed_is_within_the_tolerance() -> None:
    base = run_time_s(CUT)
    waited = run_time_s("N10 S1000 M3\n" + CUT) - base
    assert waited == pytest.approx(900.0 / ACCEL_RPM_S, abs=CYCLE_S)  # 0.3 s


def test_m3_in_the_cutting_block_itself_waits_too() -> None:
    base = run_time_s(CUT)
    waited = run_time_s("N30 G1 X10 F600 S1000 M3\nN40 M30") - base
    assert waited == pytest.approx(0.3, abs=CYCLE_S)


def test_a_speed_change_waits_for_the_new_range() -> None:
    # From 1000 to 2000 rpm after 1 s at speed: in range at 1800 rpm, 800 / 3000 s later.
    base = run_time_s("N10 S1000 M3\nN20 G4 F1\nN25 M8\n" + CUT)
    changed = run_time_s("N10 S1000 M3\nN20 G4 F1\nN25 S2000\n" + CUT)
    assert changed - base == pytest.approx(800.0 / ACCEL_RPM_S, abs=CYCLE_S)


def test_a_spindle_already_at_speed_costs_only_the_check() -> None:
    base = run_time_s("N10 S1000 M3\nN20 G4 F1\nN25 M8\n" + CUT)
    checked = run_time_s("N10 S1000 M3\nN20 G4 F1\n" + CUT)
    assert checked - base == pytest.approx(0.0, abs=CYCLE_S + 1e-6)


def test_rapid_traverse_does_not_wait() -> None:
    assert run_time_s("N10 S1000 M3\nN20 G0 X50\nN40 M30") == pytest.approx(
        run_time_s("N10 M8\nN20 G0 X50\nN40 M30"), abs=1e-6)


@pytest.mark.parametrize("md", [{"MD35500": {"SP": 0}}, {"MD35150": {"SP": 0.0}}])
def test_no_wait_when_the_machine_data_switch_it_off(md: dict) -> None:
    # MD35500 = 0: no feed enable on the speed; MD35150 = 0: the signal is always 1 (L54555-54556).
    assert run_time_s("N10 S1000 M3\n" + CUT, **md) == pytest.approx(
        run_time_s("N10 M8\n" + CUT), abs=1e-6)


def test_waits_ends_in_the_set_speed_range() -> None:
    # L51326-51335: WAITS ends with "spindle in setpoint range"; MD35500 = 0 leaves the cut alone.
    base = run_time_s("N10 S1000 M3\n" + CUT, MD35500={"SP": 0})
    waiting = run_time_s("N10 S1000 M3\nN20 WAITS\n" + CUT, MD35500={"SP": 0})
    assert waiting - base == pytest.approx(0.3, abs=CYCLE_S)


def test_the_program_waits_without_an_alarm_while_the_spindle_runs_up() -> None:
    nck = make("N10 S1000 M3\n" + CUT)
    began = start(nck)
    nck.run_until(lambda k: k.time_s - began >= 0.2, 1.0, max_batch_cycles=1)
    status = nck.status()
    assert (status.channel.channel_state, status.channel.program_state) == ("active", "waiting")
    assert status.alarms == ()
    assert nck.positions_mcs()["X"] == 0.0
    nck.run_until(lambda k: k.time_s - began >= 0.4, 1.0, max_batch_cycles=1)
    assert nck.status().channel.program_state == "running"
    assert nck.positions_mcs()["X"] > 0.0


def test_a_drive_that_never_reaches_the_range_holds_the_cut_until_the_speed_is_lowered() -> None:
    # A drive fault caps the actual speed at 500 rpm: S1000 never gets to 900 rpm. The
    # spindle override at 50 % sets 500 rpm, inside the range: the cut starts.
    nck = make("N10 S1000 M3\n" + CUT)
    nck.motion.spindles["SP"].drive_limit_rpm = 500.0
    began = start(nck)
    nck.run_until(lambda k: k.time_s - began >= 5.0, 6.0)
    status = nck.status()
    assert status.channel.program_state == "waiting" and status.alarms == ()
    assert nck.positions_mcs()["X"] == 0.0
    nck.submit(c.SetOverride("spindle", 50))
    assert nck.run_until(lambda k: k.situation.channel == "reset", 5.0)
    assert nck.positions_mcs()["X"] == pytest.approx(10.0)
