"""Machine area behaviour on the fake kernel: views, softkeys, program control, areas."""

from __future__ import annotations

import html
import importlib
import re

from nck import commands as c

from hmi.app import Area, HmiApp, load_area_screen
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck


def text_of(app: HmiApp, selector: str) -> str:
    """The rendered text of a widget of the current screen."""
    return str(app.screen.query_one(selector).render())


def screen_text(app: HmiApp) -> str:
    """Everything on the screen as plain text (from the SVG export)."""
    svg = html.unescape(app.export_screenshot())
    return re.sub(r"<[^>]+>", "", svg).replace("\xa0", " ")


async def test_softkey_views_and_menu_recall(fake_app: HmiApp) -> None:
    """F2 shows all G groups (softkey pressed); F10 returns to the mode's view."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("f2")
        await pilot.pause()
        assert fake_app.screen.query_one("#mach-views").current == "view-gfunc"
        assert fake_app.screen.query_one("#sk-h2").has_class("-active")
        assert "working plane X/Y" in screen_text(fake_app)  # G17's meaning (issue 27: one table)
        await pilot.press("f10")
        await pilot.pause()
        assert fake_app.screen.query_one("#mach-views").current == "view-jog"
        assert not fake_app.screen.query_one("#sk-h2").has_class("-active")


async def test_mcs_softkey_switches_coordinate_system(fake: FakeNck, fake_app: HmiApp) -> None:
    """Power-on shows the MCS (002 L31480 "the predefined setting after power-up of the HMI
    software is MCS", L31569); F1 toggles the position window to the WCS and back.
    Digest 828d-2 rank 23 (power-on in MCS, softkey toggles).
    """
    async with fake_app.run_test(size=SIZE) as pilot:
        assert text_of(fake_app, "#positions").lstrip().startswith("MCS")
        assert fake_app.screen.query_one("#sk-h1").has_class("-active")
        await pilot.press("f1")
        await pilot.pause()
        assert text_of(fake_app, "#positions").lstrip().startswith("WCS")
        assert not fake_app.screen.query_one("#sk-h1").has_class("-active")
        await pilot.press("f1", "f1")
        await pilot.pause()
        assert text_of(fake_app, "#positions").lstrip().startswith("WCS")


async def test_program_control_switches(fake: FakeNck, fake_app: HmiApp) -> None:
    """Program control: ⇧F2 dry run and ⇧F5 ROV are sent to the kernel and shown checked."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+u", "f4")
        await pilot.pause()
        await pilot.press("shift+f2", "shift+f5")
        await pilot.pause()
        assert fake.control["dry_run"] is True and fake.control["rapid_override"] is True
        shown = text_of(fake_app, "#progctl-table")
        assert "[x] Dry run" in shown and "[x] Rapid traverse override" in shown
        assert fake_app.screen.query_one("#sk-v2").has_class("-active")


async def test_single_block_type_follows_program_control(fake: FakeNck, fake_app: HmiApp) -> None:
    """⇧F1 in program control selects SBL2; Alt+K then switches single block on as SBL2."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+u", "f4", "shift+f1", "alt+k")
        await pilot.pause()
        assert fake.control["single_block"] == "SBL2"
        await pilot.press("alt+k")
        assert fake.control["single_block"] is None


async def test_softkey_not_allowed_gives_reason(fake: FakeNck, fake_app: HmiApp) -> None:
    """A greyed softkey (Select program at level 7) does nothing and says why."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+u", "f7")
        await pilot.pause()
        assert fake_app.screen.query_one("#sk-h7").has_class("-disabled")
        assert "access level 6" in text_of(fake_app, "#dialog-line")
        assert not any(isinstance(cmd, c.SelectProgram) for cmd in fake.submitted)


async def test_mda_editor_takes_focus_and_sends_text(fake: FakeNck, fake_app: HmiApp) -> None:
    """Alt+D focuses the MDA editor; typed text reaches the kernel's MDA buffer at once."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        assert fake_app.focused is fake_app.screen.query_one("#mda-editor")
        await pilot.press(*"G1 X5 F100")
        assert fake.mda_text == "G1 X5 F100"
        await pilot.press("alt+j")
        await pilot.pause()
        assert fake_app.focused is None


async def test_increment_key_cycles_through_increments(fake: FakeNck, fake_app: HmiApp) -> None:
    """Alt+I: INC 1, 10, 100, 1000, 10000, VAR, then 1 again; Alt+J back to continuous."""
    async with fake_app.run_test(size=SIZE) as pilot:
        seen = []
        for _ in range(7):
            await pilot.press("alt+i")
            seen.append(fake.increment)
        assert seen == [1, 10, 100, 1000, 10000, None, 1]
        assert fake.function == "INC"
        await pilot.press("alt+j")
        assert fake.function is None


async def test_axis_keys_select_axis(fake: FakeNck, fake_app: HmiApp) -> None:
    """Alt+Z selects Z (marked), Ctrl+Right jogs Z; Alt+C refuses a missing 4th axis."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+z", "ctrl+right")
        await pilot.pause()
        assert fake.pos["Z"] == 1.0
        assert "▸Z" in text_of(fake_app, "#positions")
        await pilot.press("alt+c")
        await pilot.pause()
        assert "no axis 4" in text_of(fake_app, "#dialog-line")


def test_missing_area_module_gives_placeholder() -> None:
    """An area without a module loads as None without a problem (placeholder)."""
    assert load_area_screen(Area("no_such_area_zz", "X", "X")) == (None, "")


def test_broken_area_module_reports_reason(monkeypatch) -> None:
    """An area module that fails to import is replaced by the placeholder with the reason."""
    real = importlib.import_module

    def broken(name: str, *args: object):
        if name == "screens.broken_zz":
            raise RuntimeError("boom")
        return real(name, *args)

    monkeypatch.setattr(importlib, "import_module", broken)
    screen_class, problem = load_area_screen(Area("broken_zz", "B", "B"))
    assert screen_class is None and "boom" in problem


async def test_ctrl_arrows_stay_with_the_mda_editor(fake: FakeNck, fake_app: HmiApp) -> None:
    """In MDA the editor keeps Ctrl+Left (word left): no JOG command is sent."""
    async with fake_app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d")
        await pilot.pause()
        await pilot.press(*"G1 X5", "ctrl+left")
        assert not any(isinstance(cmd, c.Jog) for cmd in fake.submitted)
        editor = fake_app.screen.query_one("#mda-editor")
        assert editor.cursor_location == (0, 3)
