"""The simulation's material view (issue 24): the blank being cut, stepping, the editor link.

Real kernel, the editor's simulation worker (the AUTO run and the sweep off the key path);
keys one at a time and in bursts. The program defines its own tool (``$TC_DP…``, 002
L62525-62558) so that it runs on a kernel without tool data.
"""

from __future__ import annotations

import asyncio
import math
import os
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from hmi.child_job import ChildJob
from hmi.widgets.stock_view import (
    BLOCK_CUT,
    FEED,
    OUTLINE,
    HIGHLIGHT,
    SECTION,
    StockPicture,
    Viewport,
    render_pixels,
)
from nck.commands import SetKeyswitch
from nck.queries import RecordedCut
from nck.kernel import Nck
from nck.machine import load_machine

from hmi.app import HmiApp
from screens import program_runs
from tests.program_screens.conftest import SIZE, make_program_app, nc_files, settle

SLOTS = (
    'N10 WORKPIECE(,"",,"BOX",112,0,-20,-20,-10,-10,110,80)\n'
    "N12 $TC_DP1[1,1]=120 $TC_DP3[1,1]=75 $TC_DP6[1,1]=5\n"
    "N20 G17 G90 G54 T1 M6\n"
    "N30 D1 S3000 M3\n"
    "N40 G0 X10 Y10 Z2\n"
    "N50 G1 Z-5 F300\n"
    "N60 X90 F800\n"
    "N70 Y60\n"
    "N80 X10\n"
    "N90 Y10\n"
    "N100 G0 Z5\n"
    "N110 X50 Y35\n"
    "N120 G1 Z-8 F200\n"
    "N130 G2 X50 Y35 I15 J0 F600\n"
    "N140 G0 Z20\n"
    "N150 M30\n"
)


@pytest.fixture
def slots_dir(data_dir: Path) -> Path:
    (data_dir / "MPF" / "DEMO.MPF").write_text(SLOTS)
    return data_dir


async def open_simulation(pilot) -> None:
    await pilot.press("alt+n", "f3")
    await settle(pilot)
    await pilot.press("f5")
    await settle(pilot)


def _picture() -> StockPicture:
    heights = np.zeros((10, 20), dtype=np.float32)
    heights[:, 10:] = -4.0  # the right half cut 4 deep of 8
    return StockPicture(heights=heights, x0_mm=0.0, y0_mm=0.0, resolution_mm=1.0, z_mm=(-8.0, 0.0),
                        blank_x_mm=(0.0, 20.0), blank_y_mm=(0.0, 10.0),
                        starts=np.array([[2.0, 5.0, -4.0]]), ends=np.array([[18.0, 5.0, -4.0]]),
                        rapid=np.array([False]), lines=np.array([7]), shown_chords=1)


def test_top_view_is_darker_where_deeper() -> None:
    image = render_pixels(_picture(), "XY", Viewport(10.0, 5.0, 0.5), 40, 20, overlay=False)
    top = image[4, 6].astype(int)  # x 3.25, y 7.75: uncut
    cut = image[4, 30].astype(int)  # x 15.25: 4 deep
    assert cut.sum() < top.sum()


def test_front_section_shows_the_material_below_the_surface() -> None:
    picture = _picture()
    picture.tool_mm = (5.0, 5.0, 10.0)  # the section runs through Y 5
    image = render_pixels(picture, "XZ", Viewport(10.0, -4.0, 0.5), 40, 20, overlay=False)
    # v of row r: -4 - (r - 10 + 0.5) * 0.5; Z -2 is row 5, Z -6 row 13.
    assert (image[5, 6] == SECTION).all()  # x 3.25, z -2.25: under the uncut top
    assert not (image[5, 30] == SECTION).all()  # x 15.25: cut away down to -4
    assert (image[13, 30] == SECTION).all()  # z -6.25 is still there


