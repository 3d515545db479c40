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
