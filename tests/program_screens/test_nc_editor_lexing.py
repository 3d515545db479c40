"""The NC editor's colour lexer and its pure editing helpers (renumber, search)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from hmi.widgets.nc_editor import find_text, renumber_blocks, tokenize_line


def kinds(line: str) -> list[tuple[str, str]]:
    return [(line[s:e], k) for s, e, k in tokenize_line(line)]


def test_block_words_are_classified() -> None:
    """G/M words, addresses, numbers, block numbers and comments get their own colours."""
    got = kinds("N10 G1 X10 F200 M3 ; cut")
    assert ("N10", "block_number") in got
    assert ("G1", "gword") in got
    assert ("M3", "mword") in got
    assert ("X", "address") in got and ("10", "number") in got
    assert ("; cut", "comment") in got


def test_labels_keywords_strings_variables_and_skip() -> None:
    """Labels at block start, keywords, strings, $-variables and skip levels are recognised."""
    got = kinds('/1 N5 LOOP1: IF $AA_IM[X]>5 GOTOB LOOP1 MSG("hi ; not a comment")')
    assert ("/1", "skip") in got
    assert ("LOOP1:", "label") in got
    assert ("IF", "keyword") in got and ("GOTOB", "keyword") in got
    assert ("$AA_IM", "variable") in got
    assert ('"hi ; not a comment"', "string") in got
    assert not any(kind == "comment" for _, kind in got)


def test_assignment_is_not_a_label() -> None:
    """``R1=5`` and ``DEF`` lines are not labels."""
    assert all(kind != "label" for _, kind in kinds("R1=5 DEF REAL A"))


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=80))
def test_lexer_never_raises_and_spans_are_inside_the_line(line: str) -> None:
    """Any text lexes without an exception and every span lies inside the line."""
    for start, end, _ in tokenize_line(line):
        assert 0 <= start < end <= len(line)


def test_renumber_blocks_step_10_keeps_comments_and_rewrites_jumps() -> None:
    """Renumber gives N10, N20 … to block lines and rewrites GOTO targets."""
    text = "; header\nG0 X0\nN5 G1 X1\nLAB: G1 X2\n\n/ N7 GOTOF N5\nM30"
    assert renumber_blocks(text) == "; header\nN10 G0 X0\nN20 G1 X1\nLAB: G1 X2\n\n/ N30 GOTOF N20\nN40 M30"


def test_renumber_leaves_main_blocks_and_proc_lines() -> None:
    """Main blocks (``:10``), PROC headers and % lines keep their form."""
    text = "%_N_A_MPF\nPROC A\n:10 G0 X0\nG1 X1"
    assert renumber_blocks(text, start=100, step=5) == "%_N_A_MPF\nPROC A\n:10 G0 X0\nN100 G1 X1"


def test_find_text_is_case_insensitive_and_wraps() -> None:
    """Search finds the next occurrence after the cursor and wraps to the top."""
    lines = ["G0 X0", "g1 x5", "G1 X7"]
    assert find_text(lines, "G1", (0, 0)) == (1, 0)
    assert find_text(lines, "G1", (1, 0)) == (2, 0)
    assert find_text(lines, "G0", (2, 0)) == (0, 0)
    assert find_text(lines, "Q9", (0, 0)) is None
