"""The sample program POCKET_PLATE (CYCLE61 face milling, POCKET3, POCKET4 and SLOT1, roughing
then finishing) cuts what its parameters say: worked out by hand with the end mill T1 of
radius 5 mm."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.headless import interpret_only, run_on_kernel
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path
from nck.simulation.run import simulate

SAMPLE = Path(data_path("programs")) / "POCKET_PLATE.MPF"


def _levels(moves: list) -> list[float]:
    return sorted({round(m.end_wcs["Z"], 3) for m in moves})


def _span(moves: list, axis: str) -> tuple[float, float]:
    values = [round(m.end_wcs[axis], 3) for m in moves]
    return min(values), max(values)


def test_plate_cycles_reach_their_walls_and_bottoms(tmp_path: Path) -> None:
    """CYCLE61 faces the 120 x 80 blank from Z0 to -1: roughing at -0.8 (0.2 left), finishing
    at -1, paths along X from -(5+2) to 120+5+2 = 127, 80/8 = 10 steps of 8: Y 0, 8, … 80.
    POCKET3 60 x 40 about (40, 40) from the new top -1: the finishing rectangle of the tool
    centre is half 30-5 = 25 by 20-5 = 15, so X 15 … 65 and Y 25 … 55 at Z-9; roughing 0.2
    above in ceil(7.8/3) = 3 levels of 2.6: -3.6, -6.2, -8.8. POCKET4 radius 14 about (95, 40):
    finishing circle 14-5 = 9 at Z-7; roughing circles up to 14-5-0.3 = 8.7 at ceil(5.8/3) = 2
    levels of 2.9. SLOT1: two slots 18 x 12 with their middles 26 from (95, 40) at 90° and 270°:
    (95, 66) and (95, 14); centre line 9-6 = 3 either side, so the moves end within Y 63 … 69
    / 11 … 17 (the half circles about those ends reach 1 further); finishing offset 6-5 = 1:
    X 94 … 96; roughing levels ceil(3.8/2.5) = 2 of
    1.9: -2.9, -4.8, finishing at -5."""
    data = Session.open(tmp_path / "data").ncdata
    result = interpret_only(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name,
                            text=SAMPLE.read_text(), max_blocks=100_000)
    assert result.status == "ended", result.alarms
    cut = [m for m in result.segments if m.kind != "G0"]
    face = [m for m in cut if m.end_wcs["Z"] > -1.0005]
    deeper = [m for m in cut if m.end_wcs["Z"] < -1.0005]
    pocket3 = [m for m in deeper if m.end_wcs["X"] < 75]
    pocket4 = [m for m in deeper if m.end_wcs["X"] >= 75 and 25 < m.end_wcs["Y"] < 55]
    slots = [m for m in deeper if m.end_wcs["X"] >= 75 and not 25 < m.end_wcs["Y"] < 55]
    assert _levels(face) == [-1, -0.8]
    assert _span(face, "X") == (-7, 127)
    assert sorted({round(m.end_wcs["Y"], 3) for m in face}) == [8.0 * j for j in range(11)]
    assert _span(pocket3, "X") == (15, 65) and _span(pocket3, "Y") == (25, 55)
    assert _levels(pocket3) == [-9, -8.8, -6.2, -3.6]
    radii4 = sorted({round(m.end_wcs["X"] - 95, 3) for m in pocket4 if m.kind in ("G2", "G3")})
    assert radii4[-2:] == [8.7, 9]
    assert _levels(pocket4) == [-7, -6.8, -3.9]
    assert _span(slots, "X") == (94, 96)
    assert _span([m for m in slots if m.end_wcs["Y"] > 40], "Y") == (63, 69)
    assert _span([m for m in slots if m.end_wcs["Y"] < 40], "Y") == (11, 17)
    assert _levels(slots) == [-5, -4.8, -2.9]


def test_plate_runs_to_its_end_on_the_kernel(tmp_path: Path) -> None:
    data = Session.open(tmp_path / "data").ncdata
    result = run_on_kernel(load_machine(), DirectorySource(SAMPLE.parent), data, SAMPLE.name, timeout_s=3600.0)
    assert result.status == "ended", result.alarms


def test_plate_simulates_to_the_drawing(tmp_path: Path) -> None:
    """The editor's simulation of the sample on its WORKPIECE box (120 x 80, top Z0): no alarm,
    no rapid move or stopped spindle in the material, and the heights of the drawing in the
    sample's header: the face 1 mm down, the rectangular pocket (60 x 40 about 40/40) at -9,
    the round pocket (Ø28 about 95/40) at -7, the slots (middles 95/66 and 95/14) at -5; the
    face beside the rectangular pocket (X40 Y62, 2 mm outside its wall Y60) stays at -1."""
    mill = load_machine()
    data = Session.open(tmp_path / "data", mill).ncdata
    result = simulate(SAMPLE.name, SAMPLE.read_text(), machine=mill, data=data,
                      programs=DirectorySource(SAMPLE.parent), resolution_mm=0.5)
    assert result.status == "ended" and result.alarms == [] and result.events == []
    heights = {point: result.zmap.height_at(*point) for point in
               [(5.0, 5.0), (40.0, 40.0), (95.0, 40.0), (95.0, 66.0), (95.0, 14.0), (40.0, 62.0)]}
    assert heights == pytest.approx({(5.0, 5.0): -1.0, (40.0, 40.0): -9.0, (95.0, 40.0): -7.0,
                                     (95.0, 66.0): -5.0, (95.0, 14.0): -5.0, (40.0, 62.0): -1.0}, abs=0.01)
