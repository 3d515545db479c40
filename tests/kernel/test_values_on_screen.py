"""Kernel side of issue 18 "Values on screen: what the machine really does"."""

from __future__ import annotations

import copy

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine
from tests.kernel.test_with_real_motion import factory, make  # noqa: F401 (fixture)


def machine_with(md: dict) -> object:
    machine = copy.deepcopy(load_machine())
    for key, value in md.items():
        machine.md[key] = value
    return machine


def top_speed_mm_min(nck: Nck, axis: str, seconds: float) -> float:
    """The highest actual velocity of ``axis`` seen over ``seconds`` of JOG."""
    index = [a.name for a in nck.status().axes].index(axis)
    top = 0.0
    for _ in range(int(seconds / 0.01)):
        nck.tick(0.01)
        top = max(top, abs(nck.status().axes[index].velocity))
    return top


@pytest.mark.parametrize("rapid", [True, False])
def test_jog_never_exceeds_max_ax_velo(factory, rapid: bool) -> None:  # noqa: F811
    """MD32000 MAX_AX_VELO is the axis' maximum velocity (002 L2289, L8309): JOG rapid
    (MD32010 10000) and JOG at 120 % feed override stay at 5000 mm/min when MD32000 is 5000."""
    machine = machine_with({"MD32000": {"X": 5000.0, "Y": 30000.0, "Z": 24000.0, "SP": 8000.0},
                            "MD32010": {"X": 10000.0}, "MD32020": {"X": 4500.0}})
    nck = Nck(programs=MemorySource({}), referenced=True, motion_factory=factory, machine=machine)
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.SetOverride("feed", 120.0))  # 4500 × 1.2 = 5400 > 5000
    assert nck.submit(c.Jog("X", 1, rapid=rapid)) == c.Accepted()
    top = top_speed_mm_min(nck, "X", 3.0)
    nck.submit(c.Jog("X", 0))
    assert top == pytest.approx(5000.0, rel=0.01)


def test_status_carries_length_and_radius_of_the_active_edge_with_wear(factory) -> None:  # noqa: F811
    """002 L58785-58787, L58800-58802: the active tool size is geometry + wear:
    L1 = 120 + (-0.2) = 119.8 mm, R = 5 + 0.01 = 5.01 mm. D0 has no offset."""
    nck = make(factory, {"P.MPF": "N10 T1 M6\nN20 D1\nN30 M0\nN40 D0\nN50 M30"})
    from nck.ncdata import ToolEdge
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0, 12: -0.2, 15: 0.01})
    modal = nck.status().channel.modal
    assert (modal.tool_length_mm, modal.tool_radius_mm) == (0.0, 0.0)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge) == (1, 1)
    assert modal.tool_length_mm == pytest.approx(119.8)
    assert modal.tool_radius_mm == pytest.approx(5.01)
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)


def test_mill_changes_tools_with_m6_as_its_md22550_says() -> None:
    """The mill's MD22550 TOOL_CHANGE_MODE is 1 (a mill with a magazine, 002 L57620-57625):
    the table, the machine file and the behaviour agree. T1 only prepares the tool, M6
    changes it; a D1 while T0 is active stays inactive (002 L57649-57651), and the tool
    stays visible as preselected (aux T)."""
    from nck.machine_data import MachineDataStore
    from nck.ncdata import ToolEdge

    machine = load_machine()
    assert MachineDataStore(machine).value("MD22550") == 1
    nck = Nck(programs=MemorySource({"P.MPF": "N10 T1 D1\nN20 M0\nN30 M6\nN40 D1\nN50 M0\nN60 M30"}),
              referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.tool_length_mm) == (0, 0.0)  # T0 still in the spindle
    assert modal.aux.get("T") == "1"  # T1 is preselected
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge, modal.tool_length_mm) == (1, 1, 120.0)


def test_lathe_changes_tools_with_t_as_its_md22550_says() -> None:
    """The lathe's MD22550 is 0 (turret): T1 changes the tool at once (002 L57616-57619)."""
    from nck.machine_data import MachineDataStore
    from nck.ncdata import ToolEdge

    machine = load_machine("lathe2")
    assert MachineDataStore(machine).value("MD22550") == 0
    nck = Nck(programs=MemorySource({"P.MPF": "N10 T1 D1\nN20 M0\nN30 M30"}), referenced=True,
              machine=machine)
    nck.data.tools[(1, 1)] = ToolEdge({1: 500, 2: 3, 3: 20.0, 4: 40.0, 6: 0.4})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge) == (1, 1)


