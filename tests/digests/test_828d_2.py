"""Digest 828d-2 (002, K1/K2 modes, channel, frames), ranked items 19-23 on the real
interpreter and motion.

Items 1-18 and 25 are proved in ``tests/kernel/test_section19.py`` (fake interpreter)
with counterparts in ``tests/kernel/test_real_interpreter.py``; see ``tests/README.md``.
Every expected value is worked out by hand from the manual line cited.
"""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine


def make(programs: dict[str, str]) -> Nck:
    """The default machine, real interpreter and motion, axes referenced, G54 X = 100."""
    nck = Nck(programs=MemorySource(programs), referenced=True)
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 100)) == c.Accepted()
    return nck


def start(nck: Nck, name: str) -> None:
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram(name)) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()


def until_stop(nck: Nck) -> str:
    """Run to the next M0 (or the end); returns the block shown."""
    assert nck.run_until(lambda k: k.situation.program in ("stopped", "aborted"), 60.0)
    block = nck.status().channel.current_block
    return block.text if block else ""


def wcs(nck: Nck, axis: str = "X") -> float:
    return {a.name: a.position_wcs for a in nck.status().axes}[axis]


def mcs(nck: Nck, axis: str = "X") -> float:
    return nck.positions_mcs()[axis]


def test_digest_828d_2_rank_19_settable_frame_edit_waits_for_reselection() -> None:
    """Digest 828d-2 rank 19: an HMI edit of G54 while interrupted changes nothing until G54
    is executed again (MD9440 = 0, 002 L31923-31924); then WCS = 150 - 120 = 30."""
    nck = make({"P.MPF": "N10 G54 G0 X50\nN20 M0\nN30 G54\nN40 M0\nN50 M30"})
    start(nck, "P.MPF")
    assert until_stop(nck).startswith("N20")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(50.0))  # 50 + 100
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 120)) == c.Accepted()
    nck.tick(0.1)
    assert wcs(nck) == pytest.approx(50.0)  # not yet active
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_stop(nck).startswith("N40")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(30.0))


@pytest.mark.parametrize("md9440, wcs_after_start", [(0, 50.0), (1, 30.0)])
def test_digest_828d_2_rank_19_md9440_activates_the_edit_at_the_next_nc_start(
        md9440: int, wcs_after_start: float) -> None:
    """Digest 828d-2 rank 19: with MD9440 = 1 a work offset entered while the program is stopped
    becomes active when the program continues (002 L31541-31546): after NC START the WCS is
    150 - 120 = 30 before any block selects G54 again; with MD9440 = 0 it stays 50."""
    nck = make({"P.MPF": "N10 G54 G0 X50\nN20 M0\nN30 G4 F0.5\nN40 M0\nN50 M30"})
    assert nck.submit(c.WriteData("MD9440", md9440)) == c.Accepted()
    start(nck, "P.MPF")
    assert until_stop(nck).startswith("N20")
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 120)) == c.Accepted()
    nck.tick(0.1)
    assert wcs(nck) == pytest.approx(50.0)  # stopped: not yet, with either value
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert until_stop(nck).startswith("N40")  # N30 moves nothing and selects no offset
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(wcs_after_start))


@pytest.mark.parametrize("md9440, wcs_after_edit", [(0, 150.0), (1, 130.0)])
def test_digest_828d_2_rank_19_md9440_activates_the_edit_at_once_in_reset(
        md9440: int, wcs_after_edit: float) -> None:
    """Digest 828d-2 rank 19: with MD9440 = 1 values entered in the RESET state are active at
    once (002 L28133-28137, L31541-31544): the base frame X = 20 entered at machine X150 shows
    WCS 150 - 20 = 130 at once; with MD9440 = 0 the display stays 150."""
    nck = make({"P.MPF": "N10 G500 G0 X150\nN20 M30"})
    assert nck.submit(c.WriteData("MD9440", md9440)) == c.Accepted()
    start(nck, "P.MPF")
    assert nck.run_until(lambda k: k.situation.program == "aborted", 60.0)
    nck.tick(0.5)
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(150.0))
    assert nck.submit(c.WriteData("$P_UBFR[X,TR]", 20)) == c.Accepted()
    nck.tick(0.1)
    assert wcs(nck) == pytest.approx(wcs_after_edit)


