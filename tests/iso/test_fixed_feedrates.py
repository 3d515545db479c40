"""ISO fixed feedrates F0…F9 from SD 42160 with MD 22920 (issue 20; 003 L631-652)."""

from __future__ import annotations

import pytest

from nck.iso.dialect import dialect_for
from nck import commands as c
from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.interp.interpreter import Interpreter
from nck.kernel import Nck
from nck.ncdata import NcData

# 003 L645-652: the manual's example
PROGRAM = "N10 X10. Y10. Z10. F0 G94\nN20 G01 X150. Y30. F1\nN30 X160. F2\nN40 X170. F2.\nM30\n"


def _run(md22920: bool, program: str = PROGRAM, subprograms: dict[str, str] | None = None):
    machine = load_machine(None)
    machine.md.update({"MD22920": md22920})
    data = NcData()
    data.setting_data["SD42160"] = [5000.0, 1000.0, 500.0] + [0.0] * 7
    return interpret_only(machine, MemorySource(subprograms or {}), data, "TEST.MPF", text=program,
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


def test_digest_iso_milling_rank_08_the_feed_override_scales_a_fixed_feedrate() -> None:
    """Digest iso-milling-828d rank 8: the feed override acts on F0…F9 as well (003 L678).
    F1 = SD42160[1] = 1000 mm/min; at 50 % override the path runs at 500 mm/min (the
    interpreter's ISO M on the real motion; the ramp is over after 0.2 s)."""
    machine = load_machine(None)
    machine.md.update({"MD22920": True})
    data = NcData()
    data.setting_data["SD42160"] = [5000.0, 1000.0, 500.0] + [0.0] * 7
    programs = MemorySource({"P.MPF": "N10 G01 G94 X300. F1\nM30\n"})
    nck = Nck(machine, data, programs, referenced=True,
              interpreter_factory=lambda m, p, d: Interpreter(m, p, d, dialect=dialect_for("iso-m", m)))
    assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
    assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
    assert nck.submit(c.CycleStart()) == c.Accepted()
    nck.tick(1.0)
    assert nck.status().channel.path_feed_mm_min == pytest.approx(1000.0, abs=1e-6)
    assert nck.submit(c.SetOverride("feed", 50.0)) == c.Accepted()
    nck.tick(1.0)
    assert nck.status().channel.path_feed_mm_min == pytest.approx(500.0, abs=1e-6)


def test_digest_iso_milling_rank_08_macro_call_gets_the_digit_and_a_cycle_the_feed() -> None:
    """Digest iso-milling-828d rank 8: in a G65 call F1 is handed over as the number 1 in
    $C_F, the address carries a value, not a feed (003 L680-681, L694-697); in a drilling
    cycle block F1 is the fixed feed read from SD42160[1] = 1000 (003 L682-683): the drilling
    move (the third of the G81 block) runs at 1000 mm/min."""
    macro = _run(True, "N10 G65 P10 F1\nM30\n", {"O0010": "G290\nR2=$C_F\nG291\nM99\n"})
    assert macro.status == "ended", macro.alarms
    assert macro.interpreter.r(2) == 1.0
    drilled = _run(True, "N10 G90 G00 X0 Y0 Z10. M3 S1000\nN20 G81 X10. Y10. Z-5. R2. F1\nN30 G80\nM30\n")
    assert drilled.status == "ended", drilled.alarms
    feeds = [m.feed for m in drilled.segments if m.source.line == 2]
    assert feeds[2] == 1000.0
