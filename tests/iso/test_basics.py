"""ISO M: activation, lexing, decimal point, coordinates, zero offsets, dwell."""

from __future__ import annotations

import pytest

from nck.iso.dialect import dialect_for
from nck.iso.lexing import split_words, strip_comments
from nck.iso.translate import IsoSettings, translate
from tests.iso.conftest import ends, run_iso


def test_iso_program_starts_in_g00():
    result = run_iso("X10. Y5.\nM30\n")
    assert result.status == "ended", result.alarms
    assert result.segments[0].kind == "G0"
    assert ends(result)[0][1]["X"] == 10.0


def test_same_text_in_siemens_mode_differs():
    """The program-level G00 start is ISO only (Siemens resets to G1 and needs F)."""
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF",
                            text="X10 Y5\nM30\n", max_blocks=1000)
    assert result.status == "alarm"


def test_nested_comments_hide_words():
    """Digest iso-dialects-840d rank 4 (000 L1688-1690).

    Digest iso-milling-828d rank 4.
    """
    assert strip_comments("N15 (c(c) X100) Y100").split() == ["N15", "Y100"]
    result = run_iso("N15 (a(b) X100) Y100\nM30\n")
    assert ends(result) == [(1, {"X": 0.0, "Y": 100.0, "Z": 0.0})]


def test_comment_then_words_both_run():
    """Digest iso-milling-828d rank 4."""
    result = run_iso("N10 (c(c)) X100 Y100\nM30\n")
    assert ends(result)[0][1] == {"X": 100.0, "Y": 100.0, "Z": 0.0}


def test_slash_in_comment_is_ignored():
    """Digest iso-dialects-840d rank 4.

    Digest iso-milling-828d rank 5.
    """
    result = run_iso("X100. ( /3 ) Y100\nM30\n", skip_levels=frozenset({3}))
    assert ends(result)[0][1] == {"X": 100.0, "Y": 100.0, "Z": 0.0}


def test_mid_block_skip_discards_rest_when_level_active():
    """Digest iso-dialects-840d rank 4 (000 L1679-1716).

    Digest iso-milling-828d rank 5.
    """
    skip, words = split_words("N5 G00 X100. /3 YY100", frozenset({3}))
    assert [w.letter for w in words] == ["N", "G", "X"]


def test_mid_block_skip_off_reads_garbage_as_syntax_error():
    """Digest iso-dialects-840d rank 4 (level off: 12080).

    Digest iso-milling-828d rank 5.
    """
    result = run_iso("N5 G00 X100. /3 YY100\nM30\n")
    assert result.status == "alarm" and result.alarms[0].number == 12080


@pytest.mark.parametrize("text", ["/0 X1", "/10 X1"])
def test_skip_level_out_of_range_is_14060(text):
    """Digest iso-dialects-840d rank 4 (/0, /10: 14060).

    Digest iso-milling-828d rank 5.
    """
    result = run_iso(text + "\nM30\n")
    assert result.alarms[0].number == 14060


def test_block_skip_at_start_skips_block():
    result = run_iso("/1 X50.\nY7.\nM30\n", skip_levels=frozenset({1}))
    assert ends(result) == [(2, {"X": 0.0, "Y": 7.0, "Z": 0.0})]


@pytest.mark.parametrize("text", ["N10 WAIT", "N15 G91 G500", "R1=5"])
def test_siemens_syntax_in_iso_mode_is_12080_or_unknown_g(text):
    result = run_iso(text + "\nM30\n")
    assert result.status == "alarm"
    assert result.alarms[0].number in (12080, 12470)


def test_program_number_line_is_ignored():
    result = run_iso("O0012 (part)\nG91 X1.\nM30\n")
    assert ends(result)[0][1]["X"] == 1.0


def _first_x(text: str, settings: IsoSettings) -> str:
    return translate(text, settings=settings)[0].blocks[0]


def test_decimal_point_rules():
    """Digest iso-dialects-840d rank 1 (000 L987-1050).

    Digest iso-milling-828d rank 3 (003 decimal point table).
    """
    standard = IsoSettings(pocket_calculator=False)
    assert _first_x("G90 G01 X1000 Y2000. F100", standard) == "G90 G1 X1 Y2000 F100"
    is_c = IsoSettings(pocket_calculator=False, increment_system_c=True)
    assert _first_x("G90 G01 X1000 Y2000. F100", is_c) == "G90 G1 X0.1 Y2000 F100"
    assert _first_x("G90 G01 X1000 Y2000. F100", IsoSettings()) == "G90 G1 X1000 Y2000 F100"
    assert _first_x("G95 F20", standard) == "G95 F0.2"
    assert _first_x("G94 F100", standard) == "G94 F100"


