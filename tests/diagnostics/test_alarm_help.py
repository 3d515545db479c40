"""Alarm help (issue 27): every catalogue alarm explains itself, from the list, the log and the header.

The help texts are catalogue data (``data/alarms/*.toml``: ``explanation``, ``remedy``,
``help_source``); how an alarm is cleared follows from its clear criterion. 10203 is raised by
NC START on unreferenced axes (Alt+D Alt+G, as in test_alarm_dates); its clear criterion is
CANCEL. Keys go one at a time and as bursts.
"""

from __future__ import annotations

import re

from nck.queries import alarm_catalog
from hmi.alarm_help import CLEARING, REACTIONS, AlarmHelpScreen, help_text
from hmi.app import make_app
from screens.diagnostics import DiagnosticsScreen
from tests.burst import burst
from tests.diagnostics.conftest import SIZE, app_on
from tests.diagnostics.staged import AUTO_LIMIT, JOG_LIMIT, StagedKernel, stamped

MANUAL_LINES = re.compile(r"^00[0-4] L\d+(-\d+)?$")


def test_every_catalogue_alarm_has_help() -> None:
    """Explanation and remedy in full sentences; a cited source names a manual and its lines."""
    catalogue = alarm_catalog()
    assert len(catalogue) >= 100
    for number, definition in catalogue.items():
        for field in (definition.explanation, definition.remedy):
            assert len(field.split()) >= 5 and field.endswith("."), (number, field)
        assert definition.clear in CLEARING, number
        assert all(reaction in REACTIONS for reaction in definition.reactions), number
        assert not definition.help_source or MANUAL_LINES.match(definition.help_source), number


def test_help_page_of_a_reset_alarm() -> None:
    """10860 (002 L55649: no F value programmed): explanation, remedy, RESET, reactions, source."""
    page = help_text(10860, "Channel 1 block N20: no feedrate programmed").plain
    assert "Channel 1 block N20: no feedrate programmed" in page
    assert "no feedrate F is active" in page
    assert "Program an F value" in page
    assert CLEARING["reset"] in page
    assert "NC START is disabled; the program stops at the block" in page
    assert "Source: manual 002 L55649" in page


def test_help_page_of_a_self_clearing_alarm_and_of_an_unknown_number() -> None:
    page = help_text(10621).plain
    assert CLEARING["self"] in page and "No reaction" in page
    assert "No help is stored" in help_text(99999, "Alarm 99999").plain


def vertical_key(screen: DiagnosticsScreen, action: str) -> str:
    """The Shift+F key of the vertical softkey that runs ``action`` on the current level."""
    bar = screen.current_menu().vertical
    index = next(i for i, key in enumerate(bar, start=1) if key is not None and key.action == action)
    return f"shift+f{index}"


async def test_alarm_list_help_of_the_selected_alarm() -> None:
    """Two alarms: ▼ selects the older one; Alarm help shows its page; F10 closes it."""
    nck = StagedKernel()
    nck.staged_alarms = (AUTO_LIMIT, JOG_LIMIT)
    app = stamped(app_on(nck))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+a")
        await pilot.pause()
        screen = app.screen
        assert isinstance(screen, DiagnosticsScreen)
        assert screen.selected_alarm().number == 10621  # newest first
        await burst(pilot, "down", vertical_key(screen, "alarm_help"))
        help_screen = app.screen
        assert isinstance(help_screen, AlarmHelpScreen) and help_screen.number == 10720
        page = str(help_screen.query_one("#alarm-help-body").render())
        assert "beyond the axis' software limit switch" in page
        await pilot.press("f10")
        await pilot.pause()
        assert app.screen is screen
        await burst(pilot, "up", "up", vertical_key(screen, "alarm_help"))
        assert isinstance(app.screen, AlarmHelpScreen) and app.screen.number == 10621


async def test_alarm_provoked_then_help_from_log_and_header(tmp_path) -> None:
    """NC START on unreferenced axes raises 10203; its help opens from the log and from the header."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+d", "alt+g", "alt+a", "f3")
        screen = app.screen
        assert isinstance(screen, DiagnosticsScreen) and screen.view == "log"
        assert screen.selected_alarm().number == 10203
        await pilot.press(vertical_key(screen, "alarm_help"))
        await pilot.pause()
        assert isinstance(app.screen, AlarmHelpScreen) and app.screen.number == 10203
        page = str(app.screen.query_one("#alarm-help-body").render())
        assert "has not been referenced" in page and CLEARING["cancel"] in page
        assert "NC START is disabled." in page  # 002 L20829-20833
        await pilot.press("escape")
        await pilot.pause()
        await pilot.press("alt+m")
        await pilot.pause()
        await pilot.click("#hdr-alarm")
        await pilot.pause()
        assert isinstance(app.screen, AlarmHelpScreen) and app.screen.number == 10203


def test_alarm_help_snapshot(snap_compare) -> None:
    """The help page of 10720 over the alarm list (▼ selects it, Shift+F2 is Alarm help)."""
    nck = StagedKernel()
    nck.staged_alarms = (AUTO_LIMIT, JOG_LIMIT)

    async def run(pilot) -> None:
        await burst(pilot, "alt+a", "down", "shift+f2")

    assert snap_compare(stamped(app_on(nck)), terminal_size=SIZE, run_before=run)
