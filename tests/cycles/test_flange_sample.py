"""The sample program DRILL_FLANGE (MCALL + HOLES2 + CYCLE83, then MCALL + HOLES2 + CYCLE84)
drills and taps six holes; positions and depths worked out by hand from its parameters."""

from __future__ import annotations

import math
from pathlib import Path

from nck.headless import interpret_only, run_on_kernel
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path

SAMPLE = Path(data_path("programs")) / "DRILL_FLANGE.MPF"


def _holes() -> list[tuple[float, float]]:
    """HOLES2(0, 0, 40, 0, 60, 6): radius 40, angles 0, 60, …, 300 degrees."""
    return [(round(40 * math.cos(math.radians(60 * k)), 3), round(40 * math.sin(math.radians(60 * k)), 3))
            for k in range(6)]


def _run(tmp_path: Path):
    data = Session.open(tmp_path / "data").ncdata  # a fresh data directory has T3 and T4
    return interpret_only(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name,
                          text=SAMPLE.read_text(), max_blocks=100_000)


def test_flange_drills_every_hole_in_pecks_then_taps_it(tmp_path: Path) -> None:
    """CYCLE83 FDEP -6, DAM 2, DP -18: infeeds 6, 6-2 = 4, 4-2 = 2, then 2 (not less than DAM)
    until -18: depths -6, -10, -12, -14, -16, -18 at each hole. CYCLE84 M10 (lead 1.5 mm):
    G331 to -15 at 300 rpm (1.5 x 300 = 450 mm/min), G332 back to the safety plane 2 at 600."""
    result = _run(tmp_path)
    assert result.status == "ended", result.alarms
    drills = [(round(m.end_wcs["X"], 3), round(m.end_wcs["Y"], 3), round(m.end_wcs["Z"], 3))
              for m in result.segments if m.kind == "G1"]
    assert drills == [(x, y, z) for x, y in _holes() for z in (-6, -10, -12, -14, -16, -18)]
    taps = [(m.kind, round(m.end_wcs["X"], 3), round(m.end_wcs["Y"], 3), m.end_wcs["Z"], m.lead_mm, m.feed_mm_min)
            for m in result.segments if m.kind in ("G331", "G332")]
    assert taps == [t for x, y in _holes() for t in (("G331", x, y, -15, 1.5, 450), ("G332", x, y, 2, 1.5, 900))]


def test_flange_runs_to_its_end_on_the_kernel(tmp_path: Path) -> None:
    """AUTO with NC START (as nck run): the program ends without an alarm, the tool at Z100."""
    data = Session.open(tmp_path / "data").ncdata
    result = run_on_kernel(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name, timeout_s=3600.0)
    assert result.status == "ended", result.alarms
    assert result.position_wcs is not None and round(result.position_wcs["Z"], 3) == 100
