"""At the tested minimum of 120 × 36 the JOG window's lines fit its width (no wrapped fragments).

Seen in tmux at 120 × 36: the keys line of the JOG window wrapped, 'Alt+E REPOS' stood
alone on the next line at the left edge. Keys go as a burst.
"""

from __future__ import annotations

import pytest
from nck.kernel import Nck
from textual.widgets import Static

from hmi.app import MIN_TERMINAL_SIZE, HmiApp
from tests.burst import burst


@pytest.mark.parametrize("keys", [(), ("alt+r",), ("alt+i",)])
async def test_jog_window_lines_fit_at_the_minimum_size(keys: tuple[str, ...]) -> None:
    app = HmiApp(Nck(), realtime=False)
    async with app.run_test(size=MIN_TERMINAL_SIZE) as pilot:
        await burst(pilot, *keys)
        info = app.screen.query_one("#jog-info", Static)
        width = info.content_region.width
        lines = str(info.render()).splitlines()
        assert lines and width > 0
        too_long = [line for line in lines if len(line.rstrip()) > width]
        assert not too_long, (width, too_long)
