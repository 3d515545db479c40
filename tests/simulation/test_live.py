"""Simultaneous recording (issue 24): the cut of a program running in AUTO on the session's
kernel grows as it executes and ends as the editor's simulation of the same program.

Programs from the material-view tests (tool defined in the program, 002 L62525-62558);
single block SBL1 stops after each block (002 L18080ff: NC START runs the next block).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nck import commands as cmd
from nck import queries
from nck.interp.sources import DirectorySource
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import NcData
from nck.simulation.run import simulate
from tests.program_screens.test_material_view import SHAFT, SLOTS


def started(tmp_path: Path, text: str, machine: str = "mill3", single_block: bool = False) -> Nck:
    (tmp_path / "DEMO.MPF").write_text(text)
    nck = Nck(machine=load_machine(machine), programs=DirectorySource(tmp_path), referenced=True)
    queries.record_cuts(nck)
    assert queries.answer(nck, queries.RecordedCut()) is None  # nothing started yet
    nck.submit(cmd.SelectMode("AUTO"))
    nck.submit(cmd.SelectProgram("DEMO.MPF"))
    if single_block:
        nck.submit(cmd.SetProgramControl("single_block", "SBL1"))
    nck.submit(cmd.CycleStart())
    return nck


def cut(nck: Nck):
    return queries.answer(nck, queries.RecordedCut())


def test_the_recorded_cut_grows_and_ends_as_the_simulation(tmp_path: Path) -> None:
    nck = started(tmp_path, SLOTS)
    volumes = []
    for _ in range(200):
        nck.tick(1.0)
        now = cut(nck)
        volumes.append(now.zmap.removed_volume_mm3())
        if now.status == "ended":
            break
    assert now.status == "ended"
    assert volumes == sorted(volumes) and volumes[0] < volumes[-1]  # it grew while running
    assert len(set(volumes)) > 4
    expected = simulate("DEMO.MPF", SLOTS, data=NcData(), resolution_mm=None)
    assert now.blank == expected.blank
    assert np.array_equal(now.zmap.heights, expected.zmap.heights)
    assert now.events == expected.events == []


def test_single_block_records_block_by_block(tmp_path: Path) -> None:
    """In single block the cut shown is the blocks run so far: each NC START adds one block."""
    nck = started(tmp_path, SLOTS, single_block=True)
    lines = []
    for _ in range(9):
        nck.run_until(lambda k: k.status().channel.channel_state != "active", 60.0)
        shown = cut(nck)
        lines.append(int(shown.path.lines[-1]) if len(shown.path.lines) else None)
        nck.submit(cmd.CycleStart())
    # N40 G0 (line 5) is the first motion; from there each stop shows the block just run
    assert lines[:2] == [None, None]
    assert lines[2:] == [5, 6, 7, 8, 9, 10, 11]


def test_lathe_recording_is_the_half_section(tmp_path: Path) -> None:
    nck = started(tmp_path, SHAFT, machine="lathe2")
    nck.run_until(lambda k: k.status().channel.channel_state == "reset", 300.0)
    now = cut(nck)
    assert now.status == "ended" and now.turning and now.events == []
    assert now.zmap.radius_at(-7.5) == 15.0


def test_a_long_run_stops_being_recorded_and_says_so(tmp_path: Path, monkeypatch) -> None:
    """The recording holds a bounded number of chords (an endless program must not fill the
    memory): past the bound nothing more is recorded and the status says ``full``."""
    import nck.simulation.live as live

    monkeypatch.setattr(live, "MAX_CHORDS", 4)
    nck = started(tmp_path, SLOTS)
    nck.run_until(lambda k: k.status().channel.channel_state == "reset", 300.0)
    now = cut(nck)
    assert now.status == "full"  # also after the end: the cut shown is not the whole run
    assert 4 <= len(now.path.starts) < 10
