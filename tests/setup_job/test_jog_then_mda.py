"""A program after JOG starts where the axes stand (found in the issue-22 set-up in tmux).

Touching the blank's top in INC (4 × 1 mm down), then a program whose first block selects
the edge ("D1", or "T1 M6 D1") before its first motion: the path was planned from the end of
the previous program's last block, 4 mm above the actual position, so Z jumped at the start
and alarm 25060 (speed setpoint limited) stopped it. Hand values: T1 L 75, no frame: the
carrier is at tip + 75; G0 Z5 → carrier 80; 4 mm down → 76; the program goes back to 80."""

from __future__ import annotations

import pytest

from nck import commands as cmd
from nck.kernel import Nck
from nck.ncdata import NcData, ToolEdge

from tests.jog_setup.kernels import run_in_mda_then_jog


@pytest.mark.parametrize("first_block", ["D1", "T1 M6 D1"])
def test_program_after_jog_inc_starts_at_the_actual_position(first_block: str) -> None:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 75.0, 6: 5.0})
    nck = Nck(data=data, referenced=True)
    run_in_mda_then_jog(nck, "T1 M6 D1\nG0 X20 Y20 Z5\n")
    assert nck.submit(cmd.SelectMachineFunction("INC")) == cmd.Accepted()
    assert nck.submit(cmd.SelectIncrement(1000)) == cmd.Accepted()
    for _ in range(4):
        assert nck.submit(cmd.Jog("Z", -1)) == cmd.Accepted()
        assert nck.run_until(lambda k: k.situation.channel != "active", 30.0, 16)
        nck.submit(cmd.Jog("Z", 0))
    assert nck.positions_mcs()["Z"] == pytest.approx(76.0)
    run_in_mda_then_jog(nck, f"{first_block}\nG0 X10 Y10 Z5\n")
    assert nck.alarms.active == ()
    assert [nck.positions_mcs()[a] for a in "XYZ"] == pytest.approx([10.0, 10.0, 80.0])


@pytest.mark.parametrize("set_velo, expected_mm_min", [(600.0, 600.0), (0.0, 2000.0)])
def test_jog_feed_of_settings_sd41110_moves_the_axes(set_velo: float, expected_mm_min: float) -> None:
    """Settings of JOG writes SD41110 JOG_SET_VELO; the axes then jog at it (0: MD32020, 2000
    mm/min on the shipped mill) — the kernel read only MD32020 before. Velocity after 1 s of
    continuous JOG (the ramp is over), feed override 100 %."""
    nck = Nck(referenced=True)
    nck.data.setting_data["SD41110"] = set_velo
    assert nck.submit(cmd.SelectMode("JOG")) == cmd.Accepted()
    assert nck.submit(cmd.Jog("X", 1)) == cmd.Accepted()
    for _ in range(100):
        nck.tick(0.01)
    x = {a.name: a for a in nck.status().axes}["X"]
    nck.submit(cmd.Jog("X", 0))
    assert x.velocity == pytest.approx(expected_mm_min, rel=1e-3)
