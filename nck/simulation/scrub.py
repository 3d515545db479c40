"""Scrubbing through a simulation: the blank as cut after any number of chords, and the cut of one
block.

Stepping forward sweeps only the chords between the shown state and the new one; stepping back
starts again from the nearest checkpoint (:mod:`nck.simulation.checkpoints`: the copies the
simulation's own sweep kept, and those the scrubber keeps sweeping forward) instead of from the
uncut blank. Going back also keeps a copy every :data:`NEAR_CHORDS` chords on its way from the
checkpoint (the last :data:`MAX_NEAR` of them), so that the next steps back — the operator
pressing Block ◀ again — start from a copy a few chords away. Lowering is a minimum: a state swept
from any copy is the state swept from the blank, bit for bit. Our choice: the events found while
scrubbing are the simulation's own (found once, when it ran), so the scrubber sweeps without
collecting them.

Not thread-safe: one caller at a time.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from nck.simulation.checkpoints import Checkpoints
from nck.simulation.run import Simulation, sweep_path
from nck.simulation.turning import TurnProfile
from nck.simulation.zmap import ZMap

NEAR_CHORDS = 100
"""On the way back from a checkpoint, a copy is kept every this many chords …"""
MAX_NEAR = 24
"""… the last this many of them (our choice: a few hundred chords behind the shown block, some
megabytes at the editor's resolution)."""
MAX_BLOCK_RUNS = 50
"""The cut of a block that runs more often (a loop, a subprogram called many times) is the
cut of its first this many runs (our choice: the picture would not change visibly)."""
CUT_MM = 1e-4
"""A cell counts as cut by a block when the block lowers it by more than this."""


@dataclass(frozen=True)
class BlockCut:
    """The material a block removed: per cell, the height before (``top``) and after
    (``bottom``) its runs; NaN where it removed nothing. Same grid as the simulation's model."""

    top: np.ndarray
    bottom: np.ndarray

    @property
    def mask(self) -> np.ndarray:
        """The cells the block cut."""
        return ~np.isnan(self.top)

    def removed_volume_mm3(self, resolution_mm: float) -> float:
        """The volume the block removed (a Z-map's cells; a lathe's rings are not summed here)."""
        cut = np.nan_to_num(self.top - self.bottom)
        return float(cut.astype(np.float64).sum()) * resolution_mm ** 2


class Scrubber:
    """The blank of ``simulation`` as cut after any number of its chords."""

    def __init__(self, simulation: Simulation) -> None:
        self.simulation = simulation
        self.model: ZMap | TurnProfile = simulation.zmap.fresh()
        self.chords = 0
        kept = simulation.checkpoints
        # The simulation's own copies (its sweep kept them), else from the blank on.
        self._checkpoints = kept.copy() if kept is not None else Checkpoints(self.model.heights)
        self._near: dict[int, np.ndarray] = {}

    @property
    def total(self) -> int:
        """The number of chords of the whole run."""
        return len(self.simulation.path.starts)

    def goto(self, chords: int) -> ZMap | TurnProfile:
        """The model cut by the first ``chords`` chords (it is the scrubber's own: copy it to keep it)."""
        chords = min(max(int(chords), 0), self.total)
        back = chords < self.chords
        kept = self._checkpoints.kept
        start = max(c for c in (*kept, *self._near) if c <= chords)
        if back or start > self.chords:  # going back, or a copy ahead saves sweeping up to it
            self.model.heights[...] = kept[start] if start in kept else self._near[start]
            self.chords = start
        while self.chords < chords:
            mark = self._checkpoints.next_mark(self.chords)
            near = (self.chords // NEAR_CHORDS + 1) * NEAR_CHORDS if back else mark
            upto = min(mark, near, chords)
            sweep_path(self.model, self.simulation.path, upto=upto, first=self.chords)
            self.chords = upto
            if upto == mark:
                self._checkpoints.keep(upto, self.model.heights)
            elif upto == near:
                self._keep_near(upto)
        return self.model

    def _keep_near(self, chords: int) -> None:
        if chords in self._near:
            return
        self._near[chords] = self.model.heights.copy()
        if len(self._near) > MAX_NEAR:
            del self._near[max(self._near, key=lambda kept: abs(kept - chords))]  # the farthest away

    def runs_of_line(self, line: int) -> list[tuple[int, int]]:
        """The chord ranges [first, end) the source ``line`` ran for, in order."""
        mine = np.concatenate(([False], self.simulation.path.lines == line, [False]))
        edges = np.flatnonzero(mine[1:] != mine[:-1])
        return list(zip(edges[0::2].tolist(), edges[1::2].tolist()))

    def block_cut(self, line: int) -> BlockCut | None:
        """What the block of source ``line`` cut (each of its first :data:`MAX_BLOCK_RUNS` runs:
        the heights before and after it); None when it never ran. Leaves the scrubber at the end
        of the last run looked at."""
        runs = self.runs_of_line(line)[:MAX_BLOCK_RUNS]
        if not runs:
            return None
        shape = self.model.heights.shape
        top = np.full(shape, np.nan, dtype=np.float32)
        bottom = np.full(shape, np.nan, dtype=np.float32)
        for first, end in runs:
            before = self.goto(first).heights.copy()
            after = self.goto(end).heights
            cut = before - after > CUT_MM
            top[cut] = np.fmax(top[cut], before[cut])
            bottom[cut] = np.fmin(bottom[cut], after[cut])
        return BlockCut(top, bottom)
