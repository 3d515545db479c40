"""Set WO, Position and Settings windows of JOG (issue 22).

Set WO: the WCS actual value of an axis becomes the value asked for by shifting the
active offset: WCS = MCS − offset (translation only, no tool active), so offset =
MCS − wanted; under G500 the system frame for PRESET and scratching takes it
(002 L28641, L28667). Expected values are that arithmetic on the machine position
set up by hand, not numbers read from the kernel.
"""

from __future__ import annotations

from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst
from tests.jog_setup.kernels import run_in_mda_then_jog
from tests.hmi.test_machine_area import screen_text
from tests.jog_setup.test_tsm_window import run_job

SIZE = (160, 48)


def kernel_at(x: float, y: float, z: float) -> Nck:
    """A referenced mill standing at (x, y, z) MCS, in JOG."""
    return run_in_mda_then_jog(Nck(referenced=True), f"G0 X{x} Y{y} Z{z}\n", max_ticks=2000)


def wcs(app: HmiApp) -> dict[str, float]:
    """The WCS actual values of the path axes."""
    return {a.name: a.position_wcs for a in app.bridge.status.axes if a.kind != "spindle"}


async def test_set_wo_x_zero_typed_y_and_delete_active() -> None:
    """⇧F2 Set WO, ⇧F1 X=0: WCS X 0.000, $P_SETFR X = −125.35 (G500 active); Y typed 10:
    42 − 10 = 32; ⇧F6 delete active WO: WCS = MCS again. Each shown at once."""
    app = HmiApp(kernel_at(-125.35, 42.0, 100.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f2")
        assert app.screen.query_one("#mach-views").current == "view-setwo"
        await burst(pilot, "shift+f1")
        assert abs(wcs(app)["X"] - 0.0) < 1e-6
        assert abs(app.bridge.nck.data.setframe.trans["X"] - (-125.35)) < 1e-6
        assert abs(wcs(app)["Y"] - 42.0) < 1e-6
        assert "X 0.000" in str(app.screen.query_one("#view-setwo-info").render())
        await burst(pilot, "down", "1", "0", "shift+f5")
        assert abs(wcs(app)["Y"] - 10.0) < 1e-6
        assert abs(app.bridge.nck.data.setframe.trans["Y"] - 32.0) < 1e-6
        assert "Y 10.000" in str(app.screen.query_one("#view-setwo-info").render())
        assert app.screen.query_one("#view-setwo-Y").value == ""
        await burst(pilot, "shift+f6")
        assert wcs(app) == {"X": -125.35, "Y": 42.0, "Z": 100.0}
        assert app.screen.query_one("#mach-views").current == "view-setwo"


async def test_set_wo_shows_in_the_active_work_offset_screen() -> None:
    """After X=0 and Y=0 under G500 the Parameter area's active chain (F3 Work offset, ⇧F1
    Active) shows $P_SETFR X −125.350 Y 42.000 (MCS − 0), and the total offset X 125.350 away."""
    app = HmiApp(kernel_at(-125.35, 42.0, 100.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f2", "shift+f1", "shift+f2", "alt+o", "f3", "shift+f1")
        text = screen_text(app)
        row = next(line for line in text.splitlines() if "$P_SETFR" in line)
        assert row.split()[-3:] == ["-125.350", "42.000", "0.000"], row


async def test_set_wo_in_one_burst_with_keymap_keys_between() -> None:
    """Set WO, Y typed 5 with axis and override keys pressed in the field: the field keeps
    only 5, and only Y is set (WCS Y 5, X unchanged 10)."""
    app = HmiApp(kernel_at(10.0, 20.0, 30.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f2", "down", "alt+x", "5", "ctrl+up", "alt+z", "ctrl+down")
        assert app.screen.query_one("#view-setwo-Y").value == "5"
        await burst(pilot, "shift+f5")
        assert abs(wcs(app)["Y"] - 5.0) < 1e-6
        assert abs(wcs(app)["X"] - 10.0) < 1e-6


async def test_position_window_traverses_one_axis_at_the_feed() -> None:
    """Position: Y to 25 at F 2000 (G1); the axis ends at 25 in the WCS; back in JOG."""
    app = HmiApp(kernel_at(0.0, 0.0, 0.0), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f5", "right", "down", "2", "5", "down", "ctrl+a", "ctrl+k", "2", "0", "0", "0")
        await burst(pilot, "alt+g")
        assert app.bridge.status.channel.mode == "MDA"
        run_job(app)
        await burst(pilot)
        assert app.bridge.status.channel.mode == "JOG"
        assert abs(wcs(app)["Y"] - 25.0) < 1e-6
        assert app.screen.query_one("#mach-views").current == "view-position"


async def test_settings_write_jog_feed_and_variable_increment() -> None:
    """Settings: JOG feed SD41110 = 500, variable increment SD41010 = 0.25; ⇧F1 saves them."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f6", "ctrl+a", "ctrl+k", "5", "0", "0", "down", "ctrl+a", "ctrl+k",
                    "0", ".", "2", "5", "shift+f1")
        machine_data = app.bridge.nck.machine_data
        assert float(machine_data.value("SD41110")) == 500.0
        assert float(machine_data.value("SD41010")) == 0.25


async def test_inc_var_shows_the_variable_increment_and_a_hint_when_it_is_zero() -> None:
    """INC VAR (Alt+I five times: 1, 10, 100, 1000, 10000, VAR) with SD41010 = 0: the JOG
    view says the axis keys do not move and where to set it; after Settings wrote 0.5 the
    view shows 0.5 mm and no hint."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, *(["alt+i"] * 6))
        assert app.bridge.status.channel.increment is None
        jog_info = str(app.screen.query_one("#jog-info").render())
        assert "SD41010 is 0" in jog_info
        await burst(pilot, "shift+f6", "down", "ctrl+a", "ctrl+k", "0", ".", "5", "shift+f1", "f10")
        jog_info = str(app.screen.query_one("#jog-info").render())
        assert "variable increment 0.5 mm" in jog_info
        assert "SD41010 is 0" not in jog_info
