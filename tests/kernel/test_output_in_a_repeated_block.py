"""An output goes out with its own block's motion also when the block runs again (002 L14590-14598:
an auxiliary function is output before, during or after the traversing motion of the block it is
programmed in). A subprogram called three times sets a message only in its third pass: the
message shows while the third pass runs, not at the end of the program (where the reset clears
it before anyone sees it)."""

from __future__ import annotations

from nck import commands as cmd
from nck.build import build_nck
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

MAIN = "N10 G90 G94 G0 X0 Y0 Z0\nN20 F3000\nN30 R1=0\nN40 SUB1\nN50 R1=1\nN60 SUB1\nN70 R1=2\nN80 SUB1\nN90 M30\n"
SUB1 = ('N100 G1 X5\nN105 STOPRE\nN110 IF R1<>2 GOTOF SKIP\nN120 MSG("PASS3")\nSKIP:\n'
        "N130 G1 X10\nN140 G1 X20\nN150 G1 X30\nN160 G1 X40\nN170 G0 X0\nN180 M17\n")


def test_the_third_pass_message_shows_during_the_third_pass() -> None:
    nck = build_nck(load_machine(None), NcData(), MemorySource({"MAIN.MPF": MAIN, "SUB1.SPF": SUB1}),
                    referenced=True)
    nck.submit(cmd.SelectMode("AUTO"))
    nck.submit(cmd.SelectProgram("MAIN.MPF"))
    nck.submit(cmd.CycleStart())
    shown_at_x = None
    for _ in range(5_000):
        nck.tick(0.004)
        if shown_at_x is None and nck.status().channel.message == "PASS3":
            shown_at_x = nck.positions_mcs()["X"]
        if nck.situation.channel != "active":
            break
    assert nck.situation.channel == "reset"
    # N100 of the third pass has reached X5 (the message waits for it); N130 (X10) is under way.
    assert shown_at_x is not None and 5.0 <= shown_at_x < 10.0
