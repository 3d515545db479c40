"""Workflows in the Parameter and Setup areas on the real kernel and a real NC data directory."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as c

from tests.parameter_setup.conftest import SIZE, fill, trainer


async def type_text(pilot, text: str) -> None:
    """Type ``text`` into the focused field."""
    for char in text:
        await pilot.press(char if char != " " else "space")


async def enter_password(pilot, password: str) -> None:
    """Setup → Password → Set password."""
    await pilot.press("alt+s", "f6", "shift+f1")
    await pilot.pause()
    await type_text(pilot, password)
    await pilot.press("enter")
    await pilot.pause()


def md_row(app, name: str) -> str:
    """The line of the MD list that shows ``name``."""
    lines = app.screen.query_one("#setup-table").render().plain.splitlines()
    return next(line for line in lines if f" {name} " in line)


def dialog_open(app) -> bool:
    return type(app.screen).__name__ in ("ValueDialog", "ConfirmDialog")


async def test_keyswitch_0_cannot_change_a_work_offset_customer_can(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+o", "f3", "down", "enter")  # overview, row G54, column X
        await pilot.pause()
        assert app.bridge.status.access_level == 7
        assert not dialog_open(app)
        assert "needs access level 6" in app.screen.query_one("#dialog-line").render().plain
        assert app.bridge.nck.data.settable_frames["G54"].trans.get("X", 0.0) == 0.0
        # the command itself is refused as well, naming the level
        result = app.submit(c.WriteData("$P_UIFR[1,X,TR]", 5))
        assert isinstance(result, c.Rejected) and "level 6" in result.reason

        await enter_password(pilot, "CUSTOMER")
        assert app.bridge.status.access_level == 3
        await pilot.press("alt+o", "enter")
        await pilot.pause()
        assert dialog_open(app)
        await pilot.press("ctrl+u")
        await type_text(pilot, "-123.4")
        await pilot.press("enter")
        await pilot.pause()
        assert app.bridge.nck.data.settable_frames["G54"].trans["X"] == -123.4
        assert "-123.400" in app.screen.query_one("#param-table").render().plain


async def test_evening_changes_md32000_and_it_limits_the_axis_after_set_md_active(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+s", "f3", "shift+f1")
        await type_text(pilot, "32000")
        await pilot.press("enter")
        await pilot.pause()
        await pilot.press("enter")  # edit MAX_AX_VELO of X at level 7: refused in the HMI
        await pilot.pause()
        assert not dialog_open(app)
        assert "needs access level 2" in app.screen.query_one("#dialog-line").render().plain

        await enter_password(pilot, "EVENING")
        await pilot.press("f3", "enter")
        await pilot.pause()
        assert dialog_open(app)
        await pilot.press("ctrl+u")
        await type_text(pilot, "1200")
        await pilot.press("enter")
        await pilot.pause()
        row = md_row(app, "MAX_AX_VELO")
        assert "1200" in row and row.rstrip().endswith("*")  # stored, not active yet
        assert app.bridge.nck.machine.md_value("MD32000", "X", None) != 1200

        await pilot.press("f7")  # Set MD active (cf)
        await pilot.pause()
        assert app.bridge.nck.machine.md_value("MD32000", "X", None) == 1200
        assert not md_row(app, "MAX_AX_VELO").rstrip().endswith("*")

        nck = app.bridge.nck
        nck.motion.set_referenced("X", True)
        for axis in nck.machine.path_axes:
            nck.motion.set_referenced(axis, True)
        app.submit(c.SelectMode("MDA"))
        app.submit(c.SetMdaProgram("G0 X100"))
        assert app.submit(c.CycleStart()) == c.Accepted()
        start = nck.time_s
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30, dt_s=0.05)
        assert nck.positions_mcs()["X"] == pytest.approx(100.0, abs=1e-3)
        assert nck.time_s - start == pytest.approx(100 / 1200 * 60, rel=0.05)


async def test_power_on_data_take_effect_only_after_reset_po(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await enter_password(pilot, "SUNRISE")
        app.submit(c.WriteData("MD28050", 50))  # MM_NUM_R_PARAM, power on
        await pilot.press("alt+q")  # RESET does not activate po data
        await pilot.pause()
        assert len(app.bridge.nck.data.r) == 100
        await pilot.press("alt+s", "f8")
        await pilot.pause()
        assert dialog_open(app)
        await pilot.press("y")
        await pilot.pause()
        assert len(app.bridge.nck.data.r) == 50
        assert app.bridge.status.access_level == 1  # the password survives power off/on
        await pilot.press("alt+o", "f4")
        await pilot.pause()
        assert "of 50" in app.screen.query_one("#param-table").render().plain


async def test_tools_are_created_edited_and_survive_a_restart(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+t", "alt+t", "alt+t")  # keyswitch position 3: level 4
        await pilot.press("alt+o", "shift+f1")
        await pilot.pause()
        await type_text(pilot, "5 200")
        await pilot.press("enter")
        await pilot.pause()
        assert app.bridge.nck.data.tools[(5, 1)].tool_type == 200
        await pilot.press("right", "enter")  # Length 1
        await pilot.pause()
        await pilot.press("ctrl+u")
        await type_text(pilot, "95.5")
        await pilot.press("enter", "shift+f2")  # and a second edge
        await pilot.pause()
        assert app.bridge.nck.data.tools[(5, 1)].get(3) == 95.5
        assert (5, 2) in app.bridge.nck.data.tools
        await pilot.press("f2", "left", "left", "left", "enter")  # wear: ΔLength 1 of T5 D2
        await pilot.pause()
        await pilot.press("ctrl+u")
        await type_text(pilot, "-0.05")
        await pilot.press("enter")
        await pilot.pause()
        assert app.bridge.nck.data.tools[(5, 2)].get(12) == -0.05
        await pilot.press("ctrl+q")
    again = trainer(tmp_path)
    async with again.run_test(size=SIZE) as pilot:
        data = again.bridge.nck.data
        assert data.tools[(5, 1)].get(3) == 95.5 and data.tools[(5, 2)].get(12) == -0.05
        assert again.bridge.status.access_level == 4  # the keyswitch position is retained


async def test_refused_values_and_clear_all_r_parameters(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+t", "alt+t")  # level 5
        await pilot.press("alt+o", "f3", "down", "right", "right", "right", "right", "enter")  # G54 rot X
        await pilot.pause()
        await pilot.press("ctrl+u")
        await type_text(pilot, "400")
        await pilot.press("enter")
        await pilot.pause()
        assert "rotation outside" in app.screen.query_one("#dialog-line").render().plain
        assert app.bridge.nck.data.settable_frames["G54"].rot.get("X", 0.0) == 0.0
        await pilot.press("f4", "shift+f1")
        await pilot.pause()
        await pilot.press("n")  # asked first: no
        await pilot.pause()
        assert app.bridge.nck.data.r[1] == 12.5
        await pilot.press("shift+f1", "y")
        await pilot.pause()
        assert set(app.bridge.nck.data.r) == {0.0}


async def test_user_variables_and_setting_data(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+t", "alt+t", "alt+t")  # level 4
        await pilot.press("alt+o", "f5", "enter")  # COUNT (INT)
        await pilot.pause()
        await pilot.press("ctrl+u")
        await type_text(pilot, "2.5")
        await pilot.press("enter")
        await pilot.pause()
        assert "whole number" in app.screen.query_one("#dialog-line").render().plain
        assert app.bridge.nck.data.gud["COUNT"] == 3
        await pilot.press("f6")
        for _ in range(10):
            await pilot.press("down")  # SD42100 DRY_RUN_FEED (after JOG 3, spindle 3, work area 12 rows)
        app.screen.cursors["sd"].row = 18
        await pilot.press("enter")
        await pilot.pause()
        assert "DRY_RUN_FEED" in app.screen.query_one("#value-hint").render().plain
        await pilot.press("ctrl+u")
        await type_text(pilot, "1500")
        await pilot.press("enter")
        await pilot.pause()
        assert app.bridge.nck.data.setting_data["SD42100"] == 1500.0


async def test_password_change_and_delete(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await enter_password(pilot, "CUSTOMER")
        await pilot.press("shift+f2")
        await pilot.pause()
        await pilot.press("enter")  # level 3 proposed
        await type_text(pilot, "MYPASS")
        await pilot.press("enter")
        await type_text(pilot, "MYPASS")
        await pilot.press("enter")
        await pilot.pause()
        assert "New password for level 3" in app.screen.query_one("#dialog-line").render().plain
        await pilot.press("shift+f3")
        await pilot.pause()
        assert app.bridge.status.access_level == 7
        assert "7 — keyswitch position 0" in app.screen.query_one("#setup-access").render().plain
        assert isinstance(app.submit(c.EnterPassword("CUSTOMER")), c.Rejected)
        later_s = app.bridge.clock() + 1.0  # the panel waits 1 s after one wrong password
        app.bridge.clock = lambda: later_s
        await enter_password(pilot, "MYPASS")
        assert app.bridge.status.access_level == 3


async def test_reading_tools_needs_the_read_level(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await enter_password(pilot, "EVENING")
        app.submit(c.WriteData("MD9200", 5))  # USER_CLASS_READ_TOA, takes effect at once
        app.submit(c.DeletePassword())
        await pilot.press("alt+o", "f1")
        await pilot.pause()
        text = app.screen.query_one("#param-table").render().plain
        assert "Reading tool offsets needs access level 5" in text and "Twist drill" not in text
        await pilot.press("alt+t", "alt+t", "f1")
        await pilot.pause()
        assert "Twist drill" in app.screen.query_one("#param-table").render().plain


async def test_a_truncated_data_file_at_start_gives_the_alarm_and_the_backup(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+t", "alt+t", "alt+t")  # level 4
        app.submit(c.WriteData("$TC_DP3[3,1]", 50))
        app.submit(c.WriteData("$TC_DP3[3,1]", 60))  # the second save keeps the first as backup
        app.submit(c.WriteData("R2", 7))
        await pilot.press("ctrl+q")
    tools_file = tmp_path / "retained" / "tools.json"
    tools_file.write_bytes(tools_file.read_bytes()[:40])
    again = trainer(tmp_path)
    async with again.run_test(size=SIZE) as pilot:
        await pilot.pause()
        alarms = again.bridge.status.alarms
        assert [a.number for a in alarms] == [4065] and "tools.json" in alarms[0].text
        data = again.bridge.nck.data
        assert data.tools[(3, 1)].get(3) == 50.0  # the backup generation
        assert data.r[2] == 7.0  # nothing else lost
        assert list((tmp_path / "retained").glob("tools.json.bad-*"))


async def test_mda_buffer_and_part_counters_survive_a_restart(tmp_path: Path) -> None:
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE):
        app.submit(c.SetMdaProgram("G0 X10\nM30"))
        app.submit(c.WriteData("$AC_TOTAL_PARTS", 17))
        app.submit(c.WriteData("$AC_REQUIRED_PARTS", 40))
    app.action_quit_hmi()
    again = trainer(tmp_path)
    async with again.run_test(size=SIZE):
        channel = again.bridge.status.channel
        assert channel.mda_text == "G0 X10\nM30"
        assert (channel.parts_total, channel.parts_required) == (17, 40)


async def test_areas_on_a_kernel_without_nc_data_do_not_break() -> None:
    from hmi.app import HmiApp
    from tests.hmi.fake_nck import FakeNck

    app = HmiApp(FakeNck(), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+o", "f4", "enter", "alt+s", "f3", "enter", "f7", "f6", "f8", "y")
        await pilot.pause()
        assert "needs the NC data directory" in app.hint
        assert app.internal_errors == []


async def test_reset_po_keeps_the_override_switch_positions(tmp_path: Path) -> None:
    """The override switches are on the machine control panel: an NCK restart does not turn
    them, so after Reset (po) the new NCK reads the positions the switches stand in."""
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+down", "ctrl+down", "ctrl+pagedown")  # switches turned down
        await pilot.pause()
        before = dict(app.bridge.status.channel.overrides)
        assert before["feed"] < 100.0 and before["spindle"] < 100.0
        assert app.power_on_reset()  # Setup → Reset (po) → yes
        await pilot.pause()
        after = app.bridge.status.channel.overrides
        assert after["feed"] == before["feed"] and after["spindle"] == before["spindle"]
        await pilot.press("ctrl+up")  # the switch moves on from where it stands
        await pilot.pause()
        assert app.bridge.status.channel.overrides["feed"] > before["feed"]
