"""The handwheel on the keyboard (issue 22): Alt+Right / Alt+Left are one detent + / −.

Weighting: the INC increment (0.001 mm units: INC 100 → 0.1 mm per detent); detents add
up like INC presses; without INC the dialog line asks for it and nothing moves.
"""

from __future__ import annotations

from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst

SIZE = (160, 48)


def mcs(app: HmiApp, axis: str) -> float:
    """Machine position of ``axis``."""
    return {a.name: a.position_mcs for a in app.bridge.status.axes}[axis]


async def test_detents_in_one_burst_add_up_with_the_inc_weighting() -> None:
    """INC 100, axis Y: three detents + and one − in one burst: Y = (3 − 1) × 0.1 = 0.2 mm."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+i", "alt+i", "alt+i", "alt+y", "alt+right", "alt+right", "alt+right")
        assert app.bridge.status.channel.increment == 100
        app.bridge.advance(2.0)
        assert abs(mcs(app, "Y") - 0.3) < 1e-9
        await burst(pilot, "alt+left")
        app.bridge.advance(2.0)  # simulated time: the JOG feed covers 0.1 mm in far less
        assert abs(mcs(app, "Y") - 0.2) < 1e-9
        assert mcs(app, "X") == 0.0


async def test_handwheel_without_inc_asks_for_the_weighting() -> None:
    """Continuous JOG: a detent moves nothing and the dialog line says to select INC."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+x", "alt+right")
        app.bridge.advance(0.5)
        assert mcs(app, "X") == 0.0
        assert "select its weighting with INC" in str(app.screen.query_one("#dialog-line").render())


async def test_handwheel_keys_never_reach_a_field() -> None:
    """In the T,S,M window's T field Alt+Right/Left turn the handwheel, they type nothing."""
    app = HmiApp(Nck(referenced=True), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "1", "alt+right", "alt+left", "2")
        assert app.screen.query_one("#view-tsm-tool").value == "12"
