"""The header shows the active program influences in every area (issue 18).

002 L18120-18123: active single block is shown in the status line of the
operator interface; the other program influences of the Program control view
(dry run, M01, program test, rapid override, skip levels) are shown beside it
the same way, so the operator sees them from every area.
"""

from __future__ import annotations

from nck import commands as cmd
from nck.kernel import Nck

from hmi.app import HmiApp

SIZE = (160, 48)


def program_line(app: HmiApp) -> str:
    """The header's third line as the operator reads it (program and influences)."""
    header = app.screen.query_one("#header")
    return " ".join(str(header.query_one(f"#{name}").render())
                    for name in ("hdr-program", "hdr-influences"))


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
        assert line.split()[-6:] == ["SBL", "DRY", "M01", "PRT", "ROV", "SKP"], line
        await pilot.press("alt+n")
        await pilot.pause()
        assert program_line(app).split()[-6:] == ["SBL", "DRY", "M01", "PRT", "ROV", "SKP"]
        app.submit(cmd.SetProgramControl("dry_run", False))
        await pilot.pause()
        assert "DRY" not in program_line(app)
