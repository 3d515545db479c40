"""Operator workflows end to end on the real kernel, driven with exactly the keymap keys.

The kernel is advanced explicitly (``bridge.run_until`` / ``bridge.advance``); no sleeps.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as c
from nck.kernel import Nck

from hmi.app import HmiApp
from hmi.programs import DirectoryPrograms
from tests.hmi.conftest import SIZE

STEP_PROGRAM = "N10 G90 G0 X0 Y0 Z10\nN20 G1 X10 F1000\nN30 Y10\nN40 X0\nN50 M30\n"
LONG_PROGRAM = "N10 G90 G1 X100 F600\nN20 M30\n"


@pytest.fixture
def programs(tmp_path: Path) -> DirectoryPrograms:
    """Two part programs in a temporary directory."""
    (tmp_path / "STEP.MPF").write_text(STEP_PROGRAM)
    (tmp_path / "LONG.MPF").write_text(LONG_PROGRAM)
    return DirectoryPrograms([tmp_path])


def real_app(programs: DirectoryPrograms, referenced: bool = True) -> HmiApp:
    """The HMI on a real kernel (no wall-clock timer)."""
    return HmiApp(Nck(programs=programs, referenced=referenced), realtime=False)


def text_of(app: HmiApp, selector: str) -> str:
    """The rendered text of a widget of the current screen."""
    return str(app.screen.query_one(selector).render())


SETTLE_S = 1.0
"""Time for the position controllers to pull the actual values onto the set points."""

TOL_MM = 0.002
"""Positions are compared to this after settling (the servo model leaves µm of following error)."""


def settle(app: HmiApp, predicate, max_s: float = 60.0):
    """Advance until ``predicate(status)`` holds, then let the axes settle; return the status."""
    app.bridge.run_until(predicate, max_s=max_s)
    return app.bridge.advance(SETTLE_S)


def path_referenced(status) -> bool:
    return all(a.referenced for a in status.axes if a.kind != "spindle")


async def select_in_auto(pilot, name: str) -> None:
    """Keyswitch 1 (program selection allowed), AUTO, F7 Select program, choose ``name``."""
    app = pilot.app
    await pilot.press("alt+t", "alt+u")
    await pilot.pause()
    await pilot.press("f7")
    await pilot.pause()
    names = app.program_names()
    for _ in range(names.index(name)):
        await pilot.press("down")
    await pilot.press("enter")
    await pilot.pause()
    assert app.bridge.status.channel.selected_program.upper().endswith(name)


async def test_reference_all_axes(programs: DirectoryPrograms) -> None:
    """JOG REF: X, Y, Z each with + ; the ○ marks disappear once the axes are referenced."""
    app = real_app(programs, referenced=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert text_of(app, "#positions").count("○") == 3
        await pilot.press("alt+r", "alt+x", "ctrl+right", "alt+y", "ctrl+right", "alt+z", "ctrl+right")
        status = app.bridge.run_until(path_referenced, max_s=60)
        await pilot.pause()
        assert path_referenced(status)
        assert "○" not in text_of(app, "#positions")
        assert "JOG REF" in text_of(app, "#hdr-state")


async def test_mda_block_moves_axes(programs: DirectoryPrograms) -> None:
    """MDA: typing G0 X12.5 Y-7 Z-3 and CYCLE START shows the new positions."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        assert app.focused is app.screen.query_one("#mda-editor")
        await pilot.press(*"G0 X12.5 Y-7 Z-3", "alt+g")
        settle(app, lambda s: s.channel.channel_state == "reset", max_s=30)
        await pilot.pause()
        shown = text_of(app, "#positions")
        for value in ("12.500", "-7.000", "-3.000"):
            assert value in shown
        positions = {a.name: a.position_wcs for a in app.bridge.status.axes}
        assert positions["X"] == pytest.approx(12.5, abs=TOL_MM)
        assert positions["Z"] == pytest.approx(-3, abs=TOL_MM)


