"""Position patterns HOLES1 (row), HOLES2 (circle), CYCLE801 (grid), CYCLE802 (arbitrary
positions) and the modal call MCALL that drills at each of their positions. Positions worked
out by hand from the documented geometry (data/cycles/README.md, "Positions"); alarm 61103.

Every program starts at X0 Y0 Z50 with F100 and S1000 M3 under G17 (plane X/Y)."""

from __future__ import annotations

import math

import pytest

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.cycles.helpers import PROLOGUE, run


def plane_stops(body: str) -> list[tuple[float, float]]:
    """(X, Y) of every rapid in the plane at Z50 (the pattern's positions when nothing drills)."""
    return [(s[1], s[2]) for s in run(body).ended().steps() if s[0] == "G0" and s[3] == 50]


def test_holes1_row_from_the_nearer_end() -> None:
    """Reference point (10, 20), angle 0, first hole FDIS 5 from it, DBH 10, NUM 3: holes at
    X 15, 25, 35. From X0 Y0 the first hole (distance² 15²+20² = 625) is nearer than the last
    (35²+20² = 1625): 15, 25, 35. From X100 Y20 the last (65) is nearer than the first (85):
    35, 25, 15."""
    assert plane_stops("HOLES1(10, 20, 0, 5, 10, 3)") == [(15, 20), (25, 20), (35, 20)]
    assert plane_stops("X100 Y20\nHOLES1(10, 20, 0, 5, 10, 3)") == [(100, 20), (35, 20), (25, 20), (15, 20)]


def test_holes1_row_at_an_angle() -> None:
    """STA1 30°: hole k at (FDIS + k·DBH)·(cos 30°, sin 30°) from (0, 0): k=0 → (0, 0), k=1 →
    (10·0.866025, 10·0.5) = (8.6603, 5)."""
    assert plane_stops("HOLES1(0, 0, 30, 0, 10, 2)") == [(0, 0), (8.6603, 5)]


def test_holes2_full_circle() -> None:
    """Centre (50, 50), radius 20, first hole at 45°, INDA 0 → 360/4 = 90°: angles 45, 135,
    225, 315; 20·cos 45° = 14.1421."""
    assert plane_stops("HOLES2(50, 50, 20, 45, 0, 4)") == [
        (64.1421, 64.1421), (35.8579, 64.1421), (35.8579, 35.8579), (64.1421, 35.8579)]


def test_holes2_pitch_circle() -> None:
    """INDA 30°, NUM 3 from 0°: (10, 0), (10 cos 30°, 10 sin 30°) = (8.6603, 5), (5, 8.6603)."""
    assert plane_stops("HOLES2(0, 0, 10, 0, 30, 3)") == [(10, 0), (8.6603, 5), (5, 8.6603)]


def test_holes2_in_the_g18_plane() -> None:
    """G18: abscissa Z, ordinate X, tool axis Y. Centre Z0 X0, radius 10, 0° and 180°:
    (Z, X) = (10, 0) and (-10, 0)."""
    steps = run("G18 G0 Y50\nHOLES2(0, 0, 10, 0, 180, 2)").ended().steps()
    assert steps[1:] == [("G0", 0, 50, 10), ("G0", 0, 50, -10)]


def test_cycle801_grid_in_a_meander() -> None:
    """Reference (10, 10), angle 0, columns 5 apart, rows 8 apart, 3 columns, 2 rows: row 0
    left to right X 10, 15, 20 at Y10; row 1 back X 20, 15, 10 at Y 10+8 = 18."""
    assert plane_stops("CYCLE801(10, 10, 0, 5, 8, 3, 2)") == [
        (10, 10), (15, 10), (20, 10), (20, 18), (15, 18), (10, 18)]


def test_cycle801_rotated_grid() -> None:
    """_STA 90°: a row runs along +Y (5 apart), the next row lies at 90° further, i.e. along
    -X (8 apart): (0, 0), (0, 5), then back (-8, 5), (-8, 0)."""
    assert plane_stops("CYCLE801(0, 0, 90, 5, 8, 2, 2)") == [(0, 0), (0, 5), (-8, 5), (-8, 0)]


