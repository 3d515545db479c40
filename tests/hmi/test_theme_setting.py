"""Theme chosen in Setup and kept in the retained data (issue 27).

Setup ▸ Password ▸ Change theme (Shift+F6) shows one vertical softkey per theme; the choice
applies at once, is written to the retained section ``display`` (atomically, as every
section) and comes back after a restart on the same data directory. A theme chosen in the
palette is kept the same way. A damaged theme entry is refused like any bad section (the
backup is used).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from hmi.app import make_app
from nck.persistence import RETAINED_DIR, BadFile, RetainedData, parse_section, section_text
from tests.burst import burst
from tests.hmi.conftest import SIZE


def kept_theme(data_dir: Path) -> str:
    document = json.loads((data_dir / RETAINED_DIR / "display.json").read_text())
    return document["data"]["theme"]


async def test_theme_chosen_in_setup_is_kept_over_a_restart(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    app = make_app(data_dir=str(data_dir), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        assert app.theme == "sinumerik"
        await burst(pilot, "alt+s", "f6", "shift+f6")  # Setup, Password, Change theme
        assert app.screen.view == "theme"
        labels = [key.label for key in app.screen.current_menu().vertical if key is not None]
        assert labels == ["Dark\n(default)", "Light", "High\ncontrast"]
        await burst(pilot, "shift+f2")  # Light
        assert app.theme == "operate-light"
        assert kept_theme(data_dir) == "operate-light"
        await pilot.press("ctrl+q")
    app = make_app(data_dir=str(data_dir), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.theme == "operate-light"
        await burst(pilot, "ctrl+p", *"theme", "enter")  # the palette's Theme command
        await burst(pilot, *"high", "enter")
        assert app.theme == "high-contrast"
        await pilot.pause()
        assert kept_theme(data_dir) == "high-contrast"


async def test_unknown_kept_theme_falls_back_to_the_default(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    app = make_app(data_dir=str(data_dir), realtime=False)
    app.nc_session.theme = "no-such-theme"
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        assert app.theme == "sinumerik"


def test_display_section_without_theme_or_with_a_bad_one() -> None:
    """A display file written before the theme was kept loads (default theme); a theme entry
    that cannot be a name makes the section bad (the loader then takes its backup)."""
    rd = RetainedData()
    rd.theme = "operate-light"
    text = section_text("display", rd)
    loaded = RetainedData()
    parse_section("display", text.encode(), loaded)
    assert loaded.theme == "operate-light"
    document = json.loads(text)
    del document["data"]["theme"]
    old = RetainedData()
    parse_section("display", json.dumps(document).encode(), old)
    assert old.theme == "" and old.language == "en"
    document["data"]["theme"] = "../../etc"
    with pytest.raises(BadFile):
        parse_section("display", json.dumps(document).encode(), RetainedData())