async def test_auto_single_block_steps(programs: DirectoryPrograms) -> None:
    """AUTO, select STEP.MPF, Alt+K, each Alt+G runs exactly one block (highlighted)."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await pilot.press("alt+k")
        seen = []
        for _ in range(4):
            await pilot.press("alt+g")
            status = app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=30)
            await pilot.pause()
            assert status.channel.program_state == "stopped"
            seen.append(status.channel.current_block.text.split()[0])
            assert f"▶{status.channel.current_block.text}" in text_of(app, "#auto-blocks")
        assert seen == ["N10", "N20", "N30", "N40"]
        x = {a.name: a.position_wcs for a in app.bridge.advance(SETTLE_S).axes}["X"]
        assert x == pytest.approx(0.0, abs=TOL_MM)
        await pilot.press("alt+g")
        status = app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30)
        assert status.channel.program_state == "aborted"


async def test_nc_stop_and_start_resume(programs: DirectoryPrograms) -> None:
    """NC STOP halts a running block midway; NC START continues it to its end point."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "LONG.MPF")
        await pilot.press("alt+g")
        app.bridge.advance(2.0)
        await pilot.press("alt+h")
        status = settle(app, lambda s: s.channel.channel_state == "interrupted", max_s=5)
        await pilot.pause()
        assert status.channel.program_state == "stopped"
        x_stopped = {a.name: a.position_wcs for a in status.axes}["X"]
        assert 0 < x_stopped < 100
        assert "Program stopped" in text_of(app, "#hdr-state")
        app.bridge.advance(1.0)
        x_later = {a.name: a.position_wcs for a in app.bridge.status.axes}["X"]
        assert x_later == pytest.approx(x_stopped, abs=TOL_MM)
        await pilot.press("alt+g")
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=30)
        assert {a.name: a.position_wcs for a in status.axes}["X"] == pytest.approx(100.0, abs=TOL_MM)


async def test_reset_aborts_program(programs: DirectoryPrograms) -> None:
    """RESET while a program is stopped: channel reset, program aborted."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "LONG.MPF")
        await pilot.press("alt+g")
        app.bridge.advance(1.0)
        await pilot.press("alt+h")
        app.bridge.run_until(lambda s: s.channel.channel_state == "interrupted", max_s=5)
        await pilot.press("alt+q")
        status = app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=5)
        await pilot.pause()
        assert status.channel.program_state == "aborted"
        assert "Channel reset" in text_of(app, "#hdr-state")


async def test_mode_change_refused_while_active(programs: DirectoryPrograms) -> None:
    """JOG while the program runs is refused: mode stays AUTO, the reason is on the dialog line."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "LONG.MPF")
        await pilot.press("alt+g")
        app.bridge.advance(0.5)
        await pilot.press("alt+j")
        await pilot.pause()
        assert app.bridge.status.channel.mode == "AUTO"
        assert app.bridge.status.channel.channel_state == "active"
        assert text_of(app, "#dialog-line").strip() != ""


async def test_alarm_line_shows_start_refusal(programs: DirectoryPrograms) -> None:
    """NC START with unreferenced axes: alarm 10203 appears on the alarm line."""
    app = real_app(programs, referenced=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", *"G0 X1", "alt+g")
        app.bridge.advance(0.1)
        await pilot.pause()
        assert "10203" in text_of(app, "#hdr-alarm") + text_of(app, "#dialog-line")
        assert app.bridge.status.channel.channel_state != "active"


async def test_keyswitch_changes_level_on_kernel(programs: DirectoryPrograms) -> None:
    """Alt+T: level 7 → 6; program selection (level 6) becomes possible."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+u")
        await pilot.pause()
        assert app.screen.query_one("#sk-h7").has_class("-disabled")
        await pilot.press("alt+t")
        await pilot.pause()
        assert app.bridge.status.access_level == 6
        assert "Level 6" in text_of(app, "#hdr-state")
        assert not app.screen.query_one("#sk-h7").has_class("-disabled")


async def test_jog_increment_moves_one_increment(programs: DirectoryPrograms) -> None:
    """JOG INC 100: one Ctrl+Right moves the selected axis by 0.100 mm."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+i", "alt+i", "alt+i", "alt+y", "ctrl+right")
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=10)
        await pilot.pause()
        assert "INC 100" in text_of(app, "#hdr-state")
        assert {a.name: a.position_mcs for a in status.axes}["Y"] == pytest.approx(0.1, abs=TOL_MM)


async def test_continuous_jog_stops_on_release(programs: DirectoryPrograms) -> None:
    """Continuous JOG: the axis moves while the key is held and stops when let go."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+x", "ctrl+left")
        app.bridge.advance(0.5)
        app.release_jog()
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=10)
        x = {a.name: a.position_mcs for a in status.axes}["X"]
        assert x < -1.0
        app.bridge.advance(1.0)
        assert {a.name: a.position_mcs for a in app.bridge.status.axes}["X"] == pytest.approx(x, abs=TOL_MM)


async def test_block_search_then_continue(programs: DirectoryPrograms) -> None:
    """Block search to N30, NC START (alarm 10208 shown), NC START again runs from N30 to the end."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await pilot.press("f5")
        await pilot.pause()
        assert app.focused is app.screen.query_one("#search-input")
        await pilot.press("N", "3", "0", "enter")
        app.bridge.run_until(lambda s: s.channel.stop_reason != "", max_s=5)
        await pilot.press("alt+g")
        status = app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=10)
        await pilot.pause()
        assert [a.number for a in status.alarms] == [10208]
        assert "10208" in text_of(app, "#hdr-alarm")
        assert "▶N30 Y10" in text_of(app, "#auto-blocks")
        await pilot.press("alt+g")
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=10)
        positions = {a.name: a.position_wcs for a in status.axes}
        assert positions["Y"] == pytest.approx(10.0, abs=TOL_MM)
        assert positions["X"] == pytest.approx(0.0, abs=TOL_MM)