def test_dwell_units():
    standard = IsoSettings(pocket_calculator=False)
    assert _first_x("G04 X1000", standard) == "G4 F1"
    assert _first_x("G04 X1.", standard) == "G4 F1"
    assert _first_x("G04 P1000", standard) == "G4 F1"
    assert _first_x("G04 P1000", IsoSettings()) == "G4 F1"


def test_inch_metric_map_to_g700_g710():
    assert _first_x("G20 X1.", IsoSettings()) == "G700 X1"
    assert _first_x("G21", IsoSettings()) == "G710"


def test_arc_with_radius_and_centre():
    result = run_iso("G17 G90 G0 X0 Y0\nG02 X20. Y0 R10. F100\nG03 X0 Y0 I-10. J0\nM30\n")
    assert result.status == "ended", result.alarms
    arcs = result.segments[1:]
    assert [a.kind for a in arcs] == ["G2", "G3"]
    assert round(arcs[0].center_wcs["X"], 3) == 10.0
    assert round(arcs[1].center_wcs["X"], 3) == 10.0


def test_incremental_g91():
    result = run_iso("G91 G01 X10. F100\nX10.\nM30\n")
    assert [e[1]["X"] for e in ends(result)] == [10.0, 20.0]


def test_e2_zero_offsets_g10_g54_g92_g921():
    """Digest iso-dialects-840d rank 5 (E2, 000 L4502-4518)."""
    text = ("N10 G10 L2 P1 X10 Y10\nN20 G0 X100 Y100\nN30 G54 X100 Y100\nN40 G92 X50 Y50\n"
            "N50 G0 X100 Y100\nN60 G92.1 X0 Y0\nN70 X150. Y150.\nM30\n")
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    wcs, mcs = ends(result), ends(result, "mcs")
    assert mcs[0][1]["X"] == 100.0 and wcs[0][1]["X"] == 100.0
    assert mcs[1][1]["X"] == 110.0 and wcs[1][1]["X"] == 100.0
    assert mcs[2][1]["X"] == 160.0 and wcs[2][1]["X"] == 100.0
    # after G92.1 the WCS falls back to G54: WCS 150 is MCS 160 again
    assert wcs[3][1]["X"] == 150.0 and mcs[3][1]["X"] == 160.0


def test_e2_first_part_g92_preset():
    """Digest iso-dialects-840d rank 5 (E2)."""
    text = "N10 G0 X100 Y100\nN20 G92 X10 Y10\nN30 G0 X50 Y50\nN40 G92.1 X0 Y0\nN50 X140. Y140.\nM30\n"
    result = run_iso(text)
    mcs, wcs = ends(result, "mcs"), ends(result)
    assert mcs[1][1]["X"] == 140.0 and wcs[1][1]["X"] == 50.0
    assert wcs[2][1]["X"] == 140.0 and mcs[2][1]["X"] == 140.0


def test_g52_local_offset():
    result = run_iso("G52 X5. Y5.\nG0 X10. Y10.\nM30\n")
    assert ends(result, "mcs")[0][1]["X"] == 15.0


def test_g290_switches_to_siemens_and_g291_back():
    """Digest iso-milling-828d rank 6 (G291 switches; T, D/H and G54 kept)."""
    text = "G91\nG290\nR1=5\nG291\nG01 X1. F100\nM30\n"
    result = run_iso(text)
    assert result.status == "ended", result.alarms
    assert ends(result)[0][1]["X"] == 1.0


def test_siemens_program_switches_with_g291():
    """Digest iso-dialects-840d rank 2 (Siemens start, G291 switches)."""
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    text = "G1 X1 F100\nG291\nG00 X5.\nG290\nR1=2\nM30\n"
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF", text=text,
                            max_blocks=1000)
    assert result.status == "ended", result.alarms
    assert [m.kind for m in result.segments] == ["G1", "G0"]


def _step_views(text: str, dialect: str = "iso-m"):
    """(source line, iso_gcodes, Siemens gcodes) after every block, stepping the interpreter."""
    from nck.interp.interpreter import Interpreter
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    interp = Interpreter(load_machine(None), MemorySource(), NcData(), dialect=dialect_for(dialect, load_machine(None)))
    interp.start_text("T.MPF", text)
    views = []
    while not interp.finished:
        result = interp.step()
        view = interp.modal_view()
        views.append((result.source.line, dict(view.iso_gcodes), dict(view.gcodes)))
    return views


def test_g_group_display_shows_iso_codes_in_iso_mode():
    views = _step_views("G91 G01 X1. F100\nG290\nG1 X1\nG291\nG00 X2.\nM30\n")
    by_line = {line: (iso, siemens) for line, iso, siemens in views}
    iso, siemens = by_line[1]
    assert iso[1] == "G01" and iso[3] == "G91" and iso[2] == "G17" and iso[31] == "G291"
    assert iso[8] == "G49" and iso[9] == "G80"
    # after G290 the Siemens table is shown, with the shared G91
    iso, siemens = by_line[3]
    assert iso == {} and siemens[14] == "G91" and siemens[47] == "G290"
    iso, _ = by_line[5]
    assert iso[1] == "G00" and iso[3] == "G91"


