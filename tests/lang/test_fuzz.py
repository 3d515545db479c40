"""Property tests: no input text makes the front end raise anything but an NC alarm."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck.errors import NcAlarmError
from nck.headless import check_program
from nck.interp.sources import MemorySource
from nck.lang.parser import parse_block
from nck.machine import load_machine

MACHINE = load_machine()

TOKENS = [
    "N10", ":20", "/", "/1", "G0", "G1", "G91", "G90", "G2", "G17", "X10", "Y-5", "Z=", "X=", "R1",
    "R[", "]", "[", "(", ")", "=", "==", "<>", "<", ">", "<=", ">=", "+", "-", "*", "/", "DIV", "MOD",
    "AND", "OR", "XOR", "NOT", "B_AND", "<<", "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR", "TO",
    "ENDFOR", "LOOP", "ENDLOOP", "REPEAT", "UNTIL", "GOTOF", "GOTOB", "GOTO", "GOTOC", "LBL:", "LBL",
    "DEF", "INT", "REAL", "BOOL", "STRING[5]", "AXIS", "FRAME", "VARX", "VARX[2]", "PROC", "EXTERN",
    "VAR", "M30", "M17", "M0", "RET", "STOPRE", "MSG(", "\"txt\"", "SETAL(", "61000", "L12", "P3",
    "SIN(", "SQRT(", "ATAN2(", ",", "1.5", "1EX400", "99999999999999999999", "0", "'H1F'", "$AA_IM[X]",
    "$TC_DP1[1,1]", "$P_GG[", "$MC_MM_NUM_R_PARAM", "AC(", "IC(", "F0", "F100", "S500", "M3", "T1",
    "D1", "M6", ";", "CR=", "TURN=", "X1=", "AX[", "\n", "\n", "\n",
    "CASE(", "OF", "DEFAULT", "REPEAT LBL", "REPEATB LBL", "P=2", "ENDLABEL:", "GOTOS", "SBLOF",
    "SBLON", "SET(", "REP(", "SUBA", "SUBA(", "L77", "DEF NCK REAL", "G2", "I5", "J-5", "TRANS",
    "AROT", "RPL=", "G4", "G91 X1", "ELSE", "STRLEN(", "\"LBL\"", "TRUE", "FALSE",
]
SUBPROGRAMS = {
    "SUBA.SPF": "PROC SUBA(REAL PA, VAR REAL PB)\nPB=PA+1\nR1=R1+1\nIF R1<5 GOTOB LBL\nLBL: RET\n",
    "L77.SPF": "G91 G1 X1 F100\nG90\nM17\n",
}

FAST = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _check(text: str) -> None:
    """check_program returns alarms; any other exception fails the test."""
    alarms = check_program(MACHINE, MemorySource(SUBPROGRAMS), "FUZZ.MPF", text, max_blocks=500)
    assert all(isinstance(a, NcAlarmError) and isinstance(a.number, int) for a in alarms)


@FAST
@given(st.text(max_size=300))
def test_random_text_only_raises_alarms(text: str) -> None:
    _check(text)


@FAST
@given(st.binary(max_size=200))
def test_binary_garbage_only_raises_alarms(raw: bytes) -> None:
    _check(raw.decode("latin-1"))


@FAST
@given(st.lists(st.sampled_from(TOKENS), max_size=60))
def test_random_token_sequences_only_raise_alarms(tokens: list[str]) -> None:
    _check(" ".join(tokens))


@FAST
@given(st.lists(st.sampled_from(TOKENS), max_size=40))
def test_parse_block_raises_only_alarms(tokens: list[str]) -> None:
    try:
        parse_block(" ".join(t for t in tokens if t != "\n"))
    except NcAlarmError:
        pass


def test_deep_parentheses_become_an_alarm() -> None:
    text = "R1=" + "(" * 5000 + "1" + ")" * 5000
    alarms = check_program(MACHINE, MemorySource(), "DEEP.MPF", text)
    assert [a.number for a in alarms] == [12540]


def test_huge_numbers_become_alarms() -> None:
    alarms = check_program(MACHINE, MemorySource(), "BIG.MPF", "R1=1EX300*1EX300\n")
    assert [a.number for a in alarms] == [14051]
    alarms = check_program(MACHINE, MemorySource(), "BIG.MPF", "R1=" + "9" * 400 + "\n")
    assert [a.number for a in alarms] == [12160]


def test_endless_loop_without_motion_ends_at_the_block_budget() -> None:
    alarms = check_program(MACHINE, MemorySource(), "LOOP.MPF", "LBL: R1=R1+1\nGOTOB LBL\n",
                           max_blocks=2000)
    assert alarms == []


# ----------------------------------------------------------------------------- structured programs
numbers = st.one_of(st.integers(-1000, 1000).map(str), st.floats(-1e6, 1e6, allow_nan=False).map(lambda f: f"{f:.3f}"),
                    st.sampled_from(["0", "1EX3", "'H1F'", "TRUE"]))
atoms = st.one_of(numbers, st.integers(0, 9).map(lambda i: f"R{i}"), st.sampled_from(["CNT", "VALS[1]", "$P_F", "$AA_IM[X]"]))
exprs = st.recursive(
    atoms,
    lambda inner: st.one_of(
        st.tuples(inner, st.sampled_from(["+", "-", "*", "/", " DIV ", " MOD ", "==", "<", " AND ", " OR ", "<<"]), inner)
        .map(lambda t: f"({t[0]}{t[1]}{t[2]})"),
        st.tuples(st.sampled_from(["SIN", "SQRT", "ABS", "LN", "TRUNC", "ROUND"]), inner).map(lambda t: f"{t[0]}({t[1]})"),
        st.tuples(inner, inner).map(lambda t: f"ATAN2({t[0]},{t[1]})"),
    ),
    max_leaves=6,
)
simple_lines = st.one_of(
    st.tuples(st.integers(0, 9), exprs).map(lambda t: f"R{t[0]}={t[1]}"),
    exprs.map(lambda e: f"CNT={e}"),
    st.tuples(st.integers(0, 3), exprs).map(lambda t: f"VALS[{t[0]}]={t[1]}"),
    st.tuples(st.sampled_from(["G0", "G1", "G91 G1", "G90 G0"]), exprs, exprs).map(lambda t: f"{t[0]} X={t[1]} Y={t[2]} F100"),
    exprs.map(lambda e: f"IF {e} GOTOF LBL"),
    exprs.map(lambda e: f"SUBA({e}, R3)"),
    st.integers(0, 3).map(lambda p: f"L77 P{p}"),
    exprs.map(lambda e: f'MSG("v" << {e})'),
    st.sampled_from(["LBL: R9=R9+1", "GOTOB LBL", "STOPRE", "M0", "T1 M6 D1", "S100 M3", "REPEATB LBL P=2"]),
)


def _blocks(inner: st.SearchStrategy[list[str]]) -> st.SearchStrategy[list[str]]:
    return st.one_of(
        st.tuples(exprs, inner).map(lambda t: [f"IF {t[0]}", *t[1], "ENDIF"]),
        st.tuples(exprs, inner, inner).map(lambda t: [f"IF {t[0]}", *t[1], "ELSE", *t[2], "ENDIF"]),
        st.tuples(exprs, inner).map(lambda t: [f"WHILE {t[0]}", *t[1], "ENDWHILE"]),
        st.tuples(st.integers(-3, 5), inner).map(lambda t: [f"FOR CNT=1 TO {t[0]}", *t[1], "ENDFOR"]),
        st.tuples(inner, exprs).map(lambda t: ["REPEAT", *t[0], f"UNTIL {t[1]}"]),
    )


programs = st.recursive(st.lists(simple_lines, max_size=4), lambda inner: _blocks(inner).map(list), max_leaves=8)


def _structured(parts: list[list[str]]) -> None:
    body = [line for part in parts for line in part]
    _check("\n".join(["DEF INT CNT", "DEF REAL VALS[3]", *body, "M30"]))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(programs, max_size=4))
def test_structured_random_programs_only_raise_alarms(parts: list[list[str]]) -> None:
    _structured(parts)


@pytest.mark.fuzz
@settings(max_examples=3000, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.lists(programs, max_size=6))
def test_structured_random_programs_long_run(parts: list[list[str]]) -> None:
    _structured(parts)


@pytest.mark.fuzz
@settings(max_examples=5000, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.lists(st.sampled_from(TOKENS), max_size=80))
def test_random_token_sequences_long_run(tokens: list[str]) -> None:
    _check(" ".join(tokens))
