"""A simulation can be given up between chunks of simulated time (the editor drops a run nobody
waits for any more: Recalculate, back to the editor): it then ends as a time-out, with what ran."""

from __future__ import annotations

import pytest

from nck.headless import KERNEL_CHUNK_S
from nck.simulation.run import simulate

DWELL = "N10 G0 X0 Y0 Z5\nN20 G4 F35\nN30 G1 X10 F600\nN40 M30\n"
"""A rapid move, 35 s of dwell (G4 F in seconds, 001 L6410-6415), then 10 mm at 600 mm/min (1 s)."""


def test_a_run_asked_between_chunks_ends_where_it_was_given_up() -> None:
    asked: list[int] = []

    def give_up(blocks: int) -> bool:
        asked.append(blocks)
        return len(asked) == 3

    sim = simulate("A.MPF", DWELL, give_up=give_up)
    assert sim.status == "timeout" and sim.alarms == []
    # Asked before the first chunk and after each: the third time, two chunks have run.
    assert sim.machine_time_s == pytest.approx(2 * KERNEL_CHUNK_S)
    assert asked[0] == 0 and asked == sorted(asked)
    # Still in the 35 s dwell: only the rapid move was executed, not the G1 after it.
    assert sim.path.rapid.tolist() == [True]


def test_a_run_not_given_up_runs_to_its_end() -> None:
    asked: list[int] = []
    sim = simulate("A.MPF", DWELL, give_up=lambda blocks: asked.append(blocks) or False)
    assert sim.status == "ended"
    # 35 s of dwell and 1 s of feed, plus the rapid move: more than 36 s, asked once per chunk.
    assert sim.machine_time_s > 36.0
    assert len(asked) == int(sim.machine_time_s // KERNEL_CHUNK_S) + 1
    assert sim.path.rapid.tolist() == [True, False]
