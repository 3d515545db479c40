"""Diameter programming of the transverse axis (Function Manual 002, P1 12.3) on the lathe."""

from __future__ import annotations

import pytest

from nck import canon
from nck import commands as c
from nck.headless import run_program
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.machine import load_machine
from nck.ncdata import NcData


def motions(text: str) -> list[canon.Motion]:
    result = run_program(load_machine("lathe2"), MemorySource({}), NcData(), "D.MPF", text=text)
    assert result.status == "ended", result.alarms
    return result.segments


@pytest.mark.parametrize(("code", "x_mcs"), [
    # 002 L32558-32565: DIAM90 takes diameters with G90 and radii with G91.
    ("DIAM90", (25.0, 35.0)),
    ("DIAMON", (25.0, 30.0)),  # diameter with G90 and G91
    ("DIAMOF", (50.0, 60.0)),  # radius throughout
])
def test_diam90_is_diameter_absolute_and_radius_incremental(code: str, x_mcs: tuple[float, float]) -> None:
    """Digest 828d-2 rank 24 (DIAM90)."""
    moves = motions(f"N10 {code} G94 G90 G1 X50 Z0 F1000\nN20 G91 X10\nN30 M30\n")
    assert [m.end_mcs["X"] for m in moves] == pytest.approx(list(x_mcs))


def test_diam90_shows_the_transverse_axis_in_diameter() -> None:
    # 002 L32650-32660: under DIAM90 the actual value is displayed in diameter also with G91.
    moves = motions("N10 DIAM90 G94 G90 G1 X50 Z0 F1000\nN20 G91 X10\nN30 M30\n")
    assert [m.end_wcs["X"] for m in moves] == pytest.approx([50.0, 70.0])


def test_frames_stay_radius_under_diamon() -> None:
    """Digest 828d-2 rank 24 (frames always radius)."""
    # 002 L32672-32684: programmable frames are always radius values: TRANS X10 shifts by 10 mm.
    moves = motions("N10 DIAMON G94 G90 G1 X50 Z0 F1000\nN20 TRANS X10\nN30 X50\nN40 M30\n")
    assert moves[-1].end_mcs["X"] == pytest.approx(35.0)  # 50/2 + 10
    assert moves[-1].end_wcs["X"] == pytest.approx(50.0)


def test_absolute_circle_centre_is_a_diameter_under_diamon() -> None:
    # 002 L32643-32646: interpolation parameters programmed with AC are diameters:
    # I=AC(40) is radius 20; from X40 (r 20) Z0 to X40 Z-20 about (r 20, Z-10): a half circle of R10.
    arc = motions("N10 DIAMON G94 G90 G1 X40 Z0 F1000\nN20 G3 X40 Z-20 I=AC(40) K=AC(-10)\nN30 M30\n")[-1]
    assert arc.center_mcs["X"] == pytest.approx(20.0)
    assert arc.center_wcs["X"] == pytest.approx(40.0)


def test_wcs_display_is_in_diameter_while_the_block_runs() -> None:
    """Digest 828d-2 rank 24 (WCS display in diameter)."""
    # 002 L32637-32642: under DIAMON the WCS actual position of the transverse axis is a diameter.
    nck = Nck(machine=load_machine("lathe2"), referenced=True,
              programs=MemorySource({"P.MPF": "N10 DIAMON G94 G1 X50 F100\nN20 M30"}))
    nck.submit(c.SelectMode("AUTO"))
    nck.submit(c.SelectProgram("P.MPF"))
    nck.submit(c.CycleStart())
    assert nck.run_until(lambda k: k.positions_mcs()["X"] >= 12.5, 30.0)
    x = {a.name: a for a in nck.status().axes}["X"]
    assert x.position_wcs == pytest.approx(2.0 * x.position_mcs)
