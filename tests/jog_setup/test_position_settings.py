"""Position and Settings windows of JOG (issue 22)."""

from __future__ import annotations

from nck import commands as cmd
from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst
from tests.jog_setup.test_tsm_window import run_job

SIZE = (160, 48)


def kernel_at(x: float, y: float, z: float) -> Nck:
    """A referenced mill standing at (x, y, z) MCS, in JOG."""
    nck = Nck(referenced=True)
    for command in (cmd.SelectMode("MDA"), cmd.SetMdaProgram(f"G0 X{x} Y{y} Z{z}\n"), cmd.CycleStart()):
        assert nck.submit(command) == cmd.Accepted()
    for _ in range(2000):
        nck.tick(0.01)
        if nck.status().channel.channel_state == "reset":
            break
    assert nck.submit(cmd.SetMdaProgram("")) == cmd.Accepted()
    assert nck.submit(cmd.SelectMode("JOG")) == cmd.Accepted()
    return nck


def wcs(app: HmiApp) -> dict[str, float]:
    """The WCS actual values of the path axes."""
    return {a.name: a.position_wcs for a in app.bridge.status.axes if a.kind != "spindle"}


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
