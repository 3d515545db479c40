"""The HMI shell: keymap, operating areas (MODES), softkey model, header, overlays."""

from __future__ import annotations

import io
import re

from rich.console import Console

from nck import commands as c

from hmi.app import AREAS, HmiApp
from hmi.area import AreaBase
from hmi.keymap import default_keymap, display_key, parse_keymap
from hmi.softkeys import Softkey, SoftkeyMenu
from tests.burst import burst
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck

CONTRACT_KEYS = {
    "alt+m", "alt+o", "alt+p", "alt+n", "alt+a", "alt+s", "ctrl+q", "f9", "f10", "f11", "f12",
    "alt+j", "alt+d", "alt+u", "alt+r", "alt+e", "alt+i", "alt+k", "alt+g", "alt+h", "alt+q",
    "alt+x", "alt+y", "alt+z", "alt+c", "alt+v", "ctrl+right", "ctrl+left", "alt+w", "ctrl+up",
    "ctrl+down", "ctrl+pageup", "ctrl+pagedown", "alt+t",
    *(f"f{i}" for i in range(1, 9)), *(f"shift+f{i}" for i in range(1, 9)),
}


def test_keymap_holds_every_contract_key() -> None:
    """data/keymap.toml binds every key of spec/keymap.md, each once."""
    keys = {k.strip() for b in default_keymap().bindings for k in b.keys.split(",")}
    assert CONTRACT_KEYS <= keys


def test_keymap_rejects_unknown_action_and_duplicate_key() -> None:
    """The loader reports every problem of a broken table."""
    table = {
        "key": [
            {"id": "a", "key": "f1", "action": "nonsense", "label": "x"},
            {"id": "b", "key": "f1", "action": "help", "label": "y"},
        ],
        "switches": {"feed_override_percent": [100], "spindle_override_percent": [100],
                     "increments": [1]},
    }
    try:
        parse_keymap(table)
    except ValueError as exc:
        assert "nonsense" in str(exc) and "f1 bound twice" in str(exc)
    else:  # pragma: no cover
        raise AssertionError("broken keymap accepted")


def test_display_key_uses_panel_notation() -> None:
    """Key names are shown the way the keymap contract writes them."""
    assert display_key("ctrl+pageup") == "Ctrl+PgUp"
    assert display_key("shift+f3") == "Shift+F3"
    assert display_key("alt+g") == "Alt+G"


def test_softkey_needs_level_and_state() -> None:
    """A softkey is allowed only at its access level and when its predicate holds."""
    key = Softkey("k", "K", "x", level=5, enabled=lambda ctx: ctx["ok"])
    assert key.allowed({"ok": True}, 5)
    assert not key.allowed({"ok": True}, 6)
    assert not key.allowed({"ok": False}, 0)
    broken = Softkey("b", "B", "x", enabled=lambda ctx: ctx.missing)
    assert not broken.allowed(object(), 0)
    menu = SoftkeyMenu.of([key], [broken])
    assert menu.find("b") == "v1" and menu.slot("h1") is key and menu.slot("h8") is None


async def test_area_keys_switch_operating_areas() -> None:
    """Alt+M/O/P/N/A/S show one screen stack per area (on the real kernel); each is an AreaBase."""
    from nck.kernel import Nck

    fake_app = HmiApp(Nck(), realtime=False)
    async with fake_app.run_test(size=SIZE) as pilot:
        keys = {"parameter": "alt+o", "program": "alt+p", "program_manager": "alt+n",
                "diagnostics": "alt+a", "setup": "alt+s", "machine": "alt+m"}
        for area in AREAS:
            await pilot.press(keys[area.id])
            await pilot.pause()
            assert fake_app.current_mode == area.id
            assert isinstance(fake_app.screen, AreaBase)
            header = fake_app.screen.query_one("#hdr-state").render()
            assert area.title in str(header)


async def test_menu_select_offers_areas_and_recall_goes_back(fake_app: HmiApp) -> None:
    """F9 shows the areas on the softkeys; F5 chooses Diagnostics; F10 leaves the menu."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("f9")
        await pilot.pause()
        assert fake_app.screen.current_menu().slot("h5").id == "area.diagnostics"
        await pilot.press("f10")
        assert fake_app.screen.current_menu().find("area.diagnostics") is None
        await pilot.press("f9", "f5")
        await pilot.pause()
        assert fake_app.current_mode == "diagnostics"


def help_lines(app: HmiApp) -> list[list[str]]:
    """The rows of the help overlay's table as the operator reads them, split into columns."""
    console = Console(width=160, record=True, file=io.StringIO())
    console.print(app.screen.query_one("#help-table").content)
    return [re.split(r"\s{2,}", line.strip()) for line in console.export_text().splitlines()]


