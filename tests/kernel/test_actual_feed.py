"""The actual feed of the status (T,F,S window) is the interpolator's path velocity (issue 18).

Expected values are worked out by hand from the mill's machine data (data/machines/mill3.toml:
MD32000 X 30000 mm/min, MD32300 X 2.5 m/s², MD32020 X 2000 mm/min, MD32010 X 10000 mm/min)
and the manual: the feed override multiplies the programmed feed (002 L56305-56307), G0
traverses at the path velocity the axes' MD32000 allow (002 L55344-55348) times the rapid
override (L56313-56314), JOG at MD32020 (SD41110 = 0) times the feed override. Each check
waits until the acceleration ramp is over (at most 30000 mm/min / 2.5 m/s² = 0.2 s).
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck


def make(text: str) -> Nck:
    nck = Nck(programs=MemorySource({"P.MPF": text}), referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    return nck


def feed(nck: Nck) -> float:
    return nck.status().channel.path_feed_mm_min


def test_actual_feed_follows_the_feed_override_and_is_zero_after_nc_stop() -> None:
    """F1000: 1000 mm/min at 100 %, 500 mm/min at 50 % (002 L56305-56307: the feeds are
    multiplied by the override); after NC STOP, once the axes stand, 0; the programmed F
    stays 1000."""
    nck = make("N10 G1 X300 F1000\nN20 M30")
    assert feed(nck) == 0.0
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(1.0)
    assert feed(nck) == pytest.approx(1000.0, abs=1e-6)
    assert nck.submit(c.SetOverride("feed", 50.0)) == c.Accepted()
    nck.tick(1.0)
    assert feed(nck) == pytest.approx(500.0, abs=1e-6)
    assert nck.status().channel.modal.feed == pytest.approx(1000.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.5)
    assert nck.status().axes[0].velocity == pytest.approx(0.0, abs=1e-3)  # mm/min: the axis stands
    assert feed(nck) == 0.0
    assert nck.status().channel.modal.feed == pytest.approx(1000.0)


@pytest.mark.parametrize("rapid_pct", [100.0, 50.0])
def test_actual_feed_in_g0_is_the_rapid_velocity(rapid_pct: float) -> None:
    """G0 X400 on X alone: MD32000[X] = 30000 mm/min times the rapid override
    (002 L55346-55348, L56313-56314): 30000 at 100 %, 15000 at 50 %. After 0.5 s the ramp
    (0.2 s, 50 mm at 100 %) is over and the axis is mid-way."""
    nck = make("N10 G0 X400\nN20 M30")
    assert nck.submit(c.SetOverride("rapid", rapid_pct)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(0.5)
    assert feed(nck) == pytest.approx(30000.0 * rapid_pct / 100.0, abs=1e-6)
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
    assert feed(nck) == 0.0


def test_actual_feed_is_zero_during_a_dwell() -> None:
    """G4 F2 holds the path (002 L1253 example form): no path velocity while it waits."""
    nck = make("N10 G1 X10 F1000\nN20 G4 F2\nN30 X20\nN40 M30")
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 10.0 - 1e-9, 5.0)
    nck.tick(1.0)
    assert feed(nck) == 0.0


@pytest.mark.parametrize(("rapid", "override", "expected"), [
    (False, 100.0, 2000.0), (False, 50.0, 1000.0), (True, 100.0, 10000.0),
])
def test_actual_feed_in_jog_is_the_jog_velocity(rapid: bool, override: float, expected: float) -> None:
    """JOG X+ continuous: MD32020[X] = 2000 mm/min (SD41110 = 0) times the feed override;
    with rapid MD32010[X] = 10000 mm/min. Released, the axis brakes and the feed is 0."""
    nck = Nck(programs=MemorySource({}), referenced=True)
    assert nck.submit(c.SelectMode("JOG")) == c.Accepted()
    assert nck.submit(c.SetOverride("feed", override)) == c.Accepted()
    assert nck.submit(c.Jog("X", 1, rapid=rapid)) == c.Accepted()
    nck.tick(0.5)
    assert feed(nck) == pytest.approx(expected, abs=1e-6)
    assert nck.submit(c.Jog("X", 0)) == c.Accepted()
    nck.tick(0.5)
    assert feed(nck) == 0.0


def test_actual_feed_on_the_stand_in_motion_of_program_test() -> None:
    """Program test runs on the simulated axes (instant stand-in): its feed is shown, with the
    override (F1000 at 50 % → 500 mm/min), and 0 after NC STOP."""
    nck = make("N10 G1 X300 F1000\nN20 M30")
    assert nck.submit(c.SetProgramControl("program_test", True)) == c.Accepted()
    assert nck.submit(c.SetOverride("feed", 50.0)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(1.0)
    assert feed(nck) == pytest.approx(500.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.1)
    assert feed(nck) == 0.0


@pytest.mark.parametrize(("feed_pct", "expected"), [(50.0, 15000.0), (200.0, 30000.0)])
def test_feed_switch_as_rapid_override_on_the_real_motion(feed_pct: float, expected: float) -> None:
    """Digest 828d-3 rank 9: with ROV the feed switch acts as rapid override (002
    L56367-56370), above 100 % counting as 100 %: G0 X400 runs at 30000 mm/min (MD32000[X]) ×
    50 % = 15000 mm/min, and at 200 % at 30000 (not beyond). The rapid switch (20 %) is not used."""
    nck = make("N10 G0 X400\nN20 M30")
    assert nck.submit(c.SetOverride("rapid", 20.0)) == c.Accepted()
    assert nck.submit(c.SetProgramControl("rapid_override", True)) == c.Accepted()
    assert nck.submit(c.SetOverride("feed", feed_pct)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(0.5)
    assert feed(nck) == pytest.approx(expected, abs=1e-6)
