"""Copies of the material's heights along a simulation, to go back to any number of chords.

The simulation's own sweep keeps them as it goes (a chord count it reports complete at or past
every :data:`CHECKPOINT_CHORDS`), so that the first scrub step back after a long simulation starts
from a nearby copy instead of sweeping the whole path again; the scrubber adds its own as it
sweeps forward. At most :data:`MAX_CHECKPOINTS` copies: beyond, the spacing doubles and only the
first copy of each new stretch stays (our choice: some 30 MB at the editor's resolution).
"""

from __future__ import annotations

import numpy as np

CHECKPOINT_CHORDS = 2_000
"""A copy of the heights is kept every this many chords swept forward."""
MAX_CHECKPOINTS = 64
"""At most this many copies (beyond: every other one is dropped and the spacing doubles)."""


class Checkpoints:
    """Heights after a number of chords, the blank (0 chords) always among them."""

    def __init__(self, blank_heights: np.ndarray, every: int | None = None) -> None:
        self.every = every if every is not None else CHECKPOINT_CHORDS
        self.kept: dict[int, np.ndarray] = {0: blank_heights.copy()}
        self._stretches = {0}  # chord count // every of each copy

    def next_mark(self, chords: int) -> int:
        """The chord count of the next copy after ``chords``."""
        return (chords // self.every + 1) * self.every

    def keep(self, chords: int, heights: np.ndarray) -> None:
        """Keep a copy of ``heights`` (the state after ``chords`` chords) if it opens a new stretch
        of :attr:`every` chords."""
        if chords // self.every in self._stretches:
            return
        self.kept[chords] = heights.copy()
        self._stretches.add(chords // self.every)
        if len(self.kept) > MAX_CHECKPOINTS:
            self.every *= 2
            firsts: dict[int, int] = {}
            for kept in sorted(self.kept):
                firsts.setdefault(kept // self.every, kept)
            self.kept = {kept: self.kept[kept] for kept in firsts.values()}
            self._stretches = set(firsts)

    def copy(self) -> Checkpoints:
        """Another keeper with the same copies (shared: they are never written)."""
        other = Checkpoints.__new__(Checkpoints)
        other.every, other.kept, other._stretches = self.every, dict(self.kept), set(self._stretches)
        return other
