"""ISO macros (section 9 item 14): G65 arguments in $C_…, L passes, G66/G67 modal calls,
PROC macros in Siemens mode, one call per block (12722), G05 P program calls."""

from __future__ import annotations

import pytest

from nck.iso.dialect import dialect_for
from nck.iso.translate import translate
from nck.ncdata import NcData, ToolEdge

from tests.iso.conftest import ends, run_iso

# an ISO-mode macro reads its arguments in a Siemens section (the manual's pattern)
READER = ("G290\nR1=$C_X R2=$C_F R3=$C_S R4=$C_X_PROG R5=R5+1 R6=$C_Z_PROG R7=$C_Y\n"
          "R8=$AA_IM[X]\nG291\nM99\n")


def _r(result, *numbers):
    return [result.interpreter.r(n) for n in numbers]


def test_g65_passes_arguments_and_does_not_move():
    """Digest iso-dialects-840d rank 14 (000 L2163-2556)."""
    main = "N10 G00 X1. Y2.\nN30 G65 P10 F55 X150. Y100. S2000\nN40 X50.\nM30\n"
    result = run_iso(main, {"O0010": READER})
    assert result.status == "ended", result.alarms
    assert ends(result) == [(1, {"X": 1.0, "Y": 2.0, "Z": 0.0}), (3, {"X": 50.0, "Y": 2.0, "Z": 0.0})]
    assert _r(result, 1, 2, 3, 4, 5, 6, 7, 8) == [150.0, 55.0, 2000.0, 1.0, 1.0, 0.0, 100.0, 1.0]


@pytest.mark.parametrize("block, passes", [("G65 P10 X1.", 1), ("G65 P10 L3 X1.", 3),
                                           ("G65 L2 P0010 X1.", 2)])
def test_g65_l_is_the_number_of_passes(block, passes):
    """Digest iso-dialects-840d rank 14."""
    result = run_iso(block + "\nM30\n", {"O0010": READER})
    assert result.status == "ended", result.alarms
    assert _r(result, 5) == [float(passes)]


def test_g65_incremental_axis_argument_and_typ_prog():
    mac = "G290\nR1=$C_X_PROG R2=$C_F_PROG R3=$C_TYP_PROG R4=$C_ALL_PROG R5=$C_INC_PROG\nG291\nM99\n"
    result = run_iso("G91 G65 P10 X5 F20. A1.\nM30\n", {"O0010": mac})
    assert result.status == "ended", result.alarms
    bit = {letter: 1 << (ord(letter) - ord("A")) for letter in "AFX"}
    assert _r(result, 1, 2) == [3.0, 1.0]
    assert _r(result, 3) == [float(bit["F"] | bit["A"])]  # X5 is an INTEGER
    assert _r(result, 4, 5) == [float(bit["A"] | bit["F"] | bit["X"]), float(bit["A"] | bit["X"])]


def test_g65_ijk_arrays_and_order():
    mac = ("G290\nR1=$C_I[0] R2=$C_I[1] R3=$C_I_ORDER[1] R4=$C_J_NUM R5=$C_J[1] R6=$C_K_NUM\n"
           "R7=$C_K[2] R8=$C_K_ORDER[2] R9=$C_J_ORDER[1]\nG291\nM99\n")
    result = run_iso("N5 G65 P10 I10 J10 K30 J22 K55 I44 K33\nM30\n", {"O0010": mac})
    assert result.status == "ended", result.alarms
    assert _r(result, 1, 2, 3, 4, 5, 6, 7, 8, 9) == [10.0, 44.0, 3.0, 2.0, 22.0, 3.0, 33.0, 3.0, 2.0]


def test_arguments_are_local_to_the_called_level():
    mac = "G290\nR1=$C_X\nG291\nM99\n"
    after = "G290\nR2=$C_X\nG291\nM30\n"
    result = run_iso("G65 P10 X7.\n" + after, {"O0010": mac})
    assert result.status == "ended", result.alarms
    assert _r(result, 1, 2) == [7.0, 0.0]


