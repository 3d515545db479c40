"""The keys Textual's widgets bring and Textual's "No matches found" are said in the panel's
language (issue 27): the F11 help lists an area's own keys with German meanings, the palette
says that nothing matches in German."""

from __future__ import annotations

import io
from pathlib import Path

from rich.console import Console
from textual.binding import Binding
from textual.command import CommandList

from hmi.widget_keys import TEXTUAL_KEY_DESCRIPTIONS, TEXTUAL_WIDGETS
from tests.program_screens.conftest import DEMO_PROGRAM, SIZE, make_program_app, nc_files


def test_every_key_description_of_textuals_widgets_is_in_the_table() -> None:
    """A Textual that describes a key anew fails here: add the text to hmi.widget_keys and
    translate it (python -m tests.i18n.sources)."""
    described = {binding.description if isinstance(binding, Binding) else binding[2]
                 for widget in TEXTUAL_WIDGETS for kind in widget.__mro__
                 for binding in kind.__dict__.get("BINDINGS", [])
                 if isinstance(binding, Binding) or len(binding) > 2}
    assert described - {""} <= set(TEXTUAL_KEY_DESCRIPTIONS)
    assert len(set(TEXTUAL_KEY_DESCRIPTIONS)) == len(TEXTUAL_KEY_DESCRIPTIONS)


def help_text(app) -> str:
    console = Console(width=160, record=True, file=io.StringIO())
    console.print(app.screen.query_one("#help-table").content)
    return console.export_text()


def program_app(tmp_path: Path):
    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "DEMO.MPF").write_text(DEMO_PROGRAM)
    return make_program_app(root)


async def test_the_editors_keys_are_german_in_the_help(german: None, tmp_path: Path) -> None:
    """Program editor (a Textual TextArea), F11: the editor's keys with German meanings -
    Textual's (Ctrl+Z Undo, Ctrl+K Delete to line end) and the panel's own (Ctrl+Home)."""
    app = program_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "enter")  # Program manager, open DEMO.MPF
        await pilot.pause()
        assert app.current_mode == "program"
        assert app.screen.query_one("#prog-find").placeholder == "suchen"  # the search bar's fields
        assert app.screen.query_one("#prog-replace").placeholder == "ersetzen durch"
        await pilot.press("f11")
        await pilot.pause()
        text = help_text(app)
    assert "Rückgängig" in text and "Bis Zeilenende löschen" in text and "Programmanfang" in text
    for english in ("Undo", "Delete to line end", "Start of program", "Cursor word left"):
        assert english not in text


async def test_the_palette_says_no_matches_in_german(german: None, tmp_path: Path) -> None:
    """Ctrl+P and a name nothing has: Textual's own no-matches line, in German."""
    app = program_app(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("ctrl+p")
        await pilot.pause()
        palette = app.screen
        palette._NO_MATCHES_COUNTDOWN = 0.001  # Textual waits half a second before it says so
        await pilot.press(*"qqxqq")
        command_list = palette.query_one(CommandList)
        for _ in range(100):  # the search worker, then the countdown's timer
            await app.workers.wait_for_complete()
            await pilot.pause()
            if command_list.option_count:
                break
            await pilot.pause(0.01)
        assert command_list.option_count == 1
        shown = Console(width=60, record=True, file=io.StringIO())
        shown.print(command_list.get_option_at_index(0).prompt)
        assert shown.export_text().strip() == "Keine Treffer"


async def test_the_help_joins_german_softkey_labels_and_names_the_area(tmp_path: Path) -> None:
    """F11 in German: a label broken inside a word reads whole (Hilfs-/funktionen ->
    Hilfsfunktionen), and the area's keys are headed with its name (Programm-Manager)."""
    from hmi.app import make_app
    from tests.burst import burst

    app = make_app(data_dir=str(tmp_path / "data"), realtime=False, lang="de")
    try:
        async with app.run_test(size=SIZE) as pilot:
            await burst(pilot, "alt+m", "f11")
            machine = help_text(app)
            await burst(pilot, "f11", "alt+n", "f11")
            manager = help_text(app)
    finally:
        app.nc_session.quit()
    assert "Hilfsfunktionen" in machine and "Programmbeeinfl." in machine and "Hilfs- " not in machine
    assert "Tasten von Programm-Manager" in manager
