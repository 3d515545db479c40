"""SVG snapshots of the setting-up windows of JOG (fake kernel, 160×48, no clock, no blink)."""

from __future__ import annotations

from hmi.app import HmiApp
from tests.hmi.conftest import SIZE
from tests.hmi.fake_nck import FakeNck


def app_on_referenced_fake() -> HmiApp:
    """The HMI on a referenced fake kernel at a few positions."""
    fake = FakeNck(referenced=True)
    fake.pos.update({"X": -125.35, "Y": 42.0, "Z": 100.0})
    return HmiApp(fake, realtime=False)


def test_tsm_window_filled_in(snap_compare) -> None:
    """T,S,M: T 1, D 1, S 1200, M3, M8 typed; the spindle choice field has the focus."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f1", "1", "down", "down", "1", "2", "0", "0", "down", "right",
                               "down", "8", "up"])


def test_position_window(snap_compare) -> None:
    """Position: axis Y, position 25, feed 1000 (preset), traverse with feed."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f5", "right", "down", "2", "5"])


def test_settings_window(snap_compare) -> None:
    """Settings for manual mode: JOG feed and variable increment fields, ⇧F1 Save."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE, press=["shift+f6"])


def test_set_wo_window(snap_compare) -> None:
    """Set WO: one field per axis, X typed 0.5, softkeys X=0 … Delete active WO."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f2", "0", ".", "5"])


def test_measure_workpiece_window(snap_compare) -> None:
    """Measure workpiece: edge in Y approached in − direction, setpoint 0, the preview."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f3", "right", "down", "right"])


def test_measure_tool_window(snap_compare) -> None:
    """Measure tool without a tool: the window says to load one."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE, press=["shift+f4"])


def test_measure_corner_window(snap_compare) -> None:
    """Measure workpiece, corner: X edge approached −, setpoints X0 100; no point saved yet."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f3", "shift+f2", "right", "down", "down", "ctrl+a", "ctrl+k", "1", "0", "0"])


def test_measure_rotated_corner_window(snap_compare) -> None:
    """Measure workpiece, rotated corner: the edge directions, one point saved (the cutter's
    position of the fake: no probe)."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f3", "shift+f3", "right", "right", "shift+f6"])


def test_measure_hole_window(snap_compare) -> None:
    """Measure workpiece, hole / spigot: spigot chosen, no point saved yet."""
    assert snap_compare(app_on_referenced_fake(), terminal_size=SIZE,
                        press=["shift+f3", "shift+f4", "right"])
