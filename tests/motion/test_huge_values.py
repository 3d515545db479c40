"""Huge programmed values: clamped like the control does, or their alarm — never a warning.

* Spindle speed above every limit (``S1EX300``): the setpoint is clamped to the
  gear-stage maximum / chuck limit without an alarm; the state reports
  "setpoint speed limited" (DB31 DBX83.1).
* Path feed above the axis maxima (``F1EX300``): the path velocity is limited
  so that no axis exceeds MD32000; no alarm.
* Huge or non-finite target positions: 10720 when the software limit switches
  catch them, else 12160 (value range) — without numpy overflow warnings.
"""

from __future__ import annotations

import copy
import math
import warnings

import numpy as np
import pytest

from nck.canon import Dwell, Motion, Source
from nck.headless import run_program
from nck.interp.sources import MemorySource
from nck.machine import load_machine
from nck.motion.system import PlannedMotion
from nck.ncdata import NcData


def _run(text: str, trace: list | None = None):
    def on_motion(motion: object) -> None:
        motion.enable_trace()  # type: ignore[attr-defined]
        if trace is not None:
            trace.append(motion)

    # MD35040 = 1: the spindle keeps its S and direction after M30 (002 L51036-51038), so
    # the setpoint reached in the program can still be read after the end.
    machine = copy.deepcopy(load_machine())
    machine.md["MD35040"] = {"SP": 1}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return run_program(machine, MemorySource({"P.MPF": text}), NcData(), "P.MPF",
                           on_motion=on_motion, keep_commands=False)


def test_spindle_speed_above_every_limit_is_clamped_without_alarm() -> None:
    motions: list = []
    result = _run("N10 S1EX300 M3\nN20 G4 F3\nN30 M30\n", motions)
    assert result.status == "ended" and result.alarms == []
    spindle = motions[0].spindles["SP"].state
    machine = load_machine()
    gear_max = machine.md_value("MD35130", "SP", None)
    assert spindle.setpoint_limited and not spindle.setpoint_increased
    assert spindle.setpoint_rpm == pytest.approx(gear_max)


def test_spindle_speed_inside_the_limits_is_not_flagged() -> None:
    motions: list = []
    result = _run("N10 S1000 M4\nN20 G4 F1\nN30 M30\n", motions)
    assert result.status == "ended"
    spindle = motions[0].spindles["SP"].state
    assert not spindle.setpoint_limited
    assert spindle.setpoint_rpm == pytest.approx(-1000.0)


def test_feed_above_the_axis_maximum_is_limited_without_alarm() -> None:
    motions: list = []
    huge = _run("N10 G1 X200 F1EX300\nN20 M30\n", motions)
    assert huge.status == "ended" and huge.alarms == []
    times, rows = motions[0].trace()
    speed_mm_min = np.abs(np.diff(rows[:, 0])) / np.diff(times) * 60.0
    max_x = load_machine().md_value("MD32000", "X", None)
    assert speed_mm_min.max() == pytest.approx(max_x, rel=1e-6)
    at_max = _run(f"N10 G1 X200 F{max_x:.0f}\nN20 M30\n")
    assert huge.machine_time_s == pytest.approx(at_max.machine_time_s, abs=1e-9)


def _push_one(referenced: bool, motion: Motion) -> list[int]:
    system = PlannedMotion(load_machine(), referenced=referenced)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        system.push(motion)
        system.advance(1.0)
    return [alarm.number for alarm in system.drain_alarms()]


@pytest.mark.parametrize("value", [1e300, -1e300, 1.7e308, 2e9])
def test_huge_target_ends_in_the_limit_switch_alarm(value: float) -> None:
    move = Motion(kind="G1", source=Source("P", 1, 10), plane="G17", end_wcs={}, end_mcs={"X": value},
                  feed_mm_min=1000.0)
    assert _push_one(True, move) == [10720]


@pytest.mark.parametrize("value", [1e300, -1e300, 1.7e308, 2e9, math.inf, -math.inf, math.nan])
def test_huge_target_of_an_unreferenced_axis_is_a_value_range_alarm(value: float) -> None:
    move = Motion(kind="G1", source=Source("P", 1, 10), plane="G17", end_wcs={}, end_mcs={"X": value},
                  feed_mm_min=1000.0)
    assert _push_one(False, move) == [12160]


def test_huge_arc_centre_is_a_value_range_alarm() -> None:
    arc = Motion(kind="G2", source=Source("P", 1, 10), plane="G17", end_wcs={},
                 end_mcs={"X": 1e300, "Y": 0.0}, center_mcs={"X": 5e299, "Y": 0.0}, feed_mm_min=1000.0)
    assert _push_one(True, arc) == [10720]
    assert _push_one(False, arc) == [12160]


def test_infinite_dwell_does_not_overflow() -> None:
    system = PlannedMotion(load_machine(), referenced=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        system.push(Dwell(source=Source("P", 1, 10), seconds=math.inf))
        system.advance(1.0)
    assert not system.is_idle() and system.drain_alarms() == []


@pytest.mark.parametrize("block", ["G0 X1EX300", "G0 X1EX300 Y-1EX300", "G1 X1EX300 Z1EX300 F100"])
def test_huge_programmed_target_through_the_interpreter_is_the_limit_alarm(block: str) -> None:
    # The whole chain (path builder, planner, limits) with warnings as errors.
    result = _run(f"N10 {block}\nN20 M30\n")
    assert [alarm.number for alarm in result.alarms] == [10720]
