"""Browser-safe keys and clickable panel keys (issue 26, docs/keymap.md "In a browser").

A browser may keep F10 (menu bar), F11 (full screen), F12 (developer tools) and
Ctrl+PgUp/PgDn (tab switching) for itself: each has a second key that browsers
leave to the page and terminals deliver, and in a browser tab the operator panel's
and machine control panel's keys are clickable under the softkeys (softkeys are
clickable everywhere). Keys are sent one by one and in bursts, as a browser's
terminal sends them.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from hmi.app import HmiApp
from hmi.help import HelpScreen
from hmi.keymap import default_keymap, display_key
from hmi.panel_keys import PanelKey, PanelKeys
from nck.exercise import load_exercises
from tests.burst import burst
from tests.hmi.test_exercises_panel import trainee_app
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck

BROWSER_SAFE = {  # binding id: (key a browser may keep, its browser-safe alternative)
    "menu.recall": ("f10", "alt+shift+r"),
    "help": ("f11", "alt+shift+h"),
    "alarm.cancel": ("f12", "alt+shift+c"),
    "override.spindle_up": ("ctrl+pageup", "ctrl+shift+up"),
    "override.spindle_down": ("ctrl+pagedown", "ctrl+shift+down"),
}


@pytest.fixture
def in_browser(monkeypatch: pytest.MonkeyPatch) -> None:
    """The app as textual-serve runs it: Textual's web driver says the app is on the web."""
    monkeypatch.setattr(HmiApp, "is_web", property(lambda self: True))


def test_keys_a_browser_keeps_have_an_alternative_on_the_same_binding() -> None:
    keymap = default_keymap()
    for binding_id, (kept, alternative) in BROWSER_SAFE.items():
        keys = [k.strip() for k in keymap.by_id(binding_id).keys.split(",")]
        assert keys == [kept, alternative], binding_id
    assert keymap.by_id("help").key_display == "F11, Alt+Shift+H"  # what the F11 overlay lists


async def test_alternatives_work_one_by_one_and_in_a_burst(fake: FakeNck, fake_app: HmiApp) -> None:
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+shift+h")
        assert isinstance(fake_app.screen, HelpScreen)
        await pilot.press("alt+shift+h")  # HELP again closes it
        assert not isinstance(fake_app.screen, HelpScreen)
        await burst(pilot, "ctrl+shift+down", "ctrl+shift+down", "ctrl+shift+up")
        assert fake.overrides["spindle"] == 95  # 100 → 95 → 90 → 95 (keymap switch positions)
        fake.raise_alarm(14000, "Test alarm cleared by cancel", clear="cancel", category="axis")
        fake_app.bridge.poll()
        await burst(pilot, "alt+shift+c", "alt+shift+h")
        assert not any(a.number == 14000 for a in fake_app.bridge.status.alarms)
        assert isinstance(fake_app.screen, HelpScreen)


async def test_panel_keys_are_hidden_in_a_terminal(fake_app: HmiApp) -> None:
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert not fake_app.screen.query_one(PanelKeys).display
        assert not fake_app.screen.query(PanelKey)  # not even built


async def test_panel_keys_are_shown_and_clickable_in_a_browser(in_browser: None, fake: FakeNck,
                                                               fake_app: HmiApp) -> None:
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        keys = fake_app.screen.query(PanelKey)
        assert fake_app.screen.query_one(PanelKeys).display
        texts = [str(key.render()) for key in keys]
        for text in ("MACHINE", "HELP", "RECALL", "ALM CANCEL", "JOG", "MDA", "AUTO", "START", "STOP", "RESET",
                     "S+", "S-"):
            assert text in texts
        assert all(key.region.right <= SIZE[0] for key in keys)  # every key fits the width
        await pilot.click("#pk-mode-mda")
        await pilot.pause()
        assert fake.mode == "MDA"
        await pilot.click("#pk-area-setup")
        await pilot.click("#pk-area-machine")
        await pilot.click("#pk-mode-jog")
        await pilot.click("#pk-override-spindle_down")
        await pilot.pause()
        assert fake.mode == "JOG" and fake.overrides["spindle"] == 95


def test_docs_keymap_names_every_key_and_the_browser_alternatives() -> None:
    """docs/keymap.md, the project's copy of the contract, names every panel and MCP key."""
    doc = (Path(__file__).parents[2] / "docs" / "keymap.md").read_text(encoding="utf-8")
    for binding in default_keymap().bindings:
        if binding.scope in ("op", "mcp"):
            for key in binding.keys.split(","):
                assert display_key(key.strip()) in doc, binding.id
    browser_part = doc.split("## In a browser", 1)[1]
    for kept, alternative in BROWSER_SAFE.values():
        assert display_key(alternative) in browser_part


async def test_an_exercise_records_a_clicked_panel_key_as_its_key(in_browser: None, tmp_path: Path) -> None:
    app = trainee_app(tmp_path)
    exercise = {e.exercise_id: e for e in load_exercises()}["01_power_on_reference"]
    async with app.run_test(size=SIZE) as pilot:
        assert app.start_exercise(exercise).startswith("Exercise started")
        await pilot.pause()
        await pilot.click("#pk-function-ref")
        await pilot.click("#pk-axis-select_1")
        await pilot.pause()
        keys = [e["key"] for e in app.exercise_run.progress.events if e["kind"] == "key"]
        assert keys == ["alt+r", "alt+x"]  # as if typed (keymap: REF POINT, axis X)
        app.end_exercise()
