"""The exam profile on the panel (issue 26): no hints, the access level fixed, help limited.

Exercise 13 is an exam. While it runs, the keyswitch (Alt+T) changes nothing and says
why, the command palette (Ctrl+P, which finds any softkey by name) and the alarm help
stay closed, and the side window shows the steps without hints; the key overview (F11:
the keys printed on a real panel) stays. Keys one at a time and in a burst.
"""

from __future__ import annotations

from pathlib import Path

from textual.command import CommandPalette

from hmi.app import HmiApp
from hmi.exercise_run import EXAM_HELP_LIMITED
from hmi.help import HelpScreen
from nck.access import ACCESS_LOCKED_TEXT
from tests.burst import burst
from tests.hmi.conftest import SIZE
from tests.hmi.test_exercises_panel import OPEN_LIST, START, side, trainee_app

PREVIOUS = "shift+f4"  # Previous ▲ in the exercise list: from the first, twice → the 13th of 14


def header_state(app: HmiApp) -> str:
    return str(app.screen.query_one("#hdr-state").render())


async def test_exam_has_no_hints_a_fixed_level_and_limited_help(tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press(*OPEN_LIST, PREVIOUS, PREVIOUS, START)
        assert app.hint == "Exercise started: Exam: from power on to the first part"
        assert app.exam_running and "Hint" not in side(app)
        assert app.bridge.status.access_level == 6  # the set-up's keyswitch position 1
        await pilot.press("alt+t")  # one key
        await pilot.pause()
        assert app.bridge.status.access_level == 6 and app.hint == ACCESS_LOCKED_TEXT
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+t")  # a burst: a whole turn of the key
        await pilot.pause()
        assert app.bridge.status.access_level == 6 and "Level 6" in header_state(app)
        assert app.hint == ACCESS_LOCKED_TEXT
        await pilot.press("ctrl+p")
        assert not isinstance(app.screen, CommandPalette) and app.hint == EXAM_HELP_LIMITED
        app.show_alarm_help(10203)
        assert app.hint == EXAM_HELP_LIMITED and type(app.screen).__name__ != "AlarmHelpScreen"
        await pilot.press("f11")
        assert isinstance(app.screen, HelpScreen)  # the key overview stays
        await pilot.press("f11", "alt+a", "shift+f2")  # End exercise
        assert not app.exam_running
        level = app.bridge.status.access_level
        await pilot.press("alt+t")  # the trainee's own panel: the keyswitch turns again
        await pilot.pause()
        assert app.bridge.status.access_level != level and app.hint != ACCESS_LOCKED_TEXT
