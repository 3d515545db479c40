"""SVG snapshots of every view of the Parameter and Setup areas (160×48, frozen clock, no blinking).

The HMI runs on the real kernel and a fresh NC data directory filled with a
few tools, offsets, R parameters and user variables (``conftest.fill``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.parameter_setup.conftest import SIZE, fill, trainer


def filled(tmp_path: Path):
    app = trainer(tmp_path)
    fill(app)
    return app


@pytest.mark.parametrize(("name", "keys"), [
    ("tools", ["alt+o", "down"]),
    ("wear", ["alt+o", "f2"]),
    ("wo_active", ["alt+o", "f3", "shift+f1"]),
    ("wo_overview", ["alt+o", "f3", "down", "down"]),
    ("wo_details", ["alt+o", "f3", "down", "down", "shift+f3"]),
    ("r_variables", ["alt+o", "f4", "down"]),
    ("user_variables", ["alt+o", "f5"]),
    ("setting_data", ["alt+o", "f6"]),
])
def test_parameter_views(snap_compare, tmp_path: Path, name: str, keys: list[str]) -> None:
    """Each view of the Parameter area at keyswitch position 2 (level 5: offsets yes, tools no)."""
    assert snap_compare(filled(tmp_path), terminal_size=SIZE, press=["alt+t", "alt+t", *keys])


def test_parameter_edit_dialog(snap_compare, tmp_path: Path) -> None:
    """The input field for a work offset with the datum, its meaning and the current value."""
    assert snap_compare(filled(tmp_path), terminal_size=SIZE,
                        press=["alt+t", "alt+t", "alt+o", "f3", "down", "enter"])


@pytest.mark.parametrize(("name", "keys"), [
    ("general", ["alt+s"]),
    ("channel", ["alt+s", "f2", "down"]),
    ("axis_y", ["alt+s", "f3", "shift+f3"]),
    ("display", ["alt+s", "f4"]),
    ("password", ["alt+s", "f6"]),
])
def test_setup_views(snap_compare, tmp_path: Path, name: str, keys: list[str]) -> None:
    """Each view of the Setup area at keyswitch position 0 (level 7: machine data dimmed)."""
    assert snap_compare(trainer(tmp_path), terminal_size=SIZE, press=keys)


def test_setup_search_with_pending_value(snap_compare, tmp_path: Path) -> None:
    """Search "VELO" in the axis data after EVENING stored MD32000[X] = 1200 (marked * until active)."""
    from nck import commands as c

    app = trainer(tmp_path)

    async def run_before(pilot) -> None:
        app.submit(c.EnterPassword("EVENING"))
        app.submit(c.WriteData("MD32000[X]", 1200))
        await pilot.press("alt+s", "f3", "shift+f1", *"VELO", "enter")

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)
