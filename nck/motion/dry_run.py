"""Dry run feed (002 L18151-18182): SD42100 DRY_RUN_FEED with the SD42101 mode.

The motion systems keep the programmed feed of every buffered segment and apply the dry run
feed to it, so that dry run switched on during an interruption acts on the rest of the
program, including the blocks already in the look-ahead buffer (and at block end while the
program runs: the segment in execution keeps its feed).
"""

from __future__ import annotations

from dataclasses import dataclass

from nck.canon import THREAD_AND_TAPPING_KINDS


@dataclass(frozen=True, slots=True)
class DryRun:
    """Dry run switched on: ``feed_mm_min`` (SD42100) and ``mode`` (SD42101)."""

    feed_mm_min: float
    mode: int = 0

    def feed_for(self, kind: str, programmed_mm_min: float | None) -> float | None:
        """The feed of a block of ``kind`` programmed with ``programmed_mm_min`` (mm/min, a
        revolutional feed already converted; None: none), under dry run; G0 is not affected.

        Mode 0: the larger of the two, 1: the smaller, 2: SD42100 alone; 10, 11, 12 the
        same except threads and tapping (G33-G35, G331, G332, G63), which run as programmed.
        """
        if kind == "G0" or self.feed_mm_min <= 0.0:
            return programmed_mm_min
        if self.mode >= 10 and kind in THREAD_AND_TAPPING_KINDS:
            return programmed_mm_min
        base = self.mode % 10
        if programmed_mm_min is None or base not in (0, 1):
            return self.feed_mm_min
        if base == 1:
            return min(programmed_mm_min, self.feed_mm_min)
        return max(programmed_mm_min, self.feed_mm_min)
