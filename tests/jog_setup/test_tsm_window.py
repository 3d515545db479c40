"""The T,S,M window of JOG (issue 22): fields, CYCLE START runs them as an MDA job, back to JOG.

The panel's T,S,M window changes the tool (T… M6 D…), starts the spindle with a
speed and direction (M3/M4/M5), outputs an M function, selects a work offset
(G500, G54…G57) and the unit (G71 mm / G70 inch) when CYCLE START is pressed.
The expected state is read from the kernel's snapshot after the job: what the
blocks ask for (002: T/D/S/M3 semantics as in MDA).
"""

from __future__ import annotations

from nck import commands as cmd
from nck.kernel import Nck
from nck.ncdata import ToolEdge

from hmi.app import HmiApp
from hmi.widgets.field_input import FieldInput
from screens.machine_jog_form import ChoiceField
from tests.burst import burst

SIZE = (160, 48)


def kernel_with_tools() -> Nck:
    """A referenced mill with T1 (end mill L 75, R 5) and T2."""
    nck = Nck(referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 75.0, 6: 5.0})
    nck.data.tools[(2, 1)] = ToolEdge({1: 200, 3: 90.0, 6: 4.0})
    return nck


def run_job(app: HmiApp) -> None:
    """Let the kernel run until the job is over and the channel is in reset again."""
    app.bridge.run_until(lambda s: s.channel.channel_state == "reset" and s.channel.mode == "MDA"
                         or s.channel.channel_state == "interrupted", max_s=20)


async def test_tsm_tool_spindle_offset_unit_one_key_at_a_time() -> None:
    """T2 D1, S1200 M3, M8: CYCLE START runs it; JOG is back, the MDA buffer is kept."""
    nck = kernel_with_tools()
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        app.bridge.submit(cmd.SetMdaProgram("G0 X10\n"))
        await pilot.press("shift+f1")
        await pilot.pause()
        assert app.screen.query_one("#mach-views").current == "view-tsm"
        assert isinstance(app.focused, FieldInput) and app.focused.id == "view-tsm-tool"
        for key in ("2", "down", "down", "1", "2", "0", "0", "down", "right", "down", "8"):
            await pilot.press(key)
        await pilot.pause()
        await pilot.press("alt+g")
        await pilot.pause()
        assert app.bridge.status.channel.mode == "MDA"  # the job runs as MDA blocks
        run_job(app)
        await pilot.pause()
        await pilot.pause()
        status = app.bridge.status
        modal = status.channel.modal
        assert status.channel.mode == "JOG"
        assert status.channel.mda_text == "G0 X10\n"
        assert (modal.tool, modal.edge) == (2, 1)
        assert modal.spindle_speed_rpm == 1200 and modal.spindle_state == "M3"
        assert "8" in str(modal.aux), modal.aux  # M8 was output
        assert app.screen.query_one("#mach-views").current == "view-tsm"


async def test_tsm_in_one_burst_and_keymap_keys_never_typed() -> None:
    """The whole entry in one burst; Alt/Ctrl/F keys pressed in a field do their panel job only."""
    nck = kernel_with_tools()
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "1", "alt+x", "alt+y", "ctrl+up", "ctrl+down", "alt+w", "alt+w",
                    "f11", "f11", "down", "down", "5", "0", "0", "down", "right", "right")
        tool = app.screen.query_one("#view-tsm-tool", FieldInput)
        assert tool.value == "1"
        assert app.screen.query_one("#view-tsm-speed", FieldInput).value == "500"
        assert app.screen.query_one("#view-tsm-spindle", ChoiceField).value == "M4"
        await burst(pilot, "alt+g")
        run_job(app)
        await pilot.pause()
        await pilot.pause()
        modal = app.bridge.status.channel.modal
        assert app.bridge.status.channel.mode == "JOG"
        assert (modal.tool, modal.spindle_speed_rpm, modal.spindle_state) == (1, 500, "M4")


async def test_tsm_unknown_tool_is_the_kernels_alarm_and_reset_returns_to_jog() -> None:
    """T99 does not exist: alarm 17191 (002 L58219); RESET ends the job and JOG is back."""
    app = HmiApp(kernel_with_tools(), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "9", "9", "alt+g")
        run_job(app)
        await pilot.pause()
        assert 17191 in [a.number for a in app.bridge.status.alarms]
        await burst(pilot, "alt+q")
        await pilot.pause()
        assert app.bridge.status.channel.mode == "JOG"


async def test_tsm_empty_window_says_so_and_stays_in_jog() -> None:
    """Nothing filled in: the dialog line says what is missing, no mode change."""
    app = HmiApp(kernel_with_tools(), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "down", "end", "backspace", "alt+g")
        await pilot.pause()
        assert app.bridge.status.channel.mode == "JOG"
        assert "fill in at least one field" in str(app.screen.query_one("#dialog-line").render())


async def test_tsm_work_offset_and_unit_stay_active_after_the_job() -> None:
    """G55 (X −200 in the data) and inch chosen in one burst: CYCLE START runs "G55 G70"; back in
    JOG both are still active (MD20152 keeps groups 8 and 13 on the shipped mill, 002
    L2770-2782) and the WCS display reads through G55: MCS X 0 → WCS X 200 mm, shown in inch: 200 / 25.4."""
    nck = kernel_with_tools()
    nck.data.settable_frame("G55").trans["X"] = -200.0
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "down", "down", "down", "down", "down", "right", "right", "right",
                    "down", "right", "right")
        form = app.screen.query_one("#view-tsm-work_offset", ChoiceField)
        assert form.value == "G55"
        assert app.screen.query_one("#view-tsm-unit", ChoiceField).value == "inch"
        await burst(pilot, "alt+g")
        run_job(app)
        await pilot.pause()
        await pilot.pause()
        status = app.bridge.status
        assert status.channel.mode == "JOG"
        assert (status.channel.modal.gcodes[8], status.channel.modal.gcodes[13]) == ("G55", "G70")
        x = {a.name: a for a in status.axes}["X"]
        assert abs(x.position_wcs - 200.0 / 25.4) < 1e-6  # G70: the display in inch
        assert "G55" in str(app.screen.query_one("#view-tsm-info").render())


async def test_tsm_work_offsets_in_the_order_of_their_numbers() -> None:
    """The retained data hold the settable offsets sorted as text (G505 … G54 …): the choice
    still goes — → G500 → G54 → G55 …, G505 after G57 (found in tmux: two → gave G505)."""
    nck = kernel_with_tools()
    nck.data.settable_frames = dict(sorted(nck.data.settable_frames.items()))
    assert next(iter(nck.data.settable_frames)) != "G54"
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f1", "down", "down", "down", "down", "down", "right", "right")
        assert app.screen.query_one("#view-tsm-work_offset", ChoiceField).value == "G54"
        await burst(pilot, *["right"] * 4)
        assert app.screen.query_one("#view-tsm-work_offset", ChoiceField).value == "G505"
