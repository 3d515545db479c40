"""Modes, MDA, JOG, overrides and the status snapshot (Table 9-3 situations beyond section 19)."""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.channel import TRANSITIONS, VALID_SITUATIONS, ChannelSituation, next_state
from tests.kernel.helpers import auto_start, make_nck, states, until_state, x


def test_power_on_state_is_jog_reset_aborted() -> None:
    nck = make_nck()
    status = nck.status()
    assert (status.channel.mode, status.channel.channel_state, status.channel.program_state) == (
        "JOG", "reset", "aborted")
    assert status.alarms == ()


def test_transition_table_only_leads_to_valid_situations() -> None:
    for mode in ("JOG", "MDA", "AUTO"):
        for event, table in TRANSITIONS.items():
            for (channel, program), _target in table.items():
                start = ChannelSituation(mode, channel, program)
                if (mode, channel, program) not in VALID_SITUATIONS:
                    continue
                after = next_state(start, event)
                assert after is not None
        assert next_state(ChannelSituation(mode, "active", "running"), "reset") == ChannelSituation(
            mode, "reset", "aborted")


def test_mda_buffer_runs_with_nc_start_and_is_kept() -> None:
    nck = make_nck()
    nck.submit(c.SelectMode("MDA"))
    assert isinstance(nck.submit(c.CycleStart()), c.Rejected)  # empty buffer
    assert nck.submit(c.SetMdaProgram("G0 X12.5 Y-7 Z-3")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert states(nck) == ("MDA", "active", "running")
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs() == pytest.approx({"X": 12.5, "Y": -7.0, "Z": -3.0})
    status = nck.status().channel
    assert status.mda_text == "G0 X12.5 Y-7 Z-3"
    assert status.parts_total == 0  # MDA does not count parts
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.SelectMode("MDA"))
    assert nck.status().channel.mda_text == "G0 X12.5 Y-7 Z-3"


def test_mda_stopped_can_visit_jog_but_not_auto_and_resumes() -> None:
    nck = make_nck({"P": "N1 M30"})
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G1 X60 F600"))
    nck.submit(c.CycleStart())
    nck.tick(1.0)
    nck.submit(c.CycleStop())
    assert states(nck) == ("MDA", "interrupted", "stopped")
    assert nck.submit(c.SelectMode("JOG")) == c.Accepted()
    assert states(nck) == ("JOG", "interrupted", "interrupted")
    assert isinstance(nck.submit(c.SelectMode("AUTO")), c.Rejected)
    assert isinstance(nck.submit(c.SetMdaProgram("G0 X0")), c.Rejected)
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert x(nck) == pytest.approx(60.0)


def test_mda_blocks_over_an_interrupted_auto_program() -> None:
    nck = make_nck({"P": "N10 G1 X100 F1000\nN20 M30"})
    auto_start(nck, "P")
    nck.tick(2.4)
    nck.submit(c.CycleStop())
    nck.submit(c.SelectMode("MDA"))
    assert states(nck) == ("MDA", "interrupted", "interrupted")
    nck.submit(c.SetMdaProgram("G0 Z5"))
    nck.submit(c.CycleStart())
    assert states(nck) == ("MDA", "active", "interrupted")  # situation 16
    assert until_state(nck, "interrupted", "interrupted")
    assert nck.positions_mcs()["Z"] == pytest.approx(5.0)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert x(nck) == pytest.approx(100.0)


def test_jog_increment_stopped_and_continued_with_nc_start() -> None:
    nck = make_nck()
    nck.submit(c.SelectIncrement(10000))  # 10 mm
    assert nck.status().channel.machine_function == "INC"
    nck.submit(c.Jog("X", 1))
    assert states(nck) == ("JOG", "active", "aborted")
    nck.tick(0.15)  # 2000 mm/min: 5 mm
    nck.submit(c.CycleStop())
    assert states(nck) == ("JOG", "interrupted", "aborted")  # situation 8
    held = x(nck)
    nck.tick(0.5)
    assert x(nck) == held
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_state(nck, "reset", "aborted", 2.0)
    assert x(nck) == pytest.approx(10.0)


def test_continuous_jog_moves_while_pressed_and_feed_override_scales_it() -> None:
    nck = make_nck()
    nck.submit(c.SetOverride("feed", 50))
    nck.submit(c.Jog("Y", -1))
    nck.tick(0.6)
    nck.submit(c.Jog("Y", 0))
    nck.tick(0.1)
    assert nck.positions_mcs()["Y"] == pytest.approx(-10.0, abs=0.05)  # 1000 mm/min * 0.6 s
    assert states(nck) == ("JOG", "reset", "aborted")
    assert isinstance(nck.submit(c.SetOverride("feed", 250)), c.Rejected)  # 002 L56312: 0 … 200 %


