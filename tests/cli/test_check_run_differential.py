"""``nck check`` never says ok for a block the run would refuse (issue 20), property-style.

Every program of a corpus — the bad programs of ``tests/bad`` and small programs of our own that
touch words, tools, contour definitions and limits — goes through the run (``nck run``'s
headless kernel with motion) and through the check (``nck check`` and the editor's check); both
must name the same first alarm (number and line), or both none. The run's answer is the
reference; no expected value is written here, so the test holds for every program added to the
corpus.
"""

from __future__ import annotations

from dataclasses import replace

from pathlib import Path

import pytest

from nck.check import check_text
from nck.headless import check_program, run_program
from nck.interp.sources import DirectorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge

BAD = Path(__file__).resolve().parent.parent / "bad"

OWN = {
    "thread with start angle": "N10 S100 M3\nN20 G33 Z-10 K2 SF=90\nN30 M30\n",
    "start angle out of range": "N10 S100 M3\nN20 G33 Z-10 K2 SF=400\nN30 M30\n",
    "radius in a linear block": "N10 G1 X10 F100 CR=5\nN20 M30\n",
    "helix turns in rapid": "N10 G0 X10 TURN=2\nN20 M30\n",
    "plane angle without rotation": "N10 G1 X10 F100 RPL=30\nN20 M30\n",
    "rotation in the plane": "N10 ROT RPL=30\nN20 G1 X10 F100\nN30 M30\n",
    "retraction path": "N10 G1 X10 F100 SR=2\nN20 M30\n",
    "axial override": "N10 OVRA[X]=50\nN20 M30\n",
    "tool without data at M6": "N10 T5\nN20 G0 X1\nN30 M6\nN40 M30\n",
    "tool with data": "N10 T1 M6\nN20 G0 Z10\nN30 M30\n",
    "missing edge": "N10 T1 M6\nN20 D4\nN30 M30\n",
    "angle line": "N10 G1 G18 X5 Z70 F1000\nN20 X88.8 ANG=110\nN30 M30\n",
    "angle incompatible": "N10 G1 G18 X5 Z70 F1000\nN20 Z100 ANG=110\nN30 M30\n",
    "two-line contour": "N10 G1 G18 X10 Z80 F1000\nN20 ANG=148.65 CHR=5.5\nN30 X85 Z40 ANG=100\nN40 M30\n",
    "angle in a circle": "N10 G2 G17 X10 Y0 CR=20 ANG=30 F100\nN20 M30\n",
    "chamfer without motion": "N10 G1 X10 F100\nN20 CHF=2\nN30 X20\nN40 M30\n",
    "beyond the software limit": "N10 G1 X400 F5000\nN20 X600\nN30 M30\n",
    # Block preparation stops at the block whose end point is refused (Y480 > MD36110 Y = 400):
    # the zero feed of the next block is never read, in the run as in the check.
    "beyond the limit before a refused feed": "N10 G0 X-20 Y480\nN20 G1 X-20 F0\nN30 M30\n",
    "no feed": "N10 G1 X10\nN20 M30\n",
    "dwell with an axis": "N10 G4 F1 X10\nN20 M30\n",
    "g93 with radius compensation": "N10 T1 M6 D1\nN20 G41 G1 X10 Y10 F100\nN30 G93 X20 F2\nN40 M30\n",
    "setting data write": "N10 $SC_THREAD_START_ANGLE=30\nN20 M30\n",
    "unknown name": "N10 FOO=1\nN20 M30\n",
    "g58 without md24000": "N10 G58 X10\nN20 M30\n",
    "g96 without transverse axis": "N10 G96 S100 LIMS=2000\nN20 G1 X10 F0.1\nN30 M30\n",
    "thread lead zero": "N10 S100 M3\nN20 G33 Z-10\nN30 M30\n",
    "spindle position": "N10 SPOS=90\nN20 M19\nN30 M30\n",
    "feed zero": "N10 G1 X10 F0\nN20 M30\n",
    "user alarm": "N10 SETAL(65000)\nN20 M30\n",
    "read actual value": "N10 G1 X12 F600\nN20 R1=$AA_IM[X]\nN30 IF R1<>12 GOTOF BAD\nN40 M30\nBAD: SETAL(65001)\nM30\n",
    "limit in a subprogram loop": "N10 G1 X0 F5000\nN20 REPEAT\nN30 G91 X100\nN40 UNTIL $P_EP[X]>550\nN50 M30\n",
    "circle end point error": "N10 G2 X10 Y0 I2 J0 F100\nN20 M30\n",
    "d0 with compensation": "N10 T1 M6 D1\nN20 G41 G1 X10 Y10 F100\nN30 D0 X20\nN40 M30\n",
    "plane change with compensation": "N10 T1 M6 D1\nN20 G41 G1 X10 Y10 F100\nN30 G18 X20\nN40 M30\n",
    "ok program": "N10 G0 X10 Y10\nN20 G1 X20 F100\nN30 G2 X30 Y20 CR=10\nN40 M30\n",
}

CORPUS = {f"bad/{p.stem}": p.read_text() for p in sorted(BAD.glob("*.mpf"))} | OWN


def data() -> NcData:
    nc = NcData()
    nc.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 50.0, 6: 4.0})  # T1 D1: end mill L1 = 50, R = 4
    return nc


def first(alarms) -> tuple[int, int | None] | None:
    return (alarms[0].number, alarms[0].line) if alarms else None


@pytest.mark.parametrize("name", sorted(CORPUS))
def test_check_names_the_first_alarm_of_the_run(name: str) -> None:
    text = CORPUS[name]
    machine = load_machine(None)
    programs = DirectorySource(BAD)
    run = run_program(machine, programs, data(), "P.MPF", text=text, timeout_s=600.0)
    reference = first(run.alarms)
    assert first(check_program(machine, programs, "P.MPF", text, data())) == reference
    checked = check_text("P.MPF", text, machine=machine, data=data(), programs=programs)
    # the editor's check marks an alarm of a called program on the call and keeps its own place
    assert first([replace(a, line=a.called_line) if a.called_file else a for a in checked]) == reference
    if checked and checked[0].called_file:
        assert checked[0].called_file == run.alarms[0].file
