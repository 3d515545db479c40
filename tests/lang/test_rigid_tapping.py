"""G331 / G332: tapping without compensating chuck (002 L19681, L53950) as path motion whose
feed is the programmed spindle speed times the lead of the interpolation parameter."""

from __future__ import annotations

from nck.headless import interpret_only, run_on_kernel
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

TAPPING = "G17 G90 G0 X0 Y0 Z10 S500 M3 F100\nSPOS=0\nG331 Z-10 K1.5 S300\nG332 Z5 K1.5 S600\nM30\n"


def _check(text: str):
    return interpret_only(load_machine(None), MemorySource({"t.mpf": text}), NcData(), "t.mpf",
                          text=text, max_blocks=1000)


def test_g331_and_g332_move_at_speed_times_lead() -> None:
    """G331 to Z-10 at 300 rpm x 1.5 mm = 450 mm/min; G332 back to Z5 at 600 x 1.5 = 900."""
    result = _check(TAPPING)
    assert result.status == "ended", result.alarms
    taps = [(m.kind, m.end_wcs["Z"], m.lead_mm, m.feed_mm_min) for m in result.segments if m.kind != "G0"]
    assert taps == [("G331", -10.0, 1.5, 450.0), ("G332", 5.0, 1.5, 900.0)]


def test_g331_without_lead_is_an_alarm() -> None:
    """No lead in the block nor before: 16720 (thread lead zero), as G33."""
    result = _check("G17 G0 Z10 S500 M3\nSPOS=0\nG331 Z-10\nM30\n")
    assert [a.number for a in result.alarms] == [16720]


def test_the_kernel_finishes_a_tapping_stroke_with_the_spindle_positioned() -> None:
    """After SPOS the spindle stands in position control; the tapping axis must still move (it
    does not wait for a turning spindle as a revolutional feed would)."""
    result = run_on_kernel(load_machine(None), MemorySource({"t.mpf": TAPPING}), NcData(), "t.mpf",
                           timeout_s=60.0)
    assert result.status == "ended", result.alarms
    assert result.position_wcs is not None and round(result.position_wcs["Z"], 3) == 5.0
