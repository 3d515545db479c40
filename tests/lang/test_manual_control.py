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


def _frame_rotation(program: str) -> tuple[float, float, float]:
    result = run_text(program + "R11=$P_UIFR[1,X,RT] R12=$P_UIFR[1,Y,RT] R13=$P_UIFR[1,Z,RT]\nM30\n",
                      timeout_s=5.0)
    assert result.status == "ended", result.alarms
    return (_r(result, 11), _r(result, 12), _r(result, 13))


def test_crot_reads_back_in_the_manuals_rpy_form_at_ninety_degrees() -> None:
    # 002 L27986-27988 (RPY, MD10600=1): $P_UIFR[1]=crot(x,10,y,90,z,40) reads back as
    # crot(x,0,y,90,z,30) — at y=90 only z-x matters and it is put into z.
    assert _frame_rotation("$P_UIFR[1]=crot(x,10,y,90,z,40)\n") == (0.0, 90.0, 30.0)


def test_crot_reads_back_wrapped_into_the_unique_ranges() -> None:
    # 002 L27990-27991: crot(x,190,y,0,z,-200) reads back as crot(x,-170,y,0,z,160).
    assert _frame_rotation("$P_UIFR[1]=crot(x,190,y,0,z,-200)\n") == (-170.0, 0.0, 160.0)


def test_crot_at_minus_ninety_degrees_puts_the_combined_angle_into_z() -> None:
    # 002 L27986-27988 by the same rule at y=-90: Rz(z)·Ry(-90)·Rx(x) depends on x+z only;
    # x=10, z=40 reads back as x=0, z=50.
    assert _frame_rotation("$P_UIFR[1]=CROT(X,10,Y,-90,Z,40)\n") == (0.0, -90.0, 50.0)


def _pframe_rotation(program: str) -> tuple[float, float, float]:
    result = run_text(program + "R11=$P_PFRAME[X,RT] R12=$P_PFRAME[Y,RT] R13=$P_PFRAME[Z,RT]\nM30\n",
                      timeout_s=5.0)
    assert result.status == "ended", result.alarms
    return (_r(result, 11), _r(result, 12), _r(result, 13))


def test_crpl_rotates_in_the_active_plane_or_about_the_named_axis() -> None:
    # 002 L28005-28020: CRPL(INT, REAL): 0 rotation in the active plane, 1 about z,
    # 2 about y, 3 about x; the angle in degrees.
    assert _pframe_rotation("G17\n$P_PFRAME=CRPL(0,30)\n") == (0.0, 0.0, 30.0)
    assert _pframe_rotation("G18\n$P_PFRAME=CRPL(0,30)\n") == (0.0, 30.0, 0.0)
    assert _pframe_rotation("G19\n$P_PFRAME=CRPL(0,30)\n") == (30.0, 0.0, 0.0)
    assert _pframe_rotation("$P_PFRAME=CRPL(1,30)\n") == (0.0, 0.0, 30.0)
    assert _pframe_rotation("$P_PFRAME=CRPL(2,-20)\n") == (0.0, -20.0, 0.0)
    assert _pframe_rotation("$P_PFRAME=CRPL(3,45)\n") == (45.0, 0.0, 0.0)


def test_crpl_chained_with_a_translation_moves_as_the_manual_example() -> None:
    # 002 L28034: $P_PFRAME = CTRANS(x,10) : CRPL(1,30). WCS X10 Y0 lies at
    # 10 + 10*cos(30) = 18.660254, 10*sin(30) = 5 in the machine (no other frames).
    result = run_text("$P_PFRAME = CTRANS(x,10) : CRPL(1,30)\nG0 X10 Y0\nM30\n", timeout_s=5.0)
    assert result.status == "ended", result.alarms
    end = result.segments[-1].end_mcs
    assert round(end["X"], 6) == 18.660254 and round(end["Y"], 6) == 5.0


def test_crpl_with_a_wrong_plane_number_is_an_alarm() -> None:
    # 002 L28009-28012: only 0..3 are defined; anything else is a wrong parameter (14020).
    result = run_text("$P_PFRAME=CRPL(4,30)\nM30\n", timeout_s=5.0)
    assert [a.number for a in result.alarms] == [14020]


def test_redef_is_refused_as_not_available_in_run_and_check() -> None:
    # 004 L529-536 describes REDEF without its syntax; this NC does not offer it: 12550 (name or
    # function not available) in the run and in the check, never a silent acceptance.
    from nck.check import check_text

    text = "DEF NCK REAL LIMIT\nREDEF LIMIT APWP 2\nM30\n"
    result = run_text(text, timeout_s=5.0)
    assert [(a.number, a.line) for a in result.alarms] == [(12550, 2)]
    assert [(a.number, a.line) for a in check_text("TEST.MPF", text)] == [(12550, 2)]
