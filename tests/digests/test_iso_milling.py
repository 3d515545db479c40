"""Digest iso-milling-828d (manual 003, ISO Milling programming manual): ranked items, in ISO M
through the interpreter. ``tests/README.md`` lists the items proved elsewhere.

Every expected value is worked out by hand from the manual line cited.
"""

from __future__ import annotations

import pytest

from tests.iso.conftest import run_iso


def segments(text: str) -> list[tuple[int, str, dict[str, float], dict[str, float] | None, float | None]]:
    """(line, kind, end, centre, feed mm/min) of every motion; the run must end without alarm."""
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    out = []
    for m in result.segments:
        centre = {a: round(v, 6) for a, v in m.center_wcs.items()} if m.center_wcs else None
        out.append((m.source.line, m.kind, {a: round(v, 6) for a, v in m.end_wcs.items()}, centre,
                    m.feed_mm_min))
    return out


def alarm(text: str) -> tuple[int, int]:
    """(alarm number, motions before it) of a run that must end in an alarm."""
    result = run_iso(text)
    assert result.status == "alarm"
    return result.alarms[0].number, len(result.segments)


def test_digest_iso_milling_rank_01_circle_radius_sign_and_end_point_check() -> None:
    """Digest iso-milling-828d rank 1: R > 0 for arcs up to 180°, R < 0 above (003 L945-948).
    From (0,0) CW to (10,10) with R10 the centre is (10,0) (90° arc); with R-10 it is (0,10)
    (270° arc). From (0,0) to (20,0) with R10: the semicircle about (10,0). An end point off
    the arc gives 14040 and no motion (003 L934-935)."""
    assert segments("G17 G90 G02 X20. Y0 R10. F100\nM30\n")[0][3] == {"X": 10.0, "Y": 0.0, "Z": 0.0}
    assert segments("G17 G90 G02 X10. Y10. R10. F100\nM30\n")[0][3] == {"X": 10.0, "Y": 0.0, "Z": 0.0}
    assert segments("G17 G90 G02 X10. Y10. R-10. F100\nM30\n")[0][3] == {"X": 0.0, "Y": 10.0, "Z": 0.0}
    # Centre (10,0): start radius 10, end (30,0) at radius 20 - not on the arc.
    assert alarm("G17 G90 G02 X30. Y0 I10. J0 F100\nM30\n") == (14040, 0)


def test_digest_iso_milling_rank_02_missing_or_zero_feed() -> None:
    """Digest iso-milling-828d rank 2: G01 with no F ever programmed is refused (10860, the
    path feed must be programmed, 003 L736-737); F0 without fixed feedrates is 14800
    (003 L628-629); F is modal: the second block runs at 100."""
    assert alarm("G01 X10.\nM30\n") == (10860, 0)
    assert alarm("G01 X10. F0\nM30\n") == (14800, 0)
    moves = segments("G01 X10. F100\nX20.\nM30\n")
    assert [(m[2]["X"], m[4]) for m in moves] == [(10.0, 100.0), (20.0, 100.0)]


def test_digest_iso_milling_rank_07_plane_default_and_g18_circle() -> None:
    """Digest iso-milling-828d rank 7: G17 is set at power-up (003 L889-890), so a G02 with X/Y
    words interpolates in X-Y; G18 G02 Z10 X0 K5 I0 from the origin is a semicircle in Z-X
    about Z5 X0 (003 L893, L901)."""
    (xy,) = segments("G02 X10. Y0 I5. J0 F100\nM30\n")
    assert xy[3] == {"X": 5.0, "Y": 0.0, "Z": 0.0}
    (zx,) = segments("G18 G02 Z10. X0 K5. I0 F100\nM30\n")
    assert (zx[2], zx[3]) == ({"X": 0.0, "Y": 0.0, "Z": 10.0}, {"X": 0.0, "Y": 0.0, "Z": 5.0})


def test_digest_iso_milling_rank_09_axes_not_programmed_in_g00_do_not_move() -> None:
    """Digest iso-milling-828d rank 9: axes not programmed in a G00 block are not traversed
    (003 L775)."""
    moves = segments("G01 X10. Y5. F100\nG00 X20.\nM30\n")
    assert moves[1][1:3] == ("G0", {"X": 20.0, "Y": 5.0, "Z": 0.0})


def test_digest_iso_milling_rank_10_feed_modes() -> None:
    """Digest iso-milling-828d rank 10: G93 G1 X100 F2 traverses the path in half a minute
    (003 L717-727): 100 mm / 0.5 min = 200 mm/min. G95 F0.2 at S1000 is 0.2 · 1000 =
    200 mm/min. After G94 -> G95 the feed must be reprogrammed (003 L736-737): 10860."""
    assert segments("G93 G01 X100. F2\nM30\n")[0][4] == pytest.approx(200.0)
    assert segments("M03 S1000\nG95 G01 X10. F0.2\nM30\n")[0][4] == pytest.approx(200.0)
    assert alarm("G94 G01 X10. F100\nG95 X20.\nM30\n") == (10860, 1)


def test_digest_iso_milling_rank_12_g28_goes_via_the_intermediate_point() -> None:
    """Digest iso-milling-828d rank 12: G28 Z50 traverses Z in rapid to 50, then to the
    reference point MD34100 (0 on this machine); X and Y are not traversed (003 L1211-1217)."""
    moves = segments("G01 X10. Y5. F100\nG90 G28 Z50.\nM30\n")
    assert [(m[1], m[2]) for m in moves[1:]] == [("G0", {"X": 10.0, "Y": 5.0, "Z": 50.0}),
                                                 ("G0", {"X": 10.0, "Y": 5.0, "Z": 0.0})]
