"""Values on the Machine screen are what the machine does (issue 18, "Values on screen")."""

from __future__ import annotations

import pytest

from dataclasses import replace

from hmi.app import HmiApp
from hmi.widgets.positions import position_lines
from hmi.widgets.tfs import tfs_lines
from nck.number_text import fixed, trimmed
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck
from tests.hmi.test_machine_area import screen_text


def test_fixed_and_trimmed_never_show_a_negative_zero() -> None:
    """A value that rounds to zero at the shown precision has no sign; others keep theirs."""
    assert fixed(-0.0004) == "0.000"
    assert fixed(-0.0) == "0.000"
    assert fixed(-0.2, 0, 6) == "     0"
    assert fixed(-0.0006) == "-0.001"
    assert fixed(-2.5, 1) == "-2.5"
    assert trimmed(-0.0) == "0" and trimmed(-1e-9) == "0" and trimmed(-1.25) == "-1.25"


def test_position_and_tfs_windows_show_no_negative_zero() -> None:
    """Positions, distance to go, spindle speed, feed and tool values near zero from below."""
    status = FakeNck(referenced=True).status()
    axes = tuple(replace(a, position_mcs=-0.0004, position_wcs=-0.0004, distance_to_go=-0.0001,
                         speed_rpm=-0.2 if a.kind == "spindle" else 0.0) for a in status.axes)
    modal = replace(status.channel.modal, spindle_speed_rpm=-0.0, feed=-0.0,
                    tool_length_mm=-0.0, tool_radius_mm=-0.0)
    status = replace(status, axes=axes, channel=replace(status.channel, modal=modal,
                                                        path_feed_mm_min=-0.0001))
    shown = str(position_lines(status, False, None)) + str(position_lines(status, True, None))
    shown += str(tfs_lines(status))
    assert "-0" not in shown
    assert "0.000" in shown and " 0 rpm" in shown


async def test_machine_screen_shows_no_negative_zero() -> None:
    """The whole JOG screen with an axis standing a hair below zero."""
    fake = FakeNck(referenced=True)
    fake.pos["X"] = -0.0002
    fake.spindle_rpm = -0.3
    app = HmiApp(fake, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert "-0.000" not in screen_text(app) and "-0 " not in screen_text(app)
        await pilot.press("f1")  # MCS
        await pilot.pause()
        assert "-0.000" not in screen_text(app)
        for window in ("shift+f2", "shift+f1", "shift+f6"):  # Set WO, T,S,M, Settings
            await pilot.press(window)
            await pilot.pause()
            assert "-0.000" not in screen_text(app) and "-0 " not in screen_text(app), window


async def test_tfs_window_shows_tool_once_and_the_edge_size_with_wear(tmp_path) -> None:
    """T1 D1 active after MDA `T1 M6 D1`: the T,F,S window names the tool once (not `T T1`)
    and shows L = 120 - 0.2 and R = 5 + 0.01 (002 L58785-58787, L58800-58802)."""
    from nck.kernel import Nck
    from nck.ncdata import ToolEdge
    from nck.interp.sources import MemorySource

    nck = Nck(programs=MemorySource({}), referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0, 12: -0.2, 15: 0.01})
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", *"T1 M6 D1", "alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=10)
        await pilot.pause()
        shown = str(app.screen.query_one("#tfs").render())
        first, second = shown.splitlines()[:2]
        assert first.split() == ["T1", "D1"]
        assert second.split() == ["L", "119.800", "R", "5.010"]


def tfs_feed_line(app: HmiApp) -> list[str]:
    """The words of the F line of the T,F,S window."""
    shown = str(app.screen.query_one("#tfs").render())
    return next(line for line in shown.splitlines() if line.split()[:1] == ["F"]).split()


