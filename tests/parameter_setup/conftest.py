"""Fixtures of the Parameter/Setup tests: the HMI on a real kernel and a real NC data directory."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import pytest

from hmi.app import HmiApp, make_app

SIZE = (160, 48)
FROZEN_NOW = datetime(2026, 3, 14, 9, 30, 0)


@pytest.fixture(autouse=True)
def frozen_clock(monkeypatch: pytest.MonkeyPatch) -> None:
    """The Setup area's date/time starts from a fixed moment (stable pictures)."""
    import screens.setup

    monkeypatch.setattr(screens.setup, "wall_clock", lambda: FROZEN_NOW)


def trainer(data_dir: Path) -> HmiApp:
    """The HMI on the NC data directory ``data_dir``, time advanced by the test only."""
    return make_app(data_dir=str(data_dir), realtime=False)


def fill(app: HmiApp) -> None:
    """Example data: two tools, G54/G55 and base frame, R parameters, GUDs, a setting datum."""
    data = app.nc_session.session.ncdata
    from nck.ncdata import ToolEdge

    data.tools[(1, 1)] = ToolEdge({1: 120, 2: 0, 3: 75.5, 6: 5.0, 12: -0.02})
    data.tools[(1, 2)] = ToolEdge({1: 120, 3: 80.0, 6: 4.0})
    data.tools[(12, 1)] = ToolEdge({1: 200, 3: 110.25, 6: 4.25, 15: 0.01})
    data.settable_frames["G54"].trans.update({"X": -250.0, "Y": -120.5, "Z": -310.0})
    data.settable_frames["G55"].trans.update({"X": 100.0})
    data.settable_frames["G55"].rot.update({"Z": 30.0})
    data.base_frame.trans.update({"Z": 2.5})
    data.r[1] = 12.5
    data.r[7] = -3.0
    data.gud.update({"COUNT": 3, "DEPTH": 2.5, "DONE": False, "NAME": "PART", "TAB": [1.0, 2.0, 3.0]})
    data.setting_data["SD42100"] = 2500.0
