"""Spindles in speed control: ramped speed, angle, limits, simple drive values.

The speed follows its setpoint with the acceleration of MD35200; the setpoint
is clamped to the gear-stage limits (MD35130/MD35140), the chuck limit
MD35100, the programmed limits G26/G25 (SD43220/SD43210) and the operator's
limit SD43235 (read live: a change acts at once, 002 L54713-54718) without an
alarm: like the interface signals DB31 DBX83.1/83.2, the state says when the
setpoint was limited or raised. M19/SPOS brake the spindle (MD35210) and turn
it to the position at the positioning speed MD35300 along the approach (DC/AC
the shortest way, or on in the turning direction; ACP +, ACN -): the time this
takes is exact, the angle on the way is interpolated linearly. Everything is
closed-form per call, independent of the number of IPO cycles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from typing import Any, Mapping

from nck.motion.limits import axis_setting
from nck.motion.params import SpindleParams

AMBIENT_C = 25.0


@dataclass
class SpindleState:
    """Speeds in rpm (signed: + = M3), angle in degrees, drive values."""

    programmed_rpm: float = 0.0
    setpoint_rpm: float = 0.0
    actual_rpm: float = 0.0
    angle_deg: float = 0.0
    override_pct: float = 100.0
    state: str = "M5"
    torque_nm: float = 0.0
    temperature_c: float = AMBIENT_C
    jog_direction: int = 0
    setpoint_limited: bool = False  # DB31 DBX83.1: the requested speed was clamped to a maximum
    setpoint_increased: bool = False  # DB31 DBX83.2: the requested speed was raised to a minimum


class Spindle:
    """One spindle in speed control."""

    def __init__(self, params: SpindleParams) -> None:
        self.params = params
        self.state = SpindleState()
        self._accel_rpm_s = params.accel_rev_s2 * 60.0
        self._load_torque_nm = max(params.rated_torque_nm, 1e-9)  # the motor load's divisor
        self._thermal_time_s = max(params.thermal_time_s, 1e-6)
        self.setting_data: Mapping[str, Any] | None = None  # SD43210/43220/43235, read live
        self._positioning: _Positioning | None = None
        # An injected drive fault (exercises): the actual speed stays within ± this (None: none).
        self.drive_limit_rpm: float | None = None

    def command(self, state: str | None, speed_rpm: float | None, position_deg: float | None = None,
                approach: str | None = None, positioning_rpm: float | None = None) -> None:
        """M3/M4/M5/M19 and S: set the speed setpoint (or position the spindle at
        ``positioning_rpm``, None: MD35300)."""
        st = self.state
        if speed_rpm is not None:
            rpm = abs(float(speed_rpm))
            st.programmed_rpm = rpm if rpm == rpm else 0.0  # NaN: no speed
        if state in ("M3", "M4", "M5"):
            st.state = state
            self._positioning = None
        elif state in ("M19", "SPOS"):
            st.state = "M5"
            target = st.angle_deg if position_deg is None else float(position_deg) % 360.0
            self._positioning = self._plan_positioning(target, approach or "DC",
                                                       positioning_rpm or self.params.posctrl_rpm)
        self._update_setpoint()

    def _plan_positioning(self, target_deg: float, approach: str, speed_rpm: float) -> "_Positioning":
        """Brake from the speed now, then turn to ``target_deg`` (times in s, angles in degrees)."""
        st = self.state
        p = self.params
        accel = p.posctrl_accel_rev_s2 * 360.0  # deg/s²
        v0 = st.actual_rpm * 6.0  # deg/s, signed
        brake_s = abs(v0) / accel
        stop_deg = st.angle_deg + v0 * brake_s / 2.0
        ahead = (target_deg - stop_deg) % 360.0  # the way in + direction
        if v0 > 0.0 or approach == "ACP":
            travel = ahead
        elif v0 < 0.0 or approach == "ACN":
            travel = -((360.0 - ahead) % 360.0)
        else:  # DC, AC, IC from standstill: the shortest way
            travel = ahead if ahead <= 180.0 else ahead - 360.0
        speed = speed_rpm * 6.0
        distance = abs(travel)
        if distance >= speed * speed / accel:
            move_s = distance / speed + speed / accel
        else:
            move_s = 2.0 * math.sqrt(distance / accel)
        return _Positioning(st.angle_deg, stop_deg, travel, target_deg, brake_s, move_s, speed_rpm)

    @property
    def positioning(self) -> bool:
        """True while SPOS/M19 turns the spindle to its position."""
        return self._positioning is not None

    def settle_s(self, feed_enable: bool = False) -> float:
        """Time until the spindle is positioned, stands, or turns in its set speed range.

        The set speed range ("spindle in setpoint range", DB31 DBX83.5) is the set speed
        ± MD35150 times it (002 L54545-54551); WAITS ends when the spindle enters it
        (002 L51326-51335), with MD35150 = 0 when the setpoint reaches its target
        (002 L51344-51348). ``feed_enable``: the wait of a machining block under MD35500
        (002 L51282-51288, L54530-54536): a spindle without a set speed (M5) does not hold
        the path (that is MD35510's), nor does MD35150 = 0 (002 L54555-54556).
        """
        if self._positioning is not None:
            return self._positioning.remaining_s
        st = self.state
        set_rpm = st.setpoint_rpm
        tolerance = self.params.speed_tolerance
        if feed_enable and (set_rpm == 0.0 or tolerance == 0.0):
            return 0.0
        window_rpm = tolerance * abs(set_rpm)
        if self.drive_limit_rpm is not None and abs(set_rpm) - window_rpm > self.drive_limit_rpm:
            return math.inf  # the faulty drive never reaches the set speed range
        return max(abs(set_rpm - st.actual_rpm) - window_rpm, 0.0) / self._accel_rpm_s

    def jog(self, direction: int) -> None:
        """Spindle JOG: turn at the JOG speed (MD32020 in rpm) while ``direction`` ≠ 0."""
        self.state.jog_direction = 0 if direction == 0 else (1 if direction > 0 else -1)
        self._update_setpoint()

    def set_override(self, percent: float) -> None:
        """Spindle override (0 … 200 %)."""
        self.state.override_pct = max(float(percent), 0.0)
        self._update_setpoint()

    def stop(self) -> None:
        """RESET: the spindle brakes (M5) and its programmed S is deleted (002 L51032-51035)."""
        self.state.state = "M5"
        self.state.programmed_rpm = 0.0
        self.state.jog_direction = 0
        self._positioning = None
        self._update_setpoint()

    def _update_setpoint(self) -> None:
        st = self.state
        p = self.params
        if st.jog_direction:
            target = st.jog_direction * p.jog_rpm * st.override_pct / 100.0
        elif st.state == "M3":
            target = st.programmed_rpm * st.override_pct / 100.0
        elif st.state == "M4":
            target = -st.programmed_rpm * st.override_pct / 100.0
        else:
            target = 0.0
        upper = min(p.max_rpm, p.gear_max_rpm)
        lower = p.gear_min_rpm
        data = self.setting_data
        if data:
            # 002 L55616-55630: G26/SD43220 is never exceeded, G25/SD43210 not undercut;
            # 002 L54713-54718: the operator's SD43235 limits the setpoint too.
            upper = min(upper, float(axis_setting(data, 43220, p.name, math.inf)),
                        float(axis_setting(data, 43235, p.name, math.inf)))
            lower = max(lower, float(axis_setting(data, 43210, p.name, 0.0)))
        requested = abs(target)
        magnitude = min(requested, upper)
        if magnitude > 0.0:
            magnitude = min(max(magnitude, lower), upper)
        # The speed is clamped without an alarm; only the interface signals report it.
        st.setpoint_limited = requested > upper
        st.setpoint_increased = 0.0 < requested < magnitude
        st.setpoint_rpm = math.copysign(magnitude, target) if target else 0.0

    def advance(self, dt_s: float) -> None:
        """Ramp the speed towards its setpoint and turn the spindle."""
        st = self.state
        p = self.params
        if self._positioning is not None:
            self._advance_positioning(dt_s)
            return
        if self.setting_data:
            self._update_setpoint()  # the limits in the setting data act at once
        if dt_s <= 0.0:
            return  # no time passed (a step ending at a block event): speed, torque, heat stay
        start = st.actual_rpm
        reachable = st.setpoint_rpm
        if self.drive_limit_rpm is not None:
            reachable = math.copysign(min(abs(reachable), self.drive_limit_rpm), reachable)
        diff = reachable - start
        ramp_s = abs(diff) / self._accel_rpm_s
        if ramp_s >= dt_s:
            end = start + math.copysign(self._accel_rpm_s * dt_s, diff)
            revolutions = (start + end) / 2.0 * dt_s / 60.0
            accel = math.copysign(self._accel_rpm_s, diff)
        else:
            end = reachable
            revolutions = ((start + end) / 2.0 * ramp_s + end * (dt_s - ramp_s)) / 60.0
            accel = 0.0
        st.actual_rpm = end
        st.angle_deg = (st.angle_deg + revolutions * 360.0) % 360.0
        st.torque_nm = p.inertia_kgm2 * accel * 2.0 * math.pi / 60.0 + (0.02 * p.rated_torque_nm if end else 0.0)
        load = (st.torque_nm / self._load_torque_nm) ** 2
        target = AMBIENT_C + p.rated_temp_rise_k * load
        st.temperature_c = target + (st.temperature_c - target) * math.exp(-dt_s / self._thermal_time_s)

    def seconds_for_revolutions(self, revolutions: float) -> float:
        """Time to turn ``revolutions`` from now: along the ramp to the setpoint, then at it.

        0 when the spindle neither turns nor is about to (the dwell has nothing to count).
        """
        st = self.state
        start, end = abs(st.actual_rpm) / 60.0, abs(st.setpoint_rpm) / 60.0  # rev/s
        if revolutions <= 0.0 or (start <= 0.0 and end <= 0.0):
            return 0.0
        accel = self._accel_rpm_s / 60.0 if end >= start else -self._accel_rpm_s / 60.0  # rev/s²
        ramp_s = (end - start) / accel if accel else 0.0
        ramp_rev = (start + end) / 2.0 * ramp_s
        if ramp_rev >= revolutions:
            # start·t + accel·t²/2 = revolutions, the root on the ramp
            return (-start + math.sqrt(start * start + 2.0 * accel * revolutions)) / accel
        if end <= 0.0:
            return 0.0  # the spindle stops before the revolutions are done
        return ramp_s + (revolutions - ramp_rev) / end

    def _advance_positioning(self, dt_s: float) -> None:
        move = self._positioning
        assert move is not None
        st = self.state
        move.elapsed_s += dt_s
        t = move.elapsed_s
        if t >= move.brake_s + move.move_s:
            st.angle_deg = move.target_deg % 360.0
            st.actual_rpm = 0.0
            self._positioning = None
            return
        if t < move.brake_s:
            share = t / move.brake_s
            v0 = (move.stop_deg - move.start_deg) * 2.0 / move.brake_s
            st.angle_deg = (move.start_deg + v0 * t * (1.0 - share / 2.0)) % 360.0
            st.actual_rpm = v0 * (1.0 - share) / 6.0
        else:
            share = (t - move.brake_s) / move.move_s
            st.angle_deg = (move.stop_deg + move.travel_deg * share) % 360.0
            st.actual_rpm = math.copysign(move.speed_rpm, move.travel_deg) if move.travel_deg else 0.0

    @property
    def moving(self) -> bool:
        """True while the spindle turns or its speed changes."""
        return (abs(self.state.actual_rpm) > 1e-9 or abs(self.state.setpoint_rpm) > 1e-9
                or self._positioning is not None)


@dataclass
class _Positioning:
    """A running SPOS/M19: braking (``brake_s``), then ``travel_deg`` in ``move_s``."""

    start_deg: float
    stop_deg: float
    travel_deg: float
    target_deg: float
    brake_s: float
    move_s: float
    speed_rpm: float
    elapsed_s: float = 0.0

    @property
    def remaining_s(self) -> float:
        """Time left until the spindle stands at the target."""
        return max(self.brake_s + self.move_s - self.elapsed_s, 0.0)
