"""Running hostile program text through the whole kernel, with guards.

:func:`run_hostile` selects the text as a main program in AUTOMATIC, starts it
with NC START and lets simulated time run (``nck run`` does the same), with a
simulated-time budget (the ``--timeout`` of the CLI); a hang is caught by the
suite's per-test timeout, never by timing a run. It returns the :class:`~nck.headless.HeadlessRun` after asserting the contract
of issue 13: the run ended normally, with an NC alarm or at the time budget;
the kernel logged no internal error (alarm 1 "internal error" is how the
kernel reports a Python exception).
"""

from __future__ import annotations

from pathlib import Path

from nck.errors import NcAlarmError
from nck.headless import HeadlessRun, run_on_kernel
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.ncdata import NcData

MACHINE = load_machine()
GOLDEN_DIR = Path(__file__).resolve().parents[1] / "golden"
SIM_BUDGET_S = 20.0
"""Simulated seconds a hostile program may run (like ``nck run --timeout 20``)."""

SUBPROGRAMS = {
    "SUBA.SPF": "PROC SUBA(REAL PA, VAR REAL PB)\nPB=PA+1\nR1=R1+1\nIF R1<5 GOTOB LBL\nLBL: RET\n",
    "L77.SPF": "G91 G1 X1 F100\nG90\nM17\n",
    "SELF.SPF": "PROC SELF\nSELF\nRET\n",
}


def golden_programs() -> dict[str, str]:
    """The main programs of the golden cases (name of the case -> text)."""
    found: dict[str, str] = {}
    for case in sorted(GOLDEN_DIR.iterdir()):
        main = case / "main.mpf"
        if main.is_file():
            found[case.name] = main.read_text(encoding="latin-1")
    return found


def golden_subprograms() -> dict[str, str]:
    """Every subprogram file of the golden cases (first one of a name wins)."""
    found: dict[str, str] = dict(SUBPROGRAMS)
    for path in sorted(GOLDEN_DIR.glob("*/*")):
        if path.suffix.upper() in (".SPF", ".MPF") and path.name.lower() != "main.mpf":
            found.setdefault(path.name.upper(), path.read_text(encoding="latin-1"))
    return found


ALL_SUBPROGRAMS = golden_subprograms()


def run_hostile(text: str, sim_budget_s: float = SIM_BUDGET_S) -> HeadlessRun:
    """Run ``text`` through the kernel and assert it ended cleanly (see module doc)."""
    result = run_on_kernel(MACHINE, MemorySource(ALL_SUBPROGRAMS), NcData(), "FUZZ.MPF",
                           text=text, timeout_s=sim_budget_s)
    assert result.status in ("ended", "alarm", "timeout"), result.status
    for alarm in result.alarms:
        assert isinstance(alarm, NcAlarmError) and isinstance(alarm.number, int)
    internal = [a for a in result.alarms if a.number == 1]
    assert not internal, f"kernel internal error for program {text[:200]!r}: {internal[0].params}"
    return result