def test_path_overlay_switches_and_highlights_the_block() -> None:
    port = Viewport(10.0, 5.0, 0.5)
    row = 10  # y 5 - (10 - 10 + 0.5) * 0.5 = 4.75: the row of the path at y 5
    with_path = render_pixels(_picture(), "XY", port, 40, 20, overlay=True)
    assert any((with_path[row - 1:row + 1, 10] == FEED).all(axis=1))
    without = render_pixels(_picture(), "XY", port, 40, 20, overlay=False)
    assert not any((without[row - 1:row + 1, 10] == FEED).all(axis=1))
    marked = render_pixels(_picture(), "XY", port, 40, 20, overlay=True, highlight_line=7)
    assert any((marked[row - 1:row + 1, 10] == HIGHLIGHT).all(axis=1))


async def test_simulation_cuts_the_blank_and_steps_block_by_block(slots_dir: Path) -> None:
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        assert screen.stock.display and not screen.toolpath.display
        simulation = screen._material
        assert simulation is not None and simulation.alarms == [] and simulation.events == []
        assert "no alarms" in screen.stock.status_text
        full = screen.stock.picture
        assert full.shown_chords == len(simulation.path.starts)
        assert float(full.heights.min()) == pytest.approx(-8.0)
        # three steps back in one burst: the block before is shown, the editor follows
        await pilot.press("shift+f6", "shift+f6", "shift+f6")
        await settle(pilot)
        blocks = simulation.blocks_in_order()
        line, chords = blocks[-4]
        assert screen.stock.highlight_line == line
        assert screen.editor.cursor_location[0] == line - 1
        assert screen.stock.picture.shown_chords == chords
        assert f"block {len(blocks) - 3}/{len(blocks)}" in screen.stock.status_text
        # the modal state at the shown block N110 G0 X50 Y35 (line 12): G0 in G17 G40 G54 G90
        # G94 (N20 and the reset states), T1 D1 (N20, N30), F800 still in force (N60), S3000 (N30)
        assert "line 12: G0 G17 G40 G54 G90 G94 T1 D1 F800 S3000" in screen.stock.status_text
        # one forward, singly
        await pilot.press("shift+f7")
        await settle(pilot)
        assert screen.stock.highlight_line == blocks[-3][0]
        # back to the start of the cut: the circle's pocket is not cut yet
        for _ in range(len(blocks)):
            await pilot.press("shift+f6")
        await settle(pilot)
        assert screen.stock.picture.shown_chords == blocks[0][1]
        assert float(screen.stock.picture.heights.min()) == pytest.approx(0.0)


async def test_opening_another_program_leaves_the_simulation(slots_dir: Path) -> None:
    """A program opened from the Program manager while the Program area shows a simulation opens
    in the editor: not beside the other program's cut, whose time and alarms the title would
    show, and F5 is the Simulation softkey again (in the simulation it zooms out)."""
    (slots_dir / "MPF" / "OTHER.MPF").write_text("N10 G0 X0 Y0 Z10\nN20 G1 X5 F100\nN30 M30\n")
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        assert screen.program.endswith("DEMO.MPF") and screen.simulating
        assert screen._material is not None
        await pilot.press("alt+n", "down", "f3")  # OTHER.MPF, in one burst
        await settle(pilot)
        screen = pilot.app.screen
        assert screen.program.endswith("OTHER.MPF")
        assert not screen.simulating and screen._material is None
        assert screen.editor.has_focus and not screen.stock.display
        await pilot.press("f5")
        await settle(pilot)
        assert screen.simulating
        lines = {int(line) for line in screen._material.path.lines}
        assert lines and lines <= {1, 2}  # OTHER's own blocks N10 and N20, none of DEMO's


def _record_jobs(monkeypatch) -> list:
    """Every child process the editor starts for a simulation (hmi.child_job.ChildJob), in order
    (the checks' child processes are left out: their job is the worker's ``check``)."""
    jobs: list[ChildJob] = []

    class RecordedJob(ChildJob):
        def __init__(self, job) -> None:
            super().__init__(job)
            if job.__name__ == "simulate":
                jobs.append(self)

    monkeypatch.setattr(program_runs, "ChildJob", RecordedJob)
    return jobs


