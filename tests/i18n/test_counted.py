"""Counts in texts take the singular for exactly one, in both languages: "(1 entry)", not
"(1 entries)" — the Program manager's title line of a folder with one program, the simulation's
note, the class pack's import message."""

from __future__ import annotations

from pathlib import Path

import pytest

from hmi.i18n import N_, counted

from tests.program_screens.conftest import SIZE, make_program_app, nc_files

ENTRIES = (N_("({count} entry)"), N_("({count} entries)"))


@pytest.mark.parametrize(("count", "english"), [(0, "(0 entries)"), (1, "(1 entry)"), (2, "(2 entries)")])
def test_english(count: int, english: str) -> None:
    assert counted(count, *ENTRIES) == english


@pytest.mark.parametrize(("count", "german_text"), [(0, "(0 Einträge)"), (1, "(1 Eintrag)"), (12, "(12 Einträge)")])
def test_german(german: None, count: int, german_text: str) -> None:
    assert counted(count, *ENTRIES) == german_text


async def test_the_program_managers_folder_with_one_program(tmp_path: Path) -> None:
    root = tmp_path / "nc"
    nc_files(root)
    (root / "MPF" / "ONLY.MPF").write_text("G0 X0\nM30\n")
    app = make_program_app(root)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+n")
        await pilot.pause()
        title = str(app.screen.query_one("#pm-path").render())
        assert title.endswith("MPF   (1 entry)")
