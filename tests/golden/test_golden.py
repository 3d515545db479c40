"""Golden programs: each folder holds main.mpf (+ subprograms) and the expected trace.

The trace lists every canonical command (motion end points, aux functions,
messages, stops) and the final state (status, alarms, changed G groups,
position, tool, spindle, R parameters); it shows only that nothing changed. The values
the manuals determine are asserted in ``test_golden_values.py``. Regenerate deliberately with
``GOLDEN_UPDATE=1 pytest tests/golden`` and review the diff by hand.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.golden.trace import run_case

HERE = Path(__file__).parent
CASES = sorted(p for p in HERE.iterdir() if p.is_dir() and (p / "main.mpf").is_file())


def test_there_are_enough_golden_cases() -> None:
    assert len(CASES) >= 25


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_golden_case(case: Path) -> None:
    actual = run_case(case)
    expected_file = case / "expected.trace"
    if os.environ.get("GOLDEN_UPDATE") or not expected_file.exists():
        expected_file.write_text(actual)
        if not os.environ.get("GOLDEN_UPDATE"):
            pytest.fail(f"{expected_file} was missing and has been written; review it")
    assert actual == expected_file.read_text()
