"""The lathe's removal model (rotational profile swept by the insert) against volumes and radii
computed by hand, and the events of a turning program.

Tool data (002 L62525-62558): ``$TC_DP1`` type 500 (turning tool), ``$TC_DP2`` cutting edge
position, ``$TC_DP3``/``$TC_DP4`` lengths 1 (X) and 2 (Z), ``$TC_DP6`` the nose radius. Position
3 (002 W1 §18.4.3, L58653-58680; table in ``nck.geometry.cutting_edge``): the tip P lies at
−r in Z and −r in X (radius) from the nose centre S, so the nose touches the line X = P.x
below it and the line Z = P.z on its chuck side. X is programmed as a diameter (DIAMON).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from nck.persistence import Session
from nck.resources import data_path
from nck.simulation.run import simulate
from nck.simulation.turning import bar

# A bar of 40 mm diameter from Z -60 (chuck side) to the face Z 0 (bits 64: Z1 absolute).
BAR = 'N1 WORKPIECE(,"",,"CYLINDER",64,0,-60,-60,40)\n'
TOOL = "N2 $TC_DP1[1,1]=500 $TC_DP2[1,1]=3 $TC_DP3[1,1]=20 $TC_DP4[1,1]=40 $TC_DP6[1,1]={nose}\n"
START = "N3 G18 G90 DIAMON G95 T1 D1\nN4 G97 S1000 M4\n"


def turn(body: str, nose_mm: float):
    text = BAR + TOOL.format(nose=nose_mm) + START + body + "N999 M30\n"
    result = simulate("T.MPF", text, machine=load_machine("lathe2"), data=NcData(), resolution_mm=0.05)
    assert result.status == "ended" and result.alarms == []
    return result


def test_turned_diameter() -> None:
    """Ø40 turned to Ø36 from the face to Z-30 with a 0.8 nose, then straight up in X.

    The nose centre ends at Z-29.2, radius 18.8; between Z-30 and Z-29.2 the arc
    r(u) = 18.8 - sqrt(0.64 - u²), u = z + 29.2, is left. Removed:
    π (20² - 18²) · 29.2 = π · 2219.2 = 6971.82 mm³, plus over the arc
    π ∫ (400 - (18.8 - s)²) du = π (0.8·46.56 + 37.6·(π·0.64/4) - (0.64·0.8 - 0.8³/3))
    = π · 55.8065 = 175.32 mm³; total 7147.14 mm³."""
    result = turn("N10 G0 X36 Z2\nN20 G1 Z-30 F0.2\nN30 X42\nN40 G0 Z5\n", 0.8)
    arc = 0.8 * 46.56 + 37.6 * (math.pi * 0.64 / 4.0) - (0.64 * 0.8 - 0.8 ** 3 / 3.0)
    exact = math.pi * (400.0 - 324.0) * 29.2 + math.pi * arc
    profile = result.zmap
    assert profile.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    assert profile.radius_at(-10.0) == pytest.approx(18.0)
    assert profile.radius_at(-29.925) == pytest.approx(18.8 - math.sqrt(0.64 - 0.725 ** 2), abs=1e-4)
    assert profile.radius_at(-30.025) == pytest.approx(20.0)  # behind the cut: the bar
    assert result.events == []


def test_the_half_section_is_made_once() -> None:
    """A lathe's path as the views draw it (Z across, the radius up: N20 ends at Z −30, radius 18) is
    the same arrays at every call: the material view keeps its overlay per path arrays and finds
    them again at each scrub step."""
    result = turn("N10 G0 X36 Z2\nN20 G1 Z-30 F0.2\n", 0.8)
    starts, ends = result.drawn_path()
    assert result.drawn_path()[0] is starts and result.drawn_path()[1] is ends
    assert ends[-1].tolist() == pytest.approx([-30.0, 0.0, 18.0])  # N20's end Ø36 Z-30 (G40: the programmed point)


def test_shoulder() -> None:
    """Ø36 to Z-30, then Ø30 to Z-15 with a face up to Ø36 (nose 0.4, position 3).

    Rings: π (400 - 324) · 30 = 7162.83 and π (324 - 225) · 15 = 4665.27 mm³, less the
    fillets the nose leaves in the corners Z-30 and Z-15 (centre 0.4 above and right of P):
    π ∫ ((R + 0.4 - s)² - R²) du over u ∈ [-0.4, 0], s = sqrt(0.16 - u²):
    R 18: π (14.56·0.4 - 36.8·0.125664 + 0.042667) = π · 1.24232 = 3.9029;
    R 15: π (12.16·0.4 - 30.8·0.125664 + 0.042667) = π · 1.03650 = 3.2563; total 11820.94 mm³."""
    body = ("N10 G0 X36 Z2\nN20 G1 Z-30 F0.2\nN30 X41\nN40 G0 Z2\n"
            "N50 G0 X30\nN60 G1 Z-15 F0.2\nN70 X41\nN80 G0 Z5\n")
    result = turn(body, 0.4)
    quarter = math.pi * 0.16 / 4.0
    fillets = [(2 * r * 0.4 + 0.16) * 0.4 - 2 * (r + 0.4) * quarter + (0.064 - 0.064 / 3.0) for r in (18.0, 15.0)]
    exact = math.pi * (76.0 * 30.0 + 99.0 * 15.0) - math.pi * sum(fillets)
    profile = result.zmap
    assert profile.removed_volume_mm3() == pytest.approx(exact, rel=0.01)
    assert profile.radius_at(-7.5) == pytest.approx(15.0)
    assert profile.radius_at(-20.0) == pytest.approx(18.0)
    assert profile.radius_at(-15.025) == pytest.approx(18.0)  # behind the shoulder face
    assert profile.radius_at(-14.975) == pytest.approx(15.4 - math.sqrt(0.16 - 0.375 ** 2), abs=1e-4)
    assert profile.radius_at(-45.0) == pytest.approx(20.0)


def test_rapid_into_the_bar_is_an_event_of_its_block() -> None:
    """G0 from Ø42 down to Ø36 at Z-10 plunges 2 mm (radius) into the bar: N20 names it."""
    result = turn("N10 G0 X42 Z-10\nN20 X36\nN30 G0 X42\nN40 Z5\n", 0.8)
    assert [(e.kind, e.n) for e in result.events] == [("rapid_cut", 20)]
    assert result.events[0].depth_mm == pytest.approx(2.0, abs=0.05)


def test_turn_shaft_sample_cuts_without_rapid_into_material(tmp_path: Path) -> None:
    """The sample TURN_SHAFT on the lathe with a fresh lathe data directory's tools: rapid moves
    stay clear of the material (the mill's Z-map on the lathe's path reported three rapid cuts),
    and the finished profile has the contour's diameters (SHAFT_CONTOUR: Ø24 to Z-25 with the
    groove Ø21.6 at Z-25…-21 and the thread's core, Ø30 to Z-40, Ø40 to Z-60). The bar is the
    default set-up's (Ø60, 100 long) with its face at Z0, given here so that the test does not
    depend on the data directory's work offset."""
    lathe = load_machine("lathe2")
    data = Session.open(tmp_path / "data", lathe).ncdata
    sample = Path(data_path("programs")) / "TURN_SHAFT.MPF"
    result = simulate(sample.name, sample.read_text(), machine=lathe, data=data,
                      programs=DirectorySource(sample.parent), resolution_mm=0.1, blank=bar(60.0, -100.0, 0.0))
    assert result.status == "ended" and result.alarms == []
    assert result.events == []
    profile = result.zmap
    assert 2 * profile.radius_at(-23.0) == pytest.approx(21.6)  # groove base
    assert 2 * profile.radius_at(-35.0) == pytest.approx(30.0)
    assert 2 * profile.radius_at(-55.0) == pytest.approx(40.0)