def test_g66_calls_after_every_motion_block_only():
    """Digest iso-dialects-840d rank 14."""
    main = ("N10 G66 P10 X5.\nN20 G00 X50.\nN30 M03 S100\nN40 Y10.\nN50 G67\nN60 X0\nM30\n")
    result = run_iso(main, {"O0010": READER})
    assert result.status == "ended", result.alarms
    assert [line for line, _ in ends(result)] == [2, 4, 6]
    assert _r(result, 5) == [2.0]  # after N20 and N40, not after N10, N30 or N60
    assert _r(result, 1, 8) == [5.0, 50.0]  # the G66 arguments; called after the move


def test_new_g66_replaces_the_modal_call():
    main = "G66 P10 X1.\nG00 X1.\nG66 P11 X2.\nG00 X2.\nG67\nM30\n"
    other = "G290\nR9=R9+1 R10=$C_X\nG291\nM99\n"
    result = run_iso(main, {"O0010": READER, "O0011": other})
    assert result.status == "ended", result.alarms
    assert _r(result, 5, 9, 10) == [1.0, 1.0, 2.0]


def test_g66_l_passes_per_call():
    result = run_iso("G66 P10 L2 X5.\nG00 X1.\nG67\nM30\n", {"O0010": READER})
    assert result.status == "ended", result.alarms
    assert _r(result, 5) == [2.0]


def test_proc_macro_runs_in_siemens_mode():
    """Digest iso-dialects-840d rank 14."""
    proc = "PROC MAC10\nDEF REAL XA\nXA=$C_X+1\nG1 X=XA F100\nR6=$C_F\nM17\n"
    result = run_iso("G65 P10 X4. F200\nG00 Y1.\nM30\n", {"O0010": proc})
    assert result.status == "ended", result.alarms
    assert [point["X"] for _, point in ends(result)] == [5.0, 5.0]
    assert _r(result, 6) == [200.0]


def test_macro_without_proc_runs_in_iso_mode():
    """Digest iso-dialects-840d rank 14."""
    iso = "G00 X5. (an ISO comment)\nM99\n"
    result = run_iso("G65 P10 X4.\nM30\n", {"O0010": iso})
    assert result.status == "ended", result.alarms
    siemens_only = "G00 X5.\nDEF REAL A\nM99\n"
    result = run_iso("G65 P10 X4.\nM30\n", {"O0010": siemens_only})
    assert result.alarms[0].number == 12080


@pytest.mark.parametrize("block", ["G05 P1 M98 P21", "G65 P10 M98 P21", "G05 P3 G65 P10"])
def test_two_calls_in_one_block_raise_12722(block):
    """Digest iso-dialects-840d rank 14."""
    result = run_iso(block + "\nM30\n", {"O0010": READER, "O0021": "M99\n"})
    assert result.status == "alarm"
    assert result.alarms[0].number == 12722


def test_g05_p_calls_program_unpadded():
    result = run_iso("G05 P10123 L3\nM30\n", {"10123": "G91 G01 X1. F10\nM99\n"})
    assert result.status == "ended", result.alarms
    assert [point["X"] for _, point in ends(result)] == [1.0, 2.0, 3.0]


@pytest.mark.parametrize("block", ["G05 X1.", "G05 P1 X1.", "G05 P0 X1.", "G05.1 P1 X1."])
def test_g05_hsc_forms_are_skipped_and_the_words_run(block):
    result = run_iso(block + "\nM30\n")  # CYCLE305 is not part of this control
    assert result.status == "ended", result.alarms
    assert ends(result) == [(1, {"X": 1.0, "Y": 0.0, "Z": 0.0})]


