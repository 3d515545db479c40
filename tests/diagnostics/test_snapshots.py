"""SVG snapshots of every Diagnostics view (real kernel and motion, 160×48, no clock, no blink).

The kernel is deterministic (simulated time only); the system utilisation view
measures wall time, so its clock is replaced by one that advances 1 ms per call.
"""

from __future__ import annotations

import itertools

import pytest

from nck import commands as cmd
from screens import diagnostics_service
from tests.diagnostics.conftest import SIZE, app_on, kernel, kv1_machine


@pytest.fixture(autouse=True)
def fake_clock(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every reading of the wall clock is 1 ms after the previous one."""
    ticks = itertools.count()
    monkeypatch.setattr(diagnostics_service, "CLOCK", lambda: next(ticks) * 0.001)


def limit_alarms_app():
    """JOG at the X software limit (10621) after an AUTO run into it (10720, still pending)."""
    nck = kernel()
    for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("LIMIT.MPF"), cmd.CycleStart()):
        nck.submit(command)
    nck.tick(1.0)
    nck.submit(cmd.SelectMode("JOG"))
    nck.submit(cmd.SelectIncrement(10000))
    for _ in range(2):
        nck.submit(cmd.Jog("X", 1))
        nck.tick(0.05)
        nck.submit(cmd.Jog("X", 0))
        nck.tick(3.0)
    return app_on(nck)


def moving_app():
    """FEED.MPF on the Kv = 1 machine, X moving at F1000 (1 mm following error)."""
    nck = kernel(kv1_machine())
    for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("FEED.MPF"), cmd.CycleStart()):
        nck.submit(command)
    nck.run_until(lambda k: k.positions_mcs()["X"] < -99.9, 30.0)
    nck.run_until(lambda k: k.positions_mcs()["X"] > -80.0, 30.0)
    return app_on(nck)


async def _open(pilot, *keys: str) -> None:
    await pilot.press("alt+a", *keys)
    await pilot.pause()


def test_alarm_list(snap_compare) -> None:
    """10621 (self-clearing, ◌) above 10720 (RESET, ⟲), newest first, with their sources."""
    assert snap_compare(limit_alarms_app(), terminal_size=SIZE, run_before=lambda p: _open(p))


def test_alarm_log_after_reset(snap_compare) -> None:
    """After RESET: both alarms with come and go times in the log."""

    async def run(pilot) -> None:
        pilot.app.submit(cmd.Reset())
        pilot.app.submit(cmd.Jog("X", -1))
        pilot.app.bridge.advance(0.05)
        pilot.app.submit(cmd.Jog("X", 0))
        pilot.app.bridge.advance(2.0)
        await _open(pilot, "f3")

    assert snap_compare(limit_alarms_app(), terminal_size=SIZE, run_before=run)


def test_messages(snap_compare) -> None:
    """The MSG text of the program stopped at M0."""
    nck = kernel()
    for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("MSG.MPF"), cmd.CycleStart()):
        nck.submit(command)
    nck.tick(0.5)
    assert snap_compare(app_on(nck), terminal_size=SIZE, run_before=lambda p: _open(p, "f2"))


def test_service_overview(snap_compare) -> None:
    assert snap_compare(moving_app(), terminal_size=SIZE, run_before=lambda p: _open(p, "f4"))


def test_service_axis_moving(snap_compare) -> None:
    """X at F1000 with Kv = 1: following error 1.000 mm, Kv 1.000."""
    assert snap_compare(moving_app(), terminal_size=SIZE, run_before=lambda p: _open(p, "f5"))


def test_service_drive(snap_compare) -> None:
    assert snap_compare(moving_app(), terminal_size=SIZE, run_before=lambda p: _open(p, "f6"))


def test_system_utilisation(snap_compare) -> None:
    """Figures from the replaced clock: 1 ms per tick call."""

    async def run(pilot) -> None:
        await _open(pilot, "f8", "f1")
        for _ in range(10):
            pilot.app.bridge.advance(0.04)
        await pilot.pause()

    assert snap_compare(moving_app(), terminal_size=SIZE, run_before=run)


def test_trace_of_x(snap_compare) -> None:
    """X position and following error recorded from NC START over TRACE.MPF, cursor moved right."""
    nck = kernel()

    async def run(pilot) -> None:
        await _open(pilot, "f7")
        await pilot.press("shift+f1", "shift+f2", "shift+f2", "shift+f2")  # slot 2: X.following_error
        await pilot.press("shift+f3", "shift+f4", "shift+f5")  # on NC START, 10 s, start
        for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("TRACE.MPF"), cmd.CycleStart()):
            pilot.app.submit(command)
        pilot.app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30.0)
        pilot.app.bridge.advance(0.01)
        await pilot.pause()
        await pilot.press(*["shift+f8"] * 10)
        await pilot.pause()

    assert snap_compare(app_on(nck), terminal_size=SIZE, run_before=run)


def test_version_and_logbook(snap_compare) -> None:
    """The logbook after the keyswitch was turned to position 2."""

    async def run(pilot) -> None:
        pilot.app.submit(cmd.SetKeyswitch(2))
        await _open(pilot, "f8", "f3")

    assert snap_compare(app_on(kernel()), terminal_size=SIZE, run_before=run)


def test_version(snap_compare) -> None:
    assert snap_compare(app_on(kernel()), terminal_size=SIZE, run_before=lambda p: _open(p, "f8", "f2"))
