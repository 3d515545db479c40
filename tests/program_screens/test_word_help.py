"""Word help of the editor (issue 27): the meaning of the word under the cursor, one table.

G functions: group, modal or not and the code's meaning from data/gcode/siemens.toml, the
table the G functions screen shows; M functions and system variables from
data/gcode/words.toml; cycles from their input forms. Groups as the programming manual lists
them (G0..G3 group 1 modal; G4 group 2 non-modal; G17..G19 group 6; G90/G91 group 14).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from rich.console import Console

from hmi.i18n import set_language
from hmi.widgets.gfunctions import MAIN_GROUPS, all_groups_table
from hmi.word_help import g_functions, word_at, word_help
from tests.burst import burst
from tests.program_screens.conftest import SIZE, make_program_app, settle


def test_g_functions_with_group_and_modality() -> None:
    assert word_help("G01") == "G1: straight line at the feedrate F — group 1 (modal motion commands), modal"
    assert "group 2" in word_help("g4") and "non-modal" in word_help("G4")
    assert "group 6" in word_help("G18") and ", modal" in word_help("G18")
    assert word_help("G91").startswith("G91: incremental dimensions — group 14")


UNDESCRIBED = {"G335", "G336"}
"""Group 1 members the manuals at hand do not describe (data/gcode/siemens.toml says where it was
looked: 002 L4728-4731, 001 L564): their help gives the group only."""


def test_every_code_of_the_main_groups_has_a_meaning() -> None:
    """The G functions window's groups (motion, plane, TRC, zero offset, exact stop, units …)."""
    for name, g_function in g_functions().items():
        if g_function.group in MAIN_GROUPS and name not in UNDESCRIBED:
            assert g_function.meaning, name
    assert word_help("G335") == "G335: group 1 (modal motion commands), modal"


def test_m_functions_system_variables_and_cycles() -> None:
    assert word_help("M30") == "M30: end of the program, as M2"
    assert word_help("m03") == "M3: spindle on, clockwise"
    assert "machine coordinate system" in word_help("$AA_IM")
    assert "channel machine data" in word_help("$MC_AXCONF_GEOAX_NAME_TAB")
    assert word_help("CYCLE81") == "CYCLE81: cycle Centering — CYCLE81(RTP, RFP, SDIS, DP, DPR)"
    assert word_help("X10") == word_help("N10") == word_help("") == ""


def test_word_under_or_behind_the_cursor() -> None:
    line = "N10 G1 X10 R1=$AA_IM[X]"
    assert word_at(line, 4) == word_at(line, 6) == "G1"
    assert word_at(line, 16) == "$AA_IM"
    assert word_at(line, 3) == "N10"


def test_g_functions_screen_uses_the_same_table() -> None:
    console = Console(width=160, record=True)
    console.print(all_groups_table({1: "G1", 14: "G91"}))
    shown = console.export_text()
    assert "straight line at the feedrate F" in shown and "incremental dimensions" in shown
    assert "plane selection" in shown  # no active code: the group's meaning


@pytest.mark.parametrize("language, name, g1_text, m30_text", [
    ("en", "words", "G1: straight line at the feedrate F — group 1 (modal motion commands), modal",
     "M30: end of the program, as M2"),
    ("de", "worte", "G1: Gerade mit dem Vorschub F — Gruppe 1 (modale Bewegungsbefehle), modal",
     "M30: Programmende, wie M2"),
])
async def test_editor_message_line_shows_the_meaning(language: str, name: str, g1_text: str, m30_text: str,
                                                     data_dir: Path) -> None:
    """Typed in a burst; Up, Home and Right keys put the cursor on G01, then Down, End on M30;
    in either language of the panel."""
    set_language(language)
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "f2", *name, "enter")
        screen = app.screen
        assert screen.AREA_ID == "program"
        await burst(pilot, "ctrl+end", *"N10 G01 X10 F100", "enter", *"N20 M30", "up", "home")
        # On a busy machine a check may have run on a half-typed line ("N10 G01 X1": no feed),
        # and its mark takes the message line until the next check: check the typed text now.
        screen.check_now()
        await settle(pilot)
        message = lambda: str(screen.query_one("#prog-message").render())  # noqa: E731
        await burst(pilot, "right", "right", "right", "right", "right")
        assert g1_text in message()
        await burst(pilot, "down", "end")
        assert m30_text in message()


@pytest.mark.parametrize(("word", "dialect", "text"), [
    # ISO Dialect T: G71 is the stock removal cycle along the longitudinal axis of the non-modal
    # group 18 (000 L701-712), not the Siemens G71 (metric, group 13); ISO M's G00 rapid traverse,
    # group 1 (000 L578)
    ("G71", "iso-t", "G71: stock removal along the longitudinal axis — ISO Dialect T group 18 (non-modal "
                     "functions (turning cycles G70-G76, G92 preset and spindle limit)), non-modal (this block only)"),
    ("G0", "iso-m", "G00: rapid traverse — ISO Dialect M group 1 (motion), modal"),
    ("G500", "iso-m", ""),  # a Siemens code, no ISO one
    ("M3", "iso-t", "M3: spindle on, clockwise"),
])
def test_word_help_on_a_line_read_in_iso_dialect(word: str, dialect: str, text: str) -> None:
    assert word_help(word, dialect) == text


async def test_the_editor_reads_a_g291_line_and_the_lines_after_it_in_iso(data_dir: Path) -> None:
    """A Siemens program that switches with G291 on the mill (ISO Dialect M): G00 before the
    switch is the Siemens G0, after it ISO M's; G290 switches back."""
    (data_dir / "MPF" / "MIXED.MPF").write_text("N10 G00 X0\nN20 G291\nN30 G00 X1.\nN40 G290\nN50 G00 X2\nM30\n")
    app = make_program_app(data_dir)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "alt+n", "down", "enter")
        screen = app.screen
        assert screen.program == "MPF/MIXED.MPF"
        await settle(pilot)
        message = lambda: str(screen.query_one("#prog-message").render())  # noqa: E731
        seen = []
        for _row in range(3):
            await burst(pilot, "home", "right", "right", "right", "right", "right")
            seen.append(message().split("│ ")[-1])
            await burst(pilot, "down", "down")
        assert seen[0].startswith("G0: ") and "ISO" not in seen[0]
        assert seen[1] == "G00: rapid traverse — ISO Dialect M group 1 (motion), modal"
        assert seen[2].startswith("G0: ") and "ISO" not in seen[2]


@pytest.mark.parametrize("dialect", ["iso-m", "iso-t"])
def test_every_iso_code_has_a_meaning(dialect: str) -> None:
    """Every member of every G group of both ISO dialects says what it does (000 table 2-2)."""
    from hmi.word_help import iso_g_functions

    functions = iso_g_functions(dialect)
    assert len(functions) > 60
    assert all(f.meaning for f in functions.values())
