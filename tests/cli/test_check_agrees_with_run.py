"""``nck check`` (headless and the editor's check) refuses the motions the run refuses.

Software limits (MD36110 X = 500 on the default mill) and the working area act on referenced
axes before a block starts (002 L2378-2400, L2456-2620); NC START needs referenced axes, so
the check assumes them referenced. The run's own answer is the reference for each program.
"""

from __future__ import annotations

import pytest

from nck.check import check_text
from nck.headless import check_program, run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

PLAIN_LINES = "".join(f"N{10 * (k + 1)} G1 X{k} F20000\n" for k in range(60))
PROGRAMS = {
    "line beyond the limit": ("N10 G1 X400 F5000\nN20 X600\nN30 M30\n", 10720, 2),
    "arc bulging over the limit": ("N10 G0 X495 Y0\nN20 G3 X495 Y20 CR=10 F100\nN30 M30\n", 10720, 2),
    "after a run of plain blocks": (PLAIN_LINES + "N999 X600\nN1000 M30\n", 10720, 61),
    "working area from G26": ("N10 G26 X100\nN20 WALIMON\nN30 G1 X150 F1000\nN40 M30\n", 10730, 3),
    "inside every limit": ("N10 G0 X495 Y0\nN20 G2 X495 Y20 CR=10 F100\nN30 M30\n", None, None),
}


def numbers_and_lines(alarms) -> list[tuple[int, int | None]]:
    return [(a.number, a.line) for a in alarms]


@pytest.mark.parametrize("case", sorted(PROGRAMS))
def test_check_refuses_what_the_run_refuses(case: str) -> None:
    text, number, line = PROGRAMS[case]
    machine = load_machine(None)

    def data() -> NcData:
        nc = NcData()
        nc.setting_data["SD43400"] = {"X": 1}  # working area + limit of X switched on
        return nc

    expected = [] if number is None else [(number, line)]
    run = run_program(machine, MemorySource({}), data(), "P.MPF", text=text, timeout_s=600.0)
    assert numbers_and_lines(run.alarms) == expected  # the reference: what the run does
    assert numbers_and_lines(check_program(machine, MemorySource({}), "P.MPF", text, data())) == expected
    assert numbers_and_lines(check_text("P.MPF", text, machine=machine, data=data())) == expected
