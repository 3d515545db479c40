"""Settings for manual mode (issue 22): retraction plane, safety distance and measuring feed in
the JOG Settings window, retained, and used by Measure workpiece with a 3D probe: CYCLE START
searches the surface at the measuring feed over at most 2 × the safety distance (MEAS=1), then
backs off by the safety distance (edge) or to the retraction plane (Z surface).

Hand values: the default mill blank X -50…50, Y -40…40, top Z -220; probe T1 (type 710, ball
radius 2, L 150 to the ball centre), G500 and no offsets, so WCS = MCS of the ball centre.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from nck import commands as cmd
from nck.kernel import Nck
from nck.machine import load_machine
from nck.manual_settings import ManualSettings
from nck.ncdata import NcData, ToolEdge
from nck.persistence import Session
from nck.queries import ManualSettingsData, answer
from nck.workpiece import default_machine_setup

from hmi.app import HmiApp
from screens.machine_jog_blocks import probing_blocks
from tests.burst import burst
from tests.jog_setup.kernels import run_in_mda_then_jog
from tests.jog_setup.test_measure_windows import info, wcs
from tests.jog_setup.test_tsm_window import run_job

SIZE = (160, 48)


def probe_kernel(start: str) -> Nck:
    data = NcData()
    data.machine_setup = default_machine_setup("mill")
    data.tools[(1, 1)] = ToolEdge({1: 710.0, 3: 150.0, 6: 2.0})
    nck = Nck(data=data, referenced=True)
    return run_in_mda_then_jog(nck, f"T1 D1 M6\nG0 {start}\n")


def test_blocks_search_twice_the_safety_distance_and_back_off() -> None:
    assert probing_blocks("X", 1, 50.0, 8.0, 300.0) == "G91 G94 MEAS=1 G1 X16 F300\nG91 G0 X-8\nG90\n"
    assert probing_blocks("Y", -1, 50.0, 2.5, 150.0) == "G91 G94 MEAS=1 G1 Y-5 F150\nG91 G0 Y2.5\nG90\n"
    assert probing_blocks("Z", 1, -150.0, 8.0, 300.0) == "G91 G94 MEAS=1 G1 Z-16 F300\nG90 G0 Z-150\n"


def test_settings_are_retained_and_checked(tmp_path: Path) -> None:
    session = Session.open(tmp_path, load_machine("mill3"), install_samples=False)
    assert session.ncdata.manual_settings == ManualSettings()
    session.ncdata.manual_settings = ManualSettings(-150.0, 8.0, 250.0)
    session.save()
    assert Session.open(tmp_path, load_machine("mill3")).ncdata.manual_settings == ManualSettings(-150.0, 8.0, 250.0)
    nck = Nck()
    assert isinstance(nck.submit(cmd.WriteManualSettings(ManualSettings(10.0, 0.0, 300.0))), cmd.Rejected)
    assert answer(nck, ManualSettingsData()) == ManualSettings()


async def test_settings_window_writes_them_in_one_burst() -> None:
    """RP -150, SC 8, measuring feed 250 typed below the JOG feed and the increment; ⇧F1."""
    nck = Nck(referenced=True)
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f6", "down", "down", "ctrl+a", "ctrl+k", "-", "1", "5", "0", "down",
                    "ctrl+a", "ctrl+k", "8", "down", "ctrl+a", "ctrl+k", "2", "5", "0", "shift+f1")
        assert answer(nck, ManualSettingsData()) == ManualSettings(-150.0, 8.0, 250.0)
        assert "RP -150 mm   SC 8 mm   measuring feed 250 mm/min" in info(app, "settings")
        await burst(pilot, "up", "ctrl+a", "ctrl+k", "0", "shift+f1")  # SC 0: refused, nothing written
        assert answer(nck, ManualSettingsData()).safety_distance_mm == 8.0
        assert "Safety distance: enter a value greater than 0" in app.hint


@pytest.mark.parametrize(("start", "keys", "edge", "after"), [
    # ball centre at X -60, face at -50: switches at -52 (8 mm into a 16 mm search), backs off 8
    ("X-60 Y0 Z-230", [], "Edge X (MCS) -50.000", ("X", -60.0)),
    # over the top (-220) with the ball centre at -210: switches at -218, up to RP -150
    ("X0 Y0 Z-210", ["right", "right"], "Edge Z (MCS) -220.000", ("Z", -150.0)),
])
async def test_cycle_start_probes_the_edge_and_backs_off(start: str, keys: list[str], edge: str,
                                                       after: tuple[str, float]) -> None:
    nck = probe_kernel(start)
    assert nck.submit(cmd.WriteManualSettings(ManualSettings(-150.0, 8.0, 300.0))) == cmd.Accepted()
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f3", *keys, "alt+g")
        assert app.bridge.status.channel.mode == "MDA"
        run_job(app)
        await burst(pilot)
        assert app.bridge.status.channel.mode == "JOG"
        assert edge in info(app, "measwp"), info(app, "measwp")
        axis, position = after
        # the edge: back by SC from where MEAS braked (a little past the trigger, in the overtravel)
        assert wcs(app)[axis] == pytest.approx(position, abs=0.5 if axis != "Z" else 1e-6)
        await burst(pilot, "shift+f5")
        assert "Set WO" in app.hint


async def test_cycle_start_with_a_cutter_says_a_probe_is_needed() -> None:
    nck = Nck(referenced=True)
    nck.data.tools[(1, 1)] = ToolEdge({1: 120.0, 3: 75.0, 6: 5.0})
    run_in_mda_then_jog(nck, "T1 D1 M6\n")
    app = HmiApp(nck, realtime=False)
    async with app.run_test(size=SIZE) as pilot:
        await burst(pilot, "shift+f3", "alt+g")
        assert "3D probe" in app.hint and app.bridge.status.channel.mode == "JOG"
