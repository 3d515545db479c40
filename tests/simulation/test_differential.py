"""The simulation reports the same alarms at the same blocks as the AUTO run (``nck run``).

Differential: every golden and bad program goes through ``nck run``'s headless run and
through the simulation; both must list the same alarms (number, line), in the same order —
never "no errors" for a program AUTO stops. The run's answer is the reference.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck.headless import run_program
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge
from nck.simulation.run import simulate

TESTS = Path(__file__).resolve().parent.parent
PROGRAMS = {f"bad/{p.stem}": p for p in sorted((TESTS / "bad").glob("*.mpf"))} | {
    f"golden/{p.parent.name}": p for p in sorted((TESTS / "golden").glob("*/main.mpf"))}


def data() -> NcData:
    nc = NcData()
    nc.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 50.0, 6: 4.0})
    return nc


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_simulation_names_the_alarms_of_the_run(name: str) -> None:
    path = PROGRAMS[name]
    text = path.read_text()
    programs = DirectorySource(path.parent)
    run = run_program(load_machine(None), programs, data(), "MAIN.MPF", text=text, timeout_s=600.0)
    sim = simulate("MAIN.MPF", text, machine=load_machine(None), programs=programs, data=data(),
                   resolution_mm=1.0, timeout_s=600.0)
    assert [(a.number, a.line) for a in sim.alarms] == [(a.number, a.line) for a in run.alarms]
    assert sim.status == run.status
    assert sim.machine_time_s == pytest.approx(run.machine_time_s)
