"""The lathe runs a Siemens-mode turning program out of the box: a fresh data directory of a
lathe starts with turning tools (data/sample_tools_lathe.toml), not the milling tools."""

from __future__ import annotations

from pathlib import Path

from nck.headless import run_on_kernel
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.persistence import Session

PROGRAM = """G18 G90 DIAMON G54
T1 D1
G96 S200 LIMS=3000 M4
G95 F0.2
G0 X100
Z2
G0 X60 Z2
G1 X40 Z0
G1 Z-30
G1 X50
G2 X60 Z-35 CR=5
G1 Z-50
G0 X80 Z50
M30
"""


def test_a_fresh_lathe_data_directory_has_turning_tools(tmp_path: Path) -> None:
    """Types 500 roughing, 510 finishing, 520 grooving (two edges), 540 threading."""
    tools = Session.open(tmp_path / "data", load_machine("lathe2")).ncdata.tools
    assert {key: int(edge.params[1]) for key, edge in tools.items()} == {
        (1, 1): 500, (2, 1): 510, (3, 1): 520, (3, 2): 520, (4, 1): 540}


def test_a_fresh_mill_data_directory_keeps_the_milling_tools(tmp_path: Path) -> None:
    tools = Session.open(tmp_path / "data", load_machine()).ncdata.tools
    assert sorted(tools) == [(1, 1), (2, 1), (3, 1), (4, 1)] and int(tools[(1, 1)].params[1]) == 120


def test_a_turning_program_with_t1_d1_runs_in_auto(tmp_path: Path) -> None:
    """T1 D1: length 1 = 20 along X (radius), length 2 = 40 along Z. The end point X80 Z50 under
    DIAMON is radius 40, so the slide stands at MCS X 40+20 = 60, Z 50+300+40 = 390 (G54 Z 300:
    the face of the bar a fresh lathe data directory has clamped; the tool goes out in X before
    it comes along Z, clear of the bar Ø60, and cuts it without a crash)."""
    data = Session.open(tmp_path / "data", load_machine("lathe2")).ncdata
    result = run_on_kernel(load_machine("lathe2"), MemorySource({"TURN.MPF": PROGRAM}), data, "TURN.MPF",
                           timeout_s=600.0)
    assert result.status == "ended", result.alarms
    assert result.position_mcs is not None
    assert (round(result.position_mcs["X"], 3), round(result.position_mcs["Z"], 3)) == (60, 390)


def test_each_machine_gets_its_own_sample_programs(tmp_path: Path) -> None:
    """data/sample_programs.toml: the lathe gets the turned shaft (and its contour), not the
    milling samples that use Y and the milling cycles; the mill gets those and not the shaft."""
    lathe = Session.open(tmp_path / "lathe", load_machine("lathe2")).files
    mill = Session.open(tmp_path / "mill", load_machine("mill3")).files
    for name in ("TURN_SHAFT.MPF", "SHAFT_CONTOUR.SPF"):
        assert lathe.exists(lathe.canonical(name)) and not mill.exists(mill.canonical(name))
    for name in ("DRILL_FLANGE.MPF", "POCKET_PLATE.MPF", "FIRST_STEPS.MPF"):
        assert mill.exists(mill.canonical(name)) and not lathe.exists(lathe.canonical(name))
