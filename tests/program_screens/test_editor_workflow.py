"""Pilot tests of the Program manager and editor on the real kernel, driven by the keymap keys.

Checks run in a worker thread; the tests trigger them where the debounce timer
would (``check_now``) and wait for the worker, no sleeps.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import screens.program
from hmi.i18n import set_language

from tests.program_screens.conftest import SIZE, make_program_app, settle


async def test_create_fix_save_select_and_run(data_dir: Path) -> None:
    """New program, a faulty block gets its alarm mark, fixed, saved, executed in AUTO to the end."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n")  # PROGRAM MANAGER
        await pilot.pause()
        await pilot.press("f2", *"train1", "enter")  # New → name → editor opens
        await pilot.pause()
        screen = app.screen
        assert screen.AREA_ID == "program" and screen.program == "MPF/TRAIN1.MPF"
        await pilot.press("ctrl+end", *"N10 G0 X10 Y==5", "enter", *"N20 M30")
        screen.check_now()
        await settle(pilot)
        marks = screen.editor.error_marks
        assert [(m.line, m.number) for m in marks.values()] == [(1, 12080)]
        await pilot.press("shift+f1")  # next error
        await pilot.pause()
        assert screen.editor.cursor_location[0] == 1
        assert "12080" in str(screen.query_one("#prog-message").render())
        # fix the block: Y==5 → Y5
        await pilot.press("end", "backspace", "backspace", "backspace", "5")
        screen.check_now()
        await settle(pilot)
        assert screen.editor.error_marks == {}
        # the message about the faulty line went with its cause (issue 18)
        assert str(screen.query_one("#prog-message").render()) == "no errors found"
        await pilot.press("f4")  # Save
        await pilot.pause()
        saved = (data_dir / "MPF" / "TRAIN1.MPF").read_text()
        assert "N10 G0 X10 Y5" in saved and "N20 M30" in saved
        assert not screen.is_modified()
        await pilot.press("f6")  # Execute: AUTO, select, Machine area
        await pilot.pause()
        status = app.bridge.status
        assert status.channel.mode == "AUTO"
        assert status.channel.selected_program.upper().endswith("TRAIN1.MPF")
        assert app.current_mode == "machine"
        await pilot.press("alt+g")  # NC START
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30)
        status = app.bridge.advance(2.0)  # let the axes settle (following error)
        await pilot.pause()
        x = {a.name: a.position_wcs for a in status.axes}["X"]
        assert abs(x - 10.0) < 0.01
        assert not [a for a in status.alarms if a.number < 60000]


async def test_typing_is_checked_after_the_debounce(data_dir: Path) -> None:
    """Without any help from the test, the debounce timer starts the check and marks the line."""
    import screens.program_runs as program_module

    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        program_module.CHECK_DEBOUNCE_S = 0.01
        try:
            await pilot.press("alt+n", "f3")  # open DEMO.MPF
            await pilot.pause()
            screen = app.screen
            await pilot.press("ctrl+end", *"X=)")
            for _ in range(50):
                await settle(pilot)
                if screen.editor.error_marks:
                    break
                await pilot.pause(0.02)
            assert 9 in screen.editor.error_marks
        finally:
            program_module.CHECK_DEBOUNCE_S = 0.4


async def test_close_with_unsaved_changes_asks(data_dir: Path) -> None:
    """Close with changes asks; Discard closes without writing; Save writes."""
    app = make_program_app(data_dir)
    original = (data_dir / "MPF" / "DEMO.MPF").read_text()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")
        await pilot.pause()
        screen = app.screen
        await pilot.press(*"; note", "f8")  # type, Close
        await pilot.pause()
        assert type(app.screen).__name__ == "ChoiceDialog"
        await pilot.press("down", "enter")  # "Discard changes"
        await pilot.pause()
        assert screen.program is None
        assert (data_dir / "MPF" / "DEMO.MPF").read_text() == original
        assert app.current_mode == "program_manager"
        # again, this time Save
        await pilot.press("f3", *"; kept", "f8")
        await pilot.pause()
        await pilot.press("enter")  # "Save changes"
        await pilot.pause()
        assert (data_dir / "MPF" / "DEMO.MPF").read_text().startswith("; kept")


