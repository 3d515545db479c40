"""The training programs shipped in data/programs run as their comments promise."""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.headless import check_program
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.resources import data_path

PROGRAMS = sorted(Path(data_path("programs")).glob("*.MPF"))


@pytest.mark.parametrize("path", PROGRAMS, ids=[p.stem for p in PROGRAMS])
def test_sample_program_checks(path: Path) -> None:
    alarms = check_program(load_machine(), DirectorySource(path.parent), path.name, path.read_text())
    numbers = [a.number for a in alarms]
    if path.stem == "ALARM_DEMO":
        assert numbers == [10860] and alarms[0].n == 30
    else:
        assert numbers == []


def test_there_are_samples() -> None:
    assert len(PROGRAMS) >= 5
