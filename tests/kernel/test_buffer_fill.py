"""The diagnosis' block buffer fill (``queries.BufferFill``): what the motion system holds
and how much it can hold, asked of the motion system itself (its public ``buffer_fill``)."""

from __future__ import annotations

from nck import commands as cmd
from nck import queries
from nck.build import build_nck
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.motion.instant import BUFFER_SEGMENTS, instant_motion_factory
from nck.ncdata import NcData

PROGRAM = "G90 G1 F500\n" + "".join(f"X{i} Y{i % 2}\n" for i in range(1, 40)) + "M30\n"
"""39 short G1 blocks: more than the look-ahead holds at once is not needed, only some."""


def started(motion_factory=None):
    nck = build_nck(load_machine("mill3"), NcData(), MemorySource({"P.MPF": PROGRAM}), referenced=True,
                    motion_factory=motion_factory)
    assert queries.answer(nck, queries.BufferFill())[0] == 0  # nothing buffered before NC START
    for command in (cmd.SelectMode("AUTO"), cmd.SelectProgram("P.MPF"), cmd.CycleStart()):
        assert nck.submit(command) == cmd.Accepted()
    nck.step(5)
    return nck


def test_the_planned_motion_reports_its_look_ahead_and_md28060() -> None:
    nck = started()
    items, capacity = queries.answer(nck, queries.BufferFill())
    assert capacity == 64  # data/machines/mill3.toml: MD28060 = 64 (MM_IPO_BUFFER_SIZE)
    assert 0 < items <= capacity


def test_the_stand_in_motion_reports_its_queue() -> None:
    nck = started(instant_motion_factory)
    items, capacity = queries.answer(nck, queries.BufferFill())
    assert capacity == BUFFER_SEGMENTS
    assert 0 < items <= capacity
