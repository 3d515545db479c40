"""Simple motion lines (:data:`nck.lang.plain.SIMPLE_LINE`) are valid without the parser.

The load scan and the editor's check skip the parser for them (issue 25: a CAM program is
mostly arcs with I/J or CR=); that is only right if every such line parses without an
alarm and carries nothing the scan indexes (labels, control structures, jumps, definitions,
G codes of one group twice). The properties compare the scan that skips them with the scan
that parses every line on random programs.
"""

from __future__ import annotations

import re
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.errors import NcAlarmError
from nck.interp import program as program_module
from nck.lang import ast
from nck.lang.parser import parse_block
from nck.lang.plain import SIMPLE_LINE, is_plain, parses_without_alarm, simple_block
from nck.interp.program import load_program
from tests.lang.test_plain_fast_path import plain_lines

NEVER = re.compile(r"(?!)")


def _number(draw: Any, signed: bool) -> str:
    whole = draw(st.integers(0, 99999))
    style = draw(st.sampled_from(["int", "dec", "dot", "lead", "long"]))
    text = {"int": f"{whole}", "dec": f"{whole}.{draw(st.integers(0, 999)):03d}", "dot": f"{whole}.",
            "lead": f".{draw(st.integers(0, 99))}",
            "long": f"{draw(st.integers(0, 999999999))}.{draw(st.integers(0, 999999999)):09d}"}[style]
    return (draw(st.sampled_from(["", "-", "+"])) if signed else "") + text


@st.composite
def simple_lines(draw: Any) -> str:
    """Lines of the simple-motion grammar, and near misses (other addresses, lower case, order)."""
    words: list[str] = []
    if draw(st.booleans()):
        words.append(f"N{draw(st.integers(0, 999999999))}")
    gwords = []
    if draw(st.booleans()):
        gwords.append(draw(st.sampled_from(["G0", "G1", "G2", "G3", "G00", "G01", "G02", "G03"])))
    if draw(st.integers(0, 4)) == 0:
        gwords.append(draw(st.sampled_from(["G90", "G91"])))
    words += draw(st.permutations(gwords))
    for axis in ("X", "Y", "Z", "I", "J", "K", "CR="):
        if draw(st.booleans()):
            words.append(axis + _number(draw, True))
    if draw(st.integers(0, 3)) == 0:
        words.append("F" + _number(draw, False))
    if draw(st.integers(0, 6)) == 0:  # a near miss: another word, a second G of group 1, a swap
        words.insert(draw(st.integers(0, len(words))),
                     draw(st.sampled_from(["G17", "G2", "M3", "X1", "IF", "L1:", "x2", "CR=R1", "I=AC(3)"])))
    separator = draw(st.sampled_from([" ", " ", "\t", ""]))
    line = separator.join(words)
    if draw(st.integers(0, 5)) == 0:
        line += draw(st.sampled_from([" ; cut G2 X1", ";", "  ;I J K"]))
    return line


@settings(max_examples=400, deadline=None)
@given(simple_lines())
def test_a_simple_line_is_valid_for_the_parser(line: str) -> None:
    if SIMPLE_LINE.fullmatch(line) is None:
        return
    block = parse_block(line, 1)
    assert block.skip_level is None and block.label is None
    assert program_module._check_gcodes(block) is None
    assert all(isinstance(s, (ast.GWord, ast.AddressWord)) for s in block.statements)
    assert is_plain(line) or block.statements


@settings(max_examples=600, deadline=None)
@given(simple_lines(), st.integers(1, 10**6))
def test_the_tree_of_a_simple_line_is_the_parsers(line: str, number: int) -> None:
    """Bit for bit: repr tells the int 0 from the float 0.0 and -0.0 from 0.0."""
    tree = simple_block(line, number)
    if SIMPLE_LINE.fullmatch(line) is None:
        assert tree is None
        return
    assert repr(tree) == repr(parse_block(line, number))


@pytest.mark.parametrize("line", ["", "   ", ";", "N10", "X-0 Y-0.0 Z+.5 I-.5", "N7 G3 CR=-2 F.5 ;hi",
                                  "  N007 G02X1.;", "G91 G2 X1", "CR=+2 F0", "G00 G90", "X123456789.123456789"])
def test_the_tree_of_simple_line_examples(line: str) -> None:
    assert repr(simple_block(line, 3)) == repr(parse_block(line, 3))