async def test_tfs_actual_feed_is_the_path_velocity_with_override_and_zero_after_stop() -> None:
    """MDA `G1 X300 F1000`, feed override switch down eight positions (100, 95, 90, 85, 80, 75,
    70, 60, 50 %: the keymap's steps): the actual feed reads 1000 × 50 % = 500 mm/min (002 L56305-56307), the
    programmed 1000; after NC STOP, once the axes stand, 0. Keys sent as one burst."""
    from nck.kernel import Nck
    from nck.interp.sources import MemorySource

    nck = Nck(programs=MemorySource({}), referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", *"G1 X300 F1000", "alt+g", *["ctrl+down"] * 8)
        app.bridge.advance(2.0)
        await pilot.pause()
        assert nck.status().channel.overrides["feed"] == 50.0
        assert tfs_feed_line(app)[:5] == ["F", "500.000", "/", "1000.000", "mm/min"]
        await pilot.press("alt+h")
        app.bridge.advance(0.5)
        await pilot.pause()
        assert tfs_feed_line(app)[:5] == ["F", "0.000", "/", "1000.000", "mm/min"]


@pytest.mark.parametrize("feed_type", ["G95", "G96", "G97"])
def test_tfs_feed_per_revolution_names_both_units(feed_type) -> None:
    """G95, and G96/G97 "as with G95" (001 L2584, 002 L5773): the programmed F is per
    revolution, the actual path velocity per minute (0.25 mm/rev at 1000 rpm = 250 mm/min,
    002 L55411-55420): each value carries its unit."""
    status = FakeNck(referenced=True).status()
    modal = replace(status.channel.modal, gcodes={**status.channel.modal.gcodes, 15: feed_type}, feed=0.25)
    status = replace(status, channel=replace(status.channel, modal=modal, path_feed_mm_min=250.0))
    line = next(row for row in str(tfs_lines(status)).splitlines() if row.split()[:1] == ["F"])
    assert line.split()[:6] == ["F", "250.000", "mm/min", "/", "0.250", "mm/rev"]


def test_tfs_feed_under_g961_stays_per_minute() -> None:
    """G961: constant cutting rate with a linear feed (002 L19676 lists it apart from the
    revolutional G95/G96/G97): F is shown in mm/min."""
    status = FakeNck(referenced=True).status()
    modal = replace(status.channel.modal, gcodes={**status.channel.modal.gcodes, 15: "G961"}, feed=200.0)
    status = replace(status, channel=replace(status.channel, modal=modal, path_feed_mm_min=200.0))
    line = next(row for row in str(tfs_lines(status)).splitlines() if row.split()[:1] == ["F"])
    assert line.split()[:5] == ["F", "200.000", "/", "200.000", "mm/min"]


async def test_tfs_window_shows_a_tool_waiting_for_m6() -> None:
    """Mill (MD22550 = 1): MDA `T1 D1` leaves T0 in the spindle and T1 preselected (002
    L57620-57625, L57649-57651); the T,F,S window says so, and after `M6` shows T1 with its
    length."""
    from nck.kernel import Nck
    from nck.ncdata import ToolEdge
    from nck.interp.sources import MemorySource

    nck = Nck(programs=MemorySource({}), referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0})
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", *"T1 D1", "enter", *"M0", "enter", *"M6", "alt+g")
        app.bridge.run_until(lambda s: s.channel.program_state == "stopped", max_s=10)
        await pilot.pause()
        first = str(app.screen.query_one("#tfs").render()).splitlines()[0]
        assert first.split() == ["no", "tool", "D1", "T1", "preselected"]
        await pilot.press("alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=10)
        await pilot.pause()
        first, second = str(app.screen.query_one("#tfs").render()).splitlines()[:2]
        assert first.split() == ["T1", "D1"] and second.split()[1] == "120.000"


async def test_tfs_window_says_when_a_speed_limit_clamps_the_spindle() -> None:
    """MDA `G26 S500` then `S1000 M3`: G26 is never exceeded (002 L55616-55621), the spindle
    turns at 500 and the T,F,S window says "setpoint speed limited" (DB31 DBX83.1, 002
    L54541-54543) instead of clamping silently; `S400` lifts the message."""
    from nck.kernel import Nck
    from nck.interp.sources import MemorySource

    nck = Nck(programs=MemorySource({}), referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", *"G26 S500", "enter", *"S1000 M3", "alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=10)
        app.bridge.advance(3.0)
        await pilot.pause()
        lines = str(app.screen.query_one("#tfs").render()).splitlines()
        s_line = next(i for i, line in enumerate(lines) if line.split()[:1] == ["S1"])
        assert lines[s_line].split()[:5] == ["S1", "500", "/", "1000", "rpm"]
        assert lines[s_line + 1].strip() == "setpoint speed limited"
        await pilot.press("shift+f1", *"S400", "alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=10)
        app.bridge.advance(3.0)
        await pilot.pause()
        assert "limited" not in str(app.screen.query_one("#tfs").render())
