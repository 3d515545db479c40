"""ISO fixed feedrates F0…F9 from SD 42160 with MD 22920 (issue 20; 003 L631-652)."""

from __future__ import annotations

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

# 003 L645-652: the manual's example
PROGRAM = "N10 X10. Y10. Z10. F0 G94\nN20 G01 X150. Y30. F1\nN30 X160. F2\nN40 X170. F2.\nM30\n"


def _run(md22920: bool, program: str = PROGRAM):
    machine = load_machine(None)
    machine.md.update({"MD22920": md22920})
    data = NcData()
    data.setting_data["SD42160"] = [5000.0, 1000.0, 500.0] + [0.0] * 7
    return interpret_only(machine, MemorySource({}), data, "TEST.MPF", text=program,
                          max_blocks=1000, timeout_s=1e6, dialect="iso-m")


def _feeds(md22920: bool, program: str = PROGRAM) -> list[tuple[int, float | None]]:
    result = _run(md22920, program)
    assert result.status == "ended", result.alarms
    return [(m.source.line, m.feed) for m in result.segments if m.kind == "G1"]


def test_f0_to_f9_take_the_setting_data_when_md22920_is_set() -> None:
    """Digest iso-dialects-840d rank 8 and iso-milling-828d rank 8."""
    # 003 L639-641: with MD22920 = TRUE F0…F9 come from SD42160[n]: F1 = 1000, F2 = 500;
    # F2. (with a decimal point) is an ordinary feed of 2 mm/min (own choice: only the
    # single digits without a point are the fixed feedrates).
    assert _feeds(True) == [(2, 1000.0), (3, 500.0), (4, 2.0)]


def test_f1_to_f9_are_ordinary_feeds_without_md22920() -> None:
    # 003 L637-638: "If the machine data is set to FALSE, F1 - F9 is interpreted as normal
    # feed programming, e.g. F2 = 2 mm/min".
    assert _feeds(False, PROGRAM.replace(" F0", "")) == [(2, 1.0), (3, 2.0), (4, 2.0)]


def test_f0_without_md22920_is_14800() -> None:
    """Digest iso-milling-828d rank 2 and rank 8."""
    # 003 L629-631: F0 without the fixed-feedrate function → 14800 (path velocity <= 0).
    result = _run(False, "N10 G01 X10. F0\nM30\n")
    assert [a.number for a in result.alarms] == [14800]
