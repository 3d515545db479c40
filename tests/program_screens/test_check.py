"""``nck.check``: the editor's live check and the headless run behind the simulation."""

from __future__ import annotations

import pytest

from nck.check import check_text, iter_check
from nck.interp.sources import MemorySource


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


def test_syntax_and_structure_errors_are_listed_together_as_nck_check_lists_them() -> None:
    """A text with a syntax error (N20: an address without value) and an IF without ENDIF
    (N30): the editor lists both, as ``nck check`` does, so a trainee who fixes the syntax
    error is not surprised by a second one; no run follows (it would stop at the first)."""
    from nck.headless import check_program
    from nck.machine import load_machine

    text = "N10 G0 X0 Y0\nN20 G1 X10 Y F100\nN30 IF R1>0\nN40 G1 X20\nN50 M30\n"
    alarms = check_text("A.MPF", text)
    assert [(a.number, a.line, a.n) for a in alarms] == [(12080, 2, 20), (12640, 3, 30)]
    headless = check_program(load_machine(), MemorySource({}), "A.MPF", text)
    assert [(a.number, a.line) for a in alarms] == [(a.number, a.line) for a in headless]


def test_run_time_alarm_found_by_interpretation() -> None:
    """A jump to a missing label is only found by interpreting: alarm 14080 on its line."""
    alarms = check_text("A.MPF", "N10 G1 X10 F100\nGOTOF NIX\nM30")
    assert [(a.number, a.line) for a in alarms] == [(14080, 2)]


def test_an_alarm_in_a_called_program_is_marked_on_the_call() -> None:
    """The editor marks lines of the text it shows: an alarm that comes in a cycle or a
    subprogram belongs on the line that called it (DISPLOF keeps the block display at the call
    block, 000 L802, 002 L23164), with the called program and its line kept for the message.
    CYCLE82 feeds to depth with its line 8 ``G1 AX[_AX]=_ZFIN`` at the feed programmed before
    the call: none here, so alarm 10860 there (data/cycles/CYCLE82.SPF)."""
    call = "CYCLE82(5,0,2,-15,0,1)"
    direct = check_text("A.MPF", f"; drilled\nN10 G0 X0 Y0 Z10\nN20 {call}\nN30 G0 X10\nN40 M30\n")
    assert [(a.number, a.line, a.called_file, a.called_line) for a in direct] == [(10860, 3, "CYCLE82.SPF", 8)]
    # a modal call runs after the motion block that ends at the position: that block is the call
    modal = check_text("A.MPF", f"N10 G0 X0 Y0 Z10\nN20 MCALL {call}\nN30 G0 X10\nN40 X20\nN50 MCALL\nN60 M30\n")
    assert [(a.line, a.called_file) for a in modal] == [(3, "CYCLE82.SPF")]
    # two levels down: the line of the main program's call of the subprogram
    programs = MemorySource({"HOLE.SPF": f"PROC HOLE\n{call}\nRET\n"})
    nested = check_text("A.MPF", "N10 G0 X0 Y0 Z10\nN20 G0 X5\nN30 HOLE\nN40 M30\n", programs=programs)
    assert [(a.line, a.called_file, a.called_line) for a in nested] == [(3, "CYCLE82.SPF", 8)]
    # an alarm of the text itself keeps its own line and names no other program
    own = check_text("A.MPF", "N10 G0 X0\nN20 G1 X10\nN30 M30\n")
    assert [(a.number, a.line, a.called_file) for a in own] == [(10860, 2, None)]


def test_a_program_switching_to_iso_mode_is_read_in_iso_mode() -> None:
    """G291 switches to ISO dialect mode (000 L740, L776): ``G81 X.. Y.. Z.. R.. F..`` is its
    drilling cycle (000 L3431), not a Siemens syntax error in ``R2`` (the editor marked it 12080
    while ``nck check`` found the program correct). An error in the Siemens part after G290
    is still found on its line."""
    iso = "G291\nG90 G54 G17\nS1000 M3\nG00 X0 Y0 Z10\nG81 X10 Y10 Z-5 R2 F100\nX20\nG80\nG290\nM30\n"
    assert check_text("ISO.MPF", iso) == []
    broken = iso.replace("G290\n", "G290\nG1 X==5\n")
    assert [(a.number, a.line) for a in check_text("ISO.MPF", broken)] == [(12080, 9)]
