"""Digest programming-840c (manual 001, 840C Programming Guide): ranked items whose behaviour
carries over to the 840D sl language this product speaks, written in its syntax.

840C-only forms (@-codes, strict left-to-right arithmetic, ``L..`` subroutines, 3xxx alarm
numbers, G16, M37, B as radius address) are listed as not modelled in ``tests/README.md``.
Expected values come from the manual lines cited, worked out by hand.
"""

from __future__ import annotations

import pytest

from nck import canon
from tests.lang.conftest import run_text


def motions(text: str) -> list[canon.Motion]:
    result = run_text(text)
    assert result.status == "ended", result.alarms
    return list(result.segments)


def alarm_of(text: str) -> int:
    result = run_text(text)
    assert result.status == "alarm"
    return result.alarms[0].number


def test_digest_programming_840c_rank_02_absolute_and_incremental_reach_the_same_point() -> None:
    """Digest programming-840c rank 2: from P1 (20, 10), ``G90 X60 Y30`` and ``G91 X40 Y20``
    both reach P2 (60, 30) (001 L1666-1688); Z, not written, stays."""
    for move in ("G90 X60 Y30", "G91 X40 Y20"):
        end = motions(f"G0 X20 Y10 Z5\n{move}\nM30\n")[-1].end_mcs
        assert end == pytest.approx({"X": 60.0, "Y": 30.0, "Z": 5.0})


def test_digest_programming_840c_rank_03_coarse_plus_fine_offset_and_g53() -> None:
    """Digest programming-840c rank 3: the settable offset is coarse + fine (001 L1830-2036):
    G54 X = 100 + 0.1 puts WCS X0 at machine 100.1; G53 (non-modal) suppresses it for its block
    only, so the next X0 is at 100.1 again."""
    ends = [m.end_mcs["X"] for m in motions(
        "$P_UIFR[1,X,TR]=100\n$P_UIFR[1,X,FI]=0.1\nG54 G90 G0 X0\nG53 X0\nX0\nM30\n")]
    assert ends == pytest.approx([100.1, 0.0, 100.1])


def test_digest_programming_840c_rank_05_quarter_arc_from_centre_offsets() -> None:
    """Digest programming-840c rank 5: from X0 Y25, ``G02 X25 Y0 I0 J-25`` (I/J from the start
    point, 001 L3094-3250, helix example L3737-3742) is the CW quarter arc about (0, 0); with
    a negative radius (840D: ``CR=-25``) the arc over 180° about (25, 25)."""
    arc = motions("G17 G90 G0 X0 Y25\nG02 X25 Y0 I0 J-25 F100\nM30\n")[-1]
    assert (arc.kind, arc.center_wcs) == ("G2", pytest.approx({"X": 0.0, "Y": 0.0, "Z": 0.0}))
    big = motions("G17 G90 G0 X0 Y25\nG02 X25 Y0 CR=-25 F100\nM30\n")[-1]
    assert big.center_wcs == pytest.approx({"X": 25.0, "Y": 25.0, "Z": 0.0})


def test_digest_programming_840c_rank_12_g00_keeps_the_programmed_feed() -> None:
    """Digest programming-840c rank 12: with G00 the F programmed remains stored and is active
    again with G01 (001 L3009); a feed type change needs a new F (001 L2439; 840D 10860)."""
    feeds = [m.feed_mm_min for m in motions("G1 X10 F300\nG0 X20\nG1 X30\nM30\n")]
    assert (feeds[0], feeds[2]) == (300.0, 300.0)
    assert alarm_of("G94 G1 X10 F300\nG95 S100 M3\nG1 X20\nM30\n") == 10860


def test_digest_programming_840c_rank_13_m3_and_m4_in_one_block_are_refused() -> None:
    """Digest programming-840c rank 13: more than one of M3/M4/M5/M19 in a block is an alarm
    (001 Ch.5, L2479-2600; 840C 3006, the 840D raises its own number)."""
    assert alarm_of("M3 M4 S100\nM30\n") > 0


def test_digest_programming_840c_rank_18_dwell_alone_in_its_block() -> None:
    """Digest programming-840c rank 18: ``G04 X11.5`` dwells 11.5 s, ``G04 S50`` 50 spindle
    revolutions; no other function may be in a dwell block (001 L6402-6419). In 840D syntax
    ``G4 F2.5`` and ``G4 S10``; a G4 with an axis word or an M function is refused (it used
    to drop X5 and M8 silently)."""
    result = run_text("G4 F2.5\nM3 S600\nG4 S10\nM30\n")
    dwells = [(c.seconds, c.revolutions) for c in result.commands if isinstance(c, canon.Dwell)
              and not c.wait_spindle]
    assert dwells == [(2.5, None), (None, 10.0)]
    assert alarm_of("G4 F1 X5\nM30\n") == 12080
    assert alarm_of("G4 F1 M8\nM30\n") == 12080


@pytest.mark.parametrize(("md11470", "rest_s"), [(0, 0.0), (1, 4.0)])
def test_digest_programming_840c_rank_18_nc_stop_cancels_a_dwell(md11470: int, rest_s: float) -> None:
    """Digest programming-840c rank 18: NC STOP during ``G04 X`` cancels the dwell (001
    L6467-6469); on the 840D MD11470 bit 0 makes NC START resume the rest of it instead (002
    L19242-19243). G4 F5, NC STOP after 1 s, 0.5 s stopped, NC START: the rest is 0 s, or the
    4 s left (the time stopped does not count); then N20 moves X by 10 mm at 600 mm/min, 1 s.
    Before, the dwell went on counting while the channel was stopped."""
    import dataclasses

    from nck import commands as c
    from nck.interp.sources import MemorySource
    from nck.kernel import Nck
    from nck.machine import load_machine

    machine = load_machine()
    machine = dataclasses.replace(machine, md={**machine.md, "MD11470": md11470})
    nck = Nck(machine=machine, programs=MemorySource({"P.MPF": "N10 G4 F5\nN20 G1 X10 F600\nN30 M30\n"}),
              referenced=True, batch_cycles=1)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(1.0)
    assert nck.submit(c.CycleStop()) == c.Accepted()
    nck.tick(0.5)
    assert nck.situation.program == "stopped"
    restart_s = nck.time_s
    assert nck.submit(c.CycleStart()) == c.Accepted()
    assert nck.run_until(lambda k: k.situation.channel == "reset", 30.0)
    assert nck.time_s - restart_s == pytest.approx(rest_s + 1.0, abs=0.05)
