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