def test_g05_p_call_runs_the_block_words_first():
    result = run_iso("G05 P10123 Y2.\nM30\n", {"10123": "G00 X1.\nM99\n"})
    assert result.status == "ended", result.alarms
    assert [point for _, point in ends(result)] == [{"X": 0.0, "Y": 2.0, "Z": 0.0},
                                                    {"X": 1.0, "Y": 2.0, "Z": 0.0}]


def test_g65_without_p_or_with_five_digits_is_rejected():
    assert run_iso("G65 X1.\nM30\n").alarms[0].number == 12080
    assert run_iso("G65 P12345\nM30\n").alarms[0].number == 12080
    assert run_iso("G65 P10.\nM30\n").alarms[0].number == 12080


def test_macro_program_missing_raises_14011():
    assert run_iso("G65 P77\nM30\n").alarms[0].number == 14011


def test_c_variables_are_read_only_in_siemens_mode():
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF",
                            text="$C_X=5\nM30\n", max_blocks=10)
    assert result.alarms[0].number == 17070


def test_translation_of_a_g65_block():
    (line,) = translate("N30 G65 P10 F55 X150.")
    assert len(line.blocks) == 1
    block = line.blocks[0]
    assert block.startswith("N30 ") and block.endswith('CALL "O0010"')
    assert "$C_F=55" in block and "$C_X=150" in block


def _modes_per_block(text: str, programs: dict[str, str]) -> list[tuple[str, str]]:
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    interp = Interpreter(load_machine(None), MemorySource(programs), NcData(), dialect=dialect_for("iso-m", load_machine(None)))
    interp.start_text("T.MPF", text)
    seen = []  # (program of the next block, language mode it runs in)
    while not interp.finished:
        seen.append((interp.current_source().file, interp.modal.gcodes.get(47)))
        interp.step()
    return seen


def test_proc_macro_switches_to_siemens_mode_and_back():
    proc = "PROC MAC10\nR1=1\nM17\n"
    seen = _modes_per_block("G65 P10 X1.\nG00 X1.\nM30\n", {"O0010": proc})
    assert {mode for name, mode in seen if name == "O0010"} == {"G290"}
    assert seen[-2:] == [("T.MPF", "G291")] * 2  # the blocks after the macro: ISO mode again


def test_iso_macro_stays_in_iso_mode_and_c_writes_need_iso_mode():
    seen = _modes_per_block("G65 P10 X1.\nM30\n", {"O0010": "G00 X1.\nM99\n"})
    assert {mode for name, mode in seen if name == "O0010"} == {"G291"}
    # in a Siemens-mode macro $C_… stays read-only (a further G65 needs G291 first)
    result = run_iso("G65 P10 X1.\nM30\n", {"O0010": "PROC MAC10\n$C_X=3\nM17\n"})
    assert result.alarms[0].number == 17070


def test_m98_of_a_proc_program_also_switches_and_returns_at_end_of_file():
    seen = _modes_per_block("M98 P21\nG00 X1.\nM30\n", {"O0021": "PROC SUB21\nR2=1\n"})
    assert {mode for name, mode in seen if name == "O0021"} == {"G290"}
    assert seen[-2:] == [("T.MPF", "G291")] * 2


# ---------------------------------------------------------------- the manual's examples, rebuilt
MAIN_M10 = ("N10 M3 S1000 F1000\nN20 X100. Y50. Z33.\nN30 G65 P10 F55 X150. Y100. S2000\n"
            "N40 X50.\nN200 M30\n")


def test_manual_macro_in_siemens_mode():
    macro = ("PROC MAC10\nN10 DEF REAL X_AXIS, Y_AXIS, SPEED, FEEDRATE\n"
             "N15 X_AXIS=$C_X Y_AXIS=$C_Y SPEED=$C_S FEEDRATE=$C_F\n"
             "N20 G01 F=FEEDRATE G95 S=SPEED\nN25 X=X_AXIS Y=Y_AXIS\nN80 M17\n")
    result = run_iso(MAIN_M10, {"O0010": macro})
    assert result.status == "ended", result.alarms
    assert ends(result) == [(2, {"X": 100.0, "Y": 50.0, "Z": 33.0}),
                            (5, {"X": 150.0, "Y": 100.0, "Z": 33.0}),
                            (4, {"X": 50.0, "Y": 100.0, "Z": 33.0})]
    feed_move = result.segments[1]
    assert feed_move.kind == "G1" and feed_move.source.file == "O0010"


