"""SVG snapshots of every view of the Machine area (fake kernel, 160×48, no clock, no blink).

The fake kernel keeps the pictures independent of how the real kernel evolves;
the workflow tests (test_workflows.py) run on the real kernel.
"""

from __future__ import annotations

from dataclasses import replace

from nck.status import BlockView

from hmi.app import HmiApp
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck


def app_on(fake: FakeNck) -> HmiApp:
    """The HMI on ``fake`` without the wall-clock timer."""
    return HmiApp(fake, realtime=False)


def referenced_fake() -> FakeNck:
    """A fake kernel with all axes referenced and a few positions."""
    fake = FakeNck(referenced=True)
    fake.pos.update({"X": -125.35, "Y": 42.0, "Z": 100.0})
    return fake


def auto_fake() -> FakeNck:
    """AUTO with PART1.MPF selected, stopped in single block after N40."""
    fake = referenced_fake()
    fake.keyswitch = 1
    fake.submit_all = None
    for command in ():
        fake.submit(command)
    from nck import commands as c

    fake.submit(c.SelectProgram("PART1.MPF"))
    fake.submit(c.SelectMode("AUTO"))
    fake.submit(c.SetProgramControl("single_block", "SBL1"))
    for _ in range(4):
        fake.submit(c.CycleStart())
    return fake


def test_jog_power_on(snap_compare) -> None:
    """JOG after power on: every axis marked ○ (not referenced), X selected."""
    assert snap_compare(app_on(FakeNck()), terminal_size=SIZE)


def test_jog_ref_partly_referenced(snap_compare) -> None:
    """JOG REF: X and Y referenced (mark gone), Z still ○; the view lists what is missing."""
    assert snap_compare(app_on(FakeNck()), terminal_size=SIZE,
                        press=["alt+r", "ctrl+right", "alt+y", "ctrl+right"])


def test_jog_inc_100_mcs(snap_compare) -> None:
    """JOG INC 100 with Y selected and the positions in MCS (softkey pressed, the power-on
    setting, 002 L31480)."""
    assert snap_compare(app_on(referenced_fake()), terminal_size=SIZE,
                        press=["alt+i", "alt+i", "alt+i", "alt+y"])


def test_mda_editor_with_block(snap_compare) -> None:
    """MDA: the editor has the focus and shows the typed block."""
    assert snap_compare(app_on(referenced_fake()), terminal_size=SIZE,
                        press=["alt+d", *"G0 X12.5 Y-7 Z-3"])


def test_mda_after_cycle_start(snap_compare) -> None:
    """MDA block executed: the positions show the programmed end point."""

    async def run(pilot) -> None:
        await pilot.press("alt+d", *"G0 X12.5 Y-7 Z-3", "alt+g")
        pilot.app.bridge.advance(0.5)
        await pilot.pause()

    assert snap_compare(app_on(referenced_fake()), terminal_size=SIZE, run_before=run)


def test_auto_single_block_stopped(snap_compare) -> None:
    """AUTO, PART1.MPF, single block: stopped after N40, the current block highlighted."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE)


class CycleFake(FakeNck):
    """Stopped in single block inside CYCLE81 (at the drill's depth), with the basic block
    display the kernel reports there (tests/kernel/test_basic_blocks.py)."""

    BASIC_BLOCKS = ("N20 T1 D1", "N30 S1200 M3", "N40 G0 X10 Y20 Z50", "Z2", "G1 Z-5 F300")

    def status(self):
        status = super().status()
        views = tuple(BlockView("DRILL.MPF", 5, text) for text in self.BASIC_BLOCKS)
        channel = replace(status.channel, basic_blocks=views, basic_block_index=len(views) - 1)
        return replace(status, channel=channel)


def test_auto_basic_blocks_in_a_cycle(snap_compare) -> None:
    """⇧F2 Basic blocks: under the program (stopped on its CYCLE81 call) the blocks the cycle
    executes, the one at the drill's depth marked."""
    from nck import commands as c

    fake = CycleFake(referenced=True)
    fake.programs["DRILL.MPF"] = ["N10 G90 G54 G17 F300", "N20 T1 D1", "N30 M3 S1200",
                                  "N40 G0 X10 Y20 Z50", "N50 CYCLE81(10, 0, 2, -5)", "N60 M30"]
    fake.submit(c.SelectMode("AUTO"))
    fake.submit(c.SelectProgram("DRILL.MPF"))
    fake.submit(c.SetProgramControl("single_block", "SBL1"))
    for _ in range(4):
        fake.submit(c.CycleStart())
    fake.pos["Z"] = -5.0
    assert snap_compare(app_on(fake), terminal_size=SIZE, press=["shift+f2"])


def test_auto_with_alarm(snap_compare) -> None:
    """An alarm on the alarm line (coloured by category) over the AUTO view."""

    async def run(pilot) -> None:
        pilot.app.bridge.nck.raise_alarm(
            10720, "Channel 1 block N60 axis X software limit switch +", category="axis")
        pilot.app.bridge.poll()
        await pilot.pause()

    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE, run_before=run)


