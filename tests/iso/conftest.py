"""Helpers for the ISO dialect tests: run ISO text through the interpreter (no time simulated)."""

from __future__ import annotations

from nck.headless import HeadlessRun, interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def run_iso(text: str, subprograms: dict[str, str] | None = None, dialect: str = "iso-m",
            skip_levels: frozenset[int] = frozenset(), data: NcData | None = None) -> HeadlessRun:
    """Run ``text`` as TEST.MPF in ``dialect``; returns the HeadlessRun."""
    source = MemorySource(subprograms or {})
    return interpret_only(load_machine(None), source, data or NcData(), "TEST.MPF", text=text,
                          timeout_s=100_000.0, max_blocks=100_000, dialect=dialect,
                          skip_levels=skip_levels)


def ends(result: HeadlessRun, frame: str = "wcs") -> list[tuple[int, dict[str, float]]]:
    """(source line, end point rounded to 1 µm) of every motion segment."""
    out = []
    for motion in result.segments:
        point = motion.end_wcs if frame == "wcs" else motion.end_mcs
        out.append((motion.source.line, {axis: round(value, 3) for axis, value in point.items()}))
    return out