def test_manual_macro_in_iso_mode_with_a_siemens_section():
    macro = ("G290\nN15 R10=$C_X R11=$C_Y R12=$C_S\nN20 G01 F=$C_F S=$C_S\n"
             "N10 G1 X=$C_X Y=$C_Y\nG291\nN15 M3 G54\nN80 M99\n")
    result = run_iso(MAIN_M10, {"O0010": macro})
    assert result.status == "ended", result.alarms
    assert [point for _, point in ends(result)][1:] == [{"X": 150.0, "Y": 100.0, "Z": 33.0},
                                                        {"X": 50.0, "Y": 100.0, "Z": 33.0}]
    assert [result.interpreter.r(n) for n in (10, 11, 12)] == [150.0, 100.0, 2000.0]


def test_manual_typ_prog_of_m98_arguments():
    sub = "G290\nR1=$C_TYP_PROG R2=$C_X R3=$C_Y\nG291\nM99\n"
    result = run_iso("M98 P21 Y100. X100\nM30\n", {"O0021": sub})
    assert result.status == "ended", result.alarms
    assert [result.interpreter.r(n) for n in (1, 2, 3)] == [float(1 << 24), 100.0, 100.0]
    assert ends(result) == [(1, {"X": 100.0, "Y": 100.0, "Z": 0.0})]  # the words move first


# ---------------------------------------------------------------- M- and G-code macros (MD 10814–10817)
MACRO_MD = {"MD10814": [101, 6, 30], "MD10815": ["M101_MACRO", "M6_MACRO", "M30_MACRO"],
            "MD10816": [21, 123, 421], "MD10817": ["G21_MACRO", "G123_MACRO", "G123_MACRO"]}


def _run_md(text: str, programs: dict[str, str]):
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData, ToolEdge
    machine = load_machine(None)
    machine.md.update(MACRO_MD)
    data = NcData()
    data.tools[(2, 1)] = ToolEdge({1: 120.0})  # T2 needs its data set (17191, 002 L58219)
    return interpret_only(machine, MemorySource(programs), data, "T.MPF", dialect="iso-m",
                          text=text, max_blocks=2000)


def test_m_code_macro_gets_arguments_and_its_own_m_stays_an_m_function():
    from nck import canon
    m6 = "G290\nR10=R10+11.11 R1=$C_X_PROG R2=$C_V\nG291\nM6\nM99\n"
    result = _run_md("T2\nN10 M6 X10. V20.\nM30\n", {"M6_MACRO": m6})
    assert result.status == "ended", result.alarms
    assert ends(result) == []  # X and V are arguments, not moves
    assert [result.interpreter.r(n) for n in (1, 2, 10)] == [1.0, 20.0, 11.11]
    changes = [c for c in result.commands if isinstance(c, canon.ToolSelect) and c.change]
    assert [(c.source.file, c.tool) for c in changes] == [("M6_MACRO", 2)]  # M6 inside: no recursion


def test_m_code_macro_l_passes_and_fixed_m_functions_are_never_replaced():
    counter = "G290\nR5=R5+1\nG291\nM99\n"
    result = _run_md("M101 L3\nM30\n", {"M101_MACRO": counter, "M30_MACRO": counter})
    assert result.status == "ended", result.alarms
    assert result.interpreter.r(5) == 3.0  # and M30 ended the program (M30 is fixed)


