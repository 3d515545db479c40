"""SVG snapshots of every Diagnostics view (160×48, no clock, no blink).

The kernel is real but its alarms, messages and axis values are staged
(:mod:`tests.diagnostics.staged`), so the pictures stay put when the motion
dynamics are tuned; the system utilisation view measures wall time, so its
clock is replaced by one that advances 1 ms per reading.
"""

from __future__ import annotations

import itertools

import pytest

from nck import commands as cmd
from hmi import utilisation
from tests.diagnostics.conftest import SIZE, app_on
from tests.diagnostics.staged import AUTO_LIMIT, CYCLE_ALARM, JOG_LIMIT, StagedKernel, stamped, staged_trace


@pytest.fixture(autouse=True)
def fake_clock(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every reading of the wall clock is 1 ms after the previous one."""
    ticks = itertools.count()
    monkeypatch.setattr(utilisation, "CLOCK", lambda: next(ticks) * 0.001)


async def _open(pilot, *keys: str) -> None:
    await pilot.press("alt+a", *keys)
    await pilot.pause()


def test_alarm_list(snap_compare) -> None:
    """10621 (self-clearing, ◌) above 10720 (RESET, ⟲), newest first, with date, time and source."""
    nck = StagedKernel()
    nck.staged_alarms = (AUTO_LIMIT, JOG_LIMIT)
    assert snap_compare(stamped(app_on(nck)), terminal_size=SIZE, run_before=lambda p: _open(p))


def test_alarm_log(snap_compare) -> None:
    """Come and go dates and times, newest first; one entry from before the last power on (PO-) below."""
    nck = StagedKernel()
    earlier = AUTO_LIMIT.__class__(**{**{f: getattr(AUTO_LIMIT, f) for f in AUTO_LIMIT.__slots__},
                                      "seq": -1, "came_s": 100.0, "went_s": 130.5})
    went = AUTO_LIMIT.__class__(**{**{f: getattr(AUTO_LIMIT, f) for f in AUTO_LIMIT.__slots__},
                                   "went_s": 9.75})
    nck.staged_history = (earlier, went, JOG_LIMIT)
    assert snap_compare(stamped(app_on(nck)), terminal_size=SIZE, run_before=lambda p: _open(p, "f3"))


def test_messages(snap_compare) -> None:
    """An NC message (MSG) and a pending cycle alarm."""
    nck = StagedKernel()
    nck.staged_message = "Clamp the part, then NC START"
    nck.staged_alarms = (CYCLE_ALARM,)
    assert snap_compare(stamped(app_on(nck)), terminal_size=SIZE, run_before=lambda p: _open(p, "f2"))


def moving() -> StagedKernel:
    nck = StagedKernel()
    nck.staged_moving = True
    return nck


def test_service_overview(snap_compare) -> None:
    assert snap_compare(app_on(moving()), terminal_size=SIZE, run_before=lambda p: _open(p, "f4"))


def test_service_axis_moving(snap_compare) -> None:
    """X at F1000 with Kv = 1: following error 1.000 mm, Kv 1.000."""
    assert snap_compare(app_on(moving()), terminal_size=SIZE, run_before=lambda p: _open(p, "f5"))


def test_service_drive(snap_compare) -> None:
    assert snap_compare(app_on(moving()), terminal_size=SIZE, run_before=lambda p: _open(p, "f6"))


def test_system_utilisation(snap_compare) -> None:
    """Figures from the replaced clock: 1 ms per reading, 25 ticks of 10 IPO cycles (one second
    of control time: the view redraws its figures once a second)."""

    async def run(pilot) -> None:
        await _open(pilot, "f8", "f1")
        for _ in range(25):
            pilot.app.bridge.advance(0.04)
        await pilot.pause()

    assert snap_compare(app_on(StagedKernel()), terminal_size=SIZE, run_before=run)


def test_trace(snap_compare) -> None:
    """A finished recording of X position and following error, cursor moved right."""

    async def run(pilot) -> None:
        await _open(pilot, "f7")
        screen = pilot.app.screen
        screen.trace.slots[1] = "X.following_error"
        screen.trace.trigger = "nc_start"
        screen.trace.duration_s = 2.0
        screen.trace.recorder = staged_trace(pilot.app.bridge.nck.machine)
        pilot.app.bridge.advance(0.004)
        await pilot.pause()
        await pilot.press(*["shift+f8"] * 10)
        await pilot.pause()

    assert snap_compare(app_on(StagedKernel()), terminal_size=SIZE, run_before=run)


def test_logbook(snap_compare) -> None:
    """The logbook after the keyswitch was turned to position 2."""

    async def run(pilot) -> None:
        pilot.app.submit(cmd.SetKeyswitch(2))
        await _open(pilot, "f8", "f3")

    assert snap_compare(stamped(app_on(StagedKernel())), terminal_size=SIZE, run_before=run)


def test_version(snap_compare) -> None:
    assert snap_compare(app_on(StagedKernel()), terminal_size=SIZE, run_before=lambda p: _open(p, "f8", "f2"))
