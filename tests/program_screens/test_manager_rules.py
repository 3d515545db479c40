"""Pilot tests of the Program manager: the NC file-system rules as the operator meets them."""

from __future__ import annotations

from pathlib import Path

from tests.program_screens.conftest import SIZE, make_program_app


def hint(app) -> str:
    return str(app.screen.query_one("#dialog-line").render())


def listed(app) -> list[str]:
    return [e.name for e in app.screen.entries]


async def open_manager(pilot) -> None:
    await pilot.press("alt+n")
    await pilot.pause()


async def test_new_program_name_rules(data_dir: Path) -> None:
    """New refuses an invalid or existing name with a message; a valid name creates the file."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f2", *"1bad", "enter")
        await pilot.pause()
        assert "1BAD" in hint(app) and app.current_mode == "program_manager"
        await pilot.press("f2", *"demo", "enter")
        await pilot.pause()
        assert "already exists" in hint(app)
        assert listed(app) == ["DEMO.MPF"]


async def test_copy_paste_gets_a_free_name(data_dir: Path) -> None:
    """Copy + Paste in the same directory creates DEMO_1.MPF with the same content."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f4", "f5")  # Copy, Paste
        await pilot.pause()
        assert listed(app) == ["DEMO.MPF", "DEMO_1.MPF"]
        assert (data_dir / "MPF" / "DEMO_1.MPF").read_text() == (data_dir / "MPF" / "DEMO.MPF").read_text()


async def test_rename_rules(data_dir: Path) -> None:
    """Rename refuses bad and taken names; a good name renames the file."""
    (data_dir / "MPF" / "OTHER.MPF").write_text("M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f6", "ctrl+u", *"OTHER", "enter")  # DEMO → OTHER: taken
        await pilot.pause()
        assert "already exists" in hint(app)
        await pilot.press("f6", "ctrl+u", *"x y", "enter")  # invalid characters
        await pilot.pause()
        assert listed(app) == ["DEMO.MPF", "OTHER.MPF"]
        await pilot.press("f6", "ctrl+u", *"POCKET", "enter")
        await pilot.pause()
        assert listed(app) == ["OTHER.MPF", "POCKET.MPF"]
        assert (data_dir / "MPF" / "POCKET.MPF").read_text().startswith("; pocket")


async def test_delete_asks_and_cancel_keeps(data_dir: Path) -> None:
    """Delete asks first: Cancel keeps the file, Delete removes it."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f7")
        await pilot.pause()
        assert type(app.screen).__name__ == "ChoiceDialog"
        await pilot.press("enter")  # "Cancel" is the first choice
        await pilot.pause()
        assert (data_dir / "MPF" / "DEMO.MPF").exists()
        await pilot.press("f7", "down", "enter")  # "Delete"
        await pilot.pause()
        assert not (data_dir / "MPF" / "DEMO.MPF").exists()
        assert listed(app) == []


async def test_program_being_executed_cannot_be_renamed_or_deleted(data_dir: Path) -> None:
    """While DEMO.MPF runs (stopped at M0), Rename and Delete are refused; it stays marked ▶."""
    (data_dir / "MPF" / "DEMO.MPF").write_text("N10 G0 X5\nN20 M0\nN30 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f1")  # Execute
        await pilot.pause()
        assert app.current_mode == "machine"
        await pilot.press("alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=30)
        await open_manager(pilot)
        await pilot.pause()
        manager = app.screen
        mark, name = (str(cell) for cell in manager.table.get_row_at(0)[:2])
        assert (mark, name) == ("▶", "DEMO.MPF")
        await pilot.press("f7")
        await pilot.pause()
        assert "cannot be deleted" in hint(app)
        assert type(app.screen).__name__ == "ProgramManagerScreen"
        await pilot.press("f6")
        await pilot.pause()
        assert "cannot be renamed" in hint(app)
        assert (data_dir / "MPF" / "DEMO.MPF").exists()


async def test_import_export_and_search(data_dir: Path, tmp_path: Path, monkeypatch) -> None:
    """Export writes a local copy; Import brings a local file into SPF; Search finds it."""
    monkeypatch.chdir(tmp_path)  # short relative paths to type
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "contour.spf").write_text("G1 X1\nM17\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("shift+f2", "ctrl+u", *"outside", "enter")  # Export
        await pilot.pause()
        assert (outside / "DEMO.MPF").read_text() == (data_dir / "MPF" / "DEMO.MPF").read_text()
        await pilot.press("shift+f5")  # Subprograms
        await pilot.press("shift+f1", *"outside/contour.spf", "enter")  # Import
        await pilot.pause()
        assert listed(app) == ["CONTOUR.SPF"]
        await pilot.press("shift+f4")  # Part programs
        await pilot.pause()
        assert app.screen.directory == "MPF"
        await pilot.press("f8", *"tou", "enter")  # Search
        await pilot.pause()
        assert app.screen.directory == "SPF"
        assert app.screen.current_entry().name == "CONTOUR.SPF"


async def test_workpiece_folder(data_dir: Path) -> None:
    """New in Workpieces creates a folder with its main program; Enter lists the folder."""
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("shift+f6", "f2", *"shaft", "enter")
        await pilot.pause()
        assert listed(app) == ["SHAFT.WPD"]
        await pilot.press("enter")  # open the folder
        await pilot.pause()
        assert app.screen.directory == "WKS/SHAFT.WPD"
        assert listed(app) == ["SHAFT.MPF"]


async def test_keyswitch_0_may_not_edit(data_dir: Path) -> None:
    """At keyswitch 0 (level 7) New is refused and the editor opens the program read-only."""
    app = make_program_app(data_dir, keyswitch=0)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        await pilot.press("f2")  # New needs level 4
        await pilot.pause()
        assert "needs access level 4" in hint(app)
        assert type(app.screen).__name__ == "ProgramManagerScreen"
        await pilot.press("f3")  # Open is allowed: reading needs level 7
        await pilot.pause()
        screen = app.screen
        assert screen.program == "MPF/DEMO.MPF"
        assert screen.editor.read_only
        assert screen.read_only_reason == "editing needs access level 4"
        await pilot.press("alt+t", "alt+t", "alt+t")  # keyswitch 3: level 4
        await pilot.pause()
        await pilot.pause()
        assert not screen.editor.read_only


async def test_a_dangling_link_and_a_fifo_are_skipped_and_named(data_dir: Path) -> None:
    """An odd entry named like a program is left out and reported; the rest is listed."""
    import os

    (data_dir / "MPF" / "OTHER.MPF").write_text("M30\n")
    (data_dir / "MPF" / "DANGLING.MPF").symlink_to(data_dir / "nowhere")
    os.mkfifo(data_dir / "MPF" / "PIPE.MPF")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_manager(pilot)
        assert listed(app) == ["DEMO.MPF", "OTHER.MPF"]
        assert "DANGLING.MPF, PIPE.MPF" in hint(app) and "skipped" in hint(app)
