"""Shared helpers for the motion tests: machines, canonical moves, running to idle."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from nck.canon import Dwell, Motion, Source
from nck.machine import MachineConfig, load_machine
from nck.motion.system import PlannedMotion


def machine(**md_overrides: object) -> MachineConfig:
    """The default mill with some machine data replaced (``MD32200={"X": 1.0}``)."""
    base = load_machine("mill3")
    md = dict(base.md)
    for key, value in md_overrides.items():
        if isinstance(value, dict) and isinstance(md.get(key), dict):
            merged = dict(md[key])
            merged.update(value)
            md[key] = merged
        else:
            md[key] = value
    return replace(base, md=md)


def motion(referenced: bool = True, **md_overrides: object) -> PlannedMotion:
    """A referenced motion system on the default mill, with tracing on."""
    m = PlannedMotion(machine(**md_overrides), referenced=referenced)
    m.enable_trace()
    return m


_line = [0]


def move(kind: str = "G1", feed: float | None = 1000.0, *, exact_stop: bool = False, window: str = "G601",
         soft: bool = False, center: dict[str, float] | None = None, plane: str = "G17", **end: float) -> Motion:
    """A canonical motion to ``end`` (MCS) with the given feed (mm/min)."""
    _line[0] += 1
    return Motion(
        kind=kind, source=Source("TEST.MPF", _line[0], _line[0]), plane=plane,
        end_wcs=dict(end), end_mcs=dict(end), center_mcs=center, center_wcs=center,
        feed_mm_min=None if kind == "G0" else feed, exact_stop=exact_stop, exact_stop_window=window,
        gcodes={21: "SOFT" if soft else "BRISK"},
    )


def dwell(seconds: float) -> Dwell:
    _line[0] += 1
    return Dwell(source=Source("TEST.MPF", _line[0], _line[0]), seconds=seconds)


def run_to_idle(m: PlannedMotion, step_s: float = 0.1, limit_s: float = 600.0, feed: list | None = None) -> float:
    """Advance until idle (pushing ``feed`` items while there is room); return the machine time."""
    pending = list(feed or [])
    while True:
        while pending and m.can_accept():
            m.push(pending.pop(0))
        if not pending and m.is_idle():
            return m.time_s
        m.advance(step_s)
        assert m.time_s < limit_s, "motion did not finish"


def derivatives(m: PlannedMotion) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Sampled setpoints and their velocity, acceleration and jerk (finite differences)."""
    _t, rows = m.trace()
    T = m.ipo_cycle_s
    v = np.diff(rows, axis=0) / T
    a = np.diff(v, axis=0) / T
    j = np.diff(a, axis=0) / T
    return rows, v, a, j
