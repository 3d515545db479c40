"""The kernel with the real Siemens interpreter (the default ``Nck`` set-up)."""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory
from nck.ncdata import ToolEdge
from tests.kernel.helpers import states, until_state


def make(programs: dict[str, str]) -> Nck:
    return Nck(programs=MemorySource(programs), referenced=True, motion_factory=instant_motion_factory,
               batch_cycles=1)


def start(nck: Nck, name: str) -> None:
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram(name)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()


def gcode(nck: Nck, group: int) -> str:
    return nck.status().channel.modal.gcodes.get(group, "")


def test_reset_restores_reset_g_codes() -> None:
    """Digest programming-840c rank 1 (reset restores the initial G codes; 840D's set)."""
    nck = make({"P.MPF": "N10 G91 G1 X10 F100\nN20 X10\nN30 M30"})
    start(nck, "P.MPF")
    nck.tick(1.0)
    assert gcode(nck, 14) == "G91"
    nck.submit(c.Reset())
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert gcode(nck, 14) == "G90"
    assert gcode(nck, 1) in ("G0", "G1")  # MD20150 default of group 1


def test_program_runs_to_end_with_real_blocks() -> None:
    nck = make({"P.MPF": "N10 G0 X10 Y5\nN20 G1 Z-2 F600\nN30 M30"})
    start(nck, "P.MPF")
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 10.0, "Y": 5.0, "Z": -2.0})
    assert nck.status().channel.parts_total == 1
    assert nck.internal_errors == []


def test_single_block_sbl1_and_m0_with_the_real_interpreter() -> None:
    """Digest 828d-3 rank 6 and 828d-2 rank 10 (real interpreter)."""
    nck = make({"P.MPF": "N10 G1 X10 F6000\nN20 R1=5\nN30 X20\nN40 M0\nN50 X30\nN60 M30"})
    nck.submit(c.SetProgramControl("single_block", "SBL1"))
    start(nck, "P.MPF")
    seen = []
    for _ in range(8):
        nck.run_until(lambda k: k.situation.channel != "active", 10.0)
        if nck.situation.channel == "reset":
            break
        seen.append(nck.status().channel.current_block.text.split()[0])
        nck.submit(c.CycleStart())
    assert seen[:2] == ["N10", "N30"]
    assert "N40" in seen
    assert nck.positions_mcs()["X"] == pytest.approx(30.0)
    assert nck.data.r[1] == 5.0


def test_mda_with_the_real_interpreter() -> None:
    nck = make({})
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G0 X12.5 Y-7 Z-3"))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 12.5, "Y": -7.0, "Z": -3.0})


def test_mda_after_jog_starts_from_the_actual_position() -> None:
    nck = make({})
    nck.submit(c.SelectIncrement(10000))
    nck.submit(c.Jog("X", 1))
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(10.0)
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G91 G1 X5 F600"))
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["X"] == pytest.approx(15.0)


def test_block_search_with_the_real_interpreter() -> None:
    program = "N10 G0 X10 Y10\nN20 S3000 M3\nN30 G1 X50 F1200\nN40 Y40\nN50 M30"
    nck = make({"P.MPF": program})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    assert nck.submit(c.StartBlockSearch("N40")) == c.Accepted()
    assert nck.status().channel.current_block.text.startswith("N40")
    nck.submit(c.CycleStart())
    assert 10208 in [a.number for a in nck.status().alarms]
    assert nck.status().channel.modal.spindle_state == "M3"
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 50.0, "Y": 40.0, "Z": 0.0})


def test_program_alarm_from_the_real_interpreter() -> None:
    nck = make({"P.MPF": "N10 G1 X5 F600\nN20 X=\nN30 M30"})
    start(nck, "P.MPF")
    assert until_state(nck, "interrupted", "stopped")
    alarm = nck.status().alarms[0]
    assert alarm.number == 12080 and alarm.n == 20
    assert nck.positions_mcs()["X"] == pytest.approx(5.0)
    nck.submit(c.Reset())
    assert nck.status().alarms == ()