def test_md22550_0_on_the_mill_changes_the_tool_with_t() -> None:
    """The behaviour follows the datum, not the machine kind: the mill with MD22550 = 0
    changes the tool with T at once (002 L57616-57619), D1 active, length 120 without M6."""
    from nck.ncdata import ToolEdge

    nck = Nck(programs=MemorySource({"P.MPF": "N10 T1 D1\nN20 M0\nN30 M30"}), referenced=True,
              machine=machine_with({"MD22550": 0}))
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0})
    start(nck)
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge, modal.tool_length_mm) == (1, 1, 120.0)


def test_tool_changed_in_mda_stays_for_the_next_mda_block_and_the_program() -> None:
    """Mill, MD22550 = 1: MDA `T1` preselects, the next MDA `M6` changes (002 L57620-57625)
    and activates D1 (MD20270, 002 L57652ff); the tool stays in the spindle for an AUTO
    program, whose `G0 Z0` ends 120 mm higher in the machine (length 1 = 120 on Z, G17)."""
    from nck.ncdata import ToolEdge

    nck = Nck(programs=MemorySource({"P.MPF": "N10 G0 Z0\nN20 M0\nN30 M30"}), referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0})
    run_mda(nck, "T1")
    modal = nck.status().channel.modal
    assert (modal.tool, modal.aux.get("T")) == (0, "1")  # preselected, still T0
    run_mda(nck, "M6")
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge, modal.tool_length_mm) == (1, 1, 120.0)
    start(nck)
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    assert nck.positions_mcs()["Z"] == pytest.approx(120.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge) == (1, 1)


SPINDLE_PROGRAM = "N10 M3 S1000\nN20 G1 X50 F500\nN30 M30"


def spindle_view(nck: Nck) -> tuple[str, float, float]:
    """(direction shown, programmed S shown, actual speed rounded to 1 rpm)."""
    status = nck.status()
    actual = next(a.speed_rpm for a in status.axes if a.kind == "spindle")
    return status.channel.modal.spindle_state, status.channel.modal.spindle_speed_rpm, round(actual)


def start(nck: Nck, name: str = "P.MPF") -> None:
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram(name))
    assert nck.submit(c.CycleStart()) == c.Accepted()


def test_mode_change_keeps_the_spindle_turning(factory) -> None:  # noqa: F811
    """NC STOP, AUTO → JOG → AUTO, NC START: the spindle turns on at 1000 rpm all along. The
    mode changes of an interrupted channel (002 L17768-17801) stop no spindle; only RESET /
    program end do, as MD35040 says (002 L51017-51038). The program goes on at 1000 rpm."""
    nck = make(factory, {"P.MPF": SPINDLE_PROGRAM})
    start(nck)
    nck.tick(1.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)
    nck.submit(c.CycleStop())
    nck.tick(0.5)
    assert nck.submit(c.SelectMode("JOG")) == c.Accepted()
    nck.tick(1.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)
    # Jogging the spindle meanwhile does not take its programmed rotation away.
    nck.submit(c.Jog("SP", 1))
    nck.tick(0.5)
    nck.submit(c.Jog("SP", 0))
    nck.tick(1.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    nck.tick(0.5)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)


@pytest.mark.parametrize("ending", ["RESET", "M30"])
def test_md35040_0_reset_and_program_end_stop_the_spindle_and_delete_s(factory, ending) -> None:  # noqa: F811
    """MD35040 = 0 (default): at RESET or program end the spindle brakes and the last S and
    direction are deleted (002 L51031-51035): the display says M5, S 0, 0 rpm."""
    nck = make(factory, {"P.MPF": SPINDLE_PROGRAM})
    start(nck)
    nck.tick(1.0)
    if ending == "RESET":
        nck.submit(c.Reset())
    else:
        assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)
    nck.tick(3.0)
    assert spindle_view(nck) == ("M5", 0.0, 0)


@pytest.mark.parametrize("ending", ["RESET", "M30"])
def test_md35040_1_spindle_keeps_turning_after_reset_and_program_end(factory, ending) -> None:  # noqa: F811
    """MD35040 = 1: S and direction are kept and the spindle is not braked (002 L51036-51038)."""
    machine = machine_with({"MD35040": {"SP": 1}})
    nck = Nck(programs=MemorySource({"P.MPF": SPINDLE_PROGRAM}), referenced=True,
              motion_factory=factory, machine=machine)
    start(nck)
    nck.tick(1.0)
    if ending == "RESET":
        nck.submit(c.Reset())
    else:
        assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)
    nck.tick(3.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)


