"""The block display while a DISPLOF subprogram (a cycle) runs: the control shows the calling
block for the whole subprogram (002 L21867-21868, L23164), not a later block the interpreter
has already read ahead in the calling program."""

from __future__ import annotations

import pytest

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion.instant import instant_motion_factory


def _started(programs: dict[str, str]) -> Nck:
    nck = Nck(programs=MemorySource(programs), referenced=True, motion_factory=instant_motion_factory,
              batch_cycles=1)
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    return nck


def _shown(nck: Nck) -> str:
    block = nck.status().channel.current_block
    assert block is not None
    return block.text.split()[0]


PROGRAMS = {
    "P.MPF": "N10 G1 X1 F600\nN20 CYC1\nN30 G1 X100\nN40 X200\nN50 M30",
    "CYC1.SPF": "PROC CYC1 DISPLOF\nN100 G1 X10\nN110 X20\nN120 RET",
}


def test_calling_block_is_shown_while_the_displof_subprogram_moves() -> None:
    nck = _started(PROGRAMS)
    # F600 = 10 mm/s: X1 after 0.1 s, then N100 to X10 and N110 to X20 (1 s each)
    nck.tick(0.6)
    assert 4.0 < nck.positions_mcs()["X"] < 10.0  # in N100 of the cycle
    assert _shown(nck) == "N20"
    nck.tick(1.0)
    assert 10.0 < nck.positions_mcs()["X"] < 20.0  # in N110 of the cycle
    assert _shown(nck) == "N20"
    assert nck.run_until(lambda k: k.positions_mcs()["X"] > 30.0, 10.0)
    assert _shown(nck) == "N30"  # back in the main program: its own block again


def test_nested_call_inside_a_displof_cycle_still_shows_the_calling_block() -> None:
    programs = {**PROGRAMS, "CYC1.SPF": "PROC CYC1 DISPLOF\nN100 G1 X10\nN110 INNER\nN120 RET",
                "INNER.SPF": "PROC INNER\nN200 G1 X20\nN210 RET"}
    nck = _started(programs)
    nck.tick(1.6)
    assert nck.positions_mcs()["X"] == pytest.approx(15.0, abs=1.0)  # in N200 of INNER
    assert _shown(nck) == "N20"


def test_calling_block_is_shown_after_many_hidden_blocks_without_motion() -> None:
    """A cycle computes a lot between two moves (here 600 blocks of a loop): the block in
    execution still shows its call, however far the interpreter has read ahead."""
    programs = {**PROGRAMS, "CYC1.SPF": "PROC CYC1 DISPLOF\nN100 G1 X10\nN105 R1=0\n"
                "LOOP: R1=R1+1\nIF R1<300 GOTOB LOOP\nN110 X20\nN120 RET"}
    nck = _started(programs)
    nck.tick(0.6)
    assert 4.0 < nck.positions_mcs()["X"] < 10.0  # in N100 of the cycle
    assert _shown(nck) == "N20"


def test_turn_shaft_shows_each_cycle_call_while_the_cycle_runs(tmp_path) -> None:
    """The sample TURN_SHAFT on the lathe (planned motion, as in AUTO): while a cycle (DISPLOF) runs, the block display stays
    on its call block (N50, N100, N150, N200) although the interpreter reads ahead: the shown
    block numbers never go back, and each cycle call is shown."""
    from pathlib import Path

    from nck.interp.sources import DirectorySource
    from nck.machine import load_machine
    from nck.persistence import Session
    from nck.resources import data_path

    lathe = load_machine("lathe2")
    data = Session.open(tmp_path / "data", lathe).ncdata
    nck = Nck(lathe, data, DirectorySource(Path(data_path("programs"))), referenced=True)  # planned motion
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("TURN_SHAFT.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    shown: list[int] = []
    for _ in range(4000):
        nck.tick(0.5)
        if nck.situation.channel == "reset":
            break
        block = nck.status().channel.current_block
        number = int(block.text.split()[0][1:])
        if not shown or shown[-1] != number:
            shown.append(number)
    assert nck.situation.channel == "reset"
    assert shown == sorted(shown), shown
    assert {50, 100, 150, 200} <= set(shown)
