"""Program control and statements as the Programming Manual describes them (issue 20, language items).

Every expected value is derived by hand from the manual text cited next to it.
"""

from __future__ import annotations

from tests.lang.conftest import run_text


def _r(result, number: int) -> float:
    return result.interpreter.data.r[number]


def test_repeat_between_its_own_labels_repeats_up_to_the_repeat_block() -> None:
    # 002 L21385-21387: "If the REPEAT instruction is between the Start and End label, only the
    # part program section from the Start label to the REPEAT instruction is repeated."
    # Without P the section is repeated exactly once (002 L21356-21357): START..N30 runs twice.
    result = run_text(
        "N10 START_1: R1=R1+1\n"
        "N20 R2=R2+1\n"
        "N30 REPEAT START_1 END_1\n"
        "N40 END_1: R3=R3+1\n"
        "N50 M30\n", timeout_s=5.0)
    assert result.status == "ended", result.alarms
    assert (_r(result, 1), _r(result, 2), _r(result, 3)) == (2, 2, 1)


def test_repeat_between_its_labels_with_passes() -> None:
    # 002 L21385-21387 with P=n (002 L21403-21407): the section START..REPEAT block runs
    # once normally and n more times: P=3 gives four passes; the END block runs once after.
    result = run_text(
        "START_1: R1=R1+1\n"
        "REPEAT START_1 END_1 P=3\n"
        "END_1: R3=R3+1\n"
        "M30\n", timeout_s=5.0)
    assert result.status == "ended", result.alarms
    assert (_r(result, 1), _r(result, 3)) == (4, 1)


def test_case_without_parentheses_as_in_the_manual_example() -> None:
    # 002 L23209-23211: "CASE $P_UIFRNUM OF 0 GOTOF _G500 1 GOTOF _G54 ... DEFAULT GOTOF END";
    # after G55 the settable frame number is 2 ($P_UIFRNUM: G54=1, G55=2), so the jump goes
    # to the block of the constant 2.
    result = run_text(
        "N10 G55\n"
        "N20 CASE $P_UIFRNUM OF 0 GOTOF _G500 1 GOTOF _G54 2 GOTOF _G55 DEFAULT GOTOF END\n"
        "N30 _G500: R1=500 GOTOF END\n"
        "N40 _G54: R1=54 GOTOF END\n"
        "N50 _G55: R1=55 GOTOF END\n"
        "N60 END: M30\n", timeout_s=5.0)
    assert result.status == "ended", result.alarms
    assert _r(result, 1) == 55


def test_case_with_parentheses_and_default() -> None:
    # 002 L23209: the DEFAULT branch is taken when no constant matches.
    result = run_text(
        "R2=7\n"
        "CASE (R2) OF 1 GOTOF ONE 2 GOTOF TWO DEFAULT GOTOF OTHER\n"
        "ONE: R1=1 GOTOF FIN\n"
        "TWO: R1=2 GOTOF FIN\n"
        "OTHER: R1=3\n"
        "FIN: M30\n", timeout_s=5.0)
    assert result.status == "ended", result.alarms
    assert _r(result, 1) == 3