def test_cycle802_arbitrary_positions() -> None:
    """All absolute (1 per position): (10, 10); (20, Y not programmed: stays 10); (X not
    programmed: stays 20, 30). The empty positions 3 … 8 are skipped."""
    assert plane_stops("CYCLE802(111111111, 111111111, 10, 10, 20, , , 30)") == [(10, 10), (20, 10), (20, 30)]


def test_cycle802_incremental_position() -> None:
    """First digit 1 (absolute), second 0 (incremental): (10, 10), then (10+5, 10+5)."""
    assert plane_stops("CYCLE802(100000000, 100000000, 10, 10, 5, 5)") == [(10, 10), (15, 15)]


def test_modal_call_drills_at_every_hole_of_a_circle() -> None:
    """MCALL CYCLE81 then HOLES2 with two holes at (10, 0) and (-10, 0): each hole is
    approached in rapid at Z50, drilled to -5 from the safety plane 2 and left at RTP 50; after
    MCALL alone the next position is not drilled."""
    steps = run("MCALL CYCLE81(50, 0, 2, -5)\nHOLES2(0, 0, 10, 0, 180, 2)\nMCALL\nX0 Y0").ended().steps()
    assert steps == [
        ("G0", 10, 0, 50), ("G0", 10, 0, 2), ("G1", 10, 0, -5, 100), ("G0", 10, 0, 50),
        ("G0", -10, 0, 50), ("G0", -10, 0, 2), ("G1", -10, 0, -5, 100), ("G0", -10, 0, 50),
        ("G0", 0, 0, 50)]


def test_modal_call_drills_a_grid_with_pecks() -> None:
    """MCALL CYCLE83 (swarf removal, first depth 4, no degression, depth 6) on a 2 x 1 grid:
    each hole has the infeeds 4 and 2 (G1 to -4 and -6)."""
    steps = run("MCALL CYCLE83(50, 0, 2, -6, 0, -4, 0, 0, 0, 0, 1, 1)\nCYCLE801(0, 0, 0, 10, 10, 2, 1)\nMCALL"
                ).ended().steps()
    assert [(s[1], s[3]) for s in steps if s[0] == "G1"] == [(0, -4), (0, -6), (10, -4), (10, -6)]


def test_other_subprograms_do_not_see_the_callers_modal_call() -> None:
    """Only the position pattern cycles take over the MCALL of their caller (our choice,
    data/cycles/cycles.toml): a user's subprogram moving to X5 does not drill there."""
    text = PROLOGUE + "MCALL CYCLE81(50, 0, 2, -5)\nMOVE5\nMCALL\nM30\n"
    programs = {"main.mpf": text, "MOVE5.SPF": "PROC MOVE5\nG0 X5\nRET\n"}
    result = interpret_only(load_machine(None), MemorySource(programs), NcData(), "main.mpf", text=text,
                            max_blocks=1000)
    assert result.status == "ended"
    assert [m.kind for m in result.segments][1:] == ["G0"]


@pytest.mark.parametrize("call", [
    "HOLES1(10, 20, 0, 5, 10, 0)",
    "HOLES2(0, 0, 10, 0, 0, 0)",
    "CYCLE801(0, 0, 0, 5, 5, 0, 2)",
    "CYCLE801(0, 0, 0, 5, 5, 2, 0)",
    "CYCLE802()",
    "CYCLE802(111111111, 111111111)",
])
def test_no_holes_alarm(call: str) -> None:
    """61103 number of holes is zero, before any motion."""
    case = run("MCALL CYCLE81(50, 0, 2, -5)\n" + call)
    assert case.alarms == [61103]
    assert case.steps() == []


def test_row_geometry_matches_the_trigonometry() -> None:
    """Independent check of a longer row: 7 holes at 25° from (3, -4), FDIS 2, DBH 4.5."""
    expected = [(round(3 + (2 + k * 4.5) * math.cos(math.radians(25)), 4),
                 round(-4 + (2 + k * 4.5) * math.sin(math.radians(25)), 4)) for k in range(7)]
    assert plane_stops("HOLES1(3, -4, 25, 2, 4.5, 7)") == expected