def test_all_g_groups(snap_compare) -> None:
    """Softkey G functions: every group with number, active code and meaning."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE, press=["f2"])


def test_auxiliary_functions(snap_compare) -> None:
    """Softkey Auxiliary functions: T, D, S, F and the M functions."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE, press=["f3"])


def test_program_control(snap_compare) -> None:
    """Program control with dry run and M01 on (vertical softkeys pressed), SBL type SBL2."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE,
                        press=["f4", "shift+f2", "shift+f3", "shift+f1"])


def test_block_search(snap_compare) -> None:
    """Block search view with a target typed in the search field."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE,
                        press=["alt+q", "f5", "N", "7", "0"])


def test_block_search_end_point(snap_compare) -> None:
    """Block search view with the search mode "End point" chosen (⇧F3) and a target typed."""
    assert snap_compare(app_on(auto_fake()), terminal_size=SIZE,
                        press=["alt+q", "f5", "shift+f3", "N", "7", "0"])


def test_times_counter(snap_compare) -> None:
    """Times/Counter: program runtime and part count."""
    fake = auto_fake()
    fake.runtime_s = 3725.0
    fake.parts = 12
    assert snap_compare(app_on(fake), terminal_size=SIZE, press=["f6"])


def test_program_selection_dialog(snap_compare) -> None:
    """Select program (keyswitch 1): the list of part programs."""
    fake = referenced_fake()
    fake.keyswitch = 1
    fake.programs["DRILL.MPF"] = ["N10 G0 X0 Y0", "N20 M30"]
    assert snap_compare(app_on(fake), terminal_size=SIZE, press=["alt+u", "f7"])


def test_help_overlay(snap_compare) -> None:
    """F11: the keys in force over the Machine area."""
    assert snap_compare(app_on(FakeNck()), terminal_size=SIZE, press=["f11"])


def test_area_menu(snap_compare) -> None:
    """F9: the operating areas on the horizontal softkeys."""
    assert snap_compare(app_on(FakeNck()), terminal_size=SIZE, press=["f9"])


def test_small_terminal_120x36(snap_compare) -> None:
    """At 120×36 the frame still fits: detail is dropped, nothing breaks."""
    assert snap_compare(app_on(auto_fake()), terminal_size=(120, 36))


def test_jog_repos_with_way_back(snap_compare) -> None:
    """JOG REPOS after an interruption: the way back to the interruption point per axis."""
    fake = referenced_fake()
    fake.repos_offsets = {"X": -12.5, "Y": 0.0, "Z": 3.25}
    fake.message = "Roughing pass 2"
    assert snap_compare(app_on(fake), terminal_size=SIZE, press=["alt+e"])


def test_placeholder_area(snap_compare) -> None:
    """An area without its module yet: the frame works, the content says so."""
    from hmi.app import Area, area_screen_factory

    app = app_on(FakeNck())
    app._modes["parameter"] = area_screen_factory(Area("no_module_zz", "PARAMETER", "Parameter"))
    assert snap_compare(app, terminal_size=SIZE, press=["alt+o"])


def test_machine_area_light_theme(snap_compare) -> None:
    """The Machine area (JOG) in the Operate-like light theme."""
    app = app_on(referenced_fake())
    app.theme = "operate-light"
    assert snap_compare(app, terminal_size=SIZE)


def test_machine_area_high_contrast_theme(snap_compare) -> None:
    """The Machine area (JOG) in the high-contrast theme."""
    app = app_on(referenced_fake())
    app.theme = "high-contrast"
    assert snap_compare(app, terminal_size=SIZE)
