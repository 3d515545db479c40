"""Exercises 09 (measure a tool length) and 14 (the spindle does not reach its speed) on
scripted kernel sessions: each can be done, and its checks fail before and pass after.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as cmd
from tests.exercises.test_exercise_checks import EXERCISES, Scripted

REFERENCE_TOP_Z_MCS = -200.0  # the shipped mill's reference block: Z -250 ... -200 (nck/workpiece.py)


def mda(s: Scripted, text: str) -> None:
    s.do(cmd.SelectMode("MDA"))
    s.do(cmd.SetMdaProgram(text))
    s.do(cmd.CycleStart())
    s.run(60, lambda st: st.channel.channel_state != "active")


def touch_reference_block(s: Scripted) -> float:
    """Jog the active tool down onto the reference block until it scratches; the machine Z of the touch."""
    s.do(cmd.SelectMode("JOG"))
    seen = len(s.nck.contact_events())
    s.do(cmd.Jog("Z", -1))
    s.run(120, lambda st: len(s.nck.contact_events()) > seen)
    s.do(cmd.Jog("Z", 0))
    touch = s.nck.contact_events()[seen]
    assert (touch.kind, touch.solid, touch.tool) == ("scratch", "reference", 3)
    return touch.position_mcs["Z"]


def test_measure_tool_finds_the_true_length_not_the_listed_one(tmp_path: Path) -> None:
    exercise = EXERCISES["09_measure_tool"]
    assert not exercise.waits_for
    s = Scripted(exercise, tmp_path / "run")
    s.reference()
    assert s.progress.current == 1
    assert "T3 length is 100.000 mm" in s.progress.report()["steps"][1]["why_not"][0]
    mda(s, "T3 D1\nM6\nS500 M3\nG53 G0 X170 Y0\n")  # the tool in, over the reference block (X 150..190, Y ±20)
    touch_z = touch_reference_block(s)
    # the drill is 93.2 mm long (the set-up's true length), not the listed 100 mm: its tip
    # reaches the block's top at machine Z -200 + 93.2
    assert touch_z == pytest.approx(REFERENCE_TOP_Z_MCS + 93.2, abs=1e-6)
    s.do(cmd.WriteData("$TC_DP3[3,1]", touch_z - REFERENCE_TOP_Z_MCS + 0.05))  # a careless touch: 0.05 off
    assert not s.progress.finished
    s.do(cmd.WriteData("$TC_DP3[3,1]", touch_z - REFERENCE_TOP_Z_MCS))  # length = touch Z - top (Meas. tool)
    assert s.progress.finished, s.progress.report()


def start_spindle_program(s: Scripted) -> None:
    """Exercise 14 up to the wait: axes referenced, SPINDLE14 started in AUTOMATIC."""
    s.reference()
    s.do(cmd.SelectMode("AUTO"))
    s.do(cmd.CycleStart())
    s.run(10, lambda st: st.channel.program_state == "waiting")


def test_spindle_exercise_waits_without_alarm_and_ends_at_a_lower_override(tmp_path: Path) -> None:
    # MD35500/MD35150 (002 L51282-51285, L54545-54551): S4000 is in range from 3600 rpm; the
    # faulty drive gets to 2000 rpm, so the cut waits. At 55 % the set speed is 2200 rpm,
    # in range from 1980 rpm: the program goes on.
    exercise = EXERCISES["14_spindle_speed"]
    assert not exercise.waits_for
    assert "22050" not in str(exercise.steps) and "22050" not in str(exercise.final_checks)
    s = Scripted(exercise, tmp_path / "run")
    start_spindle_program(s)
    assert s.progress.current == 2
    s.run(5)  # it stays waiting, without an alarm, the axes standing above the part
    status = s.nck.status()
    assert (status.channel.channel_state, status.channel.program_state, status.alarms) == ("active", "waiting", ())
    spindle = next(a for a in status.axes if a.kind == "spindle")
    assert (spindle.speed_rpm, spindle.extra["setpoint_rpm"]) == (2000.0, 4000.0)
    s.do(cmd.SetOverride("spindle", 55))
    s.run(30, lambda st: st.channel.channel_state == "reset")
    assert s.progress.finished, s.progress.report()
    assert s.progress.report()["score"] == 100


def test_spindle_exercise_is_not_done_by_reset_alone(tmp_path: Path) -> None:
    s = Scripted(EXERCISES["14_spindle_speed"], tmp_path / "run")
    start_spindle_program(s)
    s.do(cmd.Reset())
    s.run(2)
    assert not s.progress.finished
    assert s.progress.current == 2
    assert "SPINDLE14 has not run to its end without alarm" in s.progress.report()["steps"][2]["why_not"]