def test_cli_bad_machine_is_a_message(capsys) -> None:
    """hmi --machine with an unknown machine prints a clear message and exits 2 (no traceback)."""
    from hmi.app import main

    assert main(["--machine", "no_such_machine", "--ephemeral"]) == 2
    err = capsys.readouterr().err
    assert "no_such_machine" in err and "Traceback" not in err


async def test_stop_jog_away_and_repos_back(programs: DirectoryPrograms) -> None:
    """NC STOP, JOG Y away by 1 mm (INC 1000), REPOS view shows the way back; AUTO + NC START ends on the path."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "LONG.MPF")
        await pilot.press("alt+g")
        app.bridge.advance(2.0)
        await pilot.press("alt+h")
        app.bridge.run_until(lambda s: s.channel.channel_state == "interrupted", max_s=5)
        await pilot.press("alt+j", "alt+i", "alt+i", "alt+i", "alt+i", "alt+y", "ctrl+right")
        status = app.bridge.run_until(
            lambda s: {a.name: a.position_wcs for a in s.axes}["Y"] > 0.999
            and s.channel.channel_state != "active", max_s=10)
        status = app.bridge.advance(SETTLE_S)
        assert {a.name: a.position_wcs for a in status.axes}["Y"] == pytest.approx(1.0, abs=TOL_MM)
        await pilot.press("alt+e")
        await pilot.pause()
        assert "REPOS" in text_of(app, "#hdr-state")
        assert "-1.000" in text_of(app, "#jog-info")
        await pilot.press("alt+u", "alt+g")
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=60)
        positions = {a.name: a.position_wcs for a in status.axes}
        assert positions["X"] == pytest.approx(100.0, abs=TOL_MM)
        assert positions["Y"] == pytest.approx(0.0, abs=TOL_MM)


async def test_rapid_overlay_reaches_the_kernel(programs: DirectoryPrograms) -> None:
    """Alt+W switches the rapid overlay on: continuous JOG then moves faster."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+x", "ctrl+right")
        app.bridge.advance(0.3)
        app.release_jog()
        slow = app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=5)
        slow_x = {a.name: a.position_mcs for a in slow.axes}["X"]
        await pilot.press("alt+w", "ctrl+right")
        await pilot.pause()
        assert "Rapid overlay: ON" in text_of(app, "#jog-info")
        app.bridge.advance(0.3)
        app.release_jog()
        fast = app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=5)
        assert {a.name: a.position_mcs for a in fast.axes}["X"] - slow_x > 1.5 * slow_x


async def test_emergency_stop_and_reset(programs: DirectoryPrograms) -> None:
    """Alt+L presses E-stop (alarm 3000, header says so); release + RESET clears it; axes stay referenced."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+l")
        app.bridge.advance(0.1)
        await pilot.pause()
        assert app.bridge.status.emergency_stop
        assert "EMERGENCY STOP" in text_of(app, "#hdr-state")
        assert 3000 in [a.number for a in app.bridge.status.alarms]
        await pilot.press("alt+l", "alt+q")
        status = app.bridge.run_until(lambda s: not s.emergency_stop, max_s=2)
        await pilot.pause()
        assert 3000 not in [a.number for a in status.alarms]
        assert "EMERGENCY STOP" not in text_of(app, "#hdr-state")
        assert all(a.referenced for a in status.axes)


async def test_keyswitch_cycles_under_a_password(programs: DirectoryPrograms) -> None:
    """With a password set (level 2) the keyswitch still turns 0 → 1 → 2 …; deleting it shows the switch's level."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        app.submit(c.EnterPassword("EVENING"))
        await pilot.press("alt+t", "alt+t")
        app.submit(c.DeletePassword())
        await pilot.pause()
        assert app.bridge.status.access_level == 5


async def test_times_counter_softkeys_write_part_counters(programs: DirectoryPrograms) -> None:
    """Times/Counter: ⇧F2 asks for the required parts (written to the kernel), ⇧F1 resets the part count."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("f6", "shift+f2")
        await pilot.pause()
        assert app.focused is app.screen.query_one("#value-input")
        await pilot.press("2", "5", "enter")  # the old value is selected: typing replaces it
        await pilot.pause()
        assert app.bridge.status.channel.parts_required == 25
        assert "Required parts           25" in text_of(app, "#times-table")
        app.submit(c.WriteData("$AC_ACTUAL_PARTS", 7))
        await pilot.press("shift+f1")
        await pilot.pause()
        assert app.bridge.status.channel.part_count == 0