def test_after_reset_m3_without_s_turns_at_the_deleted_speed(factory) -> None:  # noqa: F811
    """MD35040 = 0: RESET deletes the last S (002 L51032-51035), in the machine as on the
    screen: a following `M3` without S does not bring back the old 1000 rpm."""
    nck = make(factory, {"P.MPF": SPINDLE_PROGRAM, "Q.MPF": "N10 M3\nN20 M0\nN30 M30"})
    start(nck)
    nck.tick(1.0)
    nck.submit(c.Reset())
    nck.tick(3.0)
    start(nck, "Q.MPF")
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    nck.tick(1.0)
    assert spindle_view(nck) == ("M3", 0.0, 0)
    nck.submit(c.Reset())


def test_emergency_stop_stops_the_spindle_on_screen_too(factory) -> None:  # noqa: F811
    """EMERGENCY STOP brakes every spindle; the display does not keep claiming M3 1000."""
    nck = make(factory, {"P.MPF": SPINDLE_PROGRAM})
    start(nck)
    nck.tick(1.0)
    nck.submit(c.EmergencyStop(True))
    nck.tick(3.0)
    assert spindle_view(nck) == ("M5", 0.0, 0)


def run_mda(nck: Nck, text: str) -> None:
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram(text))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)


def test_mda_block_leaves_the_spindle_turning_for_the_next_block(factory) -> None:  # noqa: F811
    """`S1000 M3` in MDA: the buffer runs out without M2/M30, which is no program end in the
    sense of MD35040 (002 L51017-51035): the spindle keeps turning, and the next MDA block in
    G95 feeds from it: F0.1 mm/rev × 1000 rpm = 100 mm/min, X10 in 6 s (002 L51032-51035
    apply only to M2/M30 and RESET). After RESET the S is gone for the next block too."""
    nck = make(factory, {})
    run_mda(nck, "S1000 M3")
    nck.tick(2.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)
    run_mda(nck, "G95 G1 X10 F0.1")
    assert nck.positions_mcs()["X"] == pytest.approx(10.0)
    assert spindle_view(nck) == ("M3", 1000.0, 1000)
    nck.submit(c.Reset())
    nck.tick(3.0)
    assert spindle_view(nck) == ("M5", 0.0, 0)
    nck.submit(c.SetMdaProgram("M3"))
    nck.submit(c.CycleStart())
    nck.tick(1.0)
    assert spindle_view(nck) == ("M3", 0.0, 0)


def test_a_fresh_data_directory_does_not_clamp_a_normal_spindle_speed(tmp_path, factory) -> None:  # noqa: F811
    """SD43220 SPIND_MAX_VELO_G26 is the programmed limit G26 (002 L55616-55621); its default
    must not lie below what the machine can do, or `S1150 M3` runs at 1000 on a fresh data
    directory but at 1150 headless. The mill's gear stage allows 8000 (MD35130)."""
    from nck.persistence import Session

    session = Session.open(tmp_path / "data")
    nck = Nck(**{**session.kernel_arguments(), "programs": MemorySource({"P.MPF": "N10 S1150 M3\nN20 M0\nN30 M30"})},
              referenced=True, motion_factory=factory)
    start(nck)
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    nck.tick(2.0)
    assert spindle_view(nck) == ("M3", 1150.0, 1150)
    nck.submit(c.Reset())


def test_interrupted_program_shows_its_block_g_codes_and_wcs_in_jog() -> None:
    """NC STOP in N10 under G54, then JOG and back to AUTO: the control still shows the
    interrupted block N10, G54 in group 8 and the WCS with the G54 translation (WCS = MCS -
    50 mm; 002 L31561-31566: the active frame lies between MCS and WCS). The interpreter had
    read ahead to M30, whose reset state (G500, no frame) was shown (found in the operator
    day: X showed the MCS, 'G500', after Alt+H Alt+J)."""
    nck = Nck(programs=MemorySource({"P.MPF": "N5 G54 G90 G0 X0 Y0 Z0\nN10 G1 X100 F100\nN20 M30"}),
              referenced=True)
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 50)) == c.Accepted()
    for command in (c.SelectMode("AUTO"), c.SelectProgram("P.MPF"), c.CycleStart()):
        assert nck.submit(command) == c.Accepted()
    nck.tick(4.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.5)
    for mode in ("JOG", "AUTO"):
        assert nck.submit(c.SelectMode(mode)) == c.Accepted()
        nck.tick(0.1)
        status = nck.status()
        x = status.axes[0]
        assert status.channel.modal.gcodes[8] == "G54", mode
        assert x.position_wcs == pytest.approx(x.position_mcs - 50.0), mode
        assert status.channel.current_block.text == "N10 G1 X100 F100", mode
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 120.0)
    assert nck.status().axes[0].position_mcs == pytest.approx(150.0, abs=1e-3)
