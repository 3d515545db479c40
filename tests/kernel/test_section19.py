"""Section 19 of the part-2 digest (what a faithful simulator must get right), item by item.

Each test drives the kernel only through commands and time, and asserts states,
positions and alarm numbers. The fake interpreter of ``fakes.py`` stands in for
the language; the instant motion system stands in for the planner.
"""

from __future__ import annotations

import dataclasses

import pytest

from nck import commands as c
from nck.machine import load_machine
from tests.kernel.helpers import alarm_numbers, auto_start, make_nck, states, until_state, x

LINE = "N10 G1 Y10 F1000\nN20 G1 X100 F1000\nN30 M30"  # N20 takes 6 s from X0


def at_x40() -> "object":
    """AUTO running N20 of LINE, stopped with NC STOP at X = 40."""
    nck = make_nck({"P": LINE})
    auto_start(nck, "P")
    assert nck.run_until(lambda k: x(k) >= 40.0, 20.0)
    return nck


# 1 -------------------------------------------------------------------------
def test_01_start_from_reset_runs_from_first_block_and_restarts_runtime() -> None:
    """Digest 828d-2 rank 1 (002 L25799-25810)."""
    nck = make_nck({"P": LINE, "Q": "N5 G1 X1 F60\nN6 M30"})
    auto_start(nck, "Q")
    assert until_state(nck, "reset", "aborted")
    assert nck.status().channel.program_runtime_last_s == pytest.approx(1.0, abs=0.02)
    assert nck.submit(c.SelectProgram("P")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.step(1)
    status = nck.status()
    assert states(nck) == ("AUTO", "active", "running")
    assert status.channel.current_block.text.startswith("N10")
    assert status.channel.program_runtime_s == pytest.approx(nck.ipo_cycle_s, abs=1e-9)


# 2 -------------------------------------------------------------------------
def test_02_nc_stop_interrupts_and_nc_start_resumes_in_the_same_block() -> None:
    """Digest 828d-2 rank 2 (002 L70669-70673)."""
    nck = at_x40()
    assert nck.submit(c.CycleStop()) == c.Accepted()
    stopped_at = x(nck)
    nck.tick(1.0)
    status = nck.status()
    assert states(nck) == ("AUTO", "interrupted", "stopped")
    assert x(nck) == pytest.approx(stopped_at)
    assert status.channel.current_block.text.startswith("N20")
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert states(nck) == ("AUTO", "active", "running")
    assert until_state(nck, "reset", "aborted")
    assert x(nck) == pytest.approx(100.0)
    assert nck.positions_mcs()["Y"] == pytest.approx(10.0)
    assert nck.interpreters.get("AUTO").steps == 3  # N10, N20, N30 once each: N10 not re-run


# 3 -------------------------------------------------------------------------
def test_03_reset_aborts_clears_reset_alarms_and_restarts_at_block_one() -> None:
    """Digest 828d-2 rank 3 (002 L17476-17490, L24182)."""
    nck = make_nck({"P": "N10 G91 G1 X10 F600\nN20 X10\nN30 X10\nN40 M30"})
    auto_start(nck, "P")
    nck.tick(1.5)
    nck.submit(c.EmergencyStop(True))
    nck.submit(c.EmergencyStop(False))  # alarm 3000 pending, reset-clearable once released
    assert 3000 in alarm_numbers(nck)
    assert nck.submit(c.Reset()) == c.Accepted()
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert alarm_numbers(nck) == []
    interp = nck.interpreters.get("AUTO")
    assert interp.absolute is True  # G group 14 back to its reset value (G90)
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.step(1)
    assert nck.status().channel.current_block.text.startswith("N10")


# 4 -------------------------------------------------------------------------
def test_04_nc_start_refused_for_unreferenced_axes_with_10203() -> None:
    """Digest 828d-2 rank 4 (002 L20826-20834)."""
    nck = make_nck({"P": LINE}, referenced=False)
    nck.motion.set_referenced("X", True)
    nck.motion.set_referenced("Y", True)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and result.alarm == 10203
    assert 10203 in alarm_numbers(nck)
    nck.tick(1.0)
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert nck.positions_mcs() == {"X": 0.0, "Y": 0.0, "Z": 0.0}


def test_04b_axis_that_needs_no_referencing_lets_the_program_start() -> None:
    """Digest 828d-2 rank 4 (002 L20826-20834)."""
    base = load_machine()
    md = dict(base.md)
    md["MD34110"] = {"X": 2, "Y": 3, "Z": -1}
    machine = dataclasses.replace(base, md=md)
    nck = make_nck({"P": LINE}, referenced=False, machine=machine)
    nck.motion.set_referenced("X", True)
    nck.motion.set_referenced("Y", True)
    auto_start(nck, "P")
    assert states(nck) == ("AUTO", "active", "running")


# 5 -------------------------------------------------------------------------
def test_05_nc_start_refused_with_an_alarm_with_start_disable_10200() -> None:
    """Digest 828d-2 rank 5 (002 L20826-20834, L17980-17989)."""
    nck = make_nck({"P": "N10 SETAL(61000)\nN20 G1 X10 F1000\nN30 M30"})
    auto_start(nck, "P")
    assert until_state(nck, "interrupted", "stopped")
    assert 61000 in alarm_numbers(nck)
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and result.alarm == 10200
    assert states(nck) == ("AUTO", "interrupted", "stopped")
    assert x(nck) == 0.0


def test_05b_nc_start_refused_during_emergency_stop_and_in_jog() -> None:
    """Digest 828d-2 rank 5 (002 L20826-20834, L17980-17989)."""
    nck = make_nck({"P": LINE})
    assert isinstance(nck.submit(c.CycleStart()), c.Rejected)  # JOG
    assert states(nck) == ("JOG", "reset", "aborted")
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    nck.submit(c.EmergencyStop(True))
    assert isinstance(nck.submit(c.CycleStart()), c.Rejected)
    assert states(nck) == ("AUTO", "reset", "aborted")


def test_05c_nc_start_without_a_selected_program_is_refused() -> None:
    """Digest 828d-2 rank 5 (002 L20826-20834, L17980-17989)."""
    nck = make_nck({"P": LINE})
    nck.submit(c.SelectMode("AUTO"))
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and "program" in result.reason.lower()
    assert states(nck) == ("AUTO", "reset", "aborted")


# 6 -------------------------------------------------------------------------
def test_06_program_selection_only_in_reset() -> None:
    """Digest 828d-2 rank 6."""
    nck = at_x40()
    nck.submit(c.CycleStop())
    result = nck.submit(c.SelectProgram("Q"))
    assert isinstance(result, c.Rejected)
    assert nck.status().channel.selected_program == "P"
    nck.programs.programs["Q"] = "N1 M30"
    nck.submit(c.Reset())
    assert nck.submit(c.SelectProgram("Q")) == c.Accepted()
    assert nck.status().channel.selected_program == "Q"


# 7 -------------------------------------------------------------------------
def test_07_mode_change_blocked_while_active_then_allowed_after_stop() -> None:
    """Digest 828d-2 rank 7 (002 L17768-17808).

    Digest 828d-3 rank 5.
    """
    nck = at_x40()
    result = nck.submit(c.SelectMode("JOG"))
    assert isinstance(result, c.Rejected)
    assert result.reason == "Operating mode cannot be changed until after NC Stop"
    assert states(nck) == ("AUTO", "active", "running")
    nck.submit(c.CycleStop())
    assert nck.submit(c.SelectMode("JOG")) == c.Accepted()
    assert states(nck) == ("JOG", "interrupted", "interrupted")


# 8 -------------------------------------------------------------------------
def test_08_interrupt_jog_away_and_repos_back_on_nc_start() -> None:
    """Digest 828d-2 rank 8.

    Digest 828d-3 rank 5.
    Digest programming-840c rank 20.
    """
    nck = at_x40()
    nck.submit(c.CycleStop())
    stop_x = x(nck)
    nck.submit(c.SelectMode("JOG"))
    assert nck.submit(c.Jog("X", 1)) == c.Accepted()
    assert states(nck) == ("JOG", "active", "interrupted")
    nck.run_until(lambda k: x(k) >= stop_x + 20.0, 5.0)
    nck.submit(c.Jog("X", 0))
    assert until_state(nck, "interrupted", "interrupted", 2.0)
    assert states(nck)[0] == "JOG"
    assert nck.status().channel.repos_offsets["X"] < -19.0
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    trail = []
    nck.run_until(lambda k: trail.append(x(k)) or k.situation.channel == "reset", 20.0)
    assert min(trail) == pytest.approx(stop_x, abs=1e-6)  # RMI: back to the interruption point
    assert x(nck) == pytest.approx(100.0)


def test_08b_reset_in_jog_aborts_the_interrupted_program() -> None:
    """Digest 828d-2 rank 8."""
    nck = at_x40()
    nck.submit(c.CycleStop())
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.Reset())
    assert states(nck) == ("JOG", "reset", "aborted")
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    nck.step(1)
    assert nck.status().channel.current_block.text.startswith("N10")


