"""Dry run switched on while a program runs or stands (digest 828d-2 rank 16), on the real
interpreter and the planned motion (the look-ahead buffer holds the next blocks).

002 L18151-18158: with dry run the feeds programmed with G1/G2/G3/G33… (also G95) are replaced
by SD42100; L18163-18166: SD42101 = 0 takes the larger of the programmed feed and SD42100;
L18181-18182: dry run "can be selected in the automatic modes and activated on interruption of
an automatic mode or end of a block". So switched on during NC STOP it acts from the resumption
on (the rest of the interrupted block and every block after it, also those already buffered);
switched on while a block runs, that block keeps its feed and the next blocks take the dry run
feed. Here SD42100 = 5000 mm/min, SD42101 = 0 and F500: max(500, 5000) = 5000 mm/min.
The feed read is the status' actual path velocity (the interpolator's, see test_actual_feed.py);
the ramp to 5000 mm/min at MD32300 = 2.5 m/s² takes 5000/60/2500 = 0.033 s.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck

DRY_MM_MIN = 5000.0


def started(text: str) -> Nck:
    nck = Nck(programs=MemorySource({"P.MPF": text}), referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.WriteData("SD42100", DRY_MM_MIN)) == c.Accepted()
    assert nck.submit(c.WriteData("SD42101", 0)) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck


def feed(nck: Nck) -> float:
    return nck.status().channel.path_feed_mm_min


def x(nck: Nck) -> float:
    return nck.positions_mcs()["X"]


def test_dry_run_switched_on_during_nc_stop_acts_on_the_rest_of_the_program() -> None:
    """NC STOP in N10 (F500), dry run on, NC START: the rest of N10 and the buffered N20, N30
    run at 5000 mm/min; dry run off again at block end: N40 runs at its F500 again."""
    nck = started("N10 G1 X100 F500\nN20 X150\nN30 X200\nN40 X210\nN50 M30")
    nck.tick(1.0)
    assert feed(nck) == pytest.approx(500.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.5)
    assert feed(nck) == 0.0
    assert nck.submit(c.SetProgramControl("dry_run", True)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(0.2)
    assert x(nck) < 100.0  # still in N10
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
    assert nck.run_until(lambda k: x(k) > 110.0, 5.0)  # N20, buffered before the switch
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
    assert nck.run_until(lambda k: x(k) > 160.0, 5.0)  # N30
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
    assert nck.submit(c.SetProgramControl("dry_run", False)) == c.Accepted()
    nck.tick(0.1)
    assert x(nck) < 200.0 and feed(nck) == pytest.approx(DRY_MM_MIN)  # N30 keeps its feed
    assert nck.run_until(lambda k: x(k) > 202.0, 5.0)  # N40
    nck.tick(0.2)
    assert feed(nck) == pytest.approx(500.0)
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert x(nck) == pytest.approx(210.0, abs=1e-3)


def test_dry_run_switched_on_while_a_block_runs_acts_from_the_next_block() -> None:
    """Dry run on in N10 (F500): N10 ends at 500 mm/min, the buffered N20 runs at 5000."""
    nck = started("N10 G1 X20 F500\nN20 X120\nN30 M30")
    nck.tick(1.0)
    assert nck.submit(c.SetProgramControl("dry_run", True)) == c.Accepted()
    nck.tick(0.5)
    assert x(nck) < 20.0 and feed(nck) == pytest.approx(500.0)
    assert nck.run_until(lambda k: x(k) > 30.0, 5.0)
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert x(nck) == pytest.approx(120.0, abs=1e-3)


def test_dry_run_replaces_the_revolutional_feed_of_buffered_blocks() -> None:
    """002 L18156-18157: the dry run feed also replaces a G95 feed. M3 S1000, G95 F0.1:
    100 mm/min from the spindle; dry run on during NC STOP: max(100, 5000) = 5000 mm/min."""
    nck = started("N10 M3 S1000\nN20 G95 G1 X50 F0.1\nN30 X100\nN40 M30")
    assert nck.run_until(lambda k: x(k) > 1.0, 10.0)
    nck.tick(0.5)
    assert feed(nck) == pytest.approx(100.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.5)
    assert nck.submit(c.SetProgramControl("dry_run", True)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(0.2)
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
    assert nck.run_until(lambda k: x(k) > 60.0, 5.0)
    assert feed(nck) == pytest.approx(DRY_MM_MIN)
