"""The softkey Basic blocks (⇧F2 in AUTO and MDA) on the real kernel, driven with the keymap's keys:
single block through a cycle shows the cycle's blocks in the basic block display while the
program's own display stays on the call (002 L23515-23530; the expected blocks are those of
tests/kernel/test_basic_blocks.py, written by hand from CYCLE81's documented sequence)."""

from __future__ import annotations

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck

from hmi.app import HmiApp
from tests.hmi.conftest import SIZE

PROGRAM = "N10 G17 G90 F300\nN20 G0 X10 Y20 Z50\nN30 CYCLE81(10, 0, 2, -5)\nN40 M30\n"


def _app() -> HmiApp:
    nck = Nck(programs=MemorySource({"DRILL.MPF": PROGRAM}), referenced=True)
    assert nck.submit(c.SelectProgram("DRILL.MPF")) == c.Accepted()
    return HmiApp(nck, realtime=False)


def _text(app: HmiApp, selector: str) -> str:
    return str(app.screen.query_one(selector).render())


async def _stopped(pilot) -> None:
    pilot.app.bridge.run_until(lambda s: s.channel.channel_state != "active", max_s=30)
    await pilot.pause()


async def test_single_block_through_a_cycle_in_the_basic_block_display() -> None:
    app = _app()
    async with app.run_test(size=SIZE) as pilot:
        window = app.screen.query_one("#auto-basic")
        # AUTO, Basic blocks on, single block on, NC START: one burst
        await pilot.press("alt+u", "shift+f2", "alt+k", "alt+g")
        await _stopped(pilot)
        assert window.display and app.screen.query_one("#sk-v2").has_class("-active")
        assert "▶N20 G0 X10 Y20 Z50" in _text(app, "#auto-basic")
        for marked in ("▶Z2", "▶G1 Z-5 F300", "▶G0 Z10"):
            await pilot.press("alt+g")
            await _stopped(pilot)
            assert "▶N30 CYCLE81(10, 0, 2, -5)" in _text(app, "#auto-blocks")  # the call (DISPLOF)
            shown = [line.strip() for line in _text(app, "#auto-basic").splitlines()]
            assert marked in shown
            assert shown[0] == "N20 G0 X10 Y20 Z50"  # the blocks before stay in sight
        await pilot.press("shift+f2")
        await pilot.pause()
        assert not window.display and not app.screen.query_one("#sk-v2").has_class("-active")


async def test_basic_blocks_in_mda_and_keys_in_a_burst() -> None:
    """In MDA the softkey shows the same display under the MDA editor; the softkey keys of a burst
    never reach the editor as text."""
    app = _app()
    async with app.run_test(size=SIZE) as pilot:
        await pilot.press("alt+d", "shift+f2", *"G1 X5 Y6 Z7 F1000", "shift+f2", "shift+f2", "alt+g")
        app.bridge.run_until(lambda s: s.channel.channel_state == "reset", max_s=30)
        await pilot.pause()
        assert app.screen.query_one("#mda-editor").text == "G1 X5 Y6 Z7 F1000"
        assert app.screen.query_one("#mda-basic").display
        assert _text(app, "#mda-basic").split() == ["G1", "X5", "Y6", "Z7", "F1000"]  # ended: kept, unmarked