# 9 -------------------------------------------------------------------------
def test_09_ref_and_repos_only_in_jog_or_mda() -> None:
    """Digest 828d-2 rank 9."""
    nck = make_nck()
    assert nck.submit(c.SelectMachineFunction("REF")) == c.Accepted()
    assert nck.submit(c.SelectMode("MDA")) == c.Accepted()
    assert nck.submit(c.SelectMachineFunction("REPOS")) == c.Accepted()
    nck.submit(c.SelectMode("AUTO"))
    assert nck.status().channel.machine_function is None
    assert isinstance(nck.submit(c.SelectMachineFunction("REF")), c.Rejected)
    assert isinstance(nck.submit(c.SelectMachineFunction("TEACH")), c.Rejected)


# 10 ------------------------------------------------------------------------
SBL_PROGRAM = "N10 G1 X10 F1000\nN20 R1=5\nN30 X20\nN40 M30"


def _stops(nck, level: str) -> list[str]:
    nck.submit(c.SetProgramControl("single_block", level))
    auto_start(nck, "P")
    stops = []
    for _ in range(6):
        nck.run_until(lambda k: k.situation.channel != "active", 10.0)
        if nck.situation.channel == "reset":
            break
        assert states(nck) == ("AUTO", "interrupted", "stopped")
        stops.append(nck.status().channel.current_block.text.split()[0])
        nck.submit(c.CycleStart())
    return stops


