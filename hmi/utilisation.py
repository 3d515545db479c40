"""System utilisation: the wall-clock time the kernel takes per simulated IPO cycle.

The kernel has no clock; the bridge, which advances it, times every ``tick``/``step``
with :meth:`UtilisationMeter.measure` and the Diagnostics area shows the figures.
"""

from __future__ import annotations

import time
from collections import deque
from dataclasses import dataclass, field
from typing import Callable

CLOCK: Callable[[], float] = time.perf_counter
"""Wall clock of the measurement (tests replace it)."""


@dataclass
class UtilisationMeter:
    """Compute time per simulated IPO cycle and blocks per second over the last calls."""

    samples: deque = field(default_factory=lambda: deque(maxlen=50))  # (wall_s, cycles, blocks)

    def measure(self, run: Callable[[], None], counters: Callable[[], tuple[int, int]]) -> None:
        """Call ``run`` and keep its wall time with the (IPO cycles, blocks) it added to ``counters()``."""
        cycles0, blocks0 = counters()
        start = CLOCK()
        run()
        cycles1, blocks1 = counters()
        if cycles1 > cycles0:
            self.samples.append((CLOCK() - start, cycles1 - cycles0, blocks1 - blocks0))

    def figures(self, ipo_cycle_s: float) -> dict[str, float]:
        """Mean compute time per IPO cycle (µs), load (%), blocks per second (wall and simulated)."""
        wall = sum(s[0] for s in self.samples)
        cycles = sum(s[1] for s in self.samples)
        blocks = sum(s[2] for s in self.samples)
        per_cycle = wall / cycles if cycles else 0.0
        worst = max((s[0] / s[1] for s in self.samples), default=0.0)
        return {
            "cycle_compute_us": per_cycle * 1e6,
            "cycle_compute_max_us": worst * 1e6,
            "ipo_load_pct": per_cycle / ipo_cycle_s * 100.0 if ipo_cycle_s > 0 else 0.0,
            "blocks_per_s": blocks / wall if wall > 0 else 0.0,
            "blocks_per_sim_s": blocks / (cycles * ipo_cycle_s) if cycles else 0.0,
            "cycles_measured": float(cycles),
        }