async def test_the_editor_runs_the_program_once_for_both_views(slots_dir: Path, monkeypatch) -> None:
    """The toolpath view (Material off) draws the material simulation's own run: the program is
    run once per Recalculate, not once more for the toolpath."""
    jobs = _record_jobs(monkeypatch)
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        assert len(jobs) == 1 and jobs[0].result is screen._material
        simulation = screen._material
        assert len(screen.toolpath.pieces) == len(simulation.path.starts) > 0
        assert screen.toolpath.pieces[-1].end == tuple(simulation.path.ends[-1].tolist())


LONG_DWELL = "".join(f"N{10 * k} G4 F99999\n" for k in range(1, 5)) + "N50 M30\n"
"""Four dwells of the longest time G4 F takes (99,999.999 s, 001 L6410-6415): over a day of machine
time each, many seconds of computing for a run that is not given up."""


@pytest.fixture
def long_run(data_dir: Path, monkeypatch) -> list:
    """DEMO.MPF is :data:`LONG_DWELL`, its progress shown at every chance; the simulations' child
    processes are recorded (returned)."""
    (data_dir / "MPF" / "DEMO.MPF").write_text(LONG_DWELL)
    monkeypatch.setattr(program_runs, "PROGRESS_EVERY_S", 0.0)
    return _record_jobs(monkeypatch)


async def start_long_simulation(pilot):
    """Open DEMO.MPF, Simulation, wait until the progress shows; the program screen."""
    await pilot.press("alt+n", "f3")
    await settle(pilot)
    await pilot.press("f5")
    screen = pilot.app.screen
    for _ in range(1000):
        if "blocks" in screen.stock.status_text:
            break
        await pilot.pause()
    assert "calculating … " in screen.stock.status_text and "blocks" in screen.stock.status_text
    return screen


async def test_recalculate_and_leaving_give_up_the_runs_still_calculating(data_dir: Path, long_run) -> None:
    """A long simulation says how far it has come; Recalculate twice in a burst and going back to
    the editor drop the runs still calculating (each child process is stopped and waited for)
    instead of leaving them to run on beside the editor."""
    jobs = long_run
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        screen = await start_long_simulation(pilot)
        await pilot.press("f7", "f7")  # Recalculate, twice in a burst
        await pilot.press("f8")  # back to the editor
        await settle(pilot)
        assert not screen.simulating and screen._material is None
        assert len(jobs) == 3
        assert all(job.ended and job.result is None for job in jobs)
    for job in jobs:  # no process left behind: each was waited for
        with pytest.raises(ChildProcessError):
            os.waitpid(job.pid, os.WNOHANG)


async def test_leaving_the_panel_stops_a_simulation_still_calculating(data_dir: Path, long_run) -> None:
    """The panel ends (Ctrl+Q, the terminal closed) while a long simulation calculates: its child
    process is stopped and waited for with it, not left running on its own."""
    jobs = long_run
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await start_long_simulation(pilot)
        assert len(jobs) == 1
    # the editor's worker threads run in the loop's default executor; at the interpreter's exit
    # Python joins them, here the test does (each worker ends within one poll of its child)
    await asyncio.get_running_loop().shutdown_default_executor()
    assert jobs[0].ended and jobs[0].result is None
    with pytest.raises(ChildProcessError):
        os.waitpid(jobs[0].pid, os.WNOHANG)


async def test_workers_do_not_describe_themselves_by_their_arguments(slots_dir: Path, monkeypatch) -> None:
    """The editor's workers carry a fixed description: Textual would otherwise repr() the whole
    simulation (every chord, every modal state) and the program text in the UI thread at each
    start — for each Block key."""
    from nck.check import CheckContext
    from nck.simulation.run import Simulation

    described: list[str] = []
    monkeypatch.setattr(Simulation, "__repr__", lambda self: described.append("simulation") or "Simulation")
    monkeypatch.setattr(CheckContext, "__repr__", lambda self: described.append("setting") or "CheckContext")
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        await pilot.press("shift+f6", "shift+f6", "shift+f7")
        await settle(pilot)
        assert pilot.app.screen.stock.highlight_line is not None
    assert described == []


