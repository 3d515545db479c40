"""The alarm help in German (issue 27): switched in Setup, an alarm provoked, its help read.

The operator switches to German (Alt+S, F6 Password, Shift+F5 Change language, Shift+F2
Deutsch), presses NC START in AUTOMATIC with unreferenced axes (Alt+D, Alt+G: alarm 10203, as in
tests/diagnostics/test_alarm_help.py) and opens the alarm help from the alarm log. The page's
headings, the alarm text, the explanation and the remedy are German: the explanation and remedy
come from data/lang/de/alarms.toml, the headings and the clearing from hmi.po.
"""

from __future__ import annotations

from pathlib import Path

from textual.widgets import Static

from hmi.alarm_help import AlarmHelpScreen
from hmi.app import make_app
from nck.translations import overlay
from screens.diagnostics import DiagnosticsScreen
from tests.burst import burst
from tests.hmi.conftest import SIZE


def vertical_key(screen: DiagnosticsScreen, action: str) -> str:
    """The Shift+F key of the vertical softkey that runs ``action`` on the current level."""
    bar = screen.current_menu().vertical
    index = next(i for i, key in enumerate(bar, start=1) if key is not None and key.action == action)
    return f"shift+f{index}"


async def test_alarm_help_of_a_provoked_alarm_in_german(tmp_path: Path) -> None:
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    try:
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("alt+s", "f6", "shift+f5", "shift+f2")
            await pilot.pause()
            await app.workers.wait_for_complete()
            await pilot.pause()
            await burst(pilot, "alt+d", "alt+g", "alt+a", "f3")
            screen = app.screen
            assert isinstance(screen, DiagnosticsScreen) and screen.view == "log"
            assert screen.selected_alarm().number == 10203
            await pilot.press(vertical_key(screen, "alarm_help"))
            await pilot.pause()
            help_screen = app.screen
            assert isinstance(help_screen, AlarmHelpScreen) and help_screen.number == 10203
            page = str(help_screen.query_one("#alarm-help-body", Static).render())
            title = str(help_screen.query_one("#alarm-help-title", Static).render())
            assert "ALARMHILFE — 10203" in title
            assert "NC-Start abgelehnt: Achse" in page and "nicht referenziert" in page
            assert "Was ist passiert" in page and "Abhilfe" in page
            # the German explanation and remedy (data/lang/de/alarms.toml), not the English ones
            assert "Ohne Referenzpunkt kennt die Steuerung die Position der Achse nicht" in page
            assert "In JOG REF wechseln und die Achse (oder alle Achsen) referenzieren" in page
            assert "has not been referenced" not in page and "Switch to JOG REF" not in page
            assert "Alarmlöschtaste (F12)" in page
            await pilot.press("escape")
            await pilot.pause()
            await pilot.press("alt+m")
            await pilot.pause()
            await pilot.click("#hdr-alarm")  # the header's alarm line opens the same help
            await pilot.pause()
            assert isinstance(app.screen, AlarmHelpScreen) and app.screen.number == 10203
            page = str(app.screen.query_one("#alarm-help-body", Static).render())
            assert overlay("de", "alarm")["10203"]["remedy"] in page
    finally:
        app.nc_session.quit()
