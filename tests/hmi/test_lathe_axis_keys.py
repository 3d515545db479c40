"""On the lathe the panel's axis keys X and Z select the axes X and Z (a lathe's machine
control panel has keys for its own axes): Alt+Z selects Z, which is the lathe's second axis,
and Alt+Y says there is no axis Y. Keys go in one burst as well as one at a time."""

from __future__ import annotations

from nck.kernel import Nck
from nck.machine import load_machine

from hmi.app import HmiApp
from tests.burst import burst

SIZE = (160, 48)


def _positions(app: HmiApp) -> str:
    return str(app.screen.query_one("#positions").render())


async def test_alt_z_selects_z_on_the_lathe() -> None:
    app = HmiApp(Nck(machine=load_machine("lathe2"), referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+m", "alt+z")
        await pilot.pause()
        assert "▸Z" in _positions(app)
        await pilot.press("alt+x")
        await pilot.pause()
        assert "▸X" in _positions(app)
        await pilot.press("alt+y")
        await pilot.pause()
        assert "▸X" in _positions(app)
        assert "no axis Y" in str(app.screen.query_one("#dialog-line").render())
