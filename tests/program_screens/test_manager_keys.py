"""Program manager: Home/End/PgUp/PgDn in the file list; one program path however it is selected (issue 18).

Keys are sent as bursts (:func:`tests.burst.burst`).
"""

from __future__ import annotations

from pathlib import Path

from tests.burst import burst
from tests.program_screens.conftest import SIZE, make_program_app, settle

PROGRAMS = 60
"""More entries than the list shows at once (a page at 160×48 is about 35 rows)."""


def fill(data_dir: Path) -> list[str]:
    """Part programs PART00.MPF … PART59.MPF (names begin with two letters) besides DEMO.MPF; their names in list order."""
    for number in range(PROGRAMS):
        (data_dir / "MPF" / f"PART{number:02d}.MPF").write_text("M30\n")
    return sorted(["DEMO.MPF"] + [f"PART{n:02d}.MPF" for n in range(PROGRAMS)])


async def test_home_end_page_keys_move_in_the_file_list(data_dir: Path) -> None:
    """End: last entry; Home: first; PgDn a page down, PgUp back up."""
    names = fill(data_dir)
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n")
        await settle(pilot)
        screen = app.screen
        table = screen.table
        assert app.focused is table
        await burst(pilot, "end")
        assert screen.current_entry().name == names[-1]
        await burst(pilot, "home")
        assert screen.current_entry().name == names[0]
        await burst(pilot, "pagedown")
        page = table.cursor_row
        assert page >= 10
        await burst(pilot, "pageup")
        assert table.cursor_row == 0
        await burst(pilot, "pagedown", "pagedown", "pageup")
        assert table.cursor_row == min(2 * page, len(names) - 1) - page


async def test_program_path_shown_the_same_from_manager_and_from_f7(data_dir: Path) -> None:
    """Execute in the manager and F7 in AUTO give the same header text for the same program."""
    app = make_program_app(data_dir, keyswitch=3)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n")
        await settle(pilot)
        app.screen.press_softkey_id("pm.execute")
        await settle(pilot)
        from_manager = app.bridge.status.channel.selected_program
        header_manager = str(app.screen.query_one("#hdr-program").render()).strip()
        await burst(pilot, "alt+m", "f7", "enter")  # AUTO, Select program: DEMO.MPF (the only one)
        from_dialog = app.bridge.status.channel.selected_program
        header_dialog = str(app.screen.query_one("#hdr-program").render()).strip()
        assert from_manager == from_dialog
        assert header_manager == header_dialog


async def test_text_typed_after_new_goes_below_the_header(data_dir: Path) -> None:
    """F2 New, name, Enter and the first blocks in one burst: the blocks follow the header line.

    Seen in tmux: the editor opened with the cursor on line 1, so the blocks were typed
    in front of ``; TRAIN.MPF`` and the header ended up behind the last block.
    """
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f2", *"train", "enter", *"G0 X1", "enter", *"M30")
        await settle(pilot)
        assert app.screen.program == "MPF/TRAIN.MPF"
        assert app.screen.editor.text == "; TRAIN.MPF\nG0 X1\nM30"