async def test_leaving_the_area_with_unsaved_changes_asks(data_dir: Path) -> None:
    """An area key with unsaved text: the question appears in the new area; Back returns."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")
        await pilot.pause()
        await pilot.press(*"G1", "alt+m")
        await pilot.pause()
        await pilot.pause()
        assert type(app.screen).__name__ == "ChoiceDialog"
        await pilot.press("up", "enter")  # last entry: "Back to the editor"
        await pilot.pause()
        assert app.current_mode == "program"
        assert app.screen.editor.text.startswith("G1")


async def test_crash_restore_from_the_journal(data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Text typed before a kill (journal written by the autosave timer) is offered after restart."""
    # the test calls autosave itself: the real timer (wall clock) fired in the middle of the keys
    # on a loaded machine and journalled the "N" of "N6"
    monkeypatch.setattr(screens.program, "AUTOSAVE_PERIOD_S", 3600.0)
    first = make_program_app(data_dir)
    async with first.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")
        await pilot.pause()
        await pilot.press(*"N5 G0 Z100", "enter")
        first.screen.autosave()  # what the autosave timer does every few seconds
        await pilot.press(*"N6")  # a keystroke after the last autosave is lost, as expected
        # the app is dropped here without saving or closing the editor (a kill)
    assert (data_dir / "MPF" / "DEMO.MPF").read_text().startswith("; pocket")

    second = make_program_app(data_dir)
    async with second.run_test(size=SIZE) as pilot:
        await pilot.press("alt+p")  # PROGRAM: the editor offers the unsaved text
        await pilot.pause()
        await pilot.pause()
        assert type(second.screen).__name__ == "ChoiceDialog"
        await pilot.press("enter")  # "Restore MPF/DEMO.MPF"
        await settle(pilot)
        screen = second.screen
        assert screen.program == "MPF/DEMO.MPF"
        assert screen.editor.text.startswith("N5 G0 Z100\n; pocket")
        assert screen.is_modified()
        await pilot.press("f4")  # save: the journal entry is gone
        await pilot.pause()
        assert screen.journal.entries() == []
        assert (data_dir / "MPF" / "DEMO.MPF").read_text().startswith("N5 G0 Z100")


async def test_binary_file_opens_read_only(data_dir: Path) -> None:
    """A file that is not UTF-8 opens read-only with a message; typing changes nothing."""
    (data_dir / "MPF" / "BLOB.MPF").write_bytes(b"\xff\xfe\x00\x01G1 X\x80\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")  # BLOB.MPF sorts before DEMO.MPF
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/BLOB.MPF"
        assert screen.editor.read_only
        assert "not a UTF-8 text file" in str(screen.query_one("#dialog-line").render())
        before = screen.editor.text
        await pilot.press("a", "b", "f4")
        await pilot.pause()
        assert screen.editor.text == before
        assert (data_dir / "MPF" / "BLOB.MPF").read_bytes().startswith(b"\xff\xfe")