async def test_view_keys_singly_and_in_a_burst(slots_dir: Path) -> None:
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        stock = pilot.app.screen.stock
        await pilot.press("f2")
        assert stock.view == "XZ"
        await pilot.press("f3", "f4", "f4", "shift+f8")
        await pilot.pause()
        assert stock.view == "YZ" and stock.zoom == pytest.approx(2.25) and not stock.overlay
        await pilot.press("f6", "shift+f8", "f1")
        await pilot.pause()
        assert stock.view == "XY" and stock.zoom == 1 and stock.overlay
        await pilot.press("shift+f3")  # Material off: the toolpath alone
        await pilot.pause()
        assert pilot.app.screen.toolpath.display and not stock.display


async def test_the_blank_is_made_ready_for_the_next_step_back(slots_dir: Path) -> None:
    """While the operator looks at a picture, the blank is cut up to where the next Block ◀
    starts (the start of the block before the one shown), not left where the last look-up put
    it; what Block ◀ then shows is the same as without (the test above)."""
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        blocks = screen._material.blocks_in_order()
        assert screen._scrubber.chords == blocks[-3][1]  # the last block shown: ready for its predecessor
        await pilot.press("shift+f6")
        await settle(pilot)
        assert screen.stock.picture.shown_chords == blocks[-2][1]
        assert screen._scrubber.chords == blocks[-4][1]
        await pilot.press("shift+f7")  # forward: nothing made ready
        await settle(pilot)
        assert screen.stock.picture.shown_chords == blocks[-1][1] == screen._scrubber.chords


async def test_the_toolpath_view_draws_the_simulations_own_arrays(slots_dir: Path) -> None:
    """Material off shows the same run's path from the simulation's arrays (not one Python
    object per chord: for a long program that cost the screen most of a second per switch)."""
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        await pilot.press("shift+f3")  # Material off: the toolpath view is drawn
        await settle(pilot)
        path = screen._material.path
        assert screen.toolpath.display
        assert screen.toolpath.path.starts is path.starts and screen.toolpath.path.ends is path.ends
        assert screen.toolpath.pieces[-1].end == tuple(path.ends[-1].tolist())


async def test_simulation_reports_the_alarm_auto_stops_with(data_dir: Path) -> None:
    (data_dir / "MPF" / "DEMO.MPF").write_text("N10 G0 X10\nN20 G1 X20\nN30 M30\n")  # no feed: 10860
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        assert "alarm 10860 at line 2" in pilot.app.screen.stock.status_text


