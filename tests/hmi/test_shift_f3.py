"""Shift+F3 (VSK3) arrives although terminals encode it like a cursor position report."""

from __future__ import annotations

from textual import events
from textual._xterm_parser import XTermParser

from hmi.app import HmiApp
from tests.hmi.conftest import SIZE


def test_parser_reads_shift_f3_as_a_cursor_report() -> None:
    # The reason for the workaround: ESC [1;2R comes out of the parser as CursorPosition(1, 0).
    tokens = list(XTermParser().feed("\x1b[1;2R"))
    assert any(isinstance(t, events.CursorPosition) and (t.x, t.y) == (1, 0) for t in tokens)


async def test_cursor_report_1_2_presses_vertical_softkey_3(fake_app: HmiApp) -> None:
    pressed: list[str] = []
    async with fake_app.run_test(size=SIZE) as pilot:
        fake_app.screen.press_softkey = pressed.append  # type: ignore[attr-defined]
        fake_app.post_message(events.CursorPosition(1, 0))
        await pilot.pause()
        await pilot.pause()
    assert pressed == ["v3"]


async def test_other_cursor_reports_are_ignored(fake_app: HmiApp) -> None:
    pressed: list[str] = []
    async with fake_app.run_test(size=SIZE) as pilot:
        fake_app.screen.press_softkey = pressed.append  # type: ignore[attr-defined]
        fake_app.post_message(events.CursorPosition(5, 3))
        await pilot.pause()
    assert pressed == []


async def test_shift_f3_keeps_its_place_in_a_burst(fake_app: HmiApp) -> None:
    """Shift+F3 then Shift+F2 sent in one go (tmux send-keys S-F3 S-F2): VSK3 is pressed first.
    Found in tmux: the key made from the report was queued behind Shift+F2, so the second key
    met the first key's softkey level (JOG: Measure workpiece, then Corner opened Set WO)."""
    pressed: list[str] = []
    async with fake_app.run_test(size=SIZE) as pilot:
        fake_app.screen.press_softkey = pressed.append  # type: ignore[attr-defined]
        second = events.Key("shift+f2", None)
        second.set_sender(fake_app)
        fake_app.post_message(events.CursorPosition(1, 0))
        fake_app.post_message(second)
        await pilot.pause()
        await pilot.pause()
    assert pressed == ["v3", "v2"]
