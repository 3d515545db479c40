"""Kernel side of issue 18 "Values on screen: what the machine really does"."""

from __future__ import annotations

import copy

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine
from tests.kernel.test_with_real_motion import factory, make  # noqa: F401 (fixture)


def machine_with(md: dict) -> object:
    machine = copy.deepcopy(load_machine())
    for key, value in md.items():
        machine.md[key] = value
    return machine


def top_speed_mm_min(nck: Nck, axis: str, seconds: float) -> float:
    """The highest actual velocity of ``axis`` seen over ``seconds`` of JOG."""
    index = [a.name for a in nck.status().axes].index(axis)
    top = 0.0
    for _ in range(int(seconds / 0.01)):
        nck.tick(0.01)
        top = max(top, abs(nck.status().axes[index].velocity))
    return top


@pytest.mark.parametrize("rapid", [True, False])
def test_jog_never_exceeds_max_ax_velo(factory, rapid: bool) -> None:  # noqa: F811
    """MD32000 MAX_AX_VELO is the axis' maximum velocity (002 L2289, L8309): JOG rapid
    (MD32010 10000) and JOG at 120 % feed override stay at 5000 mm/min when MD32000 is 5000."""
    machine = machine_with({"MD32000": {"X": 5000.0, "Y": 30000.0, "Z": 24000.0, "SP": 8000.0},
                            "MD32010": {"X": 10000.0}, "MD32020": {"X": 4500.0}})
    nck = Nck(programs=MemorySource({}), referenced=True, motion_factory=factory, machine=machine)
    nck.submit(c.SelectMode("JOG"))
    nck.submit(c.SetOverride("feed", 120.0))  # 4500 × 1.2 = 5400 > 5000
    assert nck.submit(c.Jog("X", 1, rapid=rapid)) == c.Accepted()
    top = top_speed_mm_min(nck, "X", 3.0)
    nck.submit(c.Jog("X", 0))
    assert top == pytest.approx(5000.0, rel=0.01)


def test_status_carries_length_and_radius_of_the_active_edge_with_wear(factory) -> None:  # noqa: F811
    """002 L58785-58787, L58800-58802: the active tool size is geometry + wear:
    L1 = 120 + (-0.2) = 119.8 mm, R = 5 + 0.01 = 5.01 mm. D0 has no offset."""
    nck = make(factory, {"P.MPF": "N10 T1 M6\nN20 D1\nN30 M0\nN40 D0\nN50 M30"})
    from nck.ncdata import ToolEdge
    nck.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 120.0, 6: 5.0, 12: -0.2, 15: 0.01})
    modal = nck.status().channel.modal
    assert (modal.tool_length_mm, modal.tool_radius_mm) == (0.0, 0.0)
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.program == "stopped", 10.0)
    modal = nck.status().channel.modal
    assert (modal.tool, modal.edge) == (1, 1)
    assert modal.tool_length_mm == pytest.approx(119.8)
    assert modal.tool_radius_mm == pytest.approx(5.01)
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.situation.channel == "reset", 10.0)
