"""The control's date and time in Setup > Password is the wall clock, however late the area is first visited.

Found in the operator day in tmux (issue 18): ten minutes after power on, the first visit of
Setup showed the time ten minutes ahead (the screen took "now" as the power-on moment and
added the control time since power on).
"""

from __future__ import annotations

from datetime import datetime, timedelta
from pathlib import Path

import pytest

import screens.setup

from tests.burst import burst
from tests.parameter_setup.conftest import SIZE, trainer


async def test_first_visit_late_shows_the_wall_clock(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Power on at 09:30:00, 600 s of control time and of wall clock later Alt+S F6: 09:40:00."""
    now = [datetime(2026, 3, 14, 9, 30, 0)]
    monkeypatch.setattr(screens.setup, "wall_clock", lambda: now[0])
    app = trainer(tmp_path / "data")
    async with app.run_test(size=SIZE) as pilot:
        for _ in range(60):  # the wall clock and the control time run together
            app.bridge.advance(10.0)
            now[0] += timedelta(seconds=10)
        await burst(pilot, "alt+s", "f6")
        text = str(app.screen.access_text())
        assert "Date / time            2026-03-14 09:40:00" in text
        assert "Since power on         00:10:00" in text