def test_skip_levels_reach_the_real_interpreter() -> None:
    nck = make({"P.MPF": "N10 G1 X1 F6000\n/N20 X40\nN30 M30"})
    nck.submit(c.SetProgramControl("skip_levels", {0}))
    start(nck, "P.MPF")
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["X"] == pytest.approx(1.0)


def test_reset_deletes_the_programmable_frame() -> None:
    nck = make({"P.MPF": "N10 TRANS X10\nN20 G1 X0 F6000\nN30 M0\nN40 M30",
                "Q.MPF": "N10 G1 X0 F6000\nN20 M30"})
    start(nck, "P.MPF")
    assert until_state(nck, "interrupted", "stopped")
    assert nck.positions_mcs()["X"] == pytest.approx(10.0)  # WCS X0 is MCS X10 under TRANS
    nck.submit(c.Reset())
    nck.submit(c.SelectProgram("Q.MPF"))
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["X"] == pytest.approx(0.0)


def test_sblof_subprogram_runs_as_one_single_block_step() -> None:
    nck = make({
        "P.MPF": "N10 G1 X1 F6000\nN20 SUB1\nN30 X5\nN40 M30",
        "SUB1.SPF": "PROC SUB1 SBLOF\nN100 G1 X2\nN110 X3\nN120 X4\nN130 RET",
    })
    nck.submit(c.SetProgramControl("single_block", "SBL1"))
    start(nck, "P.MPF")
    stops = []
    for _ in range(10):
        nck.run_until(lambda k: k.situation.channel != "active", 10.0)
        if nck.situation.channel == "reset":
            break
        stops.append(round(nck.positions_mcs()["X"], 3))
        nck.submit(c.CycleStart())
    assert 2.0 not in stops and 3.0 not in stops  # no stop inside the SBLOF subprogram
    assert stops[0] == 1.0 and stops[-1] == 5.0
    assert nck.positions_mcs()["X"] == pytest.approx(5.0)


def test_wcs_display_follows_the_executing_block() -> None:
    nck = make({"P.MPF": "N10 G1 X20 F600\nN20 TRANS X10\nN30 G1 X20\nN40 M30"})
    start(nck, "P.MPF")
    nck.tick(1.0)  # in N10: X = 10, no frame yet although the interpreter read ahead
    x_axis = nck.status().axes[0]
    assert x_axis.position_mcs == pytest.approx(10.0, abs=0.05)
    assert x_axis.position_wcs == pytest.approx(x_axis.position_mcs)
    assert nck.run_until(lambda k: k.positions_mcs()["X"] > 25.0, 10.0)
    x_axis = nck.status().axes[0]
    assert x_axis.position_wcs == pytest.approx(x_axis.position_mcs - 10.0)  # N30 under TRANS X10
    assert until_state(nck, "reset", "aborted")
    x_axis = nck.status().axes[0]
    assert x_axis.position_mcs == pytest.approx(30.0)
    assert x_axis.position_wcs == pytest.approx(30.0)  # M30 deleted the programmable frame


def test_spindle_and_tool_display_follow_the_main_run() -> None:
    nck = make({"P.MPF": "N10 G1 X100 F6000\nN20 T2 M6 D1 S800 M3\nN30 G1 X0\nN40 M30"})
    nck.data.tools[(2, 1)] = ToolEdge({1: 120.0})  # T2 needs its data set (17191, 002 L58219)
    start(nck, "P.MPF")
    nck.tick(0.5)
    modal = nck.status().channel.modal
    assert (modal.spindle_state, modal.tool) == ("M5", 0)
    nck.tick(0.7)
    modal = nck.status().channel.modal
    assert (modal.spindle_state, modal.spindle_speed_rpm, modal.tool, modal.edge) == ("M3", 800.0, 2, 1)


def test_reading_actual_positions_waits_for_the_main_run() -> None:
    """Digest job-planning-variables rank 10: a main-run variable read in the program waits for the motion before it (004 L177-196)."""
    nck = make({"P.MPF": "N10 G1 X12 F600\nN20 R1=$AA_IM[X]\nN30 M30"})
    start(nck, "P.MPF")
    assert until_state(nck, "reset", "aborted")
    assert nck.data.r[1] == pytest.approx(12.0)  # not 0: N20 waited for N10 to finish