def test_10_single_block_sbl1_skips_calculation_blocks() -> None:
    """Digest 828d-2 rank 10 (002 L23364-23366)."""
    nck = make_nck({"P": SBL_PROGRAM})
    assert _stops(nck, "SBL1") == ["N10", "N30"]
    assert x(nck) == pytest.approx(20.0)
    assert nck.data.r[1] == 5.0


def test_10b_single_block_sbl2_stops_after_every_block() -> None:
    """Digest 828d-2 rank 10 (002 L23364-23366).

    Digest 828d-3 rank 6.
    Digest programming-840c rank 20.
    """
    nck = make_nck({"P": SBL_PROGRAM})
    assert _stops(nck, "SBL2") == ["N10", "N20", "N30"]
    assert states(nck) == ("AUTO", "reset", "aborted")


# 11 ------------------------------------------------------------------------
def test_11_m0_always_stops_m1_only_with_programmed_stop() -> None:
    """Digest 828d-2 rank 11 (002 L23368).

    Digest 828d-3 rank 7.
    Digest programming-840c rank 9.
    """
    program = "N10 M01\nN20 M00\nN30 G1 X5 F1000\nN40 M30"
    nck = make_nck({"P": program})
    auto_start(nck, "P")
    assert until_state(nck, "interrupted", "stopped")
    assert nck.status().channel.current_block.text == "N20 M00"
    assert nck.status().channel.stop_reason == "M0"
    nck.submit(c.Reset())
    nck.submit(c.SetProgramControl("m01", True))
    nck.submit(c.CycleStart())
    assert until_state(nck, "interrupted", "stopped")
    assert nck.status().channel.current_block.text == "N10 M01"
    nck.submit(c.CycleStart())
    assert until_state(nck, "interrupted", "stopped")
    assert nck.status().channel.current_block.text == "N20 M00"
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert x(nck) == pytest.approx(5.0)