def test_iso_t_defaults_in_display():
    """Digest iso-dialects-840d rank 2 (ISO T, 000 L5032-5050)."""
    views = _step_views("G00 X1.\nM30\n", "iso-t")
    iso = views[0][1]
    assert iso[16] == "G18" and iso[31] == "G291"


def test_hmi_g_functions_line_lists_iso_groups():
    from hmi.widgets.gfunctions import all_groups_table, main_groups_line
    from nck.iso.display import ISO_MAIN_GROUPS_M, iso_gcodes, iso_table
    view = iso_gcodes({1: "G1", 6: "G17", 14: "G91", 15: "G94", 13: "G710", 7: "G41", 8: "G55"})
    line = main_groups_line(view, ISO_MAIN_GROUPS_M).plain.split()
    assert line[2:] == ["G01", "G17", "G91", "G94", "G21", "G41", "G49", "G55"]
    table = all_groups_table(view, iso_table("iso-m")[1])
    assert table.row_count > 5


@pytest.mark.parametrize("md, expected_x", [({}, 100.0), ({"MD10884": False}, 0.1),
                                            ({"MD10884": False, "MD10886": 1}, 0.01)])
def test_machine_data_choose_decimal_point_notation(md, expected_x):
    """Digest iso-dialects-840d rank 1."""
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    machine = load_machine(None)
    machine.md.update(md)
    result = interpret_only(machine, MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text="G90 G01 X100 Y20. F100\nM30\n", max_blocks=1000)
    assert result.status == "ended", result.alarms
    assert ends(result)[0][1] == {"X": expected_x, "Y": 20.0, "Z": 0.0}


def test_cli_runs_iso_dialect(tmp_path, capsys):
    from nck.cli import main
    program = tmp_path / "ISO1.MPF"
    program.write_text("G91 G01 X5. F200\nM30\n")
    assert main(["run", str(program), "--dialect", "iso-m", "--segments", "-"]) == 0
    assert '"X": 5.0' in capsys.readouterr().out


def test_g54_1_needs_p_and_g54_p_selects_extended_offset():
    """Digest iso-dialects-840d rank 5 (G54.1 without P: 12080)."""
    assert run_iso("G54.1 X1.\nM30\n").alarms[0].number == 12080
    assert translate("G54 P1 X1.")[0].blocks == ["G507 X1"]
    assert translate("G54.1 P2 X1.")[0].blocks == ["G508 X1"]


def test_g53_incremental_values_are_skipped():
    """Digest iso-dialects-840d rank 5 (G53 G91 X10 does not move)."""
    result = run_iso("G0 X5.\nG53 G91 X10.\nM30\n")
    assert [e[1]["X"] for e in ends(result)] == [5.0]


def test_feed_and_arc_guards():
    """Digest iso-dialects-840d rank 8 (10860 after G94->G95; G02 without R/IJK is an alarm)."""
    assert run_iso("G02 X10. Y10. F100\nM30\n").status == "alarm"
    result = run_iso("G94 G01 X10. F100\nG95 X20.\nM30\n")
    assert result.alarms[0].number == 10860


def test_m99_in_main_program_restarts_it():
    from nck.headless import interpret_only
    from nck.interp.sources import MemorySource
    from nck.machine import load_machine
    from nck.ncdata import NcData
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text="G91 G01 X1. F100\nM99\n", max_blocks=40)
    assert result.status != "ended"
    assert len(result.segments) > 3


@pytest.mark.parametrize("word, expected", [("T0102", "T1 D2"), ("T1234", "T12 D34"),
                                            ("T123", "T12 D3")])
def test_iso_t_tool_word_splits_tool_and_offset(word, expected):
    assert translate(word, "iso-t")[0].blocks == [expected]


def test_e1_language_switch_keeps_modal_state():
    """Digest iso-dialects-840d rank 3 (E1, 000 L768-777)."""
    text = ("N5  G00 X100. Y100.\nN10 G90           ;ISO G90\nN15 G290         ;Siemens\n"
            "N20 G91\nN25 G291\nN30 G291\nM30\n")
    views = {line: (iso, siemens) for line, iso, siemens in _step_views(text)}
    assert views[3][0] == {} and views[3][1][14] == "G90"
    assert views[4][1][14] == "G91"
    assert views[5][0][3] == "G91" and views[6][0][3] == "G91"


def test_g28_goes_via_intermediate_point_to_reference():
    """Digest iso-milling-828d rank 12."""
    result = run_iso("G0 X10. Y10. Z10.\nG28 Z20.\nM30\n")
    assert result.status == "ended", result.alarms
    assert [e[1]["Z"] for e in ends(result, "mcs")] == [10.0, 20.0, 0.0]
    assert ends(result, "mcs")[-1][1]["X"] == 10.0
