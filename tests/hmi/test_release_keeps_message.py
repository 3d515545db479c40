"""Letting go of the + / − key does not wipe the refusal of a later key (issue 18: a message
belongs to its cause).

Found in the operator day in tmux: in REF, Alt+X Ctrl+Right Alt+R in one burst: Alt+R was
refused ("Channel active: stop the motion first") but the dialog line stayed empty, because the
release of Ctrl+R 150 ms later was sent as an accepted command, which clears the area's refusal.
"""

from __future__ import annotations

from pathlib import Path

from hmi.app import make_app
from tests.burst import burst

SIZE = (160, 48)


async def test_jog_key_release_keeps_the_refusal_on_the_dialog_line(tmp_path: Path) -> None:
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+m", "alt+j", "alt+r", "alt+x", "ctrl+right", "alt+r")
        assert app.bridge.status.channel.channel_state == "active"  # X is referencing
        refusal = "Channel active: stop the motion first"
        assert app.area_screen.area_hint == refusal
        app.release_jog()  # the + key let go (the realtime app does this by timer)
        await pilot.pause()
        assert app.area_screen.area_hint == refusal