# 12 ------------------------------------------------------------------------
def test_12_program_end_counts_parts_and_keeps_runtime_reset_does_not() -> None:
    """Digest 828d-2 rank 12 (002 L21190-21194).

    Digest 828d-3 rank 7 (M30).
    """
    nck = make_nck({"P": "N10 G91 G1 X10 F600\nN20 M30"})
    auto_start(nck, "P")
    assert until_state(nck, "reset", "aborted")
    status = nck.status().channel
    assert (status.parts_total, status.part_count, status.program_runtime_count) == (1, 1, 1)
    assert status.program_runtime_last_s == pytest.approx(1.0, abs=0.02)
    nck.submit(c.CycleStart())
    nck.tick(0.5)
    nck.submit(c.Reset())
    status = nck.status().channel
    assert (status.parts_total, status.part_count, status.program_runtime_count) == (1, 1, 1)
    assert status.program_runtime_s == pytest.approx(0.5, abs=0.02)  # halted, not zeroed
    nck.submit(c.SelectMode("JOG"))
    assert nck.status().channel.parts_total == 1


# 13 ------------------------------------------------------------------------
def test_13_emergency_stop_needs_release_and_reset_axes_stay_referenced() -> None:
    """Digest 828d-2 rank 13 (002 L32094-32110).

    Digest 828d-3 rank 8.
    """
    nck = at_x40()
    nck.submit(c.EmergencyStop(True))
    at_estop = x(nck)
    nck.tick(1.0)
    status = nck.status()
    assert 3000 in alarm_numbers(nck)
    assert status.emergency_stop and not status.mode_group_ready
    assert states(nck) == ("AUTO", "interrupted", "interrupted")
    assert x(nck) == pytest.approx(at_estop)
    nck.submit(c.Reset())
    assert 3000 in alarm_numbers(nck)  # RESET alone does nothing to the alarm
    nck.submit(c.EmergencyStop(False))
    assert 3000 in alarm_numbers(nck)  # releasing alone does nothing either
    nck.submit(c.Reset())
    status = nck.status()
    assert 3000 not in alarm_numbers(nck)
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert all(axis.referenced for axis in status.axes)


# 14 ------------------------------------------------------------------------
def test_14_reference_point_approach_in_jog_ref() -> None:
    """Digest 828d-2 rank 14 (002 L49438-49442)."""
    nck = make_nck(referenced=False)
    nck.submit(c.SelectMachineFunction("REF"))
    nck.submit(c.Jog("X", -1))
    nck.tick(2.0)
    assert not nck.status().axes[0].referenced  # minus key: nothing happens
    nck.submit(c.Jog("X", 1))
    assert states(nck) == ("JOG", "active", "aborted")
    nck.tick(2.0)
    assert nck.status().axes[0].referenced
    assert states(nck) == ("JOG", "reset", "aborted")
    nck.submit(c.Jog("Y", 1))
    nck.step(2)
    nck.submit(c.Reset())
    nck.tick(2.0)
    assert not nck.status().axes[1].referenced  # RESET during the approach


# 16 ------------------------------------------------------------------------
def _run_time(nck, program: str) -> float:
    nck.programs.programs["D"] = program
    nck.submit(c.Reset())
    nck.submit(c.SelectProgram("D"))
    nck.submit(c.CycleStart())
    start = nck.time_s
    assert until_state(nck, "reset", "aborted")
    return nck.time_s - start


