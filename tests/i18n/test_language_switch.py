"""Setup ▸ Password ▸ Change language switches every text of the panel, and the choice is kept
(issue 27). Operate offers its language selection in the Setup area; here it sits beside the
access level and the control's date and time (Password view, vertical softkey 5)."""

from __future__ import annotations

import io
import json
from pathlib import Path

from rich.console import Console
from textual.widgets import Static

from hmi.app import make_app
from hmi.help import help_table
from hmi.keymap import default_keymap
from hmi.i18n import language, set_language
from hmi.softkeys import Softkey, SoftkeyCell, SoftkeyMenu
from tests.hmi.conftest import SIZE


def header_text(app) -> str:
    return str(app.screen.query_one("#hdr-state", Static).render())


def softkey_text(app, slot: str) -> str:
    return str(app.screen.query_one(f"#sk-{slot}", SoftkeyCell).render())


def retained_language(data_dir: Path) -> str:
    document = json.loads((data_dir / "retained" / "display.json").read_text(encoding="utf-8"))
    return document["data"]["language"]


async def test_switch_to_german_in_setup_and_back(tmp_path: Path) -> None:
    """Alt+S, F6 (Password), Shift+F5 (Change language), Shift+F2 (Deutsch) in one burst:
    the Setup area is German at once, the other areas too, and the choice is in the retained data."""
    data_dir = tmp_path / "data"
    app = make_app(data_dir=str(data_dir), realtime=False)
    try:
        async with app.run_test(size=SIZE) as pilot:
            assert "MACHINE" in header_text(app)
            await pilot.press("alt+s", "f6", "shift+f5", "shift+f2")
            await pilot.pause()
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert language() == "de"
            assert app.current_mode == "setup" and app.screen.view == "language"
            assert "INBETRIEBNAHME" in header_text(app)
            assert "Kennwort" in softkey_text(app, "h6")
            assert "● Deutsch" in str(app.screen.query_one("#setup-access", Static).render())
            assert retained_language(data_dir) == "de"
            await pilot.press("alt+m")
            await pilot.pause()
            assert "MASCHINE" in header_text(app) and "Kanal RESET" in header_text(app)
            await pilot.press("alt+s", "shift+f1")  # back to English: the view is still the language list
            await pilot.pause()
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert language() == "en" and "SETUP" in header_text(app)
            assert retained_language(data_dir) == "en"
    finally:
        app.nc_session.quit()


async def test_the_language_survives_a_restart(tmp_path: Path) -> None:
    """hmi --lang de keeps German in the data directory; the next start without --lang is German."""
    data_dir = tmp_path / "data"
    first = make_app(data_dir=str(data_dir), realtime=False, lang="de")
    first.nc_session.quit()
    assert retained_language(data_dir) == "de"
    set_language("en")  # as a new process starts
    second = make_app(data_dir=str(data_dir), realtime=False)
    try:
        assert language() == "de"
        async with second.run_test(size=SIZE) as pilot:
            await pilot.pause()
            assert "MASCHINE" in header_text(second)
    finally:
        second.nc_session.quit()


async def test_palette_finds_block_search_in_german(tmp_path: Path) -> None:
    """In German, Ctrl+P "Satzsuchlauf" finds Machine ▸ Satzsuchlauf; choosing it opens block search."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        async with app.run_test(size=SIZE) as pilot:
            places = [place.path for place in app.palette_places()]
            assert "Maschine ▸ Satzsuchlauf" in places
            await pilot.press("ctrl+p", *"Satzsuchlauf")
            await pilot.pause()
            await pilot.press("down", "enter")
            await pilot.pause()
            assert app.current_mode == "machine"
    finally:
        app.nc_session.quit()



async def test_key_help_in_german(tmp_path: Path) -> None:
    """F11 in German: the overlay's title is German."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        async with app.run_test(size=SIZE) as pilot:
            await pilot.press("f11")
            await pilot.pause()
            assert "HILFE" in str(app.screen.query_one("#help-title", Static).render())
    finally:
        app.nc_session.quit()


def test_key_help_table_in_german() -> None:
    """The F11 table in German: softkey labels from the catalogue, key labels from
    data/lang/de/keymap.toml, section titles."""
    set_language("de")
    menu = SoftkeyMenu.of([Softkey("machine.search", "Block\nsearch", "noop")])
    console = Console(width=200, record=True, file=io.StringIO())
    console.print(help_table(default_keymap(), menu))
    shown = console.export_text()
    assert "Satzsuchlauf" in shown and "Betriebsart JOG" in shown and "Bedientafel" in shown
