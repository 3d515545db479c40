"""Scrubbing through a simulation (issue 24): any state reached forward, back and forward again is
the state swept from the uncut blank, and the cut of one block against a hand-computed volume."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from nck.simulation import checkpoints, scrub, zmap
from nck.simulation.scrub import Scrubber
from tests.simulation.test_removal import run

SLOT = "N10 T1 M6\nN20 D1 S2000 M3\nN30 G0 X20 Y50 Z2\nN40 G1 Z-5 F200\nN50 X80 F600\nN60 G0 Z10\n"


def test_back_and_forth_gives_the_states_swept_from_the_blank(monkeypatch) -> None:
    monkeypatch.setattr(checkpoints, "CHECKPOINT_CHORDS", 2)  # checkpoints inside this short program
    simulation = run(SLOT + "N70 G0 X50 Y20\nN80 G1 Z-3\nN90 G2 X50 Y20 I0 J10 F500\nN100 G0 Z10\n", 0.5)
    scrubber = Scrubber(simulation)
    total = scrubber.total
    assert total > 6
    for chords in (total, 3, total - 1, 0, 5, 1, total):
        expected = simulation.cut_until(chords).heights
        assert np.array_equal(scrubber.goto(chords).heights, expected), chords


def test_steps_back_from_the_copies_kept_on_the_way_give_the_states_swept_from_the_blank(monkeypatch) -> None:
    """Block ◀ pressed again and again: the first step back into a checkpoint's stretch sweeps from
    the checkpoint and keeps a copy at every chord (here) on its way; the next steps start from
    those copies and sweep nothing. Every state equals the sweep from the blank."""
    monkeypatch.setattr(checkpoints, "CHECKPOINT_CHORDS", 4)
    monkeypatch.setattr(scrub, "NEAR_CHORDS", 1)
    monkeypatch.setattr(scrub, "MAX_NEAR", 100)
    simulation = run(SLOT + "N70 G0 X50 Y20\nN80 G1 Z-3\nN90 G2 X50 Y20 I0 J10 F500\nN100 G0 Z10\n", 0.5)
    scrubber = Scrubber(replace(simulation, checkpoints=None))  # the scrubber's own copies only
    total = scrubber.total
    assert total > 8
    swept: list[int] = []
    sweep = scrub.sweep_path
    monkeypatch.setattr(scrub, "sweep_path", lambda model, path, upto=None, first=0:
                        swept.append(upto - first) or sweep(model, path, upto=upto, first=first))
    scrubber.goto(total)
    for chords in range(total - 1, -1, -1):
        swept.clear()
        expected = simulation.cut_until(chords).heights
        assert np.array_equal(scrubber.goto(chords).heights, expected), chords
        first_into_stretch = chords == total - 1 or (chords + 1) % 4 == 0
        assert sum(swept) == (chords % 4 if first_into_stretch else 0), chords


def test_the_first_step_back_starts_from_a_copy_the_simulation_kept(monkeypatch) -> None:
    """After a long simulation the first Block ◀ does not sweep the whole path again: the
    simulation's sweep kept copies along the way (one in every stretch of 4 chords here, where
    every numpy pass of the sweep takes one move)."""
    monkeypatch.setattr(checkpoints, "CHECKPOINT_CHORDS", 4)
    monkeypatch.setattr(zmap, "CELL_BUDGET", 1)
    simulation = run(SLOT + "N70 G0 X50 Y20\nN80 G1 Z-3\nN90 G2 X50 Y20 I0 J10 F500\nN100 G0 Z10\n", 0.5)
    total = len(simulation.path.starts)
    assert simulation.checkpoints is not None and len(simulation.checkpoints.kept) > 2
    swept: list[int] = []
    sweep = scrub.sweep_path
    monkeypatch.setattr(scrub, "sweep_path", lambda model, path, upto=None, first=0:
                        swept.append(upto - first) or sweep(model, path, upto=upto, first=first))
    for chords in (total - 1, total // 2, 1):
        swept.clear()
        scrubber = Scrubber(simulation)
        assert np.array_equal(scrubber.goto(chords).heights, simulation.cut_until(chords).heights), chords
        assert sum(swept) < 2 * 4, chords  # from the copy in its stretch or the one before


def test_the_cut_of_one_block() -> None:
    # Line 7 is N50 (two header lines): X20 -> X80 at Z-5 with a D10 end mill, after N40 plunged
    # at X20. N50 removes the slot without the plunge's hole: 60 * 10 * 5 = 3000 mm³
    # ((60 * 10 + pi * 25) * 5 for the slot, minus pi * 25 * 5 for the hole).
    simulation = run(SLOT, 0.1)
    cut = Scrubber(simulation).block_cut(7)
    assert cut is not None
    assert cut.removed_volume_mm3(0.1) == pytest.approx(3000.0, rel=0.01)
    zmap = simulation.zmap
    iy, ix = int((50.0 - zmap.y0_mm) / 0.1), int((50.0 - zmap.x0_mm) / 0.1)
    assert cut.top[iy, ix] == pytest.approx(0.0) and cut.bottom[iy, ix] == pytest.approx(-5.0)
    ix20 = int((20.0 - zmap.x0_mm) / 0.1)
    assert not cut.mask[iy, ix20]  # the plunge's hole is N40's
    plunge = Scrubber(simulation).block_cut(6)
    assert plunge.removed_volume_mm3(0.1) == pytest.approx(math.pi * 25.0 * 5.0, rel=0.01)
    assert Scrubber(simulation).block_cut(99) is None
