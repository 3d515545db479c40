"""The search mode softkeys of the block search view, driven with the keymap's keys on the
real kernel (digest 828d-2 rank 25; 002 L18283-18302).

STEP.MPF: N10 G90 G0 X0 Y0 Z10, N20 G1 X10 F1000, N30 Y10, N40 X0, N50 M30; the machine
stands at X0 Y0 Z0.
"""

from __future__ import annotations

import pytest
from textual.widgets import Input

from tests.hmi.conftest import SIZE
from tests.hmi.test_workflows import (  # noqa: F401 - the programs fixture
    TOL_MM, programs, real_app, select_in_auto, settle, text_of,
)


def positions(status) -> dict[str, float]:
    return {a.name: a.position_mcs for a in status.axes}


async def test_end_point_softkey_searches_to_the_block_end_point(programs) -> None:  # noqa: F811
    """⇧F3 "End point", target N30, NC START twice (10208 between): N30 (Y10) moves only Y
    from where the axes stand (002 L18295-18299), so X is still 0 when Y reaches 10; a
    search to contour would have approached X10 Z10 first."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await pilot.press("f5")
        await pilot.pause()
        await pilot.press("shift+f3")
        await pilot.pause()
        assert "with calculation, end point" in text_of(app, "#search-title")
        for key in ("N", "3", "0"):
            await pilot.press(key)
        await pilot.press("enter")
        await pilot.pause()
        assert app.bridge.status.channel.stop_reason == "search target found"
        await pilot.press("alt+g")
        await pilot.pause()
        assert [a.number for a in app.bridge.status.alarms] == [10208]
        await pilot.press("alt+g")
        status = app.bridge.run_until(lambda s: positions(s)["Y"] >= 10.0 - TOL_MM, max_s=10)
        assert positions(status)["X"] == pytest.approx(0.0, abs=TOL_MM)
        assert positions(status)["Z"] == pytest.approx(0.0, abs=TOL_MM)


async def test_without_calculation_in_one_burst(programs) -> None:  # noqa: F811
    """One burst: F5, ⇧F4 "Without calculation", N20, Enter, NC START, NC START. Nothing before
    N20 ran (002 L18284-18288): N10's Z10 never came, so the program ends at X0 Y10 Z0."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await pilot.press("f5", "shift+f4", "N", "2", "0", "enter", "alt+g", "alt+g")
        await pilot.pause()
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=20)
        assert positions(status)["X"] == pytest.approx(0.0, abs=TOL_MM)
        assert positions(status)["Y"] == pytest.approx(10.0, abs=TOL_MM)
        assert positions(status)["Z"] == pytest.approx(0.0, abs=TOL_MM)
        assert app.screen.search_type == "without_calculation"
        assert app.screen.query_one("#search-input", Input).value == "N20"  # ⇧F4 typed nothing


async def test_serupro_softkey_runs_to_the_target_and_one_nc_start_repositions(programs) -> None:  # noqa: F811
    """⇧F5 "SERUPRO", target N30 (002 L18994-19027): the program runs in program test (the
    machine stands) and stops before N30; one NC START repositions to N30's start (X10 Y0 Z10,
    the end of N20) and the program ends at X0 Y10 Z10."""
    app = real_app(programs)
    async with app.run_test(size=SIZE) as pilot:
        await select_in_auto(pilot, "STEP.MPF")
        await pilot.press("f5", "shift+f5", "N", "3", "0", "enter")
        await pilot.pause()
        status = app.bridge.run_until(lambda s: s.channel.stop_reason == "search target found", max_s=20)
        assert positions(status) == pytest.approx({"X": 0.0, "Y": 0.0, "Z": 0.0, "SP": 0.0})
        await pilot.press("alt+g")
        status = app.bridge.run_until(lambda s: positions(s)["X"] >= 10.0 - TOL_MM, max_s=10)
        assert positions(status)["Z"] == pytest.approx(10.0, abs=TOL_MM)
        status = settle(app, lambda s: s.channel.channel_state == "reset", max_s=20)
        assert positions(status)["X"] == pytest.approx(0.0, abs=TOL_MM)
        assert positions(status)["Y"] == pytest.approx(10.0, abs=TOL_MM)
