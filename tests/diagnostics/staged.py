"""A real kernel whose alarms, messages and axis values are staged, for stable snapshots.

The snapshot pictures must not change when the motion dynamics or the
interpreter's timing are tuned: the views are fed hand-made alarm entries,
NC messages and service values (those of X moving at F1000 with Kv = 1);
everything else (machine, counters, logbook, commands) is the real kernel's.
"""

from __future__ import annotations

from dataclasses import replace
from datetime import datetime, timedelta, timezone
from typing import Any

from nck.kernel import Nck
from nck.motion.system import planned_motion_factory
from nck.status import AlarmEntry, AlarmEvent, AxisStatus, NckStatus
from nck.trace import TraceRecorder, TraceSettings

from hmi.app import HmiApp
from tests.diagnostics.conftest import Programs, limit_machine

JOG_LIMIT = AlarmEntry(seq=3, number=10621, text="Channel 1 axis X stands at software limit switch +",
                       category="axis", clear="self", came_s=12.5, params=("1", "X", "+"))
AUTO_LIMIT = AlarmEntry(seq=1, number=10720,
                        text="Channel 1 block N10 axis X would pass software limit switch +",
                        category="axis", clear="reset", came_s=4.25, params=("1", "N10", "X", "+"),
                        file="LIMIT.MPF", line=1, n=10)
CYCLE_ALARM = AlarmEntry(seq=5, number=61000, text="Channel 1 block N40 cycle alarm 61000",
                         category="user", clear="reset", came_s=20.0, params=("1", "N40"),
                         file="MSG.MPF", line=4, n=40)

STAGED_STAMPS = {
    -1: {"came_at": "2026-11-25T15:02:40+01:00", "went_at": "2026-11-25T15:03:10+01:00"},
    1: {"came_at": "2026-11-26T09:12:04+01:00", "went_at": "2026-11-26T09:12:09+01:00"},
    3: {"came_at": "2026-11-26T09:12:12+01:00"},
    5: {"came_at": "2026-11-26T09:12:20+01:00"},
}
"""Date and time of the staged alarms by entry seq (-1: one from before the last power on)."""
STAGED_NOW = datetime(2026, 11, 26, 9, 12, 30, tzinfo=timezone(timedelta(hours=1)))
"""The wall clock of a staged app: when the HMI reads the staged NC message."""


def stamped(app: HmiApp) -> HmiApp:
    """``app`` with a stopped wall clock and the staged alarms' dates and times."""
    app.bridge.alarm_times.clock = lambda: STAGED_NOW
    app.bridge.alarm_times.restart(STAGED_STAMPS)
    return app


def moving_x(status: NckStatus) -> tuple[AxisStatus, ...]:
    """The axes with X moving at 1000 mm/min, Kv = 1: 1 mm following error."""
    extra = {
        "position_actual_mm": -81.0, "control_deviation_mm": 1.0, "contour_deviation_mm": 0.0,
        "velocity_setpoint_mm_min": 1000.0, "kv_calculated": 1.0, "speed_setpoint_pct": 2.857,
        "speed_actual_pct": 2.857, "motor_speed_setpoint_rpm": 100.0, "motor_speed_actual_rpm": 100.0,
        "torque_nm": 0.8, "current_pct": 12.5, "motor_temperature_c": 31.4, "controller_mode": 0.0,
        "exact_stop_coarse": 0.0, "exact_stop_fine": 0.0, "clamped": 0.0, "servo_parameter_set": 1.0,
    }
    axes = list(status.axes)
    axes[0] = replace(axes[0], position_mcs=-80.0, position_wcs=-80.0, setpoint_mcs=-80.0,
                      velocity=1000.0, following_error=1.0, extra=extra)
    return tuple(axes)


class StagedKernel(Nck):
    """``Nck`` with staged alarms, alarm log, NC message and (optionally) a moving X."""

    def __init__(self) -> None:
        super().__init__(machine=limit_machine(), programs=Programs(), referenced=True,
                         motion_factory=planned_motion_factory)
        self.staged_alarms: tuple[AlarmEntry, ...] | None = None
        self.staged_history: tuple[AlarmEntry, ...] | None = None
        self.staged_message = ""
        self.staged_moving = False

    def status(self) -> NckStatus:
        real = super().status()
        channel = replace(real.channel, message=self.staged_message) if self.staged_message else real.channel
        return replace(
            real, channel=channel,
            alarms=self.staged_alarms if self.staged_alarms is not None else real.alarms,
            axes=moving_x(real) if self.staged_moving else real.axes,
        )

    def alarm_history(self) -> tuple[AlarmEntry, ...]:
        return self.staged_history if self.staged_history is not None else super().alarm_history()

    def alarm_log_since(self, seq: int) -> tuple[AlarmEvent, ...]:
        if not self.staged_message:
            return super().alarm_log_since(seq)
        entry = AlarmEntry(seq=4, number=0, text=self.staged_message, category="message",
                           clear="self", came_s=18.0)
        return (AlarmEvent(seq=4, kind="message", time_s=18.0, entry=entry),) if seq < 4 else ()


def staged_trace(machine: Any) -> TraceRecorder:
    """A finished recording of X position and following error over 2 s (synthetic)."""
    recorder = TraceRecorder(TraceSettings(("X.position", "X.following_error"), "nc_start", 2.0), machine)
    for k in range(1, 501):
        t = k * 0.004
        ramp = min(t / 0.5, 1.0)
        recorder.times_s.append(t)
        recorder.columns["X.position"].append(-50.0 + 20.0 * max(t - 0.25, 0.0) * ramp)
        recorder.columns["X.following_error"].append(0.333 * ramp if t < 1.5 else 0.333 * (2.0 - t) / 0.5)
    recorder.state = "done"
    return recorder
