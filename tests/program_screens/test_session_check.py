"""The editor's check and simulation run on the session's machine, tools, offsets and R parameters (issue 21).

Before, both ran on the default mill with fresh NC data: a program that is right only with
the session's tool table failed the check (17191), its simulation stopped in the first block,
and a lathe's program was checked against a mill. Now the screen asks the bridge for the
session's setting (query ``CheckSetting``) and runs on a copy of it.
"""

from __future__ import annotations

from pathlib import Path

from nck import queries
from nck.commands import SetKeyswitch
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge

from hmi.app import HmiApp
from tests.program_screens.conftest import SIZE, nc_files, settle

# T5 D1 exists only in the session's tool table (000: a D without its tool is alarm 17191,
# "tool not defined"); G55 and R7 take their values from the session's work offsets and R parameters.
SESSION_PROGRAM = (
    "N10 T5 D1 M6\n"
    "N20 G55 G90 G0 X10 Y0 Z5\n"
    "N30 G1 X=R7 F100\n"
    "N40 R8=99\n"
    "N50 M30\n"
)


def session_data() -> NcData:
    """Tool 5 edge 1 (end mill, length 50 mm, radius 4 mm), G55 shifted X 100 mm, R7 = 12.5."""
    data = NcData()
    data.tools[(5, 1)] = ToolEdge({1: 120.0, 3: 50.0, 6: 4.0})
    data.settable_frame("G55").trans["X"] = 100.0
    data.r[7] = 12.5
    return data


def session_app(root: Path, nck: Nck) -> HmiApp:
    nck.submit(SetKeyswitch(3))
    return HmiApp(nck, realtime=False)


async def open_program(pilot, root: Path, name: str, text: str):
    (root / "MPF" / name).write_text(text)
    await pilot.press("alt+n", "f3")  # Program manager, open the first program
    await settle(pilot)
    screen = pilot.app.screen
    assert screen.program == f"MPF/{name}"
    return screen


async def test_check_and_simulation_use_the_session_tools_offsets_and_r_parameters(tmp_path: Path) -> None:
    root = tmp_path / "nc"
    files = nc_files(root)
    data = session_data()
    nck = Nck(data=data, programs=files, referenced=True)
    app = session_app(root, nck)
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_program(pilot, root, "SESSION.MPF", SESSION_PROGRAM)
        screen.check_now()
        await settle(pilot)
        assert screen.editor.error_marks == {}  # with fresh data: 17191 on line 1
        await pilot.press("f5")  # Simulation
        await settle(pilot)
        ends = [(tuple(round(c, 3) for c in p.end), p.rapid) for p in screen.toolpath.pieces]
        # G55: X10 in the workpiece; R7 = 12.5 is where the feed move ends
        assert ends == [((10.0, 0.0, 5.0), True), ((12.5, 0.0, 5.0), False)]
        # The first move starts at machine zero seen from the workpiece: X 0 - 100 (G55),
        # Z 0 - 50 (the tool's length 1 along Z in G17)
        start = tuple(round(c, 3) for c in screen.toolpath.pieces[0].start)
        assert start == (-100.0, 0.0, -50.0)
        # the material view's run (the AUTO run that cuts the blank) took the session's tool too:
        # with fresh data it ends with 17191 in line 1
        assert screen.stock.status_text.endswith(", no alarms")
    # the check and the simulation ran on copies: R8=99 did not reach the session
    assert nck.data.r[8] == 0.0 and nck.data.r[7] == 12.5


async def test_check_uses_the_session_machine(tmp_path: Path) -> None:
    root = tmp_path / "nc"
    files = nc_files(root)
    nck = Nck(machine=load_machine("lathe2"), programs=files, referenced=True)
    app = session_app(root, nck)
    async with app.run_test(size=SIZE) as pilot:
        screen = await open_program(pilot, root, "TURN.MPF", "N10 G0 X10 Y5\nN20 M30\n")
        screen.check_now()
        await settle(pilot)
        # the lathe has no Y axis: 12550 name not defined (on the default mill: no mark)
        assert [(m.line, m.number) for m in screen.editor.error_marks.values()] == [(0, 12550)]


def test_the_setting_is_a_copy_taken_when_asked() -> None:
    nck = Nck(data=session_data(), referenced=True)
    setting = queries.answer(nck, queries.CheckSetting())
    assert setting.machine is nck.machine
    nck.data.r[7] = 1.0  # a later change of the session does not reach a check already asked for
    result = setting.simulate("A.MPF", "N10 G0 X=R7\nN20 R7=3\nN30 M30\n")
    assert result.path.ends[:, 0].tolist() == [12.5]
    again = setting.simulate("A.MPF", "N10 G0 X=R7\nN20 M30\n")  # each run starts from the copy
    assert again.path.ends[:, 0].tolist() == [12.5]
    assert nck.data.r[7] == 1.0
