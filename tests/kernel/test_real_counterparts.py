"""Counterparts on the real interpreter and the default (planned) motion of kernel tests that
run on the fake instant interpreter (``test_section19.py``): single block, program test,
dry run, dwell, spindle, radius compensation and RND, where language and motion interact.

Times on the real motion include the acceleration ramps, so they are compared with a bound
worked out from the feed and MD32300 rather than exactly.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.ncdata import ToolEdge
from tests.kernel.helpers import states, until_state


def make(programs: dict[str, str]) -> Nck:
    return Nck(programs=MemorySource(programs), referenced=True)


def start(nck: Nck, name: str = "P.MPF") -> None:
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram(name)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()


def stops(nck: Nck, level: str) -> list[str]:
    """Blocks shown at each single-block stop until the program ends."""
    nck.submit(c.SetProgramControl("single_block", level))
    start(nck)
    seen = []
    for _ in range(12):
        assert nck.run_until(lambda k: k.situation.channel != "active", 30.0)
        if nck.situation.channel == "reset":
            break
        assert states(nck) == ("AUTO", "interrupted", "stopped")
        seen.append(nck.status().channel.current_block.text.split()[0])
        nck.submit(c.CycleStart())
    return seen


def run_time(nck: Nck) -> float:
    start(nck)
    begin = nck.time_s
    assert until_state(nck, "reset", "aborted", 120.0)
    return nck.time_s - begin


def test_sbl2_stops_after_every_block_with_real_motion() -> None:
    """Counterpart of ``test_section19.py::test_10b_*`` (digest 828d-2 rank 10): SBL2 stops
    after N10, N20 (calculation block) and N30, each time at the block's end point."""
    nck = make({"P.MPF": "N10 G1 X10 F1000\nN20 R1=5\nN30 X20\nN40 M30"})
    assert stops(nck, "SBL2") == ["N10", "N20", "N30"]
    assert nck.positions_mcs()["X"] == pytest.approx(20.0, abs=1e-3)
    assert nck.data.r[1] == 5.0


def test_m1_stops_only_with_programmed_stop_on_the_real_interpreter() -> None:
    """Counterpart of ``test_section19.py::test_11_*`` (digest 828d-2 rank 11)."""
    nck = make({"P.MPF": "N10 M01\nN20 M00\nN30 G1 X5 F1000\nN40 M30"})
    start(nck)
    assert until_state(nck, "interrupted", "stopped")
    assert nck.status().channel.current_block.text.startswith("N20")
    nck.submit(c.Reset())
    nck.submit(c.SetProgramControl("m01", True))
    nck.submit(c.CycleStart())
    assert until_state(nck, "interrupted", "stopped")
    assert nck.status().channel.current_block.text.startswith("N10")


def test_program_test_with_real_motion_keeps_the_machine_still() -> None:
    """Counterpart of ``test_section19.py::test_18_*`` (digest 828d-2 rank 18, 002
    L18007-18031): the display reaches X100, the machine stays at 0, M8 is still output."""
    nck = make({"P.MPF": "N10 G1 X100 F6000\nN20 M3 S1000 M8\nN30 M30"})
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SetProgramControl("program_test", True)) == c.Accepted()
    start(nck)
    assert until_state(nck, "reset", "aborted")
    assert nck.positions_mcs()["X"] == pytest.approx(100.0, abs=1e-3)
    assert nck.motion.positions_mcs()["X"] == pytest.approx(0.0)
    assert nck.status().channel.modal.aux.get("M") == "8"


def test_dry_run_feed_with_real_motion() -> None:
    """Counterpart of ``test_section19.py::test_16_*`` (digest 828d-2 rank 16): with SD42100 =
    2000 and SD42101 = 0, G1 X100 F500 runs at max(500, 2000): 100 mm at 2000 mm/min is 3 s
    plus the ramps (at most 2000/60/1000 s each at MD32300 >= 1 m/s²), not the 12 s of F500."""
    nck = make({"P.MPF": "N1 G1 X100 F500\nN2 M30"})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.WriteData("SD42100", 2000.0))
    nck.submit(c.WriteData("SD42101", 0))
    nck.submit(c.SetProgramControl("dry_run", True))
    assert 3.0 <= run_time(nck) <= 3.0 + 2 * (2000 / 60 / 1000) + 0.1


def test_dwell_takes_its_time_on_the_real_motion() -> None:
    """G4 F1.5 holds the program 1.5 s (002 L1253 example form; 001 L6402-6419)."""
    nck = make({"P.MPF": "N10 G4 F1.5\nN20 M30"})
    assert run_time(nck) == pytest.approx(1.5, abs=0.02)


def test_spindle_speed_and_revolutional_feed_on_the_real_motion() -> None:
    """M3 S1000 turns the spindle at 1000 rpm; G95 F0.1 feeds 0.1 · 1000 = 100 mm/min, so
    X10 takes about 6 s (002 V1: F in mm/rev times the spindle speed)."""
    nck = make({"P.MPF": "N10 M3 S1000\nN20 G95 G1 X10 F0.1\nN30 M30"})
    start(nck)
    assert nck.run_until(lambda k: k.positions_mcs()["X"] > 5.0, 30.0)
    spindle = next(a for a in nck.status().axes if a.kind == "spindle")
    assert spindle.speed_rpm == pytest.approx(1000.0)
    x_velocity = next(a for a in nck.status().axes if a.name == "X").velocity
    assert x_velocity == pytest.approx(100.0, rel=0.01)


