"""During a dwell the G-group display shows the modal state of the block in execution, not the
interpreter's look-ahead (issue 18), on the real interpreter and motion.

002 L4520-4530 (look-ahead): the NC prepares blocks ahead of the one the axes execute, so the
interpreter already holds the next block's modal state; the display belongs to the block in
execution (the block display does the same: ``nck.snapshot`` module docstring). G4 F3 holds the
path for 3 s (001 L6402-6412); meanwhile the following block with G90 is already interpreted.
"""

from __future__ import annotations

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck


def started(text: str) -> Nck:
    nck = Nck(programs=MemorySource({"P.MPF": text}), referenced=True)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck


def test_dwell_shows_the_g_codes_of_the_block_in_execution() -> None:
    """G91 (group 14) and G95 F0.5 (group 15) are active for N20 G4 F3 (the F of G4 is the
    dwell time, 001 L6410-6412, not a feed: the feed in force stays) while N30 (G90 G94
    F1000) is already interpreted; after the dwell N30 runs and the display shows G90 G94
    F1000."""
    nck = started("N10 G91 G95 S1000 M3 G1 X10 F0.5\nN20 G4 F3\nN30 G90 G94 X0 F1000\nN40 M30")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 10.0 - 1e-9, 10.0)
    nck.tick(1.0)
    status = nck.status()
    assert status.channel.current_block.line == 2
    assert nck.positions_mcs()["X"] == 10.0
    gcodes = status.channel.modal.gcodes
    assert (gcodes[14], gcodes[15]) == ("G91", "G95")
    assert status.channel.modal.feed == 0.5
    assert nck.run_until(lambda k: k.positions_mcs()["X"] < 9.0, 5.0)
    gcodes = nck.status().channel.modal.gcodes
    assert (gcodes[14], gcodes[15]) == ("G90", "G94")
    assert nck.status().channel.modal.feed == 1000.0


def test_dwell_after_a_block_without_motion_shows_that_block_s_state() -> None:
    """N20 G91 moves nothing; N30 G4 F3 runs under G91 while N40 G90 is interpreted."""
    nck = started("N10 G1 X10 F1000\nN20 G91\nN30 G4 F3\nN40 G90 X0\nN50 M30")
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 10.0 - 1e-9, 10.0)
    nck.tick(1.0)
    assert nck.status().channel.current_block.line == 3
    assert nck.status().channel.modal.gcodes[14] == "G91"
