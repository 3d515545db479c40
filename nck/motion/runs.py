"""Executable motions: a profile along a chain of path segments, or along one axis.

A run keeps its local time ``tau`` (time of the last IPO sample taken from it);
the next sample is one IPO cycle later. A run that ends inside a cycle hands
the rest of that cycle to the next run (``tau`` of the next run starts
negative), so continuous-path transitions lose no time.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from nck.motion.planner import PlannedSegment
from nck.motion.profile import Profile


@dataclass(slots=True)
class PathRun:
    """A profile over ``chain`` starting ``s_begin`` into the first segment.

    ``kind`` is ``segment`` (one whole remaining segment) or ``brake`` (NC STOP,
    override 0 or RESET braking, possibly across several segments).
    """

    chain: list[PlannedSegment]
    s_begin: float
    profile: Profile
    tau: float = 0.0
    kind: str = "segment"
    exit_target: float = 0.0
    _offsets: np.ndarray | None = field(default=None, init=False, repr=False, compare=False)

    @property
    def offsets(self) -> np.ndarray:
        """Run distance at the start of every segment of the chain, and at its end (made on
        first use: a whole segment run that ends normally never needs it)."""
        offsets = self._offsets
        if offsets is None:
            first = self.chain[0].segment.length - self.s_begin
            if len(self.chain) == 1:
                offsets = np.array([0.0, first])
            else:
                remaining = [first] + [seg.segment.length for seg in self.chain[1:]]
                offsets = np.concatenate([[0.0], np.cumsum(remaining)])
            self._offsets = offsets
        return offsets

    @property
    def finished(self) -> bool:
        """True once the last sample reached the end of the profile."""
        return self.tau >= self.profile.duration_s - 1e-12

    def positions(self, s: np.ndarray) -> np.ndarray:
        """Axis positions at run distances ``s``."""
        if len(self.chain) == 1:
            return self.chain[0].segment.positions(self.s_begin + s)
        offsets = self.offsets
        which = np.clip(np.searchsorted(offsets, s, side="right") - 1, 0, len(self.chain) - 1)
        out = None
        for index in np.unique(which):
            mask = which == index
            local = s[mask] - offsets[index] + (self.s_begin if index == 0 else 0.0)
            part = self.chain[index].segment.positions(local)
            if out is None:
                out = np.empty((len(s), part.shape[1]))
            out[mask] = part
        assert out is not None
        return out

    def split_end(self) -> tuple[int, float]:
        """Where the profile ends: (index in chain, distance into that segment)."""
        offsets = self.offsets
        length = min(self.profile.length, float(offsets[-1]))
        index = int(np.clip(np.searchsorted(offsets, length, side="right") - 1, 0, len(self.chain) - 1))
        local = length - offsets[index] + (self.s_begin if index == 0 else 0.0)
        return index, local

    def state(self) -> tuple[float, float, float]:
        """Distance, velocity and acceleration at the last sample."""
        return self.profile.state_at(max(self.tau, 0.0))


@dataclass
class AxisRun:
    """One axis moving ``direction`` from ``origin`` along ``profile`` (JOG, referencing)."""

    index: int
    origin: float
    direction: float
    profile: Profile
    purpose: str
    velocity_mm_s: float
    override: bool = True
    tau: float = 0.0
    stopping: bool = False
    limit_switch_mm: float | None = None  # a hardware limit switch this run will reach (21614 then)

    @property
    def finished(self) -> bool:
        """True once the last sample reached the end of the profile."""
        return self.tau >= self.profile.duration_s - 1e-12

    def position_at(self, s: np.ndarray) -> np.ndarray:
        """Axis positions at run distances ``s``."""
        return self.origin + self.direction * s

    @property
    def end_position(self) -> float:
        """Where the run ends."""
        return self.origin + self.direction * self.profile.length
