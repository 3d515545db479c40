"""The block window's program lines: compact storage, same window as the per-line views."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from nck.status import BlockView

from hmi.program_lines import ProgramLines
from hmi.widgets.blocks import BEFORE, block_lines, program_views, program_window

LINE = st.sampled_from(["G1 X1", "N20 Y2 ", "", "   ", "M30", "; note", "\t"])


def test_lines_match_the_kernels_line_ends() -> None:
    text = "G0 X1\r\nG1 Y2\rM30\n"
    lines = ProgramLines("P.MPF", text)
    assert list(lines) == ["G0 X1", "G1 Y2", "M30"]
    assert len(ProgramLines("E.MPF", "")) == 0
    assert list(ProgramLines("A.MPF", "X1\n\nX2")) == ["X1", "", "X2"]
    assert lines[-1] == "M30"


def test_a_long_program_keeps_no_string_per_line() -> None:
    text = "".join(f"G1 X{k}\n" for k in range(100_000))
    lines = ProgramLines("LONG.MPF", text)
    assert len(lines) == 100_000 and lines[54_321] == "G1 X54321"
    assert lines._starts.itemsize * len(lines) <= 8 * 100_000
    shown, position = lines.blocks_around(100_000, BEFORE, 20)
    assert shown == list(range(99_980, 100_000)) and position == 19


@settings(max_examples=150, deadline=None)
@given(st.lists(LINE, max_size=40), st.one_of(st.none(), st.integers(-2, 45)), st.integers(1, 12))
def test_window_equals_the_per_line_views(lines: list[str], current_line: int | None, height: int) -> None:
    """Whatever the current line (blank, missing, out of range), both ways draw the same window."""
    text = "\n".join(lines) + ("\n" if lines else "")
    program = ProgramLines("P.MPF", text)
    current = BlockView("P.MPF", current_line, "x") if current_line is not None else None
    expected = block_lines(program_views("P.MPF", tuple(text.splitlines())), current, height)
    actual = program_window(program, current, height)
    assert actual.plain == expected.plain
    assert actual.spans == expected.spans
