"""The header shows the active program influences in every area (issue 18).

002 L18120-18123: active single block is shown in the status line of the
operator interface; the other program influences of the Program control view
(dry run, M01, program test, rapid override, skip levels) are shown beside it
the same way, so the operator sees them from every area.
"""

from __future__ import annotations

from nck import commands as cmd
from nck.interp.sources import MemorySource
from nck.kernel import Nck

from hmi.app import HmiApp
from tests.burst import burst
from tests.hmi.screen_rows import screen_rows

SIZE = (160, 48)


def program_line(app: HmiApp) -> str:
    """The header's third row as the terminal shows it (program, influences, overrides)."""
    return screen_rows(app).get(app.screen.query_one("#hdr-line3").region.y, "")


async def test_influences_shown_in_every_area() -> None:
    """None shown at power on; switched on, each shows in Machine and in Program manager."""
    app = HmiApp(Nck(), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause()
        for word in ("SBL", "DRY", "M01", "PRT", "ROV", "SKP"):
            assert word not in program_line(app)
        await pilot.press("alt+k")  # single block on (keymap), then the others from the softkeys' commands
        for name, value in (("dry_run", True), ("m01", True), ("program_test", True),
                            ("rapid_override", True), ("skip_levels", frozenset({1}))):
            app.submit(cmd.SetProgramControl(name, value))
        await pilot.pause()
        line = program_line(app)
        assert "SBL DRY M01 PRT ROV SKP" in line, line
        await pilot.press("alt+n")
        await pilot.pause()
        assert "SBL DRY M01 PRT ROV SKP" in program_line(app)
        app.submit(cmd.SetProgramControl("dry_run", False))
        await pilot.pause()
        assert "DRY" not in program_line(app)


async def test_single_block_switched_on_while_a_program_runs_shows_in_the_header() -> None:
    """SBL switched on at run time appears in the header as drawn, not only in its text.

    The influences field started with no text; before the fix its width stayed 0
    (the update skipped the layout) and SBL never reached the screen.
    """
    nck = Nck(programs=MemorySource({"LONG.MPF": "G1 X100 F100\nX0\nM30\n"}), referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+u")
        assert app.submit(cmd.SelectProgram("LONG.MPF")) == cmd.Accepted()
        await burst(pilot, "alt+m", "alt+g")
        app.bridge.advance(0.5)
        assert app.bridge.status.channel.program_state == "running"
        await pilot.pause()
        assert "SBL" not in program_line(app)
        await burst(pilot, "alt+k")
        app.bridge.advance(0.1)
        await pilot.pause()
        assert "SBL" in program_line(app), program_line(app)
        await burst(pilot, "alt+k", "alt+n")
        assert "SBL" not in program_line(app)
