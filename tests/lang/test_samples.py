"""The training programs shipped in data/programs run as their comments promise.

They are checked with the NC data of a fresh data directory, which starts with the tools the
samples use (data/sample_tools.toml): a T number without a data set is alarm 17191
(002 L58219), so a sample that changes to a tool needs its data set.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.headless import check_program, interpret_only
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.persistence import Session
from nck.resources import data_path

PROGRAMS = sorted(Path(data_path("programs")).glob("*.MPF"))


@pytest.mark.parametrize("path", PROGRAMS, ids=[p.stem for p in PROGRAMS])
def test_sample_program_checks(path: Path, tmp_path: Path) -> None:
    """TURN_* samples are for the lathe (lathe2), the others for the default mill."""
    machine = load_machine("lathe2" if path.stem.startswith("TURN_") else None)
    data = Session.open(tmp_path / "data", machine).ncdata  # a fresh data directory of that machine
    alarms = check_program(machine, DirectorySource(path.parent), path.name, path.read_text(), data)
    numbers = [a.number for a in alarms]
    if path.stem == "ALARM_DEMO":
        assert numbers == [10860] and alarms[0].n == 30
    else:
        assert numbers == []


def test_there_are_samples() -> None:
    assert len(PROGRAMS) >= 5


def test_a_data_directory_with_samples_already_installed_gets_no_tools_again(tmp_path: Path) -> None:
    session = Session.open(tmp_path / "data")
    assert sorted(session.ncdata.tools) == [(1, 1), (2, 1), (3, 1), (4, 1)]
    session.ncdata.tools.clear()  # the operator deleted them
    session.save()
    assert Session.open(tmp_path / "data").ncdata.tools == {}


MILL_SAMPLES = [p for p in PROGRAMS if not p.stem.startswith("TURN_")]


@pytest.mark.parametrize("path", MILL_SAMPLES, ids=[p.stem for p in MILL_SAMPLES])
def test_mill_samples_cut_in_the_work_offset_g54(path: Path, tmp_path: Path) -> None:
    """The samples select G54 (docs/jog_setup_screens.md, 002 L2062, L28381-28386): with G54 at
    X 100, Y 200 every point of the path lies 100 / 200 mm further in the MCS than in the WCS
    (a translation of the settable frame; X and Y carry no tool length)."""
    machine = load_machine()
    data = Session.open(tmp_path / "data", machine).ncdata
    data.settable_frame("G54").trans.update({"X": 100.0, "Y": 200.0})
    result = interpret_only(machine, DirectorySource(path.parent), data, path.name, text=path.read_text(),
                            max_blocks=100_000)
    moves = [m for m in result.segments if "X" in m.end_mcs and "X" in m.end_wcs]
    assert moves
    for move in moves:
        assert (move.end_mcs["X"] - move.end_wcs["X"], move.end_mcs["Y"] - move.end_wcs["Y"]) == \
            pytest.approx((100.0, 200.0), abs=1e-9), (move.kind, move.end_wcs)
