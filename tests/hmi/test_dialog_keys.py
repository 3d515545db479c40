"""The first key after a dialog closes is not lost (issue 18).

Each test sends the keys as one burst (:func:`tests.burst.burst`): all key
events are queued before the app handles the first, as when a terminal
delivers several keys in one read.
"""

from __future__ import annotations

from pathlib import Path

from tests.burst import burst
from tests.parameter_setup.conftest import SIZE, fill, trainer


def table_cell(app, row: int, column: int) -> str:
    """The text of a cell of the Parameter area's table on display."""
    return app.screen.table.cell(row, column).text.strip()


async def test_tool_list_key_after_value_dialog(tmp_path: Path) -> None:
    """Tool list: Enter, 120, Enter, Right in one burst: Length 1 is 120, the cursor moved right."""
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+o", "right")  # keyswitch 3, Length 1
        screen = app.screen
        cursor = screen.cursors[screen.view]
        assert screen.table.columns[cursor.column].title == "Length 1"
        await burst(pilot, "enter", "ctrl+u", "1", "2", "0", "enter", "right")
        assert app.screen is screen
        assert table_cell(app, 0, 5) == "120.000"
        assert screen.table.columns[cursor.column].title == "Length 2"


async def test_work_offsets_key_after_value_dialog(tmp_path: Path) -> None:
    """Work offsets overview: G54 X = 5, then Down in the same burst reaches the G55 row."""
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+o", "f3", "down")  # overview, row G54
        screen = app.screen
        cursor = screen.cursors[screen.view]
        row = cursor.row
        await burst(pilot, "enter", "ctrl+u", "5", "enter", "down", "enter", "ctrl+u", "7", "enter")
        assert app.screen is screen
        frames = app.bridge.nck.data.settable_frames
        assert frames["G54"].trans["X"] == 5.0
        assert frames["G55"].trans["X"] == 7.0
        assert cursor.row == row + 1


async def test_diagnostics_vertical_softkey_right_after_view_key(tmp_path: Path) -> None:
    """Diagnostics: F6 (service drive) and Shift+F1 (Axis +) in one burst: the second axis shows."""
    app = trainer(tmp_path)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+a", "f6", "shift+f1")
        assert app.screen.view == "drive"
        assert app.screen.axis_index == 1


async def test_key_the_table_ignores_never_edits_the_dialog_opened_behind_it(tmp_path: Path) -> None:
    """Backspace or Ctrl+U on the tool list, then Enter, in one burst: the field shows the value.

    The table has no use for Backspace / Ctrl+U; before, such a key travelled back
    to the app behind the Enter and was run with the bindings of the dialog's field
    opened meanwhile (seen in tmux: Ctrl+U Enter opened an empty field, Backspace
    Enter turned 75.5 into 75.).
    """
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+o", "right")  # T1 D1 Length 1 (75.5)
        screen = app.screen
        for ignored in ("backspace", "ctrl+u", "delete", "end"):
            await burst(pilot, ignored, "enter")
            field = app.screen.query_one("Input")
            assert field.value == "75.5", (ignored, field.value)
            await burst(pilot, "escape")
            assert app.screen is screen
        assert table_cell(app, 0, 5) == "75.500"


async def test_typing_on_a_selected_cell_starts_its_input(tmp_path: Path) -> None:
    """A value typed on the selected cell replaces it, as on the control: the first
    character opens the input field with itself in place of the old value, the rest and
    Enter follow (issue 18, found in tmux: ``0.1`` Enter on Length 1 was dropped and Enter
    wrote the old value back). Tool list and work offsets, each as one burst."""
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+t", "alt+t", "alt+t", "alt+o", "right")  # keyswitch 3, Length 1
        screen = app.screen
        await burst(pilot, *"120.5", "enter", "right", *"-2", "enter")
        assert app.screen is screen
        assert table_cell(app, 0, 5) == "120.500"
        assert table_cell(app, 0, 6) == "-2.000"  # Length 2
        await burst(pilot, "f3", "down", *"7.25", "enter")  # work offsets overview, G54 X
        assert app.bridge.nck.data.settable_frames["G54"].trans["X"] == 7.25
