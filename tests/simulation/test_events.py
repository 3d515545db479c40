"""Events of the sweep and mirrored arcs (issue 24), against hand-computed positions.

Tool data (002 L62525-62558): ``$TC_DP1`` type, ``$TC_DP3`` length 1 (tip to the toolholder
reference point), ``$TC_DP6`` radius.
"""

from __future__ import annotations

import math

import pytest

from nck.ncdata import NcData, ToolEdge
from nck.simulation.run import simulate

HEADER = 'N1 WORKPIECE(,"",,"BOX",112,0,-30,-30,-50,-50,100,100)\nN2 G17 G90 G54 T1 M6\nN3 D1 S2000 M3\n'


def run(body: str, length_mm: float = 60.0, resolution_mm: float = 0.25):
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: length_mm, 6: 4.0})  # end mill D8
    result = simulate("P.MPF", HEADER + body + "N999 M30\n", data=data, resolution_mm=resolution_mm)
    assert result.status == "ended" and result.alarms == []
    return result


def test_a_mirrored_clockwise_arc_cuts_the_mirror_image() -> None:
    # G2 from (0, 20) to (20, 0) about (0, 0): the quarter through (14.14, 14.14), clockwise.
    # MIRROR X0 changes the sign of X and turns G2 into G3 (001 L2285-2289): the quarter from
    # (0, 20) to (-20, 0) through (-14.14, 14.14). Were only the end points mirrored, the
    # clockwise arc from (0, 20) to (-20, 0) would run the long way, through (20, 0) and (0, -20).
    body = "N10 MIRROR X0\nN20 G0 X0 Y20 Z2\nN30 G1 Z-2 F200\nN40 G2 X20 Y0 I0 J-20 F500\nN50 G0 Z10\n"
    zmap = run(body).zmap
    d = 20.0 / math.sqrt(2.0)
    assert zmap.height_at(-d, d) == pytest.approx(-2.0)  # the mirrored quarter
    assert zmap.height_at(-20.0, 0.5) == pytest.approx(-2.0)  # its end
    assert zmap.height_at(d, d) == pytest.approx(0.0)  # the programmed quarter: untouched
    assert zmap.height_at(0.0, -20.0) == pytest.approx(0.0)  # the long way round: untouched
    assert zmap.height_at(20.0, 0.0) == pytest.approx(0.0)
    # removed: a quarter of the ring 16..24 plus a D8 half-disc at each end, 2 deep:
    # (pi/4 * (24² - 16²) + pi * 4²) * 2 = (80 pi + 16 pi) * 2 = 192 pi = 603.19 mm³
    assert zmap.removed_volume_mm3() == pytest.approx(192.0 * math.pi, rel=0.01)


def test_the_unmirrored_arc_for_comparison() -> None:
    zmap = run("N20 G0 X0 Y20 Z2\nN30 G1 Z-2 F200\nN40 G2 X20 Y0 I0 J-20 F500\nN50 G0 Z10\n").zmap
    d = 20.0 / math.sqrt(2.0)
    assert zmap.height_at(d, d) == pytest.approx(-2.0)
    assert zmap.height_at(-d, d) == pytest.approx(0.0)


def test_the_tool_holder_below_the_surface_is_reported_with_its_block() -> None:
    # Length 1 is 10 mm: the toolholder reference point is 10 mm above the tip. N30 plunges to
    # Z-8 (the holder stays 2 mm above the top Z0), N50 to Z-12 (the holder 2 mm below it).
    body = ("N20 G0 X0 Y0 Z2\nN30 G1 Z-8 F100\nN40 G0 Z2\nN50 G0 X30 Y30\nN60 G1 Z-12 F100\n"
            "N70 X40\nN80 G0 Z20\n")
    result = run(body, length_mm=10.0)
    holder = [e for e in result.events if e.kind == "holder_in_material"]
    assert [e.n for e in holder] == [60, 70]
    assert holder[0].depth_mm == pytest.approx(12.0)
    assert holder[0].line == 8
    assert "N60: tool holder below the surface" in holder[0].text
    # with the 60 mm tool the same program cuts without an event
    assert run(body, length_mm=60.0).events == []


def test_rigid_tapping_after_an_oriented_stop_is_not_a_cut_with_the_spindle_stopped() -> None:
    # CYCLE84 stops the spindle in position (SPOS) and taps with G331, the spindle interpolated
    # with the axis (002 L19681); a G1 with the spindle stopped (M5) is the event.
    tapped = run("N20 G0 X0 Y0 Z2\nN30 SPOS=0\nN40 G331 Z-10 K1.5 S300\nN50 G332 Z2 K1.5\n")
    assert [e.kind for e in tapped.events] == []
    assert tapped.zmap.height_at(0.0, 0.0) == pytest.approx(-10.0)
    stopped = run("N20 G0 X0 Y0 Z2\nN30 M5\nN40 G1 Z-10 F100\nN50 G0 Z2\n")
    assert [(e.kind, e.n) for e in stopped.events] == [("spindle_stopped", 40)]
