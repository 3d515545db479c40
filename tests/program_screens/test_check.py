"""``nck.check``: the editor's live check and the headless run behind the simulation."""

from __future__ import annotations

import pytest

from nck.check import check_text, iter_check


def test_every_faulty_line_is_reported_with_its_line() -> None:
    """Two bad lines give two alarms (12080) with their 1-based lines; good lines none."""
    alarms = check_text("A.MPF", "G1 X10 F100\nG1 X==5\nN10 G0 Y2 ; ok\nY=)\nM30")
    assert [(a.number, a.line) for a in alarms] == [(12080, 2), (12080, 4)]
    assert all(a.text for a in alarms)


def test_a_clean_program_has_no_alarms() -> None:
    """A correct program checks clean."""
    assert check_text("A.MPF", "N10 G0 X0 Y0\nN20 G1 X10 F200\nN30 M30\n") == []


def test_check_can_be_stopped_early() -> None:
    """``should_stop`` ends the streaming check (the editor cancels stale checks)."""
    text = "\n".join("X==" for _ in range(500))
    seen = []
    for alarm in iter_check("A.MPF", text, should_stop=lambda: len(seen) >= 10):
        seen.append(alarm)
    assert 10 <= len(seen) < 500


@pytest.mark.parametrize("junk", ["\x00\x01\x02", "é" * 600, "(" * 5000 + "1", '"' * 3])
def test_garbage_is_an_alarm_never_an_exception(junk: str) -> None:
    """Binary junk, over-long and deeply nested lines become alarms, not tracebacks."""
    alarms = check_text("J.MPF", junk)
    assert alarms and all(isinstance(a.number, int) for a in alarms)


def test_structure_errors_are_found_without_running() -> None:
    """An IF without ENDIF is reported on its line (12640) by the structure pass."""
    alarms = check_text("A.MPF", "N10 G1 X10 F100\nN20 IF R1>5\nN30 G1 X2\nM30")
    assert [(a.number, a.line, a.n) for a in alarms] == [(12640, 2, 20)]


def test_run_time_alarm_found_by_interpretation() -> None:
    """A jump to a missing label is only found by interpreting: alarm 14080 on its line."""
    alarms = check_text("A.MPF", "N10 G1 X10 F100\nGOTOF NIX\nM30")
    assert [(a.number, a.line) for a in alarms] == [(14080, 2)]