def test_radius_compensation_on_the_real_motion() -> None:
    """G41 with a 5 mm cutter to the left of a contour along +X (002 L58897ff, digest 828d-3
    rank 22): the centre path runs 5 mm to the left, i.e. at Y = +5; G40 ends on the
    programmed point."""
    nck = make({"P.MPF": "N10 G0 X0 Y-20\nN20 T1 M6 D1\nN30 G1 G41 X0 Y0 F3000\nN40 X50\n"
                         "N45 M0\nN50 G40 G1 X60 Y-20\nN60 M30"})
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 6: 5.0})
    start(nck)
    assert until_state(nck, "interrupted", "stopped")
    assert nck.positions_mcs()["X"] == pytest.approx(50.0, abs=1e-3)
    assert nck.positions_mcs()["Y"] == pytest.approx(5.0, abs=1e-3)
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted")
    assert (nck.positions_mcs()["X"], nck.positions_mcs()["Y"]) == (pytest.approx(60.0, abs=1e-3),
                                                                   pytest.approx(-20.0, abs=1e-3))


def test_rnd_corner_on_the_real_motion() -> None:
    """RND=5 between X50 and Y50 (a 90° corner at (50, 0)) rounds with a tangent arc of
    radius 5; the path still ends exactly at the programmed (50, 50), and the corner point
    itself is never reached: the setpoint's closest approach is 5·(√2 - 1) ≈ 2.07 mm away."""
    nck = make({"P.MPF": "N10 G1 X50 F3000 RND=5\nN20 Y50\nN30 M30"})
    start(nck)
    closest = []

    def distance_of_the_setpoint_from_the_corner(k: Nck) -> float:
        setpoint = {a.name: a.setpoint_mcs for a in k.status().axes}
        return ((setpoint["X"] - 50.0) ** 2 + setpoint["Y"] ** 2) ** 0.5

    for _ in range(int(30.0 / nck.ipo_cycle_s)):  # every IPO cycle
        nck.step(1)
        closest.append(distance_of_the_setpoint_from_the_corner(nck))
        if nck.situation.channel == "reset":
            break
    assert nck.positions_mcs()["X"] == pytest.approx(50.0, abs=1e-3)
    assert nck.positions_mcs()["Y"] == pytest.approx(50.0, abs=1e-3)
    assert min(closest) == pytest.approx(5 * (2 ** 0.5 - 1), abs=0.05)


def x_velocity(nck: Nck) -> float:
    return next(a for a in nck.status().axes if a.name == "X").velocity


def test_feed_override_on_the_real_motion() -> None:
    """Counterpart of ``test_modes.py::test_feed_override_zero_holds_the_path_but_stays_running``
    (digest 828d-3 rank 9): at 50 % F1000 runs at 500 mm/min; at 0 % the axis stands while the
    program stays running (002 L56312-56319); back at 100 % it reaches the end point."""
    nck = make({"P.MPF": "N10 G1 X100 F1000\nN20 M30"})
    start(nck)
    nck.tick(1.0)
    assert x_velocity(nck) == pytest.approx(1000.0, rel=1e-3)
    nck.submit(c.SetOverride("feed", 50))
    nck.tick(1.0)
    assert x_velocity(nck) == pytest.approx(500.0, rel=1e-3)
    nck.submit(c.SetOverride("feed", 0))
    nck.tick(1.0)
    held = nck.positions_mcs()["X"]
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(held, abs=1e-6)
    assert states(nck) == ("AUTO", "active", "running")
    nck.submit(c.SetOverride("feed", 100))
    assert until_state(nck, "reset", "aborted", 30.0)
    assert nck.positions_mcs()["X"] == pytest.approx(100.0, abs=1e-3)


def test_emergency_stop_on_the_real_motion() -> None:
    """Counterpart of ``test_section19.py::test_13_*`` (digest 828d-2 rank 13): E-stop raises
    3000 and the axis comes to a stop; RESET alone and release alone keep the alarm; release
    and RESET clear it, the program is aborted and the axes stay referenced."""
    nck = make({"P.MPF": "N10 G1 X100 F1000\nN20 M30"})
    start(nck)
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 40.0, 30.0)
    nck.submit(c.EmergencyStop(True))
    nck.tick(1.0)
    stopped = nck.positions_mcs()["X"]
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(stopped, abs=1e-6)
    assert 40.0 <= stopped < 45.0
    numbers = [a.number for a in nck.status().alarms]
    assert 3000 in numbers
    nck.submit(c.Reset())
    assert 3000 in [a.number for a in nck.status().alarms]
    nck.submit(c.EmergencyStop(False))
    assert 3000 in [a.number for a in nck.status().alarms]
    nck.submit(c.Reset())
    assert 3000 not in [a.number for a in nck.status().alarms]
    assert states(nck) == ("AUTO", "reset", "aborted")
    assert all(axis.referenced for axis in nck.status().axes)
