"""The extents of a path's first n chords for any n, worked out once per path.

A scrub step shows the same path up to another chord, and the material view fits the blank and
the path drawn so far: going through the chord ends again costs milliseconds per picture on a
long program. :class:`ChordExtents` keeps per axis the least and greatest end of every whole
block of chords from the start, so only the one block cut is gone through again.
"""

from __future__ import annotations

import threading
import weakref
from dataclasses import dataclass

import numpy as np

BLOCK_CHORDS = 1024
"""Chords per block of the table."""


@dataclass(frozen=True)
class ChordExtents:
    """A path's chord ends (rows x, y, z in mm) and the table of their extents."""

    ends: np.ndarray
    block_low: np.ndarray  # row k: per axis the least end of chords 0 … (k + 1)·BLOCK_CHORDS − 1
    block_high: np.ndarray  # … and the greatest

    @classmethod
    def of(cls, ends: np.ndarray) -> ChordExtents:
        """The table of the chords ending at ``ends``."""
        whole = len(ends) // BLOCK_CHORDS * BLOCK_CHORDS
        blocks = ends[:whole].reshape(-1, BLOCK_CHORDS, ends.shape[1])
        return cls(ends, np.minimum.accumulate(blocks.min(axis=1), axis=0),
                   np.maximum.accumulate(blocks.max(axis=1), axis=0))

    def of_first(self, count: int) -> tuple[np.ndarray, np.ndarray] | None:
        """Per axis the least and the greatest end of the first ``count`` chords (None for none)."""
        count = min(max(count, 0), len(self.ends))
        if count == 0:
            return None
        whole = count // BLOCK_CHORDS
        rest = self.ends[whole * BLOCK_CHORDS:count]
        lows = [rest.min(axis=0)] if len(rest) else []
        highs = [rest.max(axis=0)] if len(rest) else []
        if whole:
            lows.append(self.block_low[whole - 1])
            highs.append(self.block_high[whole - 1])
        return np.min(lows, axis=0), np.max(highs, axis=0)


_last: list[weakref.ref[ChordExtents]] = []  # the table made last, while a picture holds it
_last_lock = threading.Lock()  # pictures are made in worker threads and in the screen's


def chord_extents(ends: np.ndarray) -> ChordExtents:
    """The table of the chords ending at ``ends``: the one made last when it is the same array
    (and a picture still holds it), else a new one (a screen shows one path at a time, step
    after step)."""
    with _last_lock:
        last = _last[0]() if _last else None
    if last is not None and last.ends is ends:
        return last
    extents = ChordExtents.of(ends)
    with _last_lock:
        _last[:] = [weakref.ref(extents)]
    return extents
