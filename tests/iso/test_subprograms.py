"""ISO subprograms (section 9 item 7): M98 counts, M99 P return target, M99 in a main
program, M30 in a subprogram, M98/M99 never output to the PLC."""

from __future__ import annotations

from nck import canon
from nck.headless import interpret_only
from nck.interp.sources import MemorySource
from nck.iso.translate import translate
from nck.machine import load_machine
from nck.ncdata import NcData

from tests.iso.conftest import ends, run_iso

STEP_SUB = "G91 G01 X1. F100\nM99\n"


def _xs(result):
    return [point["X"] for _, point in ends(result)]


def test_m98_count_in_p_runs_three_times():
    """Digest iso-dialects-840d rank 7 (000 L1920-2012)."""
    result = run_iso("M98 P30021\nM30\n", {"O0021": STEP_SUB})
    assert result.status == "ended", result.alarms
    assert _xs(result) == [1.0, 2.0, 3.0]


def test_m98_l_count_and_l_over_p_digits():
    """Digest iso-dialects-840d rank 7."""
    assert _xs(run_iso("M98 P55 L4\nM30\n", {"O0055": STEP_SUB})) == [1.0, 2.0, 3.0, 4.0]
    assert _xs(run_iso("M98 P30077 L2\nM30\n", {"O0077": STEP_SUB})) == [1.0, 2.0]


def test_m98_is_one_call_with_passes():
    assert translate("M98 P30021")[0].blocks == ['CALL "O0021" P3']
    assert translate("N20 M98 P21")[0].blocks == ['N20 CALL "O0021"']


def test_m99_p_resumes_at_block_of_caller_forward():
    """Digest iso-dialects-840d rank 7."""
    main = ("N10 G90 G00 X0 Y0\nN20 M98 P21\nN30 X30.\nN40 Y40.\nN50 M30\n")
    sub = "G90 G00 X5.\nM99 P40\n"
    result = run_iso(main, {"O0021": sub})
    assert result.status == "ended", result.alarms
    moves = [(line, point["X"], point["Y"]) for line, point in ends(result)]
    assert moves == [(1, 0.0, 0.0), (1, 5.0, 0.0), (4, 5.0, 40.0)]  # N30 skipped


def test_m99_p_searches_backward_when_not_ahead():
    """Digest iso-dialects-840d rank 7."""
    main = "N10 G90 G00 X0\nN15 Y1.\nN20 M98 P21\nN30 X30.\nN40 M30\n"
    # the sub counts its calls in R1: the first return jumps back to N15, the second goes on
    sub = ("G290\nR1=R1+1\nIF R1>1 GOTOF DONE\nRET(\"N15\")\nDONE:\nM17\n")
    result = run_iso(main, {"O0021": sub})
    assert result.status == "ended", result.alarms
    assert [line for line, _ in ends(result)] == [1, 2, 2, 4]
    assert result.interpreter.r(1) == 2


def test_m99_p_with_unknown_block_raises_14080():
    result = run_iso("N10 M98 P21\nN20 X1.\nM30\n", {"O0021": "M99 P77\n"})
    assert result.status == "alarm"
    assert result.alarms[0].number == 14080


def test_m99_p_ends_remaining_passes():
    main = "N10 M98 P30021\nN20 X50.\nN30 M30\n"
    result = run_iso(main, {"O0021": "G91 G01 X1. F100\nM99 P30\n"})
    assert result.status == "ended", result.alarms
    assert _xs(result) == [1.0]  # one pass, then N30 (N20 skipped)


def test_m99_in_main_program_restarts_it():
    """Digest iso-dialects-840d rank 7."""
    result = interpret_only(load_machine(None), MemorySource(), NcData(), "T.MPF", dialect="iso-m",
                            text="G91 G01 X1. F100\nM99\n", max_blocks=40)
    assert result.status == "timeout"
    assert len(result.segments) > 5
    assert _xs(result)[:3] == [1.0, 2.0, 3.0]


def test_m99_p_in_main_program_jumps():
    result = run_iso("N10 G00 X1.\nN20 M99 P40\nN30 X30.\nN40 Y4.\nM30\n")
    assert result.status == "ended", result.alarms
    assert [line for line, _ in ends(result)] == [1, 4]


def test_m30_in_iso_subprogram_ends_the_whole_program():
    """Digest iso-dialects-840d rank 7."""
    main = "N10 M98 P21\nN20 G00 X99.\nN30 M30\n"
    result = run_iso(main, {"O0021": "G00 X5.\nM30\n"})
    assert result.status == "ended", result.alarms
    assert _xs(result) == [5.0]  # N20 never runs
    assert result.interpreter.finished
    ends_ = [c for c in result.commands if isinstance(c, canon.ProgramEnd)]
    assert [e.source.file for e in ends_] == ["O0021"]


def test_m30_in_siemens_mode_subprogram_only_returns():
    main = "N10 M98 P21\nN20 G00 X99.\nN30 M30\n"
    result = run_iso(main, {"O0021": "PROC SUB21\nG0 X5\nM30\n"})
    assert result.status == "ended", result.alarms
    assert _xs(result) == [5.0, 99.0]


def test_m98_m99_not_output_to_plc():
    """Digest iso-dialects-840d rank 7."""
    main = "M98 P21\nM03 S1000\nM30\n"
    result = run_iso(main, {"O0021": "G00 X1.\nM08\nM99\n"})
    assert result.status == "ended", result.alarms
    aux = [c for c in result.commands if isinstance(c, canon.AuxFunction)]
    values = {(c.address, int(c.value)) for c in aux}
    assert ("M", 8) in values
    assert not {("M", 98), ("M", 99)} & values


def test_manual_repeat_count_examples():
    """N20 M98 P20123 twice, N40 M98 P55 L4 four times, N60 M98 P30077 L2 twice."""
    main = "N20 M98 P20123\nN40 M98 P55 L4\nN60 M98 P30077 L2\nM30\n"
    subs = {f"O{n:04d}": f"G91 G01 X{n}. F1000\nM99\n" for n in (123, 55, 77)}
    result = run_iso(main, subs)
    assert result.status == "ended", result.alarms
    steps = [(m.source.file, round(m.end_mcs["X"] - m.start_mcs["X"], 3)) for m in result.segments]
    assert steps == [("O0123", 123.0)] * 2 + [("O0055", 55.0)] * 4 + [("O0077", 77.0)] * 2


def test_m98_block_words_move_before_the_call():
    result = run_iso("G00 X0\nM98 P21 X10.\nM30\n", {"O0021": "G00 Y5.\nM99\n"})
    assert result.status == "ended", result.alarms
    assert [point for _, point in ends(result)][1:] == [{"X": 10.0, "Y": 0.0, "Z": 0.0},
                                                        {"X": 10.0, "Y": 5.0, "Z": 0.0}]