async def test_a_cycle_alarm_is_told_at_the_call_line(data_dir: Path) -> None:
    # CYCLE82 feeds to depth at its line 8 with the feed programmed before the call: none here
    (data_dir / "MPF" / "DEMO.MPF").write_text("N10 G0 X0 Y0 Z10\nN20 CYCLE82(5,0,2,-15,0,1)\nN30 M30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        assert "alarm 10860 at line 2 (in CYCLE82.SPF, line 8)" in screen.stock.status_text
        await pilot.press("shift+f3")  # Material off: the toolpath view says the same place
        await settle(pilot)
        assert "stopped at line 2 (in CYCLE82.SPF, line 8): 10860" in screen.toolpath.status_text


def simulation_then(*keys: str):
    """A snapshot's ``run_before``: open the simulation, press ``keys``, wait for the picture."""
    async def run_before(pilot) -> None:
        await open_simulation(pilot)
        await pilot.press(*keys)
        await settle(pilot)
    return run_before


def test_snapshot_top_view_partly_cut(snap_compare, slots_dir: Path) -> None:
    """SLOTS: the frame slot cut, the tool at the end of block N100, the circle still to come."""
    assert snap_compare(make_program_app(slots_dir), terminal_size=SIZE,
                        run_before=simulation_then("shift+f6", "shift+f6", "shift+f6", "shift+f6"))


def test_snapshot_front_section_partly_cut(snap_compare, slots_dir: Path) -> None:
    """The front section XZ through the tool, after the frame slot (N90)."""
    assert snap_compare(make_program_app(slots_dir), terminal_size=SIZE,
                        run_before=simulation_then("shift+f6", "shift+f6", "shift+f6", "shift+f6", "shift+f6", "f2"))


def test_snapshot_side_section_partly_cut(snap_compare, slots_dir: Path) -> None:
    """The side section YZ through the tool during the circle's plunge (N120), path off."""
    assert snap_compare(make_program_app(slots_dir), terminal_size=SIZE,
                        run_before=simulation_then("shift+f6", "shift+f6", "f3", "shift+f8"))


# A bar Ø40 from Z-60 to the face Z0; a turning tool (type 500, cutting edge position 3, nose
# 0.8, 002 L62525-62558) turns Ø36 to Z-30, then Ø30 to Z-15 (a shoulder), then returns.
SHAFT = (
    'N1 WORKPIECE(,"",,"CYLINDER",64,0,-60,-60,40)\n'
    "N2 $TC_DP1[1,1]=500 $TC_DP2[1,1]=3 $TC_DP3[1,1]=20 $TC_DP4[1,1]=40 $TC_DP6[1,1]=0.8\n"
    "N10 G18 G90 DIAMON G95 T1 D1\n"
    "N20 G97 S1000 M4\n"
    "N30 G0 X36 Z2\n"
    "N40 G1 Z-30 F0.2\n"
    "N50 X41\n"
    "N60 G0 Z2\n"
    "N70 X30\n"
    "N80 G1 Z-15\n"
    "N90 X41\n"
    "N100 G0 X80 Z50\n"
    "N110 M30\n"
)


def make_lathe_app(root: Path) -> HmiApp:
    """The HMI on a real lathe kernel (``lathe2``) with the programs of ``root``."""
    nck = Nck(machine=load_machine("lathe2"), programs=nc_files(root), referenced=True)
    nck.submit(SetKeyswitch(3))
    return HmiApp(nck, realtime=False)


@pytest.fixture
def shaft_dir(data_dir: Path) -> Path:
    (data_dir / "MPF" / "DEMO.MPF").write_text(SHAFT)
    return data_dir


async def test_lathe_simulation_turns_the_bar_without_false_rapid_cuts(shaft_dir: Path) -> None:
    """The lathe's material view is the half section of the bar; the rapid moves run outside
    the material, so the note says "no alarms" (the mill's Z-map said "rapid traverse into
    material" here), and the profile has the turned diameters."""
    app = make_lathe_app(shaft_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        simulation = screen._material
        assert simulation is not None and simulation.turning and simulation.events == []
        assert "no alarms" in screen.stock.status_text
        assert "rapid" not in screen.stock.status_text
        picture = screen.stock.picture
        assert picture.turning
        assert simulation.zmap.radius_at(-7.5) == pytest.approx(15.0)
        assert simulation.zmap.radius_at(-20.0) == pytest.approx(18.0)
        menu = screen.current_menu()
        for key in ("sim.xy", "sim.xz", "sim.yz"):  # greyed: the half section is a lathe's one view
            assert not menu.slot(menu.find(key)).allowed(screen, screen.access_level)
        await pilot.press("f2", "f1")  # the view softkeys leave a lathe's half section alone
        await pilot.pause()
        assert screen.stock.shown_view == "XZ"
        assert screen.area_hint == "Top view XY: not possible in this state"  # not the editor's read-only
        # A step back draws the same path: the same half-section arrays, whose overlay the view keeps.
        await pilot.press("shift+f6")
        await settle(pilot)
        assert screen.stock.picture is not picture and screen.stock.picture.shown_chords < picture.shown_chords
        assert screen.stock.picture.starts is picture.starts and screen.stock.picture.ends is picture.ends


async def test_lathe_toolpath_view_is_the_half_section(shaft_dir: Path) -> None:
    """Material off on the lathe shows the path in the plane the bar is drawn in: Z across, the
    radius up (the mill's XY view showed a lathe's path as one horizontal line); the view
    softkeys leave it so, as they leave the material view's half section."""
    app = make_lathe_app(shaft_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        await pilot.press("shift+f3", "f1")
        await settle(pilot)
        toolpath = screen.toolpath
        assert toolpath.display and toolpath.shown_view == "XZ"
        assert "Half section Z-X" in str(toolpath.render())
        # N40 (line 6) G1 Z-30 at X36 under DIAMON: ends at Z -30, radius 18 (tool tip, no TRC)
        n40 = [piece for piece in toolpath.pieces if piece.line == 6]
        assert n40 and n40[-1].end == pytest.approx((-30.0, 0.0, 18.0))


def test_snapshot_lathe_toolpath_view(snap_compare, shaft_dir: Path) -> None:
    """Material off on the lathe: the path as the half section, the block N80 marked."""
    assert snap_compare(make_lathe_app(shaft_dir), terminal_size=SIZE,
                        run_before=simulation_then(*["shift+f6"] * 3, "shift+f3"))


def test_half_section_draws_material_up_to_the_radius() -> None:
    """A profile of radius 10 over Z -20…-10 and 5 over Z -10…0: section pixels below it only."""
    heights = np.array([[10.0] * 10 + [5.0] * 10], dtype=np.float32)
    picture = StockPicture(heights=heights, x0_mm=-20.0, y0_mm=-0.5, resolution_mm=1.0, z_mm=(0.0, 10.0),
                           blank_x_mm=(-20.0, 0.0), blank_y_mm=(0.0, 0.0), turning=True)
    image = render_pixels(picture, "XZ", Viewport(-10.0, 5.0, 0.5), 40, 24, overlay=False)
    # pixel column c: z = -10 + (c - 20 + 0.5) * 0.5; row r: radius 5 - (r - 12 + 0.5) * 0.5
    assert (image[6, 4] == SECTION).all()  # z -17.75, radius 7.75: under the Ø20 part
    assert not (image[6, 30] == SECTION).all()  # z -4.75: turned down to radius 5
    assert (image[16, 30] == SECTION).all()  # radius 2.75


def test_snapshot_lathe_half_section_partly_cut(snap_compare, shaft_dir: Path) -> None:
    """The half section after the first pass (Ø36 to Z-30 and up, N50), the shoulder still to come."""
    assert snap_compare(make_lathe_app(shaft_dir), terminal_size=SIZE,
                        run_before=simulation_then(*["shift+f6"] * 5))


async def test_lathe_recording_shows_the_half_section_before_the_start(shaft_dir: Path) -> None:
    """Simultaneous recording on the lathe, before CYCLE START: the empty view is already the
    bar's half section (not the mill's top view) and the projection keys are greyed."""
    app = make_lathe_app(shaft_dir)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+u")
        await pilot.pause()
        await pilot.press("f8")
        await settle(pilot)
        screen = pilot.app.screen
        stock = screen.query_one("#simrec-stock")
        assert "next program start" in stock.status_text
        assert stock.shown_view == "XZ" and "Half section Z-X" in str(stock.render())
        menu = screen.current_menu()
        assert not menu.slot(menu.find("simrec.xy")).allowed(screen, screen.access_level)


async def start_recording(pilot) -> None:
    """AUTO, select DEMO.MPF (Select program, F7), Simult. recording (F8), NC START."""
    await pilot.press("alt+u")
    await pilot.pause()
    await pilot.press("f7")
    await pilot.pause()
    names = pilot.app.program_names()
    await pilot.press(*["down"] * [n.upper().endswith("DEMO.MPF") for n in names].index(True), "enter")
    await pilot.pause()
    await pilot.press("f8")
    await pilot.pause()
    stock = pilot.app.screen.query_one("#simrec-stock")
    assert "next program start" in stock.status_text
    await pilot.press("alt+g")
    await pilot.pause()


async def test_simultaneous_recording_grows_while_the_program_runs(slots_dir: Path) -> None:
    """Machine area, AUTO: the recording view shows the blank being cut as the program runs
    (the machine's own run, asked through the bridge) and ends as the editor's simulation."""
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await start_recording(pilot)
        stock = pilot.app.screen.query_one("#simrec-stock")
        shown = []
        for _ in range(60):
            app.bridge.advance(1.0)
            await pilot.pause()
            shown.append(stock.picture.shown_chords)
            if app.bridge.status.channel.channel_state == "reset":
                break
        await pilot.pause()
        assert shown == sorted(shown) and len(set(shown)) > 4  # it grew step by step
        assert stock.status_text.startswith("ended")
        assert float(stock.picture.heights.min()) == pytest.approx(-8.0)  # the circle's pocket
        await pilot.press("shift+f2", "minus", "f", "shift+f7")  # view keys and softkeys in a burst
        await pilot.pause()
        assert stock.view == "XZ" and stock.zoom == 1 and not stock.overlay


async def test_the_recording_is_drawn_four_times_a_second_while_running(slots_dir: Path) -> None:
    """While the program runs the panel gets 20 snapshots a second; the recording asks for the
    cut and draws it at most every 0.25 s of control time (screens.machine), and at once when
    the run ends."""
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await start_recording(pilot)
        screen = pilot.app.screen
        asked: list[float] = []
        ask = screen.ask

        def counting(question):
            if isinstance(question, RecordedCut):
                asked.append(app.bridge.status.time_s)
            return ask(question)

        screen.ask = counting
        for _ in range(40):  # two seconds of the run at the panel's refresh period
            app.bridge.advance(0.05)
            await pilot.pause()
        assert app.bridge.status.channel.channel_state == "active"
        assert 6 <= len(asked) <= 9
        assert all(later - earlier >= 0.25 - 1e-9 for earlier, later in zip(asked, asked[1:]))
        for _ in range(60):
            app.bridge.advance(1.0)
            await pilot.pause()
            if app.bridge.status.channel.channel_state == "reset":
                break
        await pilot.pause()
        stock = screen.query_one("#simrec-stock")
        assert stock.status_text.startswith("ended")
        assert float(stock.picture.heights.min()) == pytest.approx(-8.0)  # the circle's pocket


def test_snapshot_simultaneous_recording_partly_cut(snap_compare, slots_dir: Path) -> None:
    """The recording 12 s into the run: the frame slot partly cut, the tool on its way."""
    async def run_before(pilot) -> None:
        await start_recording(pilot)
        pilot.app.bridge.advance(12.0)
        await pilot.pause()
        await pilot.pause()

    assert snap_compare(make_program_app(slots_dir), terminal_size=SIZE, run_before=run_before)


async def test_program_beside_the_simulation_and_the_cursor_block_marks_its_cut(slots_dir: Path) -> None:
    """The program stands beside the simulation; the editor's cursor line marks its path (both
    views) and the material its block removed; Tab goes from the view to the editor and back."""
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        editor, stock = screen.editor, screen.stock
        assert editor.display and stock.display
        assert editor.region.width > 20 and editor.region.right <= stock.region.x  # side by side
        assert screen.focused is stock
        # to the editor, then down to line 7 (N60 X90 F800) in one burst
        await pilot.press("tab", *["down"] * 6)
        await settle(pilot)
        assert screen.focused is editor and editor.cursor_location[0] == 6
        assert stock.highlight_line == 7 and screen.toolpath.current_line == 7
        picture = stock.picture
        assert picture.cut_top is not None and picture.cut_bottom is not None
        zmap = screen._material.zmap

        def cell(x: float, y: float) -> tuple[int, int]:
            return int((y - zmap.y0_mm) / zmap.resolution_mm), int((x - zmap.x0_mm) / zmap.resolution_mm)

        # N60 cuts Y 10 ± 5 from X 10 to X 90 at Z-5 with the D10 end mill (N12); N50 plunged at X10
        assert picture.cut_top[cell(50.0, 10.0)] == pytest.approx(0.0)
        assert picture.cut_bottom[cell(50.0, 10.0)] == pytest.approx(-5.0)
        assert np.isnan(picture.cut_top[cell(50.0, 16.0)])  # beside the slot
        assert np.isnan(picture.cut_top[cell(10.0, 35.0)])  # N90's wall, not N60's
        assert np.isnan(picture.cut_top[cell(50.0, 35.0)])  # the circle (N130)
        # the removed strip: 80 x 10 x 5 = 4000 mm³ (the cells at 0.3 mm give the walls within 3 %)
        removed = np.nansum(picture.cut_top - picture.cut_bottom) * zmap.resolution_mm ** 2
        assert removed == pytest.approx(4000.0, rel=0.03)
        # the front section through Y 10 draws the removed material in the block's colour
        section = replace(picture, tool_mm=(50.0, 10.0, 20.0))
        image = render_pixels(section, "XZ", Viewport(50.0, -2.5, 0.5), 40, 20, overlay=False)
        # pixel row r: z = -2.5 - (r - 9.5) * 0.5, column c: x = 50 + (c - 19.5) * 0.5
        assert (image[9, 20] == BLOCK_CUT.astype(np.uint8)).all()  # x 50.25, z -2.25: removed by N60
        assert (image[19, 20] == SECTION).all()  # z -7.25: still there
        await pilot.press("tab")
        assert screen.focused is stock


async def test_run_to_cursor_and_playing_at_a_speed(slots_dir: Path, monkeypatch) -> None:
    """Run to cursor goes to the cursor's block; Start / Stop plays the blocks at the chosen speed
    (the test plays the time: the tick timer is set out of reach)."""

    monkeypatch.setattr(program_runs, "PLAY_TICK_S", 3600.0)
    app = make_program_app(slots_dir)
    async with app.run_test(size=SIZE) as pilot:
        await open_simulation(pilot)
        screen = pilot.app.screen
        blocks = screen._material.blocks_in_order()
        lines = [line for line, _chords in blocks]
        # the cursor on N110 (line 12), Speed + up to the top speed, Run to cursor: there at once
        await pilot.press("tab", *["down"] * 11, *["shift+f5"] * 7, "shift+f2")
        await settle(pilot)
        assert program_runs.SPEEDS_BLOCKS_S[screen._speed] == math.inf
        step = lines.index(12)
        assert screen._material_step == step and not screen.sim_playing
        assert screen.stock.picture.shown_chords == blocks[step][1]
        assert f"block {step + 1}/{len(blocks)}, line 12" in screen.stock.status_text
        # the cursor on the first block (N40, line 5): Run to cursor goes back there at once
        assert lines[0] == 5
        await pilot.press(*["up"] * 7, "shift+f2")
        await settle(pilot)
        assert screen._material_step == 0 and screen.stock.picture.shown_chords == blocks[0][1]
        # Speed - down to 1 block/s, the cursor on line 12: Run to cursor plays towards it
        await pilot.press(*["shift+f4"] * 10, *["down"] * 7, "shift+f2")
        await settle(pilot)
        assert program_runs.SPEEDS_BLOCKS_S[screen._speed] == 1.0
        assert screen.sim_playing and screen._material_step == 0
        assert screen.stock.status_text.startswith("▶ 1 blocks/s")
        screen.sim_tick(0.5)  # half a block due at 1 block/s: nothing yet
        await settle(pilot)
        assert screen._material_step == 0
        screen.sim_tick(0.5)
        await settle(pilot)
        assert screen._material_step == 1
        screen.sim_tick(60.0)  # a minute: it stops at the cursor's block
        await settle(pilot)
        assert screen._material_step == step
        assert not screen.sim_playing  # stopped at the cursor's block
        assert screen.editor.cursor_location[0] == 11  # playing to the cursor leaves it there
        # Start / Stop from the last block starts again at the first; Stop holds
        await pilot.press("shift+f1")
        await settle(pilot)
        assert screen.sim_playing
        await pilot.press("shift+f1")
        assert not screen.sim_playing


def test_top_view_draws_the_turned_blank_turned() -> None:
    """A square 20 x 20 turned by 45° (a set-up's box clamped at an angle): its outline runs
    through the corners (±14.14, 0), (0, ±14.14), not along its extents' rectangle."""
    half = 10.0 * math.sqrt(2.0)
    picture = replace(_picture(), blank_x_mm=(-half, half), blank_y_mm=(-half, half), x0_mm=-half, y0_mm=-half,
                      outline_xy=np.array([[half, 0.0], [0.0, half], [-half, 0.0], [0.0, -half]]))
    image = render_pixels(picture, "XY", Viewport(0.0, 0.0, 0.5), 80, 80, overlay=False)
    # pixel column c: x = (c - 39.5) * 0.5; row r: y = -(r - 39.5) * 0.5
    outline = np.all(image == OUTLINE, axis=2)
    assert outline[40, 68] or outline[39, 68]  # (14.25, -0.25) / (14.25, 0.25): the right corner
    assert outline[30, 58]  # x 9.25, y 4.75: on the edge x + y = 14.14 (within half a pixel)
    assert not outline[12, 12]  # (-13.75, 13.75): the extents' corner, outside the turned square
