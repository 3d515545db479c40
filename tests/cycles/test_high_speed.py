"""CYCLE832 (high-speed settings): what the cycle switches for the blocks after it, as
written down in data/cycles/README.md ("High-speed settings"); the bad-parameter alarm.
Machining types of the Operate generation (README sources): _TOLM 0 deselect, 1 finishing,
2 semi-finishing, 3 roughing, 4 precision finishing; the third parameter is the orientation
tolerance (CAM posts write 1)."""

from __future__ import annotations

import pytest

from tests.cycles.helpers import run

GROUPS = (10, 21, 30, 24)  # continuous path, acceleration profile, compressor, feedforward


def _after(body: str) -> tuple[tuple[str, ...], bool]:
    """The G codes of those groups at the last block (a G1) and whether it ends in exact stop."""
    last = run(body + "\nG1 X10 F100").ended().result.segments[-1]
    return tuple(last.gcodes[g] for g in GROUPS), last.exact_stop


@pytest.mark.parametrize("tolm", [1, 2, 3, 4, 102001, 1003])
def test_cycle832_selects_rounding_soft_compressor_feedforward(tolm: int) -> None:
    """Finishing, semi-finishing, roughing, precision finishing (units digit 1 … 4; higher digits are the
    manufacturer's variants and do not matter here): G642, SOFT, COMPCAD, FFWON stay in force
    after the call (no SAVE), so the next G1 does not stop exactly."""
    assert _after(f"CYCLE832(0.01, {tolm}, 1)") == (("G642", "SOFT", "COMPCAD", "FFWON"), False)


@pytest.mark.parametrize("deselect", ["CYCLE832()", "CYCLE832(0, 0, 1)"])
def test_cycle832_deselection_returns_to_the_reset_positions(deselect: str) -> None:
    """_TOLM 0, or the call without parameters: G60 (exact stop), BRISK, COMPOF, FFWOF."""
    assert _after(f"CYCLE832(0.01, 1, 1)\n{deselect}") == (("G60", "BRISK", "COMPOF", "FFWOF"), True)


@pytest.mark.parametrize("call", ["CYCLE832(0.01, 5, 1)", "CYCLE832(0.01, -1, 1)", "CYCLE832(-0.01, 1, 1)"])
def test_cycle832_bad_machining_type_or_tolerance_is_61002(call: str) -> None:
    case = run(call + "\nG1 X10 F100")
    assert case.alarms == [61002]
    assert [s for s in case.steps() if s[0] == "G1"] == []
