"""Language switch and mixing (section 9 item 3): shared modal state over G290/G291, foreign
syntax → 12080, Siemens control structures and calls accepted in ISO mode, MD 20734 bit 3,
and the ISO start-up unit (MD 20154[5])."""

from __future__ import annotations

import pytest

from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.iso.switching import siemens_statement
from nck.machine import load_machine
from nck.ncdata import NcData
from tests.iso.conftest import ends, run_iso


def _run(text: str, md: dict | None = None, subprograms: dict[str, str] | None = None):
    machine = load_machine(None)
    machine.md.update(md or {})
    return interpret_only(machine, MemorySource(subprograms or {}), NcData(), "TEST.MPF",
                          text=text, max_blocks=10_000, dialect="iso-m")


@pytest.mark.parametrize("text, shown", [("N10 WAIT", "WAIT"), ("N15 G91 G500", "G500")])
def test_siemens_syntax_in_iso_mode_is_12080(text, shown):
    """Digest iso-dialects-840d rank 3: WAIT and G500 in ISO mode give 12080 (000 L5566, MD20734 bit 3)."""
    result = run_iso("N5 G291\n" + text + "\nM30\n")
    assert result.status == "alarm"
    alarm = result.alarms[0]
    assert alarm.number == 12080
    assert shown in " ".join(str(p) for p in alarm.params)


def test_g_code_unknown_to_both_languages_is_12470():
    assert run_iso("G123 X1.\nM30\n").alarms[0].number == 12470


def test_if_goto_and_labels_run_in_iso_mode():
    """Digest iso-dialects-840d rank 3 (Siemens control structures accepted, 000 L2014-2054)."""
    text = ("N5 G90 G01 X1. F100\nN10 IF $P_EP[X]>0 GOTOF SKIP\nN15 X50.\nSKIP:\n"
            "N20 Y2.\nM30\n")
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert [p["X"] for _line, p in ends(result)] == [1.0, 1.0]


def test_while_and_for_loops_run_in_iso_mode():
    text = "N5 G91 G01 F100\nN10 FOR R1=1 TO 3\nN15 X1.\nN20 ENDFOR\nWHILE $P_EP[Y]<2\nY1.\nENDWHILE\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert ends(result)[-1][1] == {"X": 3.0, "Y": 2.0, "Z": 0.0}


def test_if_else_endif_in_iso_mode():
    text = "IF 1==2\nX5.\nELSE\nX7.\nENDIF\nM30\n"
    result = run_iso(text)
    assert [p["X"] for _line, p in ends(result)] == [7.0]


def test_call_runs_a_siemens_subprogram_in_iso_mode():
    """Digest iso-dialects-840d rank 3."""
    sub = "PROC SHAFT\nG1 X4 F100\nM17\n"
    result = _run('N10 CALL "SHAFT"\nN20 G00 Y3.\nM30\n', subprograms={"SHAFT": sub})
    assert result.status == "ended", result.alarms
    assert [(p["X"], p["Y"]) for _line, p in ends(result)] == [(4.0, 0.0), (4.0, 3.0)]


def test_iso_words_are_not_taken_for_siemens_statements():
    assert not siemens_statement("N10 G01 X1. F100")
    assert not siemens_statement("O0012 (part)")
    assert siemens_statement("N10 IF R1==1 GOTOF END")
    assert siemens_statement("/1 N5 CALL \"A\"")
    assert siemens_statement("END:")


def test_md20734_bit3_hands_rejected_blocks_to_siemens():
    text = "N5 G291\nN10 R1=4\nN15 G91 G500\nN20 X1. Y1.\nM30\n"
    assert _run(text).alarms[0].number == 12080
    result = _run(text, {"MD20734": 8})
    assert result.status == "ended", result.alarms
    assert ends(result)[-1][1] == {"X": 1.0, "Y": 1.0, "Z": 0.0}
    # G91 from the Siemens block N15 is active in the ISO block N20
    result = _run("G0 X5.\nN15 G91 G500\nN20 X1.\nM30\n", {"MD20734": 8})
    assert ends(result)[-1][1]["X"] == 6.0


def test_language_switch_keeps_tool_offsets_and_frames():
    """Digest iso-milling-828d rank 6."""
    text = "G52 X10.\nG290\nG0 X0\nG291\nG00 X5.\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert [p["X"] for _line, p in ends(result, "mcs")] == [10.0, 15.0]


