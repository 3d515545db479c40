"""Rules of Function Manual 002 on feeds and threads, checked by the run and by ``nck check``."""

from __future__ import annotations

import pytest

from nck.headless import check_program, run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData, ToolEdge


def data_with_tool() -> NcData:
    data = NcData()
    data.tools[(1, 1)] = ToolEdge({1: 120.0, 6: 2.0})  # end mill, radius 2 mm
    return data


def alarms(text: str, machine=None) -> tuple[list[int], list[int]]:
    """(alarms of ``nck check``, alarms of the run on the kernel) for ``text``."""
    machine = machine or load_machine()
    check = [a.number for a in check_program(machine, MemorySource({}), "P.MPF", text, data=data_with_tool())]
    run = run_program(machine, MemorySource({}), data_with_tool(), "P.MPF", text=text)
    return check, [a.number for a in run.alarms]


@pytest.mark.parametrize("text", [
    "N10 G1 X0 Y0 F100\nN20 T1 D1 G41 X10\nN30 G93 X20 F2\nN40 G40 G94 X30 F100\nM30\n",
    "N10 G93 G1 X0 Y0 F2\nN20 T1 D1 G41 X10\nN30 G40 X30\nM30\n",
])
def test_g93_is_refused_while_radius_compensation_is_active(text: str) -> None:
    """Digest 828d-3 rank 13 (G41 + G93 refused)."""
    # 002 L55402: G93 may not be used when G41/G42 is active.
    assert alarms(text) == ([10798], [10798])


def test_position_after_10798_is_where_the_axes_stand() -> None:
    """Issue 20 audit: after a block refused while the compensation look-ahead holds blocks
    back, the reported position is where the axes are, not a programmed target. G41 with
    radius 2 inside the square: the approach N30 ends at (10, 12) (perpendicular to N40);
    N40 and N45 wait in the look-ahead (their end points need the blocks after them, 002
    L18071-18073) when N50 is refused (002 L55402), so they never run: the axes stand at
    (10, 12), the machine position and the last executed segment say so."""
    text = ("N10 T1 M6 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 Y10 F1000\nN40 X30\nN45 Y30\n"
            "N50 G93 X10 F2\nN60 M30\n")
    run = run_program(load_machine(), MemorySource({}), data_with_tool(), "P.MPF", text=text)
    assert [a.number for a in run.alarms] == [10798]
    assert run.position_mcs is not None
    assert (run.position_mcs["X"], run.position_mcs["Y"]) == (pytest.approx(10.0), pytest.approx(12.0))
    last = run.segments[-1]
    assert (last.source.line, last.end_mcs["X"], last.end_mcs["Y"]) == (3, pytest.approx(10.0), pytest.approx(12.0))


def test_g93_without_radius_compensation_runs() -> None:
    assert alarms("N10 G93 G1 X10 F2\nM30\n") == ([], [])


@pytest.mark.parametrize(("frame", "expected"), [
    ("ROT X30", [10607]),  # tilts the Z thread axis: the thread length and lead change
    ("ROT Y10", [10607]),
    ("ROT Z30", []),  # 002 L55708: rotation around the thread axis is permissible
    ("TRANS X5", []),  # 002 L55710: all other frames are accepted
])
def test_thread_under_a_rotation_that_tilts_the_thread_axis(frame: str, expected: list[int]) -> None:
    # 002 L55706-55711: G33 with a ROT frame that changes the thread length: alarm 10607.
    text = f"N10 S100 M3\nN20 {frame}\nN30 G33 Z-10 K1\nN40 M30\n"
    assert alarms(text) == (expected, expected)


def test_md11410_bit_12_suppresses_10607() -> None:
    # 002 L55709-55711: bit 12 of MD11410 SUPPRESS_ALARM_MASK suppresses the alarm.
    machine = load_machine()
    machine.md["MD11410"] = 1 << 12
    assert alarms("N10 S100 M3\nN20 ROT X30\nN30 G33 Z-10 K1\nN40 M30\n", machine) == ([], [])