def test_jog_refused_in_auto() -> None:
    nck = make_nck()
    nck.submit(c.SelectMode("AUTO"))
    assert isinstance(nck.submit(c.Jog("X", 1)), c.Rejected)
    assert isinstance(nck.submit(c.Jog("Q", 1)), c.Rejected)


def test_feed_override_zero_holds_the_path_but_stays_running() -> None:
    """Digest 828d-3 rank 9 (0 % holds, program stays running)."""
    nck = make_nck({"P": "N10 G1 X10 F600\nN20 M30"})
    auto_start(nck, "P")
    nck.tick(0.5)
    nck.submit(c.SetOverride("feed", 0))
    held = x(nck)
    nck.tick(1.0)
    assert x(nck) == pytest.approx(held)
    assert states(nck) == ("AUTO", "active", "running")
    nck.submit(c.SetOverride("feed", 100))
    assert until_state(nck, "reset", "aborted")


def test_rapid_override_follows_the_feed_switch_with_rov() -> None:
    nck = make_nck({"P": "N10 G0 X300\nN20 M30"})  # rapid 24000 mm/min (slowest axis Z)
    nck.submit(c.SetOverride("feed", 50))
    auto_start(nck, "P")
    start = nck.time_s
    assert until_state(nck, "reset", "aborted")
    plain = nck.time_s - start
    nck.programs.programs["P"] = "N10 G0 X0\nN20 M30"
    nck.submit(c.SetProgramControl("rapid_override", True))
    nck.submit(c.CycleStart())
    start = nck.time_s
    assert until_state(nck, "reset", "aborted")
    assert nck.time_s - start == pytest.approx(2 * plain, rel=0.05)


def test_status_seq_grows_only_on_change() -> None:
    nck = make_nck()
    first = nck.status()
    again = nck.status()
    assert again.seq == first.seq
    nck.tick(0.1)
    assert nck.status().seq == first.seq  # time alone is not a change
    nck.submit(c.SelectMode("MDA"))
    changed = nck.status()
    assert changed.seq > first.seq and changed.channel.mode == "MDA"


def test_tick_advances_whole_ipo_cycles_and_keeps_the_rest() -> None:
    nck = make_nck()
    ipo = nck.ipo_cycle_s
    nck.tick(ipo * 2.5)
    assert nck.time_s == pytest.approx(2 * ipo)
    nck.tick(ipo * 0.5)
    assert nck.time_s == pytest.approx(3 * ipo)
    nck.step(10)
    assert nck.time_s == pytest.approx(13 * ipo)


def test_unknown_and_bad_commands_are_rejected_not_raised() -> None:
    nck = make_nck()
    assert isinstance(nck.submit(object()), c.Rejected)
    assert isinstance(nck.submit(c.SelectMode("TURBO")), c.Rejected)
    assert isinstance(nck.submit(c.SelectIncrement(7)), c.Rejected)
    assert isinstance(nck.submit(c.SetProgramControl("single_block", "SBL9")), c.Rejected)
    assert isinstance(nck.submit(c.SetProgramControl("skip_levels", {12})), c.Rejected)
    assert isinstance(nck.submit(c.WriteData("R500", 1)), c.Rejected)
    assert isinstance(nck.submit(c.WriteData("R5", "abc")), c.Rejected)
    assert nck.submit(c.WriteData("R5", 2.5)) == c.Accepted() and nck.data.r[5] == 2.5
    assert nck.submit(c.WriteData("$AC_REQUIRED_PARTS", 3)) == c.Accepted()
    assert nck.status().channel.parts_required == 3
    assert nck.internal_errors == []


def test_required_parts_wrap_the_actual_counter() -> None:
    import dataclasses

    from nck.machine import load_machine

    base = load_machine()
    machine = dataclasses.replace(base, md={**base.md, "MD27880": 0x111})
    nck = make_nck({"P": "N10 M30"}, machine=machine)
    nck.submit(c.WriteData("$AC_REQUIRED_PARTS", 2))
    auto_start(nck, "P")
    until_state(nck, "reset", "aborted")
    nck.submit(c.CycleStart())
    until_state(nck, "reset", "aborted")
    status = nck.status().channel
    assert (status.parts_total, status.part_count) == (2, 0)


def test_keyswitch_and_password_set_the_access_level() -> None:
    nck = make_nck()
    assert nck.status().access_level == 7
    nck.submit(c.SetKeyswitch(3))
    assert nck.status().access_level == 4
    assert isinstance(nck.submit(c.EnterPassword("WRONG")), c.Rejected)
    assert nck.submit(c.EnterPassword("CUSTOMER")) == c.Accepted()
    assert nck.status().access_level == 3
    nck.submit(c.DeletePassword())
    assert nck.status().access_level == 4


