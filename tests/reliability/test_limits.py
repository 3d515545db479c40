"""Limits of the language, each ending with its SINUMERIK alarm through the whole kernel."""

from __future__ import annotations

import subprocess
import sys
import tracemalloc

import pytest

from nck.interp.program import load_program
from tests.reliability.harness import run_hostile

LIMITS = {
    # control structures nested deeper than the interpreter allows
    "if_nesting_40": ("\n".join(["R1=1", *["IF R1==1"] * 40, "R2=1", *["ENDIF"] * 40, "M30"]), 12641),
    "while_nesting_20": ("\n".join([*["WHILE R1<1"] * 20, "R1=1", *["ENDWHILE"] * 20, "M30"]), 12641),
    # endless recursion of a subprogram: too many program levels
    "recursion": ("SELF\nM30\n", 14012),
    # huge numbers, NaN and infinity
    "overflow_product": ("R1=1EX300*1EX300\nM30\n", 14051),
    "ln_of_zero": ("R1=LN(0)\nM30\n", 14051),
    "sqrt_negative_nan": ("R1=SQRT(-1)\nM30\n", 14051),
    "square_overflow": ("R1=POT(1EX200)\nM30\n", 14051),
    "division_by_zero": ("R1=1/0\nM30\n", 14051),
    "infinite_feed": ("G1 X10 F=1EX300*1EX300\nM30\n", 14051),
    "literal_too_many_digits": ("R1=" + "9" * 400 + "\nM30\n", 12160),
    "axis_beyond_everything": ("G0 X1EX300\nM30\n", 10720),
    "r_index_huge": ("R[1EX20]=1\nM30\n", 17020),
    "tool_number_huge": ("T99999999999 M6\nM30\n", 12160),
    "pass_count_huge": ("L77 P99999999\nM30\n", 14013),
    # array sizes and string lengths
    "string_over_200": ("DEF STRING[300] TXT\nM30\n", 12160),
    # block length and nesting of expressions
    "block_over_512": ("R1=" + "+1" * 300 + "\nM30\n", 12540),
    "parentheses_5000": ("R1=" + "(" * 5000 + "1" + ")" * 5000 + "\nM30\n", 12540),
    "parentheses_unbalanced": ("R1=" + "(" * 5000 + "\nM30\n", 12540),
    "functions_nested_3000": ("R1=" + "SIN(" * 3000 + "1" + ")" * 3000 + "\nM30\n", 12540),
    "label_1000_chars": ("L" * 1000 + ": M30\n", 12540),
    "nul_character": ("R1=1\x00\nM30\n", 12080),
}


@pytest.mark.parametrize("name", sorted(LIMITS))
def test_limit_ends_with_its_alarm(name: str) -> None:
    text, number = LIMITS[name]
    result = run_hostile(text, sim_budget_s=5.0)
    assert result.status == "alarm"
    assert [a.number for a in result.alarms][:1] == [number]


@pytest.mark.parametrize("declaration", ["DEF REAL VALS[100000000]", "DEF REAL VALS[10000,10000,10000]",
                                         "DEF REAL VALS[-1]", "DEF INT CNT[0]"])
def test_absurd_array_sizes_are_refused_without_allocating(declaration: str) -> None:
    tracemalloc.start()
    try:
        result = run_hostile(f"{declaration}\nM30\n", sim_budget_s=5.0)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert result.status == "alarm" and result.alarms
    assert peak < 50_000_000


def test_string_assignment_longer_than_declared_is_an_alarm() -> None:
    result = run_hostile('DEF STRING[5] TXT\nTXT="abcdefghij"\nM30\n')
    assert result.status == "alarm" and result.alarms


def test_doubling_a_string_forever_ends_with_an_alarm() -> None:
    result = run_hostile('DEF STRING[200] TXT\nTXT="a"\nLBL: TXT=TXT<<TXT\nGOTOB LBL\nM30\n')
    assert result.status == "alarm" and result.alarms


def test_endless_loop_without_motion_ends_at_the_simulated_time_budget() -> None:
    result = run_hostile("LBL: R1=R1+1\nGOTOB LBL\nM30\n", sim_budget_s=2.0)
    assert result.status == "timeout" and result.exit_code == 3
    assert result.machine_time_s == pytest.approx(2.0, abs=0.1)


def test_endless_dwell_ends_at_the_time_budget() -> None:
    result = run_hostile("G4 F1EX30\nM30\n", sim_budget_s=2.0)
    assert result.status == "timeout"


def test_a_comment_longer_than_the_block_limit_is_allowed() -> None:
    """Only the program code counts towards the 512 characters; comments are stripped first."""
    result = run_hostile("R1=1 ;" + "x" * 100_000 + "\nM30\n")
    assert result.status == "ended"


def _load_peak_bytes(lines: int) -> int:
    text = "".join(f"N{i} R1=R1+1\n" for i in range(lines)) + "M30\n"
    tracemalloc.start()
    try:
        program = load_program("BIG.MPF", text, main=True)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    del program
    return peak


def test_program_memory_does_not_grow_with_its_length() -> None:
    small, large = _load_peak_bytes(2_000), _load_peak_bytes(8_000)
    assert large < 2 * small


def test_a_million_line_program_is_scanned_not_kept_as_syntax_trees() -> None:
    """Loading a 1,000,000-line program adds a small index to its text (measured in a fresh process).

    The text is built in chunks before the baseline is taken; parsed syntax trees
    (one per line) would add ~800 MB.
    """
    script = (
        "import resource\n"
        "from nck.interp.program import load_program\n"
        "chunks = [''.join(f'N{i} G1 X{i % 100}.5 Y-{i % 7} F500\\n' for i in range(k, k + 10_000))\n"
        "          for k in range(0, 1_000_000, 10_000)]\n"
        "text = ''.join(chunks) + 'R1=R1+1\\nM30\\n'\n"
        "del chunks\n"
        "base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
        "program = load_program('MILLION.MPF', text, main=True)\n"
        "assert len(program.lines) == 1_000_002 and program.lines[999_999].block.number == 999_999\n"
        "assert not program.problems() and program.plain_run_end(0) == 1_000_000\n"
        "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - base)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout) * 1024 < 40_000_000
