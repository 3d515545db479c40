"""Digest 828d-1 (002, monitoring, motion, diagnostics): ranked items not proved elsewhere,
on the real interpreter and planned motion.

The other items are proved in ``tests/motion`` and ``tests/kernel``; ``tests/README.md`` lists
where. Expected values are worked out by hand from the manual lines cited.
"""

from __future__ import annotations

import numpy as np
import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from tests.motion.helpers import derivatives, motion, move, run_to_idle


def start(programs: dict[str, str], **settings: object) -> Nck:
    nck = Nck(programs=MemorySource(programs), referenced=True)
    for name, value in settings.items():
        assert nck.submit(c.WriteData(name, value)) == c.Accepted()
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck


def alarms(nck: Nck) -> list[int]:
    return [a.number for a in nck.status().alarms]


def test_digest_828d_1_rank_03_software_limit_in_auto_with_the_real_interpreter() -> None:
    """Digest 828d-1 rank 3: N10 G1 X400 runs, N20 X600 beyond MD36110 = 500 is never started
    (002 L2378-2400: limits in MCS, active in all modes once referenced); the alarm stops the
    channel and RESET clears it."""
    nck = start({"P.MPF": "N10 G1 X400 F5000\nN20 X600\nN30 M30"}, **{"MD36110[X]": 500.0})
    assert nck.run_until(lambda k: 10720 in alarms(k), 30.0)
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(400.0, abs=1e-3)
    assert nck.situation.program != "running"
    assert nck.submit(c.Reset()) == c.Accepted()
    assert alarms(nck) == []


def test_digest_828d_1_rank_08_g0_acceleration_is_md32300_times_md32434() -> None:
    """Digest 828d-1 rank 8: G0 accelerates at MD32300 · MD32434 (002 L7617-7624), G1 BRISK at
    MD32300; with MD32300 = 1 m/s² the G1 ramp to 100 mm/s takes 100/1000 = 0.1 s."""
    g0 = motion(MD32300={"X": 1.0}, MD32434={"X": 2.0})
    run_to_idle(g0, step_s=0.004, feed=[move("G0", X=300.0)])
    _rows, _v, a, _j = derivatives(g0)
    assert np.abs(a[:, 0]).max() == pytest.approx(2000.0, rel=1e-6)  # mm/s²
    g1 = motion(MD32300={"X": 1.0}, MD32434={"X": 2.0})
    run_to_idle(g1, step_s=0.004, feed=[move("G1", 6000.0, X=100.0)])
    _rows, v, a, _j = derivatives(g1)
    assert np.abs(a[:, 0]).max() == pytest.approx(1000.0, rel=1e-6)
    speed = v[:, 0]
    ramp_s = (np.flatnonzero(speed >= 100.0 - 1e-6)[0] - np.flatnonzero(speed > 0.0)[0]) * g1.ipo_cycle_s
    assert ramp_s == pytest.approx(0.1, abs=2 * g1.ipo_cycle_s)


def test_digest_828d_1_rank_14_programmed_working_area_limit() -> None:
    """Digest 828d-1 rank 14: G26 X100 writes the + limit (002 L2603-2606), WALIMON switches it
    on (L2592) with SD43400 = 1 (L2583-2586): G1 X150 is refused with 10730 and X stays at 0;
    WALIMOF lets the same block run to 150."""
    nck = start({"P.MPF": "N10 G26 X100\nN20 WALIMON\nN30 G1 X150 F5000\nN40 M30"},
                **{"SD43400[X]": 1})
    assert nck.run_until(lambda k: 10730 in alarms(k), 30.0)
    nck.tick(1.0)
    assert nck.positions_mcs()["X"] == pytest.approx(0.0, abs=1e-6)
    nck.submit(c.Reset())
    nck = start({"P.MPF": "N10 G26 X100\nN20 WALIMOF\nN30 G1 X150 F5000\nN40 M30"},
                **{"SD43400[X]": 1})
    assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)
    assert alarms(nck) == []
    assert nck.positions_mcs()["X"] == pytest.approx(150.0, abs=1e-3)


def lowest_path_speed_near_x40(program: str) -> float:
    """The lowest X setpoint speed (mm/min) while X passes 39..41, sampled every IPO cycle."""
    nck = start({"P.MPF": program})
    xs = []
    for _ in range(5000):
        nck.step(1)
        xs.append({a.name: a.setpoint_mcs for a in nck.status().axes}["X"])
        if nck.situation.channel == "reset":
            break
    steps = [(a, b - a) for a, b in zip(xs, xs[1:]) if 39.0 < a < 41.0]
    return min(step for _x, step in steps) / nck.ipo_cycle_s * 60.0


def test_digest_828d_1_rank_07_soft_in_a_g64_sequence_stops_between_the_blocks() -> None:
    """Digest 828d-1 rank 7: in G64 a collinear transition keeps the path velocity (F3000),
    but a change between BRISK and SOFT makes the axis stop between the two blocks (002
    L4950-4956, L4969)."""
    assert lowest_path_speed_near_x40("N10 G64 G1 X40 F3000\nN20 X80\nN30 M30") == pytest.approx(3000.0)
    assert lowest_path_speed_near_x40("N10 G64 G1 X40 F3000\nN20 SOFT X80\nN30 M30") < 0.01 * 3000.0
