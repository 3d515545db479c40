"""Bad entries in every kind of input field: an operator message, never Python's, and no change.

Issue 18: tool list, edit a cell, clear it (or type ``abc``), Enter showed
``could not convert string to float: ''``. The kernel reads the typed text
(:mod:`nck.value_text`); a refusal says what to enter and leaves the datum as it was.
"""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from nck import commands as c
from nck.kernel import Nck
from nck.ncdata import ToolEdge
from nck.persistence import Session
from nck.value_text import InvalidValue, number_from_text

from tests.parameter_setup.conftest import SIZE, fill, trainer

PYTHON_WORDS = ("could not convert", "invalid literal", "float", "int(", "NoneType", "object",
                "Error", "base 10", "'")
"""Phrases of Python's exception texts (and its repr quotes), which an operator never reads."""

FIELDS = [  # (datum, the words naming it in the message)
    ("$TC_DP3[1,1]", "$TC_DP3"),  # tool list: length 1
    ("$TC_DP6[1,1]", "$TC_DP6"),  # tool list: radius
    ("$TC_DP12[1,1]", "$TC_DP12"),  # tool wear
    ("$P_UIFR[1,X,TR]", "G54 X offset"),  # work offsets
    ("$P_UIFR[2,Z,RT]", "G55 Z rotation"),
    ("$P_UBFR[Y,TR]", "Base frame Y offset"),
    ("R1", "R1"),  # R variables
    ("GUD:DEPTH", "DEPTH"),  # user variables (REAL, INT)
    ("GUD:COUNT", "COUNT"),
    ("SD42100", "SD42100"),  # setting data
    ("MD32000[X]", "MD32000"),  # machine data
    ("$AC_TOTAL_PARTS", "$AC_TOTAL_PARTS"),  # part counters (Times/Counter)
    ("$AC_REQUIRED_PARTS", "$AC_REQUIRED_PARTS"),
]
BAD_ENTRIES = ["", "   ", "abc", "1,5", "12..5", "1_000", "inf", "nan", "1e999", "--1", "X12", "²"]


@pytest.fixture()
def nck(tmp_path: Path) -> Nck:
    session = Session.open(tmp_path, install_samples=False)
    kernel = Nck(**session.kernel_arguments())
    kernel.md_store = session.md
    kernel.data.tools[(1, 1)] = ToolEdge({1: 120, 3: 75.5, 6: 5.0, 12: -0.02})
    kernel.data.gud.update({"COUNT": 3, "DEPTH": 2.5})
    kernel.data.r[1] = 12.5
    assert kernel.submit(c.EnterPassword("SUNRISE")) == c.Accepted()
    return kernel


def everything(nck: Nck) -> tuple:
    """All data an input field can change."""
    data = nck.data
    return copy.deepcopy((data.tools, data.settable_frames, data.base_frame, data.r, data.gud,
                          data.setting_data, nck.md_store.changes, vars(nck.counters)))


@pytest.mark.parametrize(("name", "label"), FIELDS)
def test_bad_entry_is_refused_in_the_operators_words(nck: Nck, name: str, label: str) -> None:
    for entry in BAD_ENTRIES:
        before = everything(nck)
        result = nck.submit(c.WriteData(name, entry))
        assert isinstance(result, c.Rejected), (name, entry)
        assert label in result.reason, (name, entry, result.reason)
        assert not any(word in result.reason for word in PYTHON_WORDS), (name, entry, result.reason)
        assert everything(nck) == before, (name, entry)


@pytest.mark.parametrize(("name", "label"), FIELDS)
def test_a_good_entry_in_the_same_field_is_taken(nck: Nck, name: str, label: str) -> None:
    assert nck.submit(c.WriteData(name, " 7 ")) == c.Accepted()


@pytest.mark.parametrize(("text", "number"), [
    ("12.5", 12.5), ("-.5", -0.5), ("+3", 3.0), ("7.", 7.0), ("1.2EX3", 1200.0), ("2e-3", 0.002),
    (" 40 ", 40.0), (5, 5.0), (2.25, 2.25),
])
def test_numbers_in_nc_notation_are_read(text: object, number: float) -> None:
    assert number_from_text(text, "R1") == number


def test_whole_numbers_and_their_messages() -> None:
    assert number_from_text("12", "COUNT", whole=True) == 12
    for entry, words in [("2.5", "COUNT: enter a whole number"), ("", "COUNT: no value entered"),
                         ("abc", "COUNT: “abc” is not a number"),
                         ("1e999", "COUNT: the value is out of range"),
                         (True, "COUNT: enter a number"), (None, "COUNT: enter a number")]:
        with pytest.raises(InvalidValue, match=words):
            number_from_text(entry, "COUNT", whole=True)


async def test_tool_list_cell_cleared_or_garbage_keeps_the_value(tmp_path: Path) -> None:
    """The issue's repro with the keys, sent as bursts: Enter, clear, Enter; Enter, abc, Enter."""
    app = trainer(tmp_path)
    fill(app)
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+t", "alt+t", "alt+t")  # level 4
        await pilot.press("alt+o", "f1", "right")  # tool list, T1 D1, Length 1
        await pilot.pause()
        for entry in ([], list("abc")):
            await pilot.press("enter")
            await pilot.pause()
            await pilot.press("ctrl+u", *entry, "enter")
            await pilot.pause()
            line = app.screen.query_one("#dialog-line").render().plain
            assert "$TC_DP3" in line and not any(word in line for word in PYTHON_WORDS), line
            assert app.bridge.nck.data.tools[(1, 1)].get(3) == 75.5


def test_alarm_log_filter_takes_any_text() -> None:
    """The alarm log filter (Diagnostics): digits of other scripts are text, not a Python error."""
    from screens.diagnostics_alarms import parse_filter

    assert parse_filter("²-5").text == "²-5"
    assert (parse_filter("10000-19999 limit").low, parse_filter("10000-19999").high) == (10000, 19999)
