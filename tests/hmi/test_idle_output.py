"""Nothing is sent to the terminal while nothing on screen changed (issue 18).

The kernel's snapshot may change while no digit on the screen does: a motor that holds an
axis against gravity warms up in every IPO cycle. The snapshot carries its temperature as the
service screen shows it (a tenth of a degree); these tests carry it to 1e-9 degrees, so that
``seq`` grows every idle tick again, and no window may repaint then. A repaint is counted where
the app hands an update to the terminal driver (``App._display``).
"""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import pytest

import nck.snapshot
import screens.setup

from hmi.app import AREAS, HmiApp, make_app
from hmi.area import AreaBase

SIZE = (160, 48)


@pytest.fixture(autouse=True)
def snapshots_change_at_idle(monkeypatch: pytest.MonkeyPatch) -> None:
    """The warming Z drive's temperature in the snapshot to 1e-9 degrees (see the docstring)."""
    monkeypatch.setattr(nck.snapshot, "TEMPERATURE_DECIMALS", 9)
AREA_KEYS = {"machine": "alt+m", "parameter": "alt+o", "program": "alt+p",
             "program_manager": "alt+n", "diagnostics": "alt+a", "setup": "alt+s"}
IDLE_TICKS = 10
SETTLE_TICKS = 3
TICK_S = 0.05


def count_displays(app: HmiApp) -> list[int]:
    """Count the updates the app hands to the terminal from now on."""
    counter = [0]
    display = app._display

    def counting(*args: object, **kwargs: object) -> object:
        counter[0] += 1
        return display(*args, **kwargs)

    app._display = counting  # type: ignore[method-assign]
    return counter


async def idle_displays(app: HmiApp, pilot: object, counter: list[int]) -> tuple[int, int]:
    """Advance the kernel through idle ticks; return (repaints, snapshot changes)."""
    for _ in range(SETTLE_TICKS):  # the view just shown may still be settling
        app.bridge.advance(TICK_S)
        await pilot.pause()
    counter[0] = 0
    seq = app.bridge.status.seq
    for _ in range(IDLE_TICKS):
        app.bridge.advance(TICK_S)
        await pilot.pause()
    return counter[0], app.bridge.status.seq - seq


@pytest.mark.parametrize("area", [a.id for a in AREAS])
async def test_idle_area_sends_nothing(tmp_path: Path, area: str) -> None:
    """Each area at idle: the snapshot changes every tick, the screen is not repainted."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        counter = count_displays(app)
        await pilot.press(AREA_KEYS[area])
        repaints, changes = await idle_displays(app, pilot, counter)
        assert changes >= IDLE_TICKS - 1  # the test really feeds new snapshots
        assert repaints == 0


@pytest.mark.parametrize("area", ["machine", "parameter", "diagnostics", "setup"])
async def test_idle_views_send_nothing(tmp_path: Path, area: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every view reached by a top-level softkey stays quiet at idle too."""
    monkeypatch.setattr(screens.setup, "wall_clock", lambda: datetime(2026, 3, 14, 9, 30, 0))
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        counter = count_displays(app)
        await pilot.press(AREA_KEYS[area])
        await pilot.pause()
        noisy = []
        for slot in ("h1", "h2", "h3", "h4", "h5", "h6", "h7", "h8"):
            app.area_screen.clear_softkey_levels()
            app.area_screen.press_softkey(slot)
            repaints, _ = await idle_displays(app, pilot, counter)
            # the Setup access view shows the control's clock: its seconds change once in the
            # 0.5 s of idle ticks (one update, two when a dialog lies over the view)
            clock_ticks = 2 if area == "setup" and app.area_screen.view == "password" else 0
            if repaints > clock_ticks:
                noisy.append((slot, repaints))
            while not isinstance(app.screen, AreaBase):
                app.screen.dismiss(None)
                await pilot.pause()
        assert noisy == []


async def test_second_level_views_stay_quiet_and_utilisation_refreshes_once_a_second(tmp_path: Path) -> None:
    """Diagnostics > More: Version and Logbook send nothing at idle; System utilisation shows
    measured figures (the IPO cycles since power on grow every tick) and refreshes them once a
    second of control time, not with every snapshot (in tmux it sent 1.19 MB in 8 s at idle)."""
    app = make_app(data_dir=str(tmp_path / "data"), realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        counter = count_displays(app)
        await pilot.press("alt+a")
        await pilot.pause()
        quiet = {}
        for slot, view in (("h2", "version"), ("h3", "logbook")):
            app.area_screen.clear_softkey_levels()
            app.area_screen.press_softkey("h8")
            app.area_screen.press_softkey(slot)
            assert app.area_screen.view == view
            quiet[view], _ = await idle_displays(app, pilot, counter)
        assert quiet == {"version": 0, "logbook": 0}
        app.area_screen.clear_softkey_levels()
        app.area_screen.press_softkey("h8")
        app.area_screen.press_softkey("h1")
        assert app.area_screen.view == "utilisation"
        await idle_displays(app, pilot, counter)  # settled
        counter[0] = 0
        for _ in range(int(2.0 / TICK_S)):  # two seconds of control time
            app.bridge.advance(TICK_S)
            await pilot.pause()
        assert 1 <= counter[0] <= 2
