"""Key channel scenarios on the default motion system and on the planned one.

Positions are end points (the real planner brakes on ramps, so intermediate
positions are only compared loosely).
"""

from __future__ import annotations

import importlib

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from tests.kernel.helpers import states, until_state


def _factories() -> list:
    factories = [None]  # the kernel's default
    try:
        module = importlib.import_module("nck.motion.system")
        factories.append(module.planned_motion_factory)
    except (ImportError, AttributeError):
        pass
    return factories


@pytest.fixture(params=_factories(), ids=lambda f: "default" if f is None else f.__name__)
def factory(request):
    return request.param


def make(factory, programs: dict[str, str], referenced: bool = True) -> Nck:
    return Nck(programs=MemorySource(programs), referenced=referenced, motion_factory=factory)


def test_stop_jog_away_and_repos_reach_the_end_point(factory) -> None:
    nck = make(factory, {"P.MPF": "N10 G1 X100 F1000\nN20 M30"})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 40.0, 10.0)
    nck.submit(c.CycleStop())
    nck.tick(0.5)
    stop_x = nck.positions_mcs()["X"]
    assert 40.0 <= stop_x < 45.0
    assert states(nck) == ("AUTO", "interrupted", "stopped")
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.Jog("X", 1))
    nck.tick(0.5)
    nck.submit(c.Jog("X", 0))
    assert until_state(nck, "interrupted", "interrupted", 5.0)
    assert nck.positions_mcs()["X"] > stop_x + 5.0
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.CycleStart())
    trail: list[float] = []
    assert nck.run_until(lambda k: trail.append(k.positions_mcs()["X"]) or k.situation.channel == "reset", 30.0)
    assert min(trail) == pytest.approx(stop_x, abs=0.01)
    assert nck.positions_mcs()["X"] == pytest.approx(100.0, abs=0.01)
    assert nck.internal_errors == []


def test_single_block_and_program_end(factory) -> None:
    nck = make(factory, {"P.MPF": "N10 G1 X10 F3000\nN20 R1=1\nN30 G0 Y20\nN40 M30"})
    nck.submit(c.SetProgramControl("single_block", "SBL1"))
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert until_state(nck, "interrupted", "stopped", 10.0)
    assert nck.positions_mcs()["X"] == pytest.approx(10.0, abs=0.01)
    nck.submit(c.CycleStart())
    assert until_state(nck, "interrupted", "stopped", 10.0)
    assert nck.positions_mcs()["Y"] == pytest.approx(20.0, abs=0.01)
    nck.submit(c.CycleStart())
    assert until_state(nck, "reset", "aborted", 10.0)
    assert nck.status().channel.parts_total == 1
    assert nck.internal_errors == []


def test_reference_all_axes_then_start(factory) -> None:
    nck = make(factory, {"P.MPF": "N10 G1 X1 F1000\nN20 M30"}, referenced=False)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    assert nck.submit(c.CycleStart()).alarm == 10203
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.SelectMachineFunction("REF"))
    for axis in ("Z", "X", "Y"):
        nck.submit(c.Jog(axis, 1))
        assert nck.run_until(lambda k, a=axis: next(s for s in k.status().axes if s.name == a).referenced, 120.0)
        nck.submit(c.Jog(axis, 0))
        assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_state(nck, "reset", "aborted", 10.0)
    assert nck.internal_errors == []


