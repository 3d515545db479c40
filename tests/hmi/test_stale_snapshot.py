"""A snapshot read before a key was handled never undoes what the key did (issue 18).

Found in the operator day in tmux: from the Program manager, ``Alt+M Alt+U F4`` in one burst
selected AUTO but lost F4 (no Program control). While Alt+M was being handled the refresh
timer read a JOG snapshot and queued it behind the keys; shown after Alt+U and F4, it looked
like a change back to JOG, and the Machine area returned to the mode's view.
"""

from __future__ import annotations

from pathlib import Path

from hmi.app import make_app
from hmi.messages import NckStatusChanged
from tests.burst import burst, key_event
from tests.hmi.screen_rows import screen_rows

SIZE = (160, 48)


async def test_snapshot_queued_behind_the_keys_does_not_reset_the_view(tmp_path: Path) -> None:
    """Alt+M Alt+U F4 with a JOG snapshot queued behind them: Program control is shown."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+m")
        await burst(pilot, "alt+n")
        read_before_the_keys = app.bridge.status
        assert read_before_the_keys.channel.mode == "JOG"
        for key in ("alt+m", "alt+u", "f4"):
            event = key_event(key)
            event.set_sender(app)
            app.post_message(event)
        app.post_message(NckStatusChanged(read_before_the_keys))
        await pilot.pause()
        await pilot.pause()
        assert app.bridge.status.channel.mode == "AUTO"
        machine = app.screen
        assert machine.query_one("#mach-views").current == "view-progctl"
        assert "│ AUTO  │" in screen_rows(app)[0]  # the header, too, shows the newest state