async def test_help_overlay_lists_keys(fake_app: HmiApp) -> None:
    """F11 lists the softkeys in force and every panel key of the keymap; F11 closes it."""
    async with fake_app.run_test(size=SIZE) as pilot:
        menu = fake_app.screen.softkey_menu()
        await pilot.press("f11")
        await pilot.pause()
        assert fake_app.screen.id == "help"
        rows = help_lines(fake_app)
        # keymap.md: the operator panel and the machine control panel, key, panel key, meaning
        for row in (["Alt+M", "MACHINE"], ["F12, Alt+Shift+C", "ALARM CANCEL"], ["Alt+U", "AUTO"],
                    ["Alt+G", "CYCLE START"], ["Alt+H", "CYCLE STOP"], ["Alt+Q", "RESET"],
                    ["Alt+K", "SINGLE BLOCK"]):
            assert any(line[:2] == row for line in rows), row
        for binding in fake_app.keymap.bindings:
            if binding.scope in ("op", "mcp"):
                assert [binding.key_display, binding.panel, binding.label] in rows, binding.id
        shown = [(f"F{i}", f"HSK{i}", key) for i, key in enumerate(menu.horizontal, 1) if key] \
            + [(f"Shift+F{i}", f"VSK{i}", key) for i, key in enumerate(menu.vertical, 1) if key]
        assert shown  # the machine area has softkeys
        for fkey, panel, softkey in shown:
            assert [fkey, panel, softkey.label.replace("\n", " ")] in rows, fkey
        await pilot.press("f11")
        await pilot.pause()
        assert isinstance(fake_app.screen, AreaBase)


async def test_keyswitch_cycles_access_level(fake: FakeNck, fake_app: HmiApp) -> None:
    """Alt+T turns the keyswitch 0→1→2→3→0; the header shows level 7→6→5→4→7."""
    async with fake_app.run_test(size=SIZE) as pilot:
        levels = []
        for _ in range(4):
            await pilot.press("alt+t")
            await pilot.pause()
            levels.append(fake_app.bridge.status.access_level)
            assert f"Level {levels[-1]}" in str(fake_app.screen.query_one("#hdr-state").render())
        assert levels == [6, 5, 4, 7]
        assert [cmd.position for cmd in fake.submitted if isinstance(cmd, c.SetKeyswitch)] == [1, 2, 3, 0]


async def test_override_switches_step_through_positions(fake: FakeNck, fake_app: HmiApp) -> None:
    """Ctrl+Up/Down move the feed switch one position; Ctrl+PgUp/PgDn the spindle switch."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+up", "ctrl+up", "ctrl+up")
        assert fake.overrides["feed"] == 115
        await pilot.press("ctrl+down", "ctrl+down", "ctrl+down", "ctrl+down")
        assert fake.overrides["feed"] == 95
        await pilot.press("ctrl+pagedown")
        assert fake.overrides["spindle"] == 95
        for _ in range(10):
            await pilot.press("ctrl+pageup")
        assert fake.overrides["spindle"] == 120
        await pilot.pause()
        assert "Feed 95 %" in str(fake_app.screen.query_one("#hdr-overrides").render())


async def test_alarm_line_shows_newest_alarm_and_f12_cancels(fake: FakeNck, fake_app: HmiApp) -> None:
    """The header's alarm line shows number and text of the newest alarm; F12 clears CANCEL alarms."""
    async with fake_app.run_test(size=SIZE) as pilot:
        fake.raise_alarm(14000, "Test alarm cleared by cancel", clear="cancel", category="axis")
        fake_app.bridge.poll()
        await pilot.pause()
        line = fake_app.screen.query_one("#hdr-alarm")
        assert "14000" in str(line.render()) and line.has_class("-alarm-red")
        await pilot.press("f12")
        await pilot.pause()
        assert "14000" not in str(line.render())


async def test_rejected_command_reason_on_dialog_line(fake: FakeNck, fake_app: HmiApp) -> None:
    """A refused command shows the kernel's reason on the dialog line."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+g")  # NC START in JOG: refused
        await pilot.pause()
        assert "not possible in JOG" in str(fake_app.screen.query_one("#dialog-line").render())


async def test_quit_saves_first() -> None:
    """Ctrl+Q calls the save hook, then exits."""
    saved = []
    app = HmiApp(FakeNck(), realtime=False, on_quit=lambda: saved.append(True))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+q")
        await pilot.pause()
    assert saved == [True]


async def test_broken_softkey_is_reported_not_fatal(monkeypatch, fake_app: HmiApp) -> None:
    """A softkey whose action raises becomes an HMI internal error on the dialog line (outside pytest)."""
    monkeypatch.delenv("PYTEST_CURRENT_TEST", raising=False)
    async with fake_app.run_test(size=SIZE) as pilot:
        screen = fake_app.screen
        monkeypatch.setattr(screen, "action_toggle_mcs", lambda: 1 / 0)
        await pilot.press("f1")
        await pilot.pause()
        assert fake_app.is_running
        assert "ZeroDivisionError" in str(screen.query_one("#dialog-line").render())
        assert len(fake_app.internal_errors) == 1


async def test_help_lists_the_keys_of_the_area(fake_app: HmiApp) -> None:
    """F11 per area (issue 27): the area's own keys stand between its softkeys and the panel keys.

    The Diagnostics area selects an alarm with the arrow keys and pages the log; the Program
    area's editor has Ctrl+Home / Ctrl+End. Each area lists only its own (pressed in a burst).
    """
    async with fake_app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+a", "f11")
        assert fake_app.screen.id == "help"
        rows = help_lines(fake_app)
        assert ["Keys of Diagnostics"] in rows
        for row in (["Up", "Select the alarm or exercise above"], ["Down", "Select the alarm or exercise below"],
                    ["PgDn", "Older log entries"], ["Shift+F2", "VSK2", "Alarm help"]):
            assert row in rows, row
        assert ["Ctrl+End", "End of program"] not in rows
        await burst(pilot, "f11", "alt+p", "f11")
        rows = help_lines(fake_app)
        assert ["Keys of Program"] in rows
        assert ["Ctrl+End", "End of program"] in rows
        assert ["Up", "Select the alarm or exercise above"] not in rows
