"""Feed, rapid and spindle behaviour of Function Manual 002 on the real interpreter and motion.

Each test cites the manual lines its expected values come from.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory


def make(programs: dict[str, str], **kwargs) -> Nck:
    return Nck(programs=MemorySource(programs), referenced=True, **kwargs)


def run_time_s(nck: Nck, program: str) -> float:
    """AUTO, select, NC START; the simulated time until the channel is back in reset."""
    nck.submit(c.SelectMode("AUTO"))
    assert nck.submit(c.SelectProgram(program)) == c.Accepted()
    start = nck.time_s
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 120.0)
    return nck.time_s - start


def test_feed_override_reaches_200_percent() -> None:
    # 002 L56312-56313: an override between 0 and 200 % for the path feed; feeds are multiplied.
    # 100 mm at F1000 takes 6 s at 100 % and 3 s at 200 % (ramps add a little to both).
    programs = {"P.MPF": "N10 G1 X100 F1000\nN20 M30"}
    plain = run_time_s(make(programs), "P.MPF")
    fast = make(programs)
    assert fast.submit(c.SetOverride("feed", 200)) == c.Accepted()
    assert run_time_s(fast, "P.MPF") == pytest.approx(plain / 2, rel=0.03)
    assert isinstance(fast.submit(c.SetOverride("feed", 201)), c.Rejected)


def test_spindle_override_accepts_0_to_200_percent() -> None:
    # 002 L56318-56319: the spindle override can be between 0 and 200 %.
    nck = make({})
    assert nck.submit(c.SetOverride("spindle", 200)) == c.Accepted()
    assert nck.submit(c.SetOverride("spindle", 0)) == c.Accepted()
    assert isinstance(nck.submit(c.SetOverride("spindle", 201)), c.Rejected)


def test_rapid_override_by_the_feed_switch_is_limited_to_100_percent() -> None:
    # 002 L56314-56315 and L56369-56370: rapid override 0 … 100 %; when the feed switch acts
    # as rapid override, feed overrides above 100 % count as 100 % for rapid traverse.
    # The instant motion stand-in moves G0 at exactly rapid × override (no axis limit to hide it).
    programs = {"P.MPF": "N10 G0 X300\nN20 M30"}
    plain = run_time_s(make(programs, motion_factory=instant_motion_factory), "P.MPF")
    nck = make(programs, motion_factory=instant_motion_factory)
    nck.submit(c.SetProgramControl("rapid_override", True))
    nck.submit(c.SetOverride("feed", 200))
    assert run_time_s(nck, "P.MPF") == pytest.approx(plain, rel=0.01)
    assert isinstance(nck.submit(c.SetOverride("rapid", 101)), c.Rejected)
