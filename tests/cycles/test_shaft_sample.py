"""The sample program TURN_SHAFT (CYCLE95 roughing and finishing on SHAFT_CONTOUR, CYCLE93
run-out groove, CYCLE97 thread M24x1.5) runs on the lathe with the tools of a fresh lathe
data directory; cuts, plunges and thread passes worked out by hand from its parameters."""

from __future__ import annotations

import math
from pathlib import Path

from nck.headless import interpret_only, run_on_kernel
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path

SAMPLE = Path(data_path("programs")) / "TURN_SHAFT.MPF"


def _run(tmp_path: Path):
    lathe = load_machine("lathe2")
    data = Session.open(tmp_path / "data", lathe).ncdata  # a fresh lathe data directory: T1 … T4
    return interpret_only(lathe, DirectorySource(SAMPLE.parent), data, SAMPLE.name, text=SAMPLE.read_text(),
                          max_blocks=100_000)


def _xz(motion) -> tuple[float, float]:
    return round(motion.end_wcs["X"], 3), round(motion.end_wcs["Z"], 3)


def test_shaft_sample_cuts_as_computed_by_hand(tmp_path: Path) -> None:
    """CYCLE95 MID 2, FALZ 0.2, FALX 0.2: the contour moved by Z+0.2 and radius +0.2 spans radius
    10.2 … 25.2: 15 mm in 8 cuts of 1.875 (X46.65 … X20.4). Crossings: the last shoulder Z-59.8
    (twice), the fillet (centre Z-39.8 radius 20.2, R5) at Z = -39.8 - sqrt(25 - h²) for
    h = -0.625, -2.5, -4.375, the collar Z-24.8, the chamfer Z0.2 - 1.875 = -1.675, the start
    Z0.2. Then finishing, the groove and the thread (comments below)."""
    result = _run(tmp_path)
    assert result.status == "ended", result.alarms
    cuts = [m for m in result.segments if m.kind == "G1"]
    fillet = [round(-39.8 - math.sqrt(25 - h * h), 3) for h in (-0.625, -2.5, -4.375)]
    levels = [round(2 * (25.2 - 1.875 * k), 3) for k in range(1, 9)]
    ends = [-59.8, -59.8] + fillet + [-24.8, -1.675, 0.2]
    assert [_xz(m) for m in cuts[:8]] == list(zip(levels, ends))
    # finishing (second CYCLE95) along the contour: start Z0 at X20, then the elements
    finish = [_xz(m) for m in result.segments if m.kind in ("G1", "G2")][8:16]
    assert finish == [(20, 0), (24, -2), (24, -25), (30, -25), (30, -40), (40, -45), (40, -60), (50, -60)]
    # CYCLE93: groove Z-25 … -21, tool 3 wide: plunges at Z-25 and Z-24 to radius 12-1.2 (X21.6),
    # finishing down at Z-25 and along the base to Z-25+4-3 = -24
    plunges = [_xz(m) for m in result.segments if m.kind == "G1" and round(m.end_wcs["X"], 3) == 21.6]
    assert plunges == [(21.6, -25), (21.6, -24), (21.6, -25), (21.6, -24)]
    # CYCLE97 VARI 3: 0.87 in 5 cuts of equal cross-section, the allowance, one idle pass
    depths = [0.87 * math.sqrt(n / 5) for n in range(1, 6)] + [0.92, 0.92]
    threads = [(m.kind, _xz(m), m.lead_mm) for m in result.segments if m.kind == "G33"]
    assert threads == [("G33", (round(24 - 2 * d, 3), -21), 1.5) for d in depths]


def test_shaft_sample_runs_in_auto(tmp_path: Path) -> None:
    """AUTO with NC START (as nck run) on a fresh lathe data directory: the bar Ø60 from the chuck
    face Z 200 to Z 300 is clamped and G54 is Z 300 (its face). The program cuts the bar without
    a crash and ends at X100 Z100 with the threading tool T4 (length 1 = 24 in radius, length 2 =
    44): MCS X 50+24, Z 300+100+44."""
    lathe = load_machine("lathe2")
    data = Session.open(tmp_path / "data", lathe).ncdata
    result = run_on_kernel(lathe, DirectorySource(SAMPLE.parent), data, SAMPLE.name, timeout_s=3600.0)
    assert result.status == "ended", result.alarms
    assert result.position_mcs is not None
    assert (round(result.position_mcs["X"], 3), round(result.position_mcs["Z"], 3)) == (74, 444)


def test_shaft_sample_cuts_the_bar_in_the_chuck(tmp_path: Path) -> None:
    """On a fresh lathe data directory the first roughing cut lies on the bar: it ends at WCS
    Z-59.8 (see above), G54 Z 300 and T1's length 2 = 40 make MCS Z 300 - 59.8 + 40 = 280.2, and
    its diameter 46.65 is inside the bar's 60, outside its chuck face Z 200."""
    lathe = load_machine("lathe2")
    data = Session.open(tmp_path / "data", lathe).ncdata
    result = interpret_only(lathe, DirectorySource(SAMPLE.parent), data, SAMPLE.name, max_blocks=100_000)
    first_cut = next(m for m in result.segments if m.kind == "G1")
    assert round(first_cut.end_mcs["Z"], 3) == 280.2
    assert round(first_cut.end_mcs["Z"] - 40 - 200, 3) == 40.2  # the tip 40.2 mm in front of the chuck