async def test_a_program_that_cannot_be_read_is_named_once(data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A program too large to read: the editor says so naming the program once, in both languages."""
    monkeypatch.setattr("nck.storage.MAX_IMPORT_BYTES", 1000)
    (data_dir / "MPF" / "BIG.MPF").write_text("G1 X1\n" * 200)  # 1200 bytes
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")  # BIG.MPF sorts before DEMO.MPF
        await pilot.pause()
        said = str(app.screen.query_one("#dialog-line").render())
        assert said == "Not opened: MPF/BIG.MPF: larger than 1000 bytes"
        set_language("de")
        try:
            app.screen.open_program("MPF/BIG.MPF")
            await pilot.pause()
            said = str(app.screen.query_one("#dialog-line").render())
        finally:
            set_language("en")
        assert said == "Nicht geöffnet: MPF/BIG.MPF: größer als 1000 Byte"


async def test_running_program_is_read_only(data_dir: Path) -> None:
    """While DEMO.MPF is executed (stopped at M0), the editor refuses edits."""
    (data_dir / "MPF" / "HOLD.MPF").write_text("N10 G0 X5\nN20 M0\nN30 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n")
        await pilot.pause()
        await pilot.press("down", "f1")  # HOLD.MPF (second row), Execute
        await pilot.pause()
        assert app.bridge.status.channel.selected_program.upper().endswith("HOLD.MPF")
        await pilot.press("alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=30)
        await pilot.pause()
        assert app.bridge.status.channel.channel_state != "reset"
        await pilot.press("alt+n")
        await pilot.pause()
        await pilot.press("f3")  # open HOLD.MPF (cursor stays on it)
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/HOLD.MPF"
        assert screen.editor.read_only
        await pilot.press("x")
        assert screen.editor.text.startswith("N10 G0 X5")
        assert screen.read_only_reason == "program is being executed"
        await pilot.press("alt+q")  # RESET: still selected, no longer executed
        app.bridge.advance(0.1)
        await pilot.pause()
        await pilot.pause()
        assert app.bridge.status.channel.channel_state == "reset"
        await pilot.press("f10")  # close the read-only view and open it again
        await pilot.pause()
        await pilot.press("alt+n", "f3")
        await pilot.pause()
        assert app.screen.program == "MPF/HOLD.MPF"
        assert not app.screen.editor.read_only  # a selected program in reset may be fixed


async def test_search_replace_renumber_undo(data_dir: Path) -> None:
    """Search finds, Replace all replaces, Renumber numbers blocks by 10, Undo restores."""
    (data_dir / "MPF" / "NUM.MPF").write_text("G0 X0\nG1 X5 F100\nG1 X7\nM30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "f3")  # DEMO, NUM → NUM.MPF is the second row
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/NUM.MPF"
        await pilot.press("f2", *"g1")  # Search bar, type
        await pilot.press("enter")
        await pilot.pause()
        assert screen.editor.selection.start == (1, 0)
        await pilot.press("tab", *"G2", "f3")  # replace field, Replace all
        await pilot.pause()
        assert screen.editor.text == "G0 X0\nG2 X5 F100\nG2 X7\nM30\n"
        await pilot.press("f8")  # back from search
        await pilot.press("f3")  # Renumber
        await pilot.pause()
        assert screen.editor.text == "N10 G0 X0\nN20 G2 X5 F100\nN30 G2 X7\nN40 M30\n"
        await pilot.press("shift+f5")  # Undo
        await pilot.pause()
        assert screen.editor.text == "G0 X0\nG2 X5 F100\nG2 X7\nM30\n"


@pytest.mark.parametrize(("away", "program"),
                         [(("alt+m", "alt+p"), "MPF/NUM.MPF"), (("alt+n", "up", "enter"), "MPF/DEMO.MPF")],
                         ids=["other-area-and-back", "another-program"])
async def test_the_search_bar_closes_with_its_softkeys(data_dir: Path, away: tuple[str, ...], program: str) -> None:
    """Leaving the editor's area resets its softkeys to the top level; the search bar goes with
    its level, so the editor never shows a search bar under the top-level softkeys (F1 there is
    Edit, not Find next)."""
    (data_dir / "MPF" / "NUM.MPF").write_text("G0 X0\nG1 X5 F100 Z-1\nM30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "enter", "f2", "Z")  # NUM.MPF, Search bar, type
        await pilot.pause()
        screen = app.screen
        bar = screen.query_one("#prog-search")
        assert bar.display and screen.current_menu().find("program.find_next") is not None
        await pilot.press(*away)
        await pilot.pause()
        assert app.screen is screen and screen.program == program
        assert not bar.display and not screen.search_open
        assert screen.current_menu().find("program.search") is not None
        await pilot.press("f2", "enter")  # the search opens again (with its text) and finds
        await pilot.pause()
        assert bar.display
        assert screen.editor.selection.start[0] == 1  # Z on the second line of either program


async def test_the_check_runs_again_when_the_nc_data_changed_meanwhile(data_dir: Path) -> None:
    """A program calling a tool the table lacks is marked (17191, 002 L58219); the trainee
    creates the tool in the Parameter area and comes back: the program is checked again on the
    new data and the mark goes. Coming back with nothing changed starts no check."""
    from nck import commands as cmd

    (data_dir / "MPF" / "TOOL.MPF").write_text("N10 T7 D1 M6\nN20 G0 X10\nN30 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "enter")
        await settle(pilot)
        screen = app.screen
        assert screen.program == "MPF/TOOL.MPF"
        assert [(m.line, m.number) for m in screen.editor.error_marks.values()] == [(0, 17191)]
        checks = screen._generation
        await pilot.press("alt+o", "alt+p")  # away and back, nothing changed: no new check
        await settle(pilot)
        assert screen._generation == checks
        await pilot.press("alt+o")
        app.submit(cmd.WriteData("$TC_DP1[7,1]", 120))  # the tool: an end mill T7 D1
        app.submit(cmd.WriteData("$TC_DP3[7,1]", 80.0))
        await pilot.press("alt+p")
        await settle(pilot)
        assert screen._generation == checks + 1
        assert screen.editor.error_marks == {}


async def test_mark_copy_paste(data_dir: Path) -> None:
    """Edit → Mark, move, Copy, move, Paste duplicates the marked block."""
    (data_dir / "MPF" / "NUM.MPF").write_text("A1\nB2\nC3\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "f3")
        await pilot.pause()
        screen = app.screen
        await pilot.press("f1", "f1", "down", "f2")  # Edit, Mark, cursor down, Copy
        await pilot.pause()
        await pilot.press("ctrl+end", "f4")  # Paste at the end
        await pilot.pause()
        assert screen.editor.text == "A1\nB2\nC3\nA1\n"


MARKING = "Marking: move the cursor, then Copy / Cut / Delete"


@pytest.mark.parametrize("leave", [("f8",), ("f10",), ("f3",), ("f5",), ("ctrl+end", "f4")],
                         ids=["back", "menu-recall", "cut", "delete", "paste"])
async def test_the_marking_line_goes_when_marking_ends(data_dir: Path, leave: tuple[str, ...]) -> None:
    """Edit → Mark says how to mark; Back, MENU RECALL, Cut, Delete and Paste end the marking, and
    the dialog line no longer says it."""
    (data_dir / "MPF" / "NUM.MPF").write_text("A1\nB2\nC3\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "f3")
        await pilot.pause()
        screen = app.screen
        line = screen.query_one("#dialog-line")
        await pilot.press("f1", "f1", "down")  # Edit, Mark, cursor down
        await pilot.pause()
        assert str(line.render()) == MARKING
        app.copy_to_clipboard("Z9\n")
        await pilot.press(*leave)
        await pilot.pause()
        assert str(line.render()) == ""
        assert screen._mark_anchor is None


async def test_simulation_shows_the_toolpath(data_dir: Path) -> None:
    """Simulation draws the moves of DEMO.MPF; views and zoom by softkeys; F8 back to the editor."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        screen = app.screen
        await pilot.press("f5")  # Simulation
        await settle(pilot)
        pieces = screen.toolpath.pieces
        assert len(pieces) >= 6
        feed_ends = {(round(p.end[0], 3), round(p.end[1], 3)) for p in pieces if not p.rapid}
        assert {(40.0, 0.0), (40.0, 30.0), (0.0, 30.0), (0.0, 0.0)} <= feed_ends
        assert any(p.rapid for p in pieces)
        await pilot.press("f2")  # XZ
        assert screen.toolpath.view == "XZ"
        await pilot.press("f4", "f4")  # zoom + twice
        assert screen.toolpath.zoom > 2
        await pilot.press("f6")  # fit
        assert screen.toolpath.zoom == 1
        await pilot.press("f8")  # back to the editor
        await pilot.pause()
        assert not screen.simulating and screen.editor.display


async def test_large_program_opens_and_scrolls(data_dir: Path) -> None:
    """A 200,000-line program opens, scrolls to the end, and its check marks the last line."""
    # 3,700 distinct blocks repeated: the check's per-line cache keeps the test quick
    lines = [f"G1 X{i % 100} Y{i % 37} F500" for i in range(1, 200_000)] + ["X=)"]
    (data_dir / "MPF" / "BIG.MPF").write_text("\n".join(lines))
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f3")  # BIG.MPF is the first row
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/BIG.MPF"
        await pilot.press("ctrl+end", "pageup", "pageup")
        await pilot.pause()
        assert screen.editor.document.line_count == 200_000
        assert screen.editor.cursor_location[0] > 199_000
        await settle(pilot)
        assert 199_999 in screen.editor.error_marks


async def test_simulation_marks_the_current_block_in_auto(data_dir: Path) -> None:
    """While the program runs in AUTO (single block), the simulation marks the executing block."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f1")  # Execute DEMO.MPF → Machine area
        await pilot.pause()
        assert app.current_mode == "machine"
        await pilot.press("alt+k", "alt+g", "alt+g", "alt+g")  # single block: three blocks
        app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=30)
        await pilot.press("alt+n", "f3")  # open DEMO.MPF in the editor (read-only: in use)
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/DEMO.MPF"
        await pilot.press("f5")  # Simulation
        await settle(pilot)
        app.bridge.advance(0.05)
        await pilot.pause()
        block = app.bridge.status.channel.current_block
        assert block is not None and block.line > 1
        assert screen.toolpath.current_line == block.line
        assert any(p.line == block.line for p in screen.toolpath.pieces)


async def test_a_refused_save_says_why_and_a_bug_is_not_hidden(data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Save refused by the NC file system: the dialog line says why, naming the program once (German
    too); any other exception is a bug and propagates instead of becoming a panel message."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "down", "f3")  # DEMO.MPF
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/DEMO.MPF"
        monkeypatch.setattr("nck.storage.MAX_IMPORT_BYTES", 10)  # the text no longer fits the NC memory
        assert screen.action_save() is False
        said = str(screen.query_one("#dialog-line").render())
        assert said == "Not saved: MPF/DEMO.MPF is too large for the NC memory"
        set_language("de")
        try:
            screen.action_save()
            said = str(screen.query_one("#dialog-line").render())
        finally:
            set_language("en")
        assert said == "Nicht gespeichert: MPF/DEMO.MPF ist zu groß für den NC-Speicher"

        def broken_save(path: str, text: str) -> None:
            raise ZeroDivisionError("a bug")

        monkeypatch.setattr(screen.files.fs, "save", broken_save)
        with pytest.raises(ZeroDivisionError):
            screen.action_save()


async def test_an_unreadable_nc_folder_lists_no_programs_and_a_bug_is_not_hidden(
        data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The program selection's list: an NC folder the disk refuses reads as no programs; any
    other exception in the listing is a bug and propagates (it is not shown as an empty list)."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert "MPF/DEMO.MPF" in app.program_names()

        def refused(self: object) -> list[object]:
            raise PermissionError(13, "Permission denied")

        monkeypatch.setattr("nck.storage.NcFileSystem.all_programs", refused)
        assert app.program_names() == []

        def broken(self: object) -> list[object]:
            raise ZeroDivisionError("a bug")

        monkeypatch.setattr("nck.storage.NcFileSystem.all_programs", broken)
        with pytest.raises(ZeroDivisionError):
            app.program_names()


async def test_a_cycle_alarm_is_marked_on_the_call_and_says_where(data_dir: Path) -> None:
    """A cycle called without a feed stops in the cycle (10860 at CYCLE82.SPF line 8): the mark
    is on the call line, Shift+F1 goes there and the message names the cycle's line (before,
    the mark went to line 8 of the program shown, which had 2 lines: nothing to go to)."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n", "f2", *"holes", "enter")
        await pilot.pause()
        screen = app.screen
        await pilot.press("ctrl+end", *"N10 G0 X0 Y0 Z10", "enter", *"N20 CYCLE82(5,0,2,-15,0,1)", "enter",
                          *"N30 M30", "ctrl+home")
        screen.check_now()
        await settle(pilot)
        assert [(m.line, m.number) for m in screen.editor.error_marks.values()] == [(2, 10860)]
        await pilot.press("shift+f1")  # next error
        await pilot.pause()
        assert screen.editor.cursor_location[0] == 2
        message = str(screen.query_one("#prog-message").render())
        assert "10860" in message and "(in CYCLE82.SPF, line 8)" in message