def test_16_dry_run_feed_modes() -> None:
    """Digest 828d-2 rank 16 (002 L18151-18181)."""
    nck = make_nck()
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.WriteData("SD42100", 2000.0))
    nck.submit(c.WriteData("SD42101", 0))
    nck.submit(c.SetProgramControl("dry_run", True))
    # 100 mm at max(F, 2000): F500 -> 2000 (3 s), F3000 -> 3000 (2 s)
    assert _run_time(nck, "N1 G1 X100 F500\nN2 M30") == pytest.approx(3.0, abs=0.05)
    assert _run_time(nck, "N1 G1 X0 F3000\nN2 M30") == pytest.approx(2.0, abs=0.05)
    nck.submit(c.WriteData("SD42101", 2))
    assert _run_time(nck, "N1 G1 X100 F3000\nN2 M30") == pytest.approx(3.0, abs=0.05)
    nck.submit(c.SetProgramControl("dry_run", False))
    assert _run_time(nck, "N1 G1 X0 F3000\nN2 M30") == pytest.approx(2.0, abs=0.05)


# 17 ------------------------------------------------------------------------
def test_17_skip_levels() -> None:
    """Digest 828d-2 rank 17 (002 L23316-23385).

    Digest programming-840c rank 11.
    """
    program = "N10 G1 X1 F6000\n/N40 X40\n/3 N50 Y50\nN60 M30"
    nck = make_nck({"P": program})
    nck.submit(c.SetProgramControl("skip_levels", {0}))
    auto_start(nck, "P")
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["X"] == pytest.approx(1.0)
    assert nck.positions_mcs()["Y"] == pytest.approx(50.0)
    nck.submit(c.SetProgramControl("skip_levels", {0, 3}))
    nck.programs.programs["P"] = "N10 G1 X0 Y0 F6000\n/N40 X40\n/3 N50 Y50\nN60 M30"
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.channel == "active", 1.0)
    assert isinstance(nck.submit(c.SetProgramControl("skip_levels", set())), c.Rejected)
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["Y"] == pytest.approx(0.0)


def test_17b_skip_levels_stay_effective_during_block_search() -> None:
    """Digest 828d-2 rank 17 (002 L23316-23385)."""
    program = "N10 G1 X1 F6000\n/N40 X40\nN50 Y5\nN60 Y9\nN70 M30"
    nck = make_nck({"P": program})
    nck.submit(c.SetProgramControl("skip_levels", {0}))
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    assert nck.submit(c.StartBlockSearch("N60")) == c.Accepted()
    nck.submit(c.CycleStart())
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 1.0, "Y": 9.0, "Z": 0.0})


# 18 ------------------------------------------------------------------------
def test_18_program_test_moves_the_display_not_the_machine() -> None:
    """Digest 828d-2 rank 18."""
    # 002 L18007-18009, L18030-18031: program test executes the program without axis or
    # spindle setpoints, but with auxiliary function outputs.
    nck = make_nck({"P": "N10 G1 X100 F6000\nN20 M3 S1000 M8\nN30 M0\nN40 M30"})
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SetProgramControl("program_test", True)) == c.Accepted()
    nck.submit(c.SelectProgram("P"))
    nck.submit(c.CycleStart())
    nck.tick(0.5)
    assert 0.0 < x(nck) < 100.0
    assert until_state(nck, "interrupted", "stopped")  # at M0
    assert x(nck) == pytest.approx(100.0)
    assert nck.status().axes[0].position_mcs == pytest.approx(100.0)
    assert nck.motion.positions_mcs()["X"] == 0.0  # the machine did not move
    assert nck.status().channel.modal.aux.get("M") == "8"  # M8 was output
    assert nck.status().channel.modal.spindle_state == "M3"  # aux functions still output
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    # M30, MD35040 = 0 (default): S and direction deleted (002 L51032-51035).
    assert nck.status().channel.modal.spindle_state == "M5"
    assert nck.submit(c.SetProgramControl("program_test", False)) == c.Accepted()
    status = nck.status()
    assert status.axes[0].position_mcs == 0.0
    assert all(axis.referenced for axis in status.axes)


