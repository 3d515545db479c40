"""The blocks the T,S,M and Position windows build from what was typed (pure text)."""

from __future__ import annotations

import pytest

from screens.machine_jog_blocks import EntryError, TsmEntry, position_blocks, tsm_blocks


def test_tool_by_number_and_by_name() -> None:
    """A number is T<n>, a name T="name" (a tool change with M6 and the edge D)."""
    assert tsm_blocks(TsmEntry(tool="5", edge="2")) == "T5 M6 D2\n"
    assert tsm_blocks(TsmEntry(tool="CUTTER_10", edge="1")) == 'T="CUTTER_10" M6 D1\n'


def test_spindle_and_m_function_each_in_its_own_block() -> None:
    assert tsm_blocks(TsmEntry(speed_rpm="1200", spindle="M4", m_function="8")) == "S1200 M4\nM8\n"
    assert tsm_blocks(TsmEntry(spindle="M5")) == "M5\n"


@pytest.mark.parametrize("entry, words", [
    (TsmEntry(), "fill in at least one field"),
    (TsmEntry(tool="1 2"), "tool number or a tool name"),
    (TsmEntry(tool="1", edge="13"), "D: enter a whole number 1 … 12"),
    (TsmEntry(speed_rpm="fast"), "Spindle speed: enter a number"),
    (TsmEntry(speed_rpm="-5"), "0 or more"),
    (TsmEntry(m_function="100"), "Other M function"),
])
def test_entries_that_cannot_be_used_say_why(entry: TsmEntry, words: str) -> None:
    with pytest.raises(EntryError, match=words):
        tsm_blocks(entry)


def test_position_block_with_feed_or_rapid() -> None:
    assert position_blocks("Y", "25", "2000", rapid=False) == "G90 G94 G1 Y25 F2000\n"
    assert position_blocks("X", "-3.5", "", rapid=True) == "G90 G0 X-3.5\n"
    with pytest.raises(EntryError, match="Feed"):
        position_blocks("X", "1", "0", rapid=False)


def test_an_entry_error_is_said_in_the_panels_language() -> None:
    """The dialog line says why a field cannot be used in German, its label too; str() stays English."""
    from hmi.i18n import set_language
    with pytest.raises(EntryError) as refused:
        tsm_blocks(TsmEntry(speed_rpm="fast"))
    set_language("de")
    try:
        assert refused.value.text() == "Spindeldrehzahl: eine Zahl eingeben"
    finally:
        set_language("en")
    assert str(refused.value) == "Spindle speed: enter a number"
