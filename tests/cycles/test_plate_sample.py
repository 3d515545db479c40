"""The sample program POCKET_PLATE (POCKET3 and POCKET4, roughing then finishing) cuts what its
parameters say: worked out by hand with the end mill T1 of radius 5 mm."""

from __future__ import annotations

from pathlib import Path

from nck.headless import interpret_only, run_on_kernel
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path

SAMPLE = Path(data_path("programs")) / "POCKET_PLATE.MPF"


def test_plate_pockets_reach_their_walls_and_bottoms(tmp_path: Path) -> None:
    """POCKET3 60 x 40 about (40, 40): the finishing rectangle of the tool centre is half
    30-5 = 25 by 20-5 = 15, so X 15 … 65 and Y 25 … 55 at Z-8; roughing stays 0.3 inside
    (X 15.3 … 64.7) and 0.2 above (ceil(7.8/3) = 3 levels of 2.6: -2.6, -5.2, -7.8).
    POCKET4 radius 14 about (95, 40): finishing circle 14-5 = 9 at Z-6; roughing circles up to
    14-5-0.3 = 8.7 at ceil(5.8/3) = 2 levels of 2.9."""
    data = Session.open(tmp_path / "data").ncdata
    result = interpret_only(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name,
                            text=SAMPLE.read_text(), max_blocks=100_000)
    assert result.status == "ended", result.alarms
    cut = [m for m in result.segments if m.kind != "G0"]
    pocket3 = [m for m in cut if m.end_wcs["X"] < 75]
    pocket4 = [m for m in cut if m.end_wcs["X"] >= 75]
    xs = [round(m.end_wcs["X"], 3) for m in pocket3]
    assert (min(xs), max(xs)) == (15, 65)
    ys = [round(m.end_wcs["Y"], 3) for m in pocket3]
    assert (min(ys), max(ys)) == (25, 55)
    levels3 = sorted({round(m.end_wcs["Z"], 3) for m in pocket3})
    assert levels3 == [-8, -7.8, -5.2, -2.6]
    radii4 = sorted({round(m.end_wcs["X"] - 95, 3) for m in pocket4 if m.kind in ("G2", "G3")})
    assert radii4[-2:] == [8.7, 9]
    assert sorted({round(m.end_wcs["Z"], 3) for m in pocket4}) == [-6, -5.8, -2.9]


def test_plate_runs_to_its_end_on_the_kernel(tmp_path: Path) -> None:
    data = Session.open(tmp_path / "data").ncdata
    result = run_on_kernel(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name, timeout_s=3600.0)
    assert result.status == "ended", result.alarms
