"""Kernels for the JOG set-up tests, brought to a starting position the way an operator does it."""

from __future__ import annotations

from nck import commands as cmd
from nck.kernel import Nck


def run_in_mda_then_jog(nck: Nck, blocks: str, max_ticks: int = 3000) -> Nck:
    """Run ``blocks`` in MDA to their end, empty the MDA buffer and select JOG again."""
    for command in (cmd.SelectMode("MDA"), cmd.SetMdaProgram(blocks), cmd.CycleStart()):
        assert nck.submit(command) == cmd.Accepted()
    for _ in range(max_ticks):
        nck.tick(0.01)
        if nck.status().channel.channel_state == "reset":
            break
    assert nck.submit(cmd.SetMdaProgram("")) == cmd.Accepted()
    assert nck.submit(cmd.SelectMode("JOG")) == cmd.Accepted()
    return nck