def test_interrupted_mda_blocks_keep_auto_out_until_reset() -> None:
    nck = make_nck({"P": "N10 G1 X100 F1000\nN20 M30"})
    auto_start(nck, "P")
    nck.tick(1.0)
    nck.submit(c.CycleStop())
    nck.submit(c.SelectMode("MDA"))
    nck.submit(c.SetMdaProgram("G1 Z50 F600"))
    nck.submit(c.CycleStart())
    nck.tick(1.0)
    nck.submit(c.CycleStop())
    assert states(nck) == ("MDA", "interrupted", "interrupted")
    assert isinstance(nck.submit(c.SelectMode("AUTO")), c.Rejected)
    nck.submit(c.CycleStart())  # the MDA blocks finish
    assert until_state(nck, "interrupted", "interrupted")
    assert nck.positions_mcs()["Z"] == pytest.approx(50.0)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert x(nck) == pytest.approx(100.0)
    assert nck.positions_mcs()["Z"] == pytest.approx(0.0)  # REPOS undid the MDA move


def test_tick_ignores_nonsense_durations() -> None:
    nck = make_nck()
    for value in (float("nan"), float("inf"), -1.0, "abc", None):
        nck.tick(value)
    assert nck.time_s == 0.0
    assert nck.internal_errors == []


def test_aux_functions_and_messages_go_out_with_the_main_run() -> None:
    program = 'N10 G1 X100 F6000\nN20 S1000 M3\nN30 MSG("cutting")\nN40 G1 X0\nN50 M30'
    nck = make_nck({"P": program})
    auto_start(nck, "P")
    nck.tick(0.5)  # N10 still moving, although N20-N40 are already interpreted
    status = nck.status().channel
    assert status.modal.spindle_state == "M5" and status.message == ""
    nck.tick(0.6)
    status = nck.status().channel
    assert status.modal.spindle_state == "M3" and status.message == "cutting"
    assert until_state(nck, "reset", "aborted")


def test_outputs_after_a_repos_wait_for_the_remainder() -> None:
    program = "N10 G1 X100 F6000\nN20 S500 M3\nN30 M0\nN40 M30"
    nck = make_nck({"P": program})
    auto_start(nck, "P")
    nck.tick(0.5)
    nck.submit(c.CycleStop())
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.Jog("Y", 1))
    nck.tick(0.3)
    nck.submit(c.Jog("Y", 0))
    nck.tick(0.1)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    nck.tick(0.2)
    assert nck.status().channel.modal.spindle_state == "M5"  # N10 not finished yet
    assert until_state(nck, "interrupted", "stopped")  # M0 after the remainder
    assert nck.positions_mcs() == pytest.approx({"X": 100.0, "Y": 0.0, "Z": 0.0})
    modal = nck.status().channel.modal
    assert (modal.spindle_state, modal.spindle_speed_rpm) == ("M3", 500.0)
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    # M30 with MD35040 = 0 (default) deletes the last S and direction (002 L51032-51035).
    modal = nck.status().channel.modal
    assert (modal.spindle_state, modal.spindle_speed_rpm) == ("M5", 0.0)


def test_power_on_status_shows_the_reset_g_codes() -> None:
    # Before any program ran, the G-function display shows the reset state of the groups.
    from nck.kernel import Nck

    gcodes = Nck().status().channel.modal.gcodes
    assert gcodes[6] == "G17" and gcodes[8] == "G500" and gcodes[14] == "G90" and gcodes[15] == "G94"


def test_jog_inc_survives_a_visit_to_mda_but_not_automatic() -> None:
    """INC 100 in JOG, MDA, back to JOG: still INC 100, one + press moves X by 0.1 mm. MDA
    offers no INC of its own (its machine functions are REF, REPOS, TEACH IN, 002
    L17591-17601), so the selection waits for the return to JOG (our choice where the manual
    is silent). Selecting AUTOMATIC disables the INC keys: they must be pressed again (002
    L17738-17739)."""
    nck = make_nck({"P": "M30"})
    nck.submit(c.SelectMode("JOG"))
    assert nck.submit(c.SelectIncrement(100)) == c.Accepted()
    nck.submit(c.SelectMode("MDA"))
    assert nck.status().channel.machine_function is None
    nck.submit(c.SelectMode("JOG"))
    channel = nck.status().channel
    assert (channel.machine_function, channel.increment) == ("INC", 100)
    nck.submit(c.Jog("X", 1))
    nck.tick(1.0)
    nck.submit(c.Jog("X", 0))
    assert x(nck) == pytest.approx(0.1)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectMode("JOG"))
    assert nck.status().channel.machine_function is None