@settings(max_examples=300, deadline=None)
@given(plain_lines())
def test_every_plain_line_is_simple(line: str) -> None:
    assert is_plain(line) and SIMPLE_LINE.fullmatch(line) is not None


def _scan(text: str) -> dict[str, Any]:
    program_module._RECENT.clear()
    program = load_program("SIMPLE.MPF", text)
    return {
        "alarms": [(a.number, a.line, a.n, a.params) for a in program.problems()],
        "labels": dict(program.labels), "partner": dict(program.partner), "proc": program.proc,
        "numbers": {n: program.find_number(n, -1, "F") for n in range(0, 40)},
    }


OTHER = ["PROC SUB", "R1=2", "X1..5", "L1:", "GOTOF L1", "GOTOB L9", "WHILE R1<3", "ENDWHILE", "IF R1>1",
         "ENDIF", "G2 G3 X1", "DEF REAL A", "N5 G0 Z5", "", "; comment", "M30", "T1 D1 M6"]


@settings(max_examples=150, deadline=None)
@given(st.lists(st.one_of(simple_lines(), st.sampled_from(OTHER)), min_size=1, max_size=30))
def test_the_scan_skipping_simple_lines_finds_what_parsing_them_finds(lines: list[str]) -> None:
    text = "\n".join(lines) + "\n"
    skipping = _scan(text)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(program_module, "SIMPLE_LINE", NEVER)
        parsing = _scan(text)
    program_module._RECENT.clear()
    assert skipping == parsing, text


def test_the_scan_and_the_editor_check_parse_no_cam_arc(monkeypatch: pytest.MonkeyPatch) -> None:
    from nck import check
    import nck.lang.parser as parser_module

    text = ("N10 G2 X10 Y0 I5 J0 F200\nN20 G03 X0 Y10 CR=-7.5\nN30 G1 X1 Y2 Z3 F100\n"
            "N40 G2 X5 Y5 Z-1 I2.5 J2.5 K0 ; helix\nN50 G2 X1 IF\n")
    assert parses_without_alarm("N20 G03 X0 Y10 CR=-7.5") and not parses_without_alarm("N50 G2 X1 IF")
    parsed: list[str] = []
    original = parser_module.parse_block

    def spy(raw: str, line: int = 1) -> Any:
        parsed.append(raw)
        return original(raw, line)

    monkeypatch.setattr(parser_module, "parse_block", spy)
    monkeypatch.setattr(program_module, "parse_block", spy)
    monkeypatch.setattr(check, "parse_block", spy)
    check._line_problem.cache_clear()
    list(check.iter_syntax_alarms(text))
    program_module._RECENT.clear()
    load_program("ARCS.MPF", text)
    program_module._RECENT.clear()
    assert parsed == ["N50 G2 X1 IF", "N50 G2 X1 IF"]


BLOCK_NUMBER = re.compile(r"\s*(?:/\d?\s*)?[Nn](\d+)\b")


def _each_line_parsed(text: str) -> list[tuple[int, int | None, tuple[str, ...], int | None]]:
    """The syntax alarms of ``text`` found by giving every non-blank line to the parser."""
    found = []
    for number, line in enumerate(text.split("\n"), start=1):
        if not line.strip():
            continue
        try:
            parse_block(line, 1)
        except NcAlarmError as error:
            block = BLOCK_NUMBER.match(line)
            n = error.n if error.n is not None else (int(block.group(1)) if block else None)
            found.append((error.number, number, error.params, n))
    return found


@settings(max_examples=200, deadline=None)
@given(st.lists(st.one_of(simple_lines(), st.sampled_from(OTHER + ["X=", "G1 X1 X2", "N12 G1 Y", "\r", "  "])),
                min_size=1, max_size=40),
       st.sampled_from(["\n", "\r\n"]), st.booleans(), st.sampled_from([1, 7, 40, 1 << 16]))
def test_the_syntax_pass_skipping_simple_lines_finds_what_parsing_every_line_finds(
        lines: list[str], end: str, last_end: bool, chunk: int) -> None:
    """The editor's syntax pass scans past stretches of simple lines in pieces of ``chunk``
    characters; it must report every faulty line, at its line number, as parsing each line does."""
    from nck import check

    text = end.join(lines) + (end if last_end else "")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(check, "SCAN_CHUNK_CHARS", chunk)
        skipping = [(a.number, a.line, a.params, a.n) for a in check.iter_syntax_alarms(text)]
    assert skipping == _each_line_parsed(text), text