def test_18b_program_test_switch_refused_outside_reset() -> None:
    """Digest 828d-2 rank 18."""
    nck = at_x40()
    assert isinstance(nck.submit(c.SetProgramControl("program_test", True)), c.Rejected)


# 25 ------------------------------------------------------------------------
SEARCH_PROGRAM = (
    "N10 G0 X10 Y10\nN20 T1 D1\nN30 S3000 M3\nN40 G1 X50 F1200\nN50 G1 Y40\nN60 G1 X0\nN70 M30"
)


def test_25_block_search_with_calculation_10208_then_continue() -> None:
    """Digest 828d-2 rank 25 (002 L18282-18332, L18489-18494)."""
    nck = make_nck({"P": SEARCH_PROGRAM})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    assert nck.submit(c.StartBlockSearch("N50")) == c.Accepted()
    status = nck.status()
    assert states(nck) == ("AUTO", "interrupted", "interrupted")
    assert status.channel.stop_reason == "search target found"
    assert status.channel.current_block.text.startswith("N50")
    assert nck.positions_mcs() == {"X": 0.0, "Y": 0.0, "Z": 0.0}  # nothing moved
    assert nck.submit(c.CycleStart()) == c.Accepted()  # action blocks
    status = nck.status()
    assert 10208 in alarm_numbers(nck)
    assert states(nck) == ("AUTO", "interrupted", "stopped")
    assert status.channel.modal.spindle_state == "M3"
    assert status.channel.modal.tool == 1
    assert nck.submit(c.CycleStart()) == c.Accepted()  # approach, then N50 on
    assert 10208 not in alarm_numbers(nck)
    nck.run_until(lambda k: k.positions_mcs()["Y"] > 10.0, 10.0)
    assert x(nck) == pytest.approx(50.0)  # approached the start of N50 (end of N40)
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 0.0, "Y": 40.0, "Z": 0.0})
    assert nck.status().channel.parts_total == 1


def test_25b_block_search_target_not_found_and_by_text_and_cascaded() -> None:
    """Digest 828d-2 rank 25 (002 L18282-18332, L18489-18494)."""
    nck = make_nck({"P": SEARCH_PROGRAM})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    assert isinstance(nck.submit(c.StartBlockSearch("N999")), c.Rejected)
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert nck.submit(c.StartBlockSearch("Y40")) == c.Accepted()
    assert nck.status().channel.current_block.text.startswith("N50")
    assert nck.submit(c.StartBlockSearch("N60")) == c.Accepted()  # cascaded
    assert nck.status().channel.current_block.text.startswith("N60")
    nck.submit(c.CycleStart())
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 0.0, "Y": 40.0, "Z": 0.0})


# 15 ------------------------------------------------------------------------
def test_15_adjusted_absolute_encoder_is_referenced_at_power_on() -> None:
    """Digest 828d-2 rank 15 (002 L49502-49508)."""
    base = load_machine()
    machine = dataclasses.replace(base, md={**base.md, "MD34210": {"X": 2, "Y": 2, "Z": 0}})
    nck = make_nck({"P": LINE}, referenced=False, machine=machine)
    referenced = {axis.name: axis.referenced for axis in nck.status().axes}
    assert referenced == {"X": True, "Y": True, "Z": False, "SP": True}
    assert nck.positions_mcs() == {"X": 0.0, "Y": 0.0, "Z": 0.0}  # no motion
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P"))
    result = nck.submit(c.CycleStart())
    assert isinstance(result, c.Rejected) and result.alarm == 10203
    assert "Z" in nck.status().alarms[0].text