@pytest.mark.parametrize("value, x_mm", [(1, 25.4), (2, 1.0), (0, 1.0)])
def test_iso_start_unit_from_md20154(value, x_mm):
    reset_values = [0] * 31
    reset_values[5] = value
    result = _run("G01 X1. F100\nM30\n", {"MD20154": reset_values})
    assert result.status == "ended", result.alarms
    assert ends(result, "mcs")[0][1]["X"] == x_mm


def test_p_extgg_shows_iso_values_in_both_modes():
    """E1 (``$P_EXTGG[3]`` = 2 after G91 in Siemens mode) and the ISO M start-up values.

    Digest iso-dialects-840d rank 2 and 3 (E1, 000 L768-777).
    """
    data = NcData()
    text = ("N5 G00 X100. Y100.\nN10 G90\nN15 G290\nR1=$P_EXTGG[1] R2=$P_EXTGG[2] R3=$P_EXTGG[3]\n"
            "R5=$P_EXTGG[5] R11=$P_EXTGG[11] R16=$P_EXTGG[16] R31=$P_EXTGG[31]\nN20 G91\n"
            "R30=$P_EXTGG[3]\nN25 G291\nN30 G68 X0 Y0 R10.\nIF $P_EXTGG[31]==2 GOTOF ISO\nX1.\n"
            "ISO:\nG290\nR40=$P_EXTGG[3] R41=$P_EXTGG[16]\nM30\n")
    result = interpret_only(load_machine(None), MemorySource(), data, "TEST.MPF", text=text,
                            max_blocks=1000, dialect="iso-m")
    assert result.status == "ended", result.alarms
    r = data.r
    assert (r[1], r[2], r[3], r[5], r[11], r[16], r[31]) == (1, 1, 1, 1, 1, 2, 1)  # G00 G17 G90
    assert r[30] == 2 and r[40] == 2  # G94 G50 G69 G290; G91 over the switch
    assert r[41] == 1  # G68
    assert len(result.segments) == 1  # the IF saw G291 (value 2) and jumped over X1.


@pytest.mark.parametrize("text, line, dialect", [
    ("N5 G291\nN10 G290 G0 X5\nM30\n", 2, "iso-m"),      # ISO mode: G290 with a motion
    ("N5 G291\nN10 G00 X1. G290\nM30\n", 2, "iso-m"),    # ISO mode: G290 after the words
    ("N5 G291 G0 X10\nM30\n", 1, "siemens"),             # Siemens mode: G291 with a motion
    ("N5 M3 G291\nM30\n", 1, "siemens"),                 # Siemens mode: G291 with an M function
])
def test_g290_g291_must_stand_alone_in_their_block(text, line, dialect):
    """Digest iso-milling-828d rank 6."""
    # 003 L393: "G290 and G291 must be programmed alone in an NC block." -> syntax error 12080
    result = run_iso(text, dialect=dialect)
    assert result.status == "alarm"
    assert (result.alarms[0].number, result.alarms[0].line) == (12080, line)
    assert not result.segments


def test_g290_g291_alone_with_a_block_number_and_comment_switch():
    # 003 L389-393: alone in the block (a block number and a comment are not instructions).
    result = run_iso("N5 G291 ; to ISO\nN10 G00 X1.\nN15 G290 ; back\nN20 G0 X2\nM30\n",
                     dialect="siemens")
    assert result.status == "ended", result.alarms
    assert [p["X"] for _line, p in ends(result)] == [1.0, 2.0]


def test_p_extgg_reads_the_iso_t_groups_in_iso_t():
    """ISO T numbers its G groups its own way: group 2 is G96/G97 there, G17/G18/G19 in ISO M
    (000 L5523, MD 20154 EXTERN_GCODE_RESET_VALUES). G96 is the first code of the group: 1."""
    data = NcData()
    text = ("N5 G96 S100\nN10 G290\nR2=$P_EXTGG[2]\nN15 G291\nN20 G97 S500\nN25 G290\n"
            "R3=$P_EXTGG[2]\nM30\n")
    result = interpret_only(load_machine("lathe2"), MemorySource(), data, "TEST.MPF", text=text,
                            max_blocks=100, dialect="iso-t")
    assert result.status == "ended", result.alarms
    assert (data.r[2], data.r[3]) == (1, 2)  # G96, then G97
