"""ISO dwell G04 (section 9 item 9): X/U/P units under MD 10884, revolutions under G95
with MD 20734 bit 2."""

from __future__ import annotations

import pytest

from nck import canon
from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData


def _dwells(text: str, **md) -> list[canon.Dwell]:
    machine = load_machine(None)
    machine.md.update(md)
    result = interpret_only(machine, MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text=text + "\nM30\n", max_blocks=1000)
    assert result.status == "ended", result.alarms
    return [c for c in result.commands if isinstance(c, canon.Dwell)]


@pytest.mark.parametrize("block", ["G04 X1000", "G04 X1.", "G04 P1000", "G04 U1000"])
def test_standard_notation_dwell_is_one_second(block):
    """Digest iso-dialects-840d rank 9 (000 L1148-1160)."""
    (dwell,) = _dwells(block, MD10884=False)
    assert dwell.seconds == pytest.approx(1.0) and dwell.revolutions is None


@pytest.mark.parametrize("block, seconds", [("G04 P1000", 1.0), ("G04 X1000", 1000.0),
                                            ("G04 X2.5", 2.5), ("G04 P250", 0.25)])
def test_pocket_calculator_dwell(block, seconds):
    """Digest iso-dialects-840d rank 9 (P always in ms)."""
    (dwell,) = _dwells(block)
    assert dwell.seconds == pytest.approx(seconds)


def test_dwell_stays_time_under_g95_without_bit2():
    (dwell,) = _dwells("M03 S1000\nG95 G04 X1000", MD10884=False)
    assert dwell.seconds == pytest.approx(1.0) and dwell.revolutions is None


@pytest.mark.parametrize("pocket, revolutions", [(False, 1.0), (True, 1000.0)])
def test_g95_dwell_in_revolutions_with_md20734_bit2(pocket, revolutions):
    """Digest iso-dialects-840d rank 9 (MD20734 bit 2)."""
    (dwell,) = _dwells("M03 S1000\nG95 G04 X1000", MD10884=pocket, MD20734=4)
    assert dwell.revolutions == pytest.approx(revolutions) and dwell.seconds is None


def test_bit2_has_no_effect_under_g94():
    (dwell,) = _dwells("G94 G04 P1500", MD20734=4)
    assert dwell.seconds == pytest.approx(1.5)


def test_dwell_keeps_position_and_feed():
    machine = load_machine(None)
    result = interpret_only(machine, MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text="G01 X10. F200\nG04 X2.\nX20.\nM30\n", max_blocks=100)
    assert result.status == "ended", result.alarms
    moves = result.segments
    assert [round(m.end_wcs["X"], 3) for m in moves] == [10.0, 20.0]


def test_g04_without_time_raises_12080():
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text="G04\nM30\n", max_blocks=10)
    assert result.alarms[0].number == 12080
