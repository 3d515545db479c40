"""``$P_SUBPAR[n]``: a PROC asks whether its n-th parameter was programmed in the call (the
standard cycles use it to tell an omitted value from a programmed 0, e.g. CYCLE802's positions).
The shared manuals do not describe the variable; the rule implemented: TRUE when the call wrote
a value at position n, FALSE when the position was left empty or the call ended before it;
n outside the PROC's parameters (or a level without PROC) is 17020 (index out of range)."""

from __future__ import annotations

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

SUB = "PROC PSUB(REAL _A, REAL _B, REAL _C)\nR[$P_STACK*10]=$P_SUBPAR[1]+2*$P_SUBPAR[2]+4*$P_SUBPAR[3]\nRET\n"


def _run(main: str) -> tuple[list[int], NcData]:
    data = NcData()
    result = interpret_only(load_machine(None), MemorySource({"main.mpf": main, "PSUB.SPF": SUB}), data,
                            "main.mpf", max_blocks=100)
    return [a.number for a in result.alarms], data


def test_programmed_and_omitted_parameters() -> None:
    """(1,,3): parameters 1 and 3 → 1 + 4 = 5; (): none → 0; (,0): only the second, even
    though its value 0 equals the default → 2."""
    alarms, data = _run("PSUB(1,,3)\nR1=R20\nPSUB()\nR2=R20\nPSUB(,0)\nR3=R20\nM30\n")
    assert alarms == []
    assert (data.r[1], data.r[2], data.r[3]) == (5, 0, 2)


def test_index_outside_the_parameters_is_17020() -> None:
    alarms, _ = _run("R1=$P_SUBPAR[1]\nM30\n")
    assert alarms == [17020]
