"""Property tests: no input text makes the front end raise anything but an NC alarm."""

from __future__ import annotations

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
]

FAST = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _check(text: str) -> None:
    """check_program returns alarms; any other exception fails the test."""
    alarms = check_program(MACHINE, MemorySource(), "FUZZ.MPF", text, max_blocks=500)
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