def test_digest_828d_2_rank_20_frame_chain_g53_g500_and_rotation() -> None:
    """Digest 828d-2 rank 20: G54 X100 + TRANS X10 at machine X150 gives WCS 40; G53 suppresses
    the frames for its block only (002 L28329, L26952); G500 drops the settable part
    (002 L28350) so WCS = 150 - 10 = 140; after ROT Z90 a WCS X10 lies at BCS Y10."""
    prog = ("N10 G54 TRANS X10\nN20 G0 X140\nN25 M0\nN30 G53 X0\nN35 M0\nN40 X40\nN45 M0\n"
            "N50 G500\nN55 M0\nN60 ROT Z90\nN70 G1 X10 F1000\nN75 M0\nN80 M30")
    nck = make({"P.MPF": prog})
    start(nck, "P.MPF")
    assert until_stop(nck).startswith("N25")
    assert mcs(nck) == pytest.approx(250.0)  # 140 + 10 + 100
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N35")
    assert mcs(nck) == pytest.approx(0.0)  # G53 X0 is machine X0
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N45")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(40.0))  # frames back
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N55")
    assert wcs(nck) == pytest.approx(140.0)  # 150 - TRANS 10, settable part gone
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N75")
    # ROT replaces the programmable frame (TRANS gone); +90 about Z turns X onto +Y.
    assert (mcs(nck, "X"), mcs(nck, "Y")) == (pytest.approx(0.0, abs=1e-6), pytest.approx(10.0))


def test_digest_828d_2_rank_22_reset_deletes_programmable_and_settable_frame() -> None:
    """Digest 828d-2 rank 22: at RESET the programmable frame is deleted and, with the default
    MD20110/MD20152, the settable frame returns to its reset value G500 (002 L24182,
    L28350): after RESET the WCS equals the MCS. The shipped mill keeps group 8 (MD20152[7] = 1,
    for T,S,M of JOG): here the machine has the control's default 0."""
    machine = load_machine("mill3")
    machine.md["MD20152"] = 0
    nck = Nck(machine=machine, programs=MemorySource({"P.MPF": "N10 G54 TRANS X10\nN20 G0 X40\nN30 M0\nN40 M30"}),
              referenced=True)
    assert nck.submit(c.WriteData("$P_UIFR[1,X,TR]", 100)) == c.Accepted()
    start(nck, "P.MPF")
    assert until_stop(nck).startswith("N30")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(150.0), pytest.approx(40.0))
    assert nck.submit(c.Reset()) == c.Accepted()
    nck.tick(0.1)
    assert wcs(nck) == pytest.approx(mcs(nck)) == pytest.approx(150.0)


def test_digest_828d_2_rank_23_programmable_frame_in_the_actual_value_display() -> None:
    """Digest 828d-2 rank 23 (002 L27814-27821): N10 X100 shows 100; N20 X0 shows 0; after
    $P_PFRAME=CTRANS(X,10), N40 X100 shows WCS 100 while the machine (= SZS here, no
    settable frame) is at 110."""
    prog = "N10 G0 X100\nN15 M0\nN20 X0\nN30 $P_PFRAME=CTRANS(X,10)\nN40 X100\nN45 M0\nN50 M30"
    nck = Nck(programs=MemorySource({"P.MPF": prog}), referenced=True)
    start(nck, "P.MPF")
    assert until_stop(nck).startswith("N15")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(100.0), pytest.approx(100.0))
    nck.submit(c.CycleStart())
    assert until_stop(nck).startswith("N45")
    assert (mcs(nck), wcs(nck)) == (pytest.approx(110.0), pytest.approx(100.0))