def test_spindle_jog_and_program_spindle_speed_on_the_planned_motion() -> None:
    module = pytest.importorskip("nck.motion.system")
    nck = make(module.planned_motion_factory, {"P.MPF": "N10 S1000 M3\nN20 G4 F2\nN30 M30"})
    assert nck.submit(c.Jog("SP", 1)) == c.Accepted()
    nck.tick(2.0)
    spindle = next(a for a in nck.status().axes if a.kind == "spindle")
    assert spindle.speed_rpm > 0.0
    assert states(nck) == ("JOG", "reset", "aborted")  # spindle JOG does not make the channel active
    nck.submit(c.Jog("SP", 0))
    nck.tick(3.0)
    nck.submit(c.SelectMode("AUTO"))
    assert isinstance(nck.submit(c.Jog("SP", 1)), c.Rejected)
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    nck.tick(1.5)
    spindle = next(a for a in nck.status().axes if a.kind == "spindle")
    assert spindle.speed_rpm == pytest.approx(1000.0, rel=0.01)
    assert until_state(nck, "reset", "aborted", 10.0)


def test_batched_cycles_give_the_same_result_as_single_cycles(factory) -> None:
    program = "N10 G0 X20 Y10\nN20 G1 X60 F2000\nN30 M0\nN40 G1 Y40\nN50 R1=$AA_IM[Y]\nN60 M30"
    results = []
    for batch in (1, 16):
        nck = Nck(programs=MemorySource({"P.MPF": program}), referenced=True,
                  motion_factory=factory, batch_cycles=batch)
        nck.submit(c.SelectMode("AUTO"))
        nck.submit(c.SelectProgram("P.MPF"))
        nck.submit(c.CycleStart())
        assert until_state(nck, "interrupted", "stopped", 30.0)
        nck.submit(c.CycleStart())
        assert until_state(nck, "reset", "aborted", 30.0)
        results.append((nck.positions_mcs(), nck.data.r[1], nck.time_s, nck.status().channel.parts_total))
    (pos1, r1, t1, parts1), (pos16, r16, t16, parts16) = results
    assert pos16 == pytest.approx(pos1, abs=1e-6)
    assert r16 == pytest.approx(r1) == pytest.approx(40.0, abs=1e-3)
    assert t16 == pytest.approx(t1, abs=0.2)  # stops are noticed at most a batch later
    assert parts1 == parts16 == 1


def test_distance_to_go_belongs_to_the_executing_run_of_a_repeated_line(factory) -> None:
    # The same subprogram line runs once per pass with another depth; the look-ahead
    # buffer holds several passes at once, and the display must show this pass's target.
    programs = {
        "P.MPF": "N10 G0 X0 Y0 Z5\nN20 R1=0\nN30 WHILE R1>-6\nN40 R1=R1-1.5\nN50 ONE_PASS(R1)\n"
                 "N60 ENDWHILE\nN70 M30",
        "ONE_PASS.SPF": "PROC ONE_PASS(REAL ZD)\nN10 G90 G1 Z=ZD F600\nN20 G91 X40\nN30 G90 G0 Z2\nN40 RET",
    }
    nck = make(factory, programs)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    seen: list[tuple[float, float]] = []

    def during_x_moves(k: Nck) -> bool:
        status = k.status()
        axes = {a.name: a for a in status.axes}
        if 1.0 < axes["X"].distance_to_go:
            seen.append((axes["Z"].position_wcs, axes["Z"].distance_to_go))
        return k.situation.channel == "reset"

    assert nck.run_until(during_x_moves, 60.0)
    assert seen, "no X move was observed"
    for z, z_to_go in seen:
        assert z_to_go == pytest.approx(0.0, abs=1e-6), (z, z_to_go)


def test_limit_alarm_with_blocks_buffered_behind_it_interrupts_the_channel(factory) -> None:
    # 10720 is raised when execution reaches the refused block; the block behind it is
    # already buffered and can never run, so the channel must not stay active forever.
    nck = make(factory, {"P.MPF": "N10 G0 X50 Y0\nN20 G1 X600 F1000\nN30 G1 Y10\nN40 M30"})
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.channel != "active", 10.0)
    assert states(nck) == ("AUTO", "interrupted", "stopped")
    assert 10720 in [alarm.number for alarm in nck.status().alarms]
    assert nck.positions_mcs()["X"] == pytest.approx(50.0, abs=0.01)
