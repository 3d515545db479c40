"""Position control, drive model and axis monitoring for every path axis.

The position controller is a P controller with gain Kv (MD32200) and optional
speed feedforward (MD32620/MD32610) acting on an ideal speed loop with the
equivalent time constant MD32810. Its following error obeys, per IPO cycle,

    e[k] = alpha * e[k-1] + b * v_set[k],   alpha = exp(-Kv T),
    b = (1 - alpha) / Kv * (1 - w + w Kv T_eq)

so at constant velocity e = v (1 - w + w Kv T_eq) / Kv, i.e. v / Kv without
feedforward. The recurrence is evaluated with numpy for a whole block of
setpoints. Injected mechanical faults (jam, drive offset, push, runaway) make
the actual position deviate from this model; the monitors of the manual
(contour 25050, speed setpoint 25060, actual velocity 25030, positioning 25080,
zero speed 25040, clamping 26000) compare the result with their machine data.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from nck.motion.servo_defer import quiet_bound, settle
from nck.motion.servo_model import AMBIENT_C, MOVING_MM_S, Fault, ServoModel
from nck.motion.servo_paths import process_fast, process_small

__all__ = ["AMBIENT_C", "MOVING_MM_S", "AxisState", "Fault", "ServoBank", "Trip", "first_order"]
SMALL_ROWS = 6  # blocks up to this many cycles go through the Python-float path


@dataclass(frozen=True, slots=True)
class AxisState:
    """What the service screens show for one axis (internal units, MCS)."""

    name: str
    position_setpoint_mm: float
    position_actual_mm: float
    following_error_mm: float
    control_deviation_mm: float
    contour_deviation_mm: float
    velocity_setpoint_mm_min: float
    velocity_actual_mm_min: float
    kv_calculated: float  # (m/min)/mm, 0 at standstill
    speed_setpoint_pct: float
    speed_actual_pct: float
    motor_speed_setpoint_rpm: float
    motor_speed_actual_rpm: float
    torque_nm: float
    current_pct: float
    motor_temperature_c: float
    controller_mode: int  # 0 position control, 4 follow-up
    exact_stop_coarse: bool
    exact_stop_fine: bool
    clamped: bool
    servo_parameter_set: int = 1
    extra: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class Trip:
    """A monitor that responded: cycle index within the block, alarm number, axis."""

    index: int
    number: int
    axis: str


def first_order(alpha: np.ndarray, u: np.ndarray, e0: np.ndarray) -> np.ndarray:
    """Solve ``e[k] = alpha e[k-1] + u[k]`` for every column, vectorised in chunks."""
    m, n = u.shape
    out = np.empty_like(u)
    ln_a = np.log(np.clip(alpha, 1e-300, 1.0))
    rate = float(np.max(-ln_a)) if n else 0.0
    chunk = m if rate <= 1e-12 else max(1, int(200.0 / rate))
    state = e0.astype(float).copy()
    start = 0
    while start < m:
        c = min(chunk, m - start)
        steps = np.arange(1, c + 1, dtype=float)[:, None]
        powers = np.exp(ln_a[None, :] * steps)
        acc = np.cumsum(u[start:start + c] / powers, axis=0)
        block = powers * (state[None, :] + acc)
        out[start:start + c] = block
        state = block[-1]
        start += c
    return out


class ServoBank(ServoModel):
    """Position controllers, drives and monitors of all path axes: the behaviour over the
    tables and state of :class:`nck.motion.servo_model.ServoModel`."""

    def settle(self) -> None:
        """Process queued setpoints now (every reader of the state calls this first)."""
        if self.pending:
            settle(self)

    # -- state ---------------------------------------------------------------
    @property
    def actual(self) -> np.ndarray:
        """Actual positions (setpoint minus following error)."""
        self.settle()
        return self.x_set - self.e

    def set_position(self, index: int, value: float) -> None:
        """Redefine one axis position without motion (referencing, power on)."""
        self.settle()
        self.x_set[index] = value
        self.e[index] = 0.0
        self.e_model[index] = 0.0

    def enter_follow_up(self) -> None:
        """Alarm reaction: setpoints follow the actual values, monitors off until reset."""
        self.settle()
        self.x_set = self.actual.copy()
        self.e[:] = 0.0
        self.e_model[:] = 0.0
        self.v_set[:] = 0.0
        self.follow_up = True

    def reset(self) -> None:
        """RESET: back to position control with the monitors on."""
        self.settle()
        if self.follow_up:
            self.x_set = self.actual.copy()
            self.e[:] = 0.0
            self.e_model[:] = 0.0
        self.follow_up = False

    def settled(self) -> bool:
        """True when every axis stands still with no following error and no fault."""
        self.settle()
        if np.any(self.v_set != 0.0) or np.any(np.abs(self.e) > 1e-12) or np.any(np.abs(self.e_model) > 1e-12):
            return False
        return not any(f.active or f.push_mm for f in self.faults)

    def idle(self, n: int) -> None:
        """``n`` IPO cycles of standstill without any following error (fast path)."""
        self.settle()
        self.e[:] = 0.0
        self.e_model[:] = 0.0
        self.v_act[:] = 0.0
        self.v_cmd[:] = 0.0
        self.a_set[:] = 0.0
        self.stop_cycles = self.stop_cycles + n
        mech = self.mech
        self.torque = mech["gravity"] * mech["torque_per_n"]
        load = (self.torque / mech["rated_torque"]) ** 2
        target = AMBIENT_C + mech["temp_rise"] * load
        self.temperature = target + (self.temperature - target) * np.exp(-n * self.T / mech["thermal_time"])

    def in_window(self, indices: np.ndarray, window_mm: np.ndarray) -> bool:
        """True when every axis of ``indices`` has its following error inside its window."""
        self.settle()
        return bool(np.all(np.abs(self.e[indices]) <= window_mm[indices]))

    def cycles_to_window(self, indices: np.ndarray, window_mm: np.ndarray) -> int | None:
        """IPO cycles until the standstill following error decays into the window (None: never)."""
        self.settle()
        worst = 0
        for i in indices:
            fault = self.faults[i]
            err = abs(float(self.e[i]))
            if err <= window_mm[i]:
                continue
            if fault.active:
                return None
            k = math.ceil(math.log(window_mm[i] / err) / math.log(self.alpha[i])) if self.alpha[i] > 0 else 1
            worst = max(worst, k)
        return worst

    # -- one block of setpoints ----------------------------------------------
    def process(self, setpoints: np.ndarray, defer: bool = False) -> tuple[np.ndarray, Trip | None]:
        """Run the controllers over ``setpoints`` (m × n); return actual positions and a trip.

        On a trip only the cycles up to and including the trip index are taken
        over into the state; the caller discards the rest of the block.

        With ``defer`` a block whose monitors are proven silent is only queued
        (:mod:`nck.motion.servo_defer`; the rows must stay unchanged until
        :meth:`settle`) and the setpoints are returned in place of the actual
        positions, which the caller then must not use.
        """
        m = setpoints.shape[0]
        if m == 0:
            return setpoints.copy(), None
        if defer and self.monitoring and not self.follow_up and self._simple():
            bound = quiet_bound(self, setpoints)
            if bound is not None:
                self.pending.append(setpoints)
                self.pending_bound = bound
                return setpoints, None
        self.settle()
        if m == 1 and self._simple():
            return self._process_one(setpoints[0])
        if self.monitoring and not self.follow_up and m <= self.fast_rows and self._simple():
            fast = process_small(self, setpoints) if m <= SMALL_ROWS else process_fast(self, setpoints)
            if fast is not None:
                return fast, None
        T = self.T
        prev = np.vstack([self.x_set[None, :], setpoints])
        v = np.diff(prev, axis=0) / T
        e_model = first_order(self.alpha, self.b[None, :] * v, self.e_model)
        dev0 = self.e - self.e_model
        steps = np.arange(1, m + 1, dtype=float)[:, None]
        dev = dev0[None, :] * np.power(self.alpha[None, :], steps)
        for i, fault in enumerate(self.faults):
            if fault.push_mm:
                dev[:, i] += fault.push_mm * np.power(self.alpha[i], steps[:, 0] - 1.0)
            if fault.jam_at_mm is not None:
                dev[:, i] = (setpoints[:, i] - fault.jam_at_mm) - e_model[:, i]
            elif fault.runaway_mm_s:
                dev[:, i] = dev0[i] - fault.runaway_mm_s * T * steps[:, 0]
            elif fault.offset_mm:
                dev[:, i] = fault.offset_mm
        if self.follow_up:
            e_model = np.zeros_like(e_model)
            dev = np.zeros_like(dev)
        e = e_model + dev
        actual = setpoints - e
        pushed = np.array([f.push_mm for f in self.faults])
        # A push moves the actual value before this block: it is not a velocity of the block.
        prev_act = np.vstack([(self.x_set - self.e - pushed)[None, :], actual])
        v_act = np.diff(prev_act, axis=0) / T
        # Speed setpoint: P share on the error beyond what the feedforward path lags by itself.
        v_cmd = self.kv[None, :] * e + self.ffw_net[None, :] * v
        trip = None if (self.follow_up or not self.monitoring) else self._monitor(v, v_act, v_cmd, e, dev)
        last = m if trip is None else trip.index + 1
        self._commit(setpoints[:last], v[:last], e[:last], e_model[:last], v_act[:last], v_cmd[:last])
        for fault in self.faults:
            fault.push_mm = 0.0
        return actual[:last], trip

    def _simple(self) -> bool:
        """True when the one-cycle fast path applies (no faults, no delayed speed limit)."""
        if self.has_ctrlout_time:
            return False
        for fault in self.faults:  # (a loop: no generator per block)
            if fault.active or fault.push_mm:
                return False
        return True

    def _process_one(self, x: np.ndarray) -> tuple[np.ndarray, Trip | None]:
        """One IPO cycle without faults: the same model and monitors as :meth:`process`."""
        T = self.T
        lim = self.limits
        v = (x - self.x_set) / T
        e_model = self.alpha * self.e_model + self.b * v
        if self.follow_up:
            e_model = np.zeros_like(e_model)
            dev = np.zeros_like(e_model)
        else:
            dev = (self.e - self.e_model) * self.alpha
        e = e_model + dev
        actual = x - e
        v_act = (actual - (self.x_set - self.e)) / T
        v_cmd = self.kv * e + self.ffw_net * v
        moving = np.abs(v) > MOVING_MM_S
        abs_e = np.abs(e)
        fine = (abs_e <= lim["fine"]) & ~moving
        since = np.where(moving, 0, self.stop_cycles + 1)
        reached = ~moving & (self.fine_since_stop | fine)
        trip = None
        if not self.follow_up and self.monitoring:
            t_since = since * T
            tol = np.where(self.clamped, lim["clamp"], lim["still"])
            bad = ~moving & reached & (t_since >= lim["still_delay"]) & (abs_e > tol)
            checks = (
                (np.abs(dev) > lim["contour"], 25050),
                (np.abs(v_cmd) * self.speed_pct_per_mm_s > lim["ctrlout"], 25060),
                (np.abs(v_act) > lim["velo"], 25030),
                (~moving & ~reached & (t_since > lim["pos_time"]), 25080),
                (bad & self.clamped, 26000),
                (bad & ~self.clamped, 25040),
            )
            for mask, number in checks:
                if mask.any():
                    trip = Trip(0, number, self.axes[int(np.argmax(mask))].name)
                    break
            self.stop_cycles = np.where(moving, 0, self.stop_cycles + 1)
            self.fine_since_stop = np.where(moving, False, self.fine_since_stop | fine)
        a = (v - self.v_set) / T
        self.x_set = x.copy()
        self.v_set = v
        self.a_set = a
        self.e = e
        self.e_model = e_model
        self.v_act = v_act
        self.v_cmd = v_cmd
        mech = self.mech
        torque = (mech["mass"] * a / 1000.0 + mech["friction"] * np.sign(v_act) + mech["gravity"]) * mech["torque_per_n"]
        self.torque = torque
        target = AMBIENT_C + mech["temp_rise"] * (torque / mech["rated_torque"]) ** 2
        self.temperature = target + (self.temperature - target) * self.cycle_decay
        return actual[None, :], trip

    def _monitor(self, v: np.ndarray, v_act: np.ndarray, v_cmd: np.ndarray, e: np.ndarray, dev: np.ndarray) -> Trip | None:
        """Evaluate every monitor on the block, all axes at once; return the earliest trip."""
        m = v.shape[0]
        lim = self.limits
        candidates: list[tuple[int, int, int, int]] = []

        def earliest(mask: np.ndarray, number: int) -> None:
            # Ties within one cycle go to the monitor checked first.
            if mask.any():
                rows = np.argmax(mask, axis=0)
                hit = mask.any(axis=0)
                for col in np.flatnonzero(hit):
                    candidates.append((int(rows[col]), len(candidates), number, int(col)))

        earliest(np.abs(dev) > lim["contour"], 25050)
        speed_pct = np.abs(v_cmd) * (self.rpm_per_mm_s / self.rated_rpm * 100.0)
        over = speed_pct > lim["ctrlout"]
        if over.any():
            for col, axis in enumerate(self.axes):
                if axis.ctrlout_limit_time_s > 0.0:
                    over[:, col] = _longer_than(over[:, col], int(round(axis.ctrlout_limit_time_s / self.T)))
        earliest(over, 25060)
        earliest(np.abs(v_act) > lim["velo"], 25030)
        # Standstill monitors: cycles since the setpoint stopped moving, and whether
        # exact stop fine has been reached since then.
        idx = np.arange(m)[:, None]
        moving = np.abs(v) > MOVING_MM_S
        last_move = np.maximum.accumulate(np.where(moving, idx, -1), axis=0)
        since = np.where(last_move >= 0, idx - last_move, self.stop_cycles[None, :] + idx + 1)
        abs_e = np.abs(e)
        fine = (abs_e <= lim["fine"]) & ~moving
        fine_idx = np.maximum.accumulate(np.where(fine, idx, -1), axis=0)
        reached = np.where(last_move >= 0, fine_idx > last_move, (fine_idx >= 0) | self.fine_since_stop[None, :])
        t_since = since * self.T
        earliest(~moving & ~reached & (t_since > lim["pos_time"]), 25080)
        watch = ~moving & reached & (t_since >= lim["still_delay"])
        tol = np.where(self.clamped, lim["clamp"], lim["still"])
        bad = watch & (abs_e > tol[None, :])
        earliest(bad & self.clamped[None, :], 26000)
        earliest(bad & ~self.clamped[None, :], 25040)
        first = None
        if candidates:
            index, _order, number, col = min(candidates)
            first = Trip(index, number, self.axes[col].name)
        cut = m if first is None else first.index + 1
        mv = moving[:cut]
        any_move = mv.any(axis=0)
        last = np.where(any_move, cut - 1 - np.argmax(mv[::-1], axis=0), -1)
        fine_cut = fine[:cut]
        after_last = np.arange(cut)[:, None] > last[None, :]
        fine_after = (fine_cut & after_last).any(axis=0)
        self.stop_cycles = np.where(any_move, cut - 1 - last, self.stop_cycles + cut)
        self.fine_since_stop = np.where(any_move, fine_after, self.fine_since_stop | fine_after)
        return first

    def _commit(self, x: np.ndarray, v: np.ndarray, e: np.ndarray, e_model: np.ndarray,
                v_act: np.ndarray, v_cmd: np.ndarray) -> None:
        if x.shape[0] == 0:
            return
        T = self.T
        a = np.diff(np.vstack([self.v_set[None, :], v]), axis=0) / T
        self.x_set = x[-1].copy()
        self.v_set = v[-1].copy()
        self.a_set = a[-1].copy()
        self.e = e[-1].copy()
        self.e_model = e_model[-1].copy()
        self.v_act = v_act[-1].copy()
        self.v_cmd = v_cmd[-1].copy()
        duration = x.shape[0] * T
        mech = self.mech
        force = mech["mass"] * a / 1000.0 + mech["friction"] * np.sign(v_act) + mech["gravity"]
        torque = force * mech["torque_per_n"]
        self.torque = torque[-1].copy()
        load = np.mean((torque / mech["rated_torque"]) ** 2, axis=0)
        target = AMBIENT_C + mech["temp_rise"] * load
        decay = np.exp(-duration / mech["thermal_time"])
        self.temperature = target + (self.temperature - target) * decay

    # -- service values ------------------------------------------------------
    def state(self, i: int) -> AxisState:
        """Service-screen values of axis ``i``."""
        self.settle()
        axis = self.axes[i]
        v_set = float(self.v_set[i])
        fe = float(self.e[i])
        kv = abs(v_set) * 60.0 / 1000.0 / abs(fe) if abs(fe) > 1e-9 and abs(v_set) > MOVING_MM_S else 0.0
        rpm = self.rpm_per_mm_s[i]
        rated = self.rated_rpm[i]
        return AxisState(
            name=axis.name,
            position_setpoint_mm=float(self.x_set[i]),
            position_actual_mm=float(self.x_set[i] - self.e[i]),
            following_error_mm=fe,
            control_deviation_mm=fe,
            contour_deviation_mm=float(self.e[i] - self.e_model[i]),
            velocity_setpoint_mm_min=v_set * 60.0,
            velocity_actual_mm_min=float(self.v_act[i]) * 60.0,
            kv_calculated=kv,
            speed_setpoint_pct=float(self.v_cmd[i]) * rpm / rated * 100.0,
            speed_actual_pct=float(self.v_act[i]) * rpm / rated * 100.0,
            motor_speed_setpoint_rpm=float(self.v_cmd[i]) * rpm,
            motor_speed_actual_rpm=float(self.v_act[i]) * rpm,
            torque_nm=float(self.torque[i]),
            current_pct=abs(float(self.torque[i])) / max(axis.rated_torque_nm, 1e-9) * 100.0,
            motor_temperature_c=float(self.temperature[i]),
            controller_mode=4 if self.follow_up else 0,
            exact_stop_coarse=abs(fe) <= axis.stop_limit_coarse_mm,
            exact_stop_fine=abs(fe) <= axis.stop_limit_fine_mm,
            clamped=bool(self.clamped[i]),
        )


def _longer_than(mask: np.ndarray, cycles: int) -> np.ndarray:
    """True where ``mask`` has been true for more than ``cycles`` consecutive samples."""
    out = np.zeros_like(mask)
    run = 0
    for k, flag in enumerate(mask):
        run = run + 1 if flag else 0
        out[k] = run > cycles
    return out
