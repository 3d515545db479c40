"""Controller enable removed, alarm 21612 (digest 828d-1 rank 13; 002 L735-790, L584-605).

The controller enable is the PLC signal DB31.DBX2.1; the trainer has no PLC, so the kernel takes
it as the command ``SetControllerEnable``. Removed while the axis moves (alone or in a path):
every axis of the motion stops at once (speed setpoint 0), alarm 21612, the axis is in follow-up
(002 L756-768, L67016-67025). Removed at standstill: the position loop opens, no alarm
(002 L752-754); a traversing request for that axis then gives 21612 and moves nothing.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.resources import alarm_catalog
from tests.motion.helpers import motion, move


def _alarms(m) -> list[tuple[int, tuple]]:
    return [(a.number, tuple(a.params)) for a in m.drain_alarms()]


def test_removed_during_a_path_motion_stops_every_axis_with_21612() -> None:
    m = motion()
    m.push(move("G1", 3000.0, X=100.0, Y=100.0))
    m.advance(1.0)
    moving = dict(m.positions_mcs())
    assert 0.0 < moving["X"] < 100.0
    m.set_controller_enable("X", False)
    assert _alarms(m) == [(21612, ("X",))]
    m.advance(1.0)
    after = m.positions_mcs()
    assert after["X"] < 100.0 - 1.0 and after["Y"] < 100.0 - 1.0  # the path did not go on
    assert m.axis_states()["X"].controller_mode == 4  # follow-up
    x = after["X"]
    m.advance(1.0)
    assert m.positions_mcs()["X"] == pytest.approx(x)


def test_removed_at_standstill_gives_no_alarm_but_blocks_traversing() -> None:
    m = motion()
    m.set_controller_enable("Y", False)
    assert _alarms(m) == []
    m.jog_continuous("Y", 1, 2000.0)
    m.advance(0.5)
    assert m.positions_mcs()["Y"] == pytest.approx(0.0)
    assert _alarms(m) == [(21612, ("Y",))]
    m.set_controller_enable("Y", True)
    m.jog_increment("Y", 1.0, 2000.0)
    m.advance(1.0)
    assert m.positions_mcs()["Y"] == pytest.approx(1.0, abs=1e-6)
    assert _alarms(m) == []


def test_a_block_moving_an_axis_without_enable_is_not_started() -> None:
    m = motion()
    m.set_controller_enable("Z", False)
    m.push(move("G1", 3000.0, Z=-10.0))
    m.advance(1.0)
    assert m.positions_mcs()["Z"] == pytest.approx(0.0)
    assert _alarms(m) == [(21612, ("Z",))]


def test_program_interrupted_by_21612_and_reset_clears_it() -> None:
    """In AUTO the alarm stops the channel (braking reaction); RESET clears it."""
    assert "controller enable" in alarm_catalog()[21612].text
    nck = Nck(programs=MemorySource({"P.MPF": "N10 G1 X200 F3000\nN20 M30\n"}), referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.run_until(lambda k: k.positions_mcs()["X"] > 20.0, 10.0)
    assert nck.submit(c.SetControllerEnable("X", False)) == c.Accepted()
    nck.run_until(lambda k: k.situation.channel != "active", 5.0)
    assert [a.number for a in nck.status().alarms] == [21612]
    assert nck.situation.channel == "interrupted"
    assert nck.positions_mcs()["X"] < 100.0
    assert nck.submit(c.SetControllerEnable("X", True)) == c.Accepted()
    nck.submit(c.Reset())
    nck.step(1)
    assert [a.number for a in nck.status().alarms] == []
    assert isinstance(nck.submit(c.SetControllerEnable("Q", False)), c.Rejected)
