"""Exports of the Diagnostics area (alarm log CSV/text) never write through a link and ask before replacing.

A link named ``alarm_log.csv`` in the export folder would send the log into
another file (and wipe it); an existing file is replaced only after the
operator confirms (Y/Enter yes, N/Esc no).
"""

from __future__ import annotations

from pathlib import Path

from tests.diagnostics.conftest import SIZE, app_on, kernel
from tests.diagnostics.test_pilot import open_diagnostics


async def test_alarm_log_export_refuses_a_link_and_asks_before_replacing(tmp_path: Path) -> None:
    victim = tmp_path / "victim.txt"
    victim.write_text("outside\n")
    (tmp_path / "alarm_log.csv").symlink_to(victim)
    (tmp_path / "alarm_log.txt").write_text("older export\n")
    app = app_on(kernel())
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_diagnostics(pilot)
        screen.export_dir = tmp_path
        await pilot.press("f3", "shift+f3")  # Alarm log, Export CSV
        await pilot.pause()
        assert victim.read_text() == "outside\n" and (tmp_path / "alarm_log.csv").is_symlink()
        assert "not a regular file" in str(app.screen.query_one("#dialog-line").render())
        await pilot.press("shift+f4")  # Export text: the file exists, so a question
        await pilot.pause()
        assert type(app.screen).__name__ == "ConfirmDialog"
        await pilot.press("n")
        await pilot.pause()
        assert (tmp_path / "alarm_log.txt").read_text() == "older export\n"
        await pilot.press("shift+f4", "y")
        await pilot.pause()
        assert (tmp_path / "alarm_log.txt").read_text() != "older export\n"
        assert "Alarm log written" in str(app.screen.query_one("#dialog-line").render())


async def test_an_existing_alarm_log_csv_is_replaced_only_when_the_operator_says_yes(tmp_path: Path) -> None:
    (tmp_path / "alarm_log.csv").write_text("older export\n")
    app = app_on(kernel())
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_diagnostics(pilot)
        screen.export_dir = tmp_path
        await pilot.press("f3", "shift+f3", "escape")  # Alarm log, Export CSV, then No (Esc)
        await pilot.pause()
        assert (tmp_path / "alarm_log.csv").read_text() == "older export\n"
        assert type(app.screen).__name__ != "ConfirmDialog"
        await pilot.press("shift+f3")
        await pilot.pause()
        assert type(app.screen).__name__ == "ConfirmDialog"
        await pilot.press("enter")  # Yes
        await pilot.pause()
        assert (tmp_path / "alarm_log.csv").read_text().splitlines()[0] != "older export"