def test_g_code_macro_runs_other_g_codes_first_and_sets_c_g():
    g123 = "G290\nR3=$C_G R4=$C_X R6=$P_GG[1]\nG291\nG21 X100.\nM99\n"
    result = _run_md("G94 F500\nN100 G1 G123 X10. Y20. G90\nM30\n", {"G123_MACRO": g123})
    assert result.status == "ended", result.alarms
    assert [result.interpreter.r(n) for n in (3, 4)] == [123.0, 10.0]
    assert result.interpreter.r(6) == 2.0  # G1 (position 2 in group 1) was active in the macro
    assert ends(result) == [(4, {"X": 100.0, "Y": 0.0, "Z": 0.0})]  # G21 inside: metric, no call
    assert result.segments[0].source.file == "G123_MACRO"


def test_two_g_codes_on_one_macro_and_decimal_c_g():
    result = _run_md("N100 G421 X10.\nM30\n", {"G123_MACRO": "G290\nR3=$C_G\nG291\nM99\n"})
    assert result.status == "ended", result.alarms
    assert result.interpreter.r(3) == 421.0


def test_macro_only_g_code_inside_a_macro_raises_12470():
    g123 = "G290\nR3=1\nG291\nG123\nM99\n"
    result = _run_md("G123 X1.\nM30\n", {"G123_MACRO": g123})
    assert result.alarms[0].number == 12470
    assert result.alarms[0].file == "G123_MACRO"


@pytest.mark.parametrize("block", ["M6 M101", "G123 M6", "M6 M98 P21", "G65 P10 M101"])
def test_two_substitutions_or_calls_in_one_block_raise_12722(block):
    result = _run_md(block + "\nM30\n", {})
    assert result.alarms[0].number == 12722


def test_without_the_machine_data_m6_is_a_plain_m_function():
    data = NcData()
    data.tools[(2, 1)] = ToolEdge({1: 120.0})  # T2 needs its data set (17191, 002 L58219)
    result = run_iso("T2 M6\nM30\n", data=data)
    assert result.status == "ended", result.alarms
    assert result.interpreter.modal.tool == 2


@pytest.mark.parametrize("head", ["PROC 0010", "PROC O0010", "N5 PROC 0010"])
def test_proc_with_the_program_number_as_name_runs_in_siemens_mode(head):
    macro = head + "\nDEF REAL XA\nXA=$C_X*2\nG1 X=XA F100\nM17\n"
    result = run_iso("G65 P10 X4.\nM30\n", {"O0010": macro})
    assert result.status == "ended", result.alarms
    assert ends(result) == [(4, {"X": 8.0, "Y": 0.0, "Z": 0.0})]
    assert result.segments[0].source.file == "O0010"


def _iso_views(text: str, programs: dict[str, str], **md) -> list[tuple[str, int, dict[int, str]]]:
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData, ToolEdge
    machine = load_machine(None)
    machine.md.update(md)
    interp = Interpreter(machine, MemorySource(programs), NcData(), dialect=dialect_for("iso-m", machine))
    interp.start_text("T.MPF", text)
    views = []
    while not interp.finished:
        source = interp.current_source()
        interp.step()
        views.append((source.file, source.line, interp.modal_view().iso_gcodes))
    return views


def test_g_group_display_shows_g66_and_g43():
    text = ("G290\n$TC_DP1[2,1]=120 $TC_DP3[2,1]=10\nG291\nT2\nG43 H1 Z0\nG66 P10 X1.\n"
            "G00 X5.\nG67\nG49 Z0\nM30\n")
    views = {(f, line): view for f, line, view in _iso_views(text, {"O0010": "M99\n"},
                                                              MD22550=0, MD20270=0)}
    main = {line: view for (f, line), view in views.items() if f == "T.MPF"}
    assert main[4][8] == "G49" and main[5][8] == "G43"
    assert main[5][12] == "G67" and main[6][12] == "G66" and main[7][12] == "G66"
    assert views[("O0010", 1)][12] == "G66"  # still shown while the macro runs
    assert main[8][12] == "G67" and main[9][8] == "G49"
