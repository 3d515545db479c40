"""SVG snapshots of the Program manager, the editor with an error mark, and the simulation.

Real kernel and NC file system, 160×48, file dates pinned (mtime and time zone),
no cursor blink; checks and the simulation run to completion before the picture.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from nck.exercise import load_exercises
from pytest_textual_snapshot import SVGImageExtension
from syrupy.assertion import SnapshotAssertion

from hmi.cycle_forms import cycle_forms
from tests.burst import burst
from tests.program_screens.conftest import (SIZE, keys_to_form, lathe_program_app, make_program_app, on_lathe,
                                            settle)

PINNED_NS = 1_790_000_000 * 10**9  # 2026-09-21 14:13 UTC


@pytest.fixture
def pinned(data_dir: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The data directory with a second program and a subprogram, every date pinned, TZ=UTC."""
    (data_dir / "MPF" / "POCKET.MPF").write_text("N10 G0 X0 Y0\nN20 M30\n")
    (data_dir / "SPF" / "CONTOUR.SPF").write_text("G1 X10\nM17\n")
    for folder in ("MPF", "SPF"):
        for path in (data_dir / folder).iterdir():
            os.utime(path, ns=(PINNED_NS, PINNED_NS))
    monkeypatch.setenv("TZ", "UTC")
    time.tzset()
    yield data_dir
    monkeypatch.undo()
    time.tzset()


def test_program_manager(snap_compare, pinned: Path) -> None:
    """Part programs listed with type, length and date; POCKET.MPF selected for execution (▶)."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "down", "f1")  # select POCKET.MPF
        await pilot.pause()
        await pilot.press("alt+n")
        await pilot.pause()

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_editor_with_error_mark(snap_compare, pinned: Path) -> None:
    """DEMO.MPF with a faulty block: gutter mark on line 4, alarm 12080 in the message line."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "f3")
        await pilot.pause()
        await pilot.press("down", "down", "down", "end", *" Y==2")
        pilot.app.screen.check_now()
        await settle(pilot)

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_simulation_side_view(snap_compare, pinned: Path) -> None:
    """Simulation of DEMO.MPF in the side view XZ: rapid moves dashed, feed moves solid."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        await pilot.press("f5")
        await settle(pilot)
        await pilot.press("shift+f3", "f2")  # Material off: the toolpath alone
        await pilot.pause()

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_simulation_top_view(snap_compare, pinned: Path) -> None:
    """Simulation of DEMO.MPF, top view XY: the 40 × 30 rectangle and the origin cross."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        await pilot.press("f5")
        await settle(pilot)
        await pilot.press("shift+f3")  # Material off: the toolpath alone
        await pilot.pause()

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_cycle_level_drilling_keys(snap_compare, pinned: Path) -> None:
    """Shift+F7 Cycles: F1 Drilling pressed, F2 Milling, F3 Turning greyed (a mill), F8 Back;
    the drilling keys on the vertical bar."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        await pilot.press("shift+f7")
        await settle(pilot)

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_cycle_level_positions_sub_level(snap_compare, pinned: Path) -> None:
    """Drilling, Positions: Line, Circle, Grid, Any positions and << Back on the vertical bar."""
    app = make_program_app(pinned)

    async def run_before(pilot) -> None:
        await pilot.press("alt+n", "f3")
        await settle(pilot)
        await pilot.press("shift+f7", "shift+f6")
        await settle(pilot)

    assert snap_compare(app, terminal_size=SIZE, run_before=run_before)


def test_program_manager_beside_the_exercise_window_at_120x36(snap_compare, pinned: Path) -> None:
    """An exercise runs: its side window (34 columns) beside the Program manager at the smallest
    terminal; the tree gives way, the list keeps Name, Type, Length and Date."""
    app = make_program_app(pinned)
    exercise = {e.exercise_id: e for e in load_exercises()}["03_single_block_flange"]
    app.exercise_report_dir = pinned / "reports"  # the report at the end: beside the test's data

    async def run_before(pilot) -> None:
        assert app.start_exercise(exercise).startswith("Exercise started")
        private = app.nc_session.session.data_dir
        for path in private.rglob("*.MPF"):
            os.utime(path, ns=(PINNED_NS, PINNED_NS))
        await pilot.press("alt+n")
        await pilot.pause()

    try:
        assert snap_compare(app, terminal_size=(120, 36), run_before=run_before)
    finally:
        app.end_exercise()


FORM_CURSOR_LINES = {"CYCLE83": 7, "POCKET3": 21, "CYCLE95": 1}
"""Fields the cursor goes down in a form before the picture: CYCLE83 on DAM (the sketch marks the
degression), POCKET3 on _RAD1 (a form longer than its window scrolls with the cursor), CYCLE95
on MID (after the contour's program name); every other form on its first field."""


@pytest.mark.parametrize("machine", ["mill", "lathe"])
async def test_cycle_forms(snapshot: SnapshotAssertion, pinned: Path, machine: str) -> None:
    """Every cycle form (Shift+F7, the menu, the cycle's keys; the turning cycles on the lathe):
    parameters with units and ranges, the help line and the sketch of the field under the cursor.

    One panel per machine opens the forms one after another (Escape, back to the editor's
    softkeys) and compares each picture with its own snapshot file, as ``snap_compare`` does
    for one picture: a panel started per form made the set cost a minute."""
    svg_snapshot = snapshot.use_extension(SVGImageExtension)
    cycles = [cycle for cycle in sorted(cycle_forms()) if on_lathe(cycle) == (machine == "lathe")]
    app = lathe_program_app(pinned) if machine == "lathe" else make_program_app(pinned)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f3")  # DEMO.MPF in the editor
        await settle(pilot)  # its check done: "no errors found" on the message line
        editor = app.screen
        for cycle in cycles:
            await burst(pilot, *keys_to_form(cycle), *["down"] * FORM_CURSOR_LINES.get(cycle, 0))
            await pilot.pause()
            await pilot.wait_for_scheduled_animations()
            await pilot.pause()
            assert app.export_screenshot(title=app.title, simplify=True) == svg_snapshot(name=cycle)
            await burst(pilot, "escape")
            await pilot.pause()
            editor.clear_softkey_levels()
