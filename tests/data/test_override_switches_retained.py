"""The override switches of the machine control panel stay where they were turned (issue 18).

A switch on the real machine control panel is a physical switch: after the control is switched
off and on, or the HMI is quit and started again, it still stands where the operator left it.
The kernel's overrides follow the switches, so after a restart they are what the switches show
(the ranges are 002 L56312-56319: feed and spindle 0 … 200 %, rapid 0 … 100 %).
"""

from __future__ import annotations

from pathlib import Path

from nck import commands as c

from hmi.app import make_app
from hmi.keymap import default_keymap
from tests.hmi.conftest import SIZE


def key(binding_id: str) -> str:
    """The key bound to ``binding_id`` in data/keymap.toml."""
    return next(b for b in default_keymap().bindings if b.id == binding_id).keys.split(",")[0].strip()


async def test_override_switches_keep_their_positions_over_quit_and_start(tmp_path: Path) -> None:
    data_dir = str(tmp_path / "data")
    app = make_app(data_dir=data_dir, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        # five steps down from 100 %: 95, 90, 85, 80, 75 (the switch positions of the keymap)
        await pilot.press(*[key("override.feed_down")] * 5, key("override.spindle_up"))
        await pilot.pause()
        assert app.submit(c.SetOverride("rapid", 50.0)).__class__.__name__ == "Accepted"
        before = dict(app.bridge.status.channel.overrides)
        assert before["feed"] == 75.0 and before["spindle"] > 100.0
    app.nc_session.quit()

    again = make_app(data_dir=data_dir, realtime=False)
    async with again.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert dict(again.bridge.status.channel.overrides) == {**before, "rapid": 50.0}
    again.nc_session.quit()
