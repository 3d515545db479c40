"""The servo model of every path axis as data: its tables and its state.

:class:`ServoModel` holds what the position controllers, drives and monitors of
:mod:`nck.motion.servo` compute with — the per-axis constants of the control
law and the monitors (from the axis parameters and the IPO cycle), the tables
of the fast paths, and the state that changes every IPO cycle (setpoints,
following errors, velocities, torque, temperature, standstill book-keeping,
queued blocks). The behaviour lives in functions over it:
:class:`nck.motion.servo.ServoBank` (the full model, monitors, service values),
:mod:`nck.motion.servo_paths` (the fast paths) and :mod:`nck.motion.servo_defer`
(the deferred queue). Everything here is read and written by those three only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from nck.motion.params import AxisParams

AMBIENT_C = 25.0  # motor temperature at rest (°C)
MOVING_MM_S = 1e-6  # below this setpoint velocity an axis counts as stopped
FAST_ROWS = 2500  # longest block of the fast path (fewer when alpha^-k would grow past e^200)
SAFETY = 1.0 - 1e-6  # the deferred queue's bounds must hold with room for rounding


@dataclass
class Fault:
    """A simulated mechanical fault of one axis (tests and training)."""

    jam_at_mm: float | None = None  # actual position frozen
    offset_mm: float = 0.0  # steady deviation the controller cannot remove
    runaway_mm_s: float = 0.0  # the actual drifts at this velocity
    push_mm: float = 0.0  # one-off displacement, applied at the next cycle

    @property
    def active(self) -> bool:
        return self.jam_at_mm is not None or self.offset_mm != 0.0 or self.runaway_mm_s != 0.0


class ServoModel:
    """Tables and state of the position controllers, drives and monitors of all path axes."""

    def __init__(self, axes: tuple[AxisParams, ...], ipo_cycle_s: float, positions: np.ndarray) -> None:
        self.axes = axes
        self.T = ipo_cycle_s
        n = len(axes)
        self.kv = np.array([a.kv_per_s for a in axes])
        self.alpha = np.exp(-self.kv * self.T)
        gain = np.array([1.0 - a.ffw_weight + a.ffw_weight * a.kv_per_s * a.equiv_speedctrl_time_s for a in axes])
        self.b = (1.0 - self.alpha) / self.kv * gain
        self.ffw = np.array([a.ffw_weight for a in axes])
        self.ffw_net = np.array([a.ffw_weight * (1.0 - a.kv_per_s * a.equiv_speedctrl_time_s) for a in axes])
        self.x_set = positions.astype(float).copy()
        self.v_set = np.zeros(n)
        self.e = np.zeros(n)
        self.e_model = np.zeros(n)
        self.v_act = np.zeros(n)
        self.v_cmd = np.zeros(n)
        self.a_set = np.zeros(n)
        self.temperature = np.full(n, AMBIENT_C)
        self.torque = np.zeros(n)
        self.faults = [Fault() for _ in axes]
        self.clamped = np.zeros(n, dtype=bool)
        self.follow_up = False
        self.monitoring = True
        self.stop_cycles = np.full(n, 10**9, dtype=np.int64)  # cycles since the axis stopped
        self.fine_since_stop = np.ones(n, dtype=bool)
        self.rpm_per_mm_s = np.array([a.motor_rpm_per_mm_s for a in axes])
        self.rated_rpm = np.array([max(a.rated_motor_rpm, 1.0) for a in axes])
        self.limits = {
            "contour": np.array([a.contour_tol_mm for a in axes]),
            "ctrlout": np.array([a.ctrlout_limit_pct for a in axes]),
            "velo": np.array([a.velo_limit_mm_s * (1.0 + 1e-9) for a in axes]),
            "fine": np.array([a.stop_limit_fine_mm for a in axes]),
            "pos_time": np.array([a.positioning_time_s for a in axes]),
            "still_delay": np.array([a.standstill_delay_s for a in axes]),
            "still": np.array([a.standstill_tol_mm for a in axes]),
            "clamp": np.array([a.clamp_tol_mm for a in axes]),
        }
        self.has_ctrlout_time = any(a.ctrlout_limit_time_s > 0.0 for a in axes)
        self.speed_pct_per_mm_s = self.rpm_per_mm_s / self.rated_rpm * 100.0
        self.cycle_decay = np.exp(-ipo_cycle_s / np.array([max(a.thermal_time_s, 1e-6) for a in axes]))
        self.mech = {
            "mass": np.array([a.mass_kg for a in axes]),
            "friction": np.array([a.friction_n for a in axes]),
            "gravity": np.array([a.gravity_n for a in axes]),
            "torque_per_n": np.array([
                a.leadscrew_pitch_mm / 1000.0 / (2.0 * math.pi) / max(a.gear_ratio, 1e-9) for a in axes
            ]),
            "rated_torque": np.array([max(a.rated_torque_nm, 1e-9) for a in axes]),
            "temp_rise": np.array([a.rated_temp_rise_k for a in axes]),
            "thermal_time": np.array([max(a.thermal_time_s, 1e-6) for a in axes]),
        }
        # Fast path tables: alpha^k and alpha^-k for k = 1 … FAST_ROWS, and the
        # following error below which no standstill monitor can respond.
        ln_alpha = np.log(np.clip(self.alpha, 1e-300, 1.0))
        rate = float(np.max(-ln_alpha)) if n else 0.0
        self.fast_rows = FAST_ROWS if rate <= 1e-12 else max(1, min(FAST_ROWS, int(200.0 / rate)))
        steps = np.arange(1, self.fast_rows + 1, dtype=float)[:, None]
        self.powers = np.exp(ln_alpha[None, :] * steps)
        self.inv_powers = np.exp(-ln_alpha[None, :] * steps)
        self.b_inv_powers = self.b[None, :] * self.inv_powers
        self.ones = np.ones(self.fast_rows)
        self.cols = np.arange(n)
        self.inv_t = 1.0 / ipo_cycle_s
        with np.errstate(divide="ignore"):
            self.ctrlout_mm_s = np.where(self.speed_pct_per_mm_s > 0.0,
                                          self.limits["ctrlout"] / self.speed_pct_per_mm_s, np.inf)
        mech = self.mech
        self.torque_per_dv = mech["mass"] / 1000.0 * mech["torque_per_n"] / ipo_cycle_s
        self.torque_friction = mech["friction"] * mech["torque_per_n"]
        self.torque_gravity = mech["gravity"] * mech["torque_per_n"]
        self.inv_rated_torque = 1.0 / mech["rated_torque"]
        self.zero_cycles = np.zeros(n, dtype=np.int64)
        self.no_fine = np.zeros(n, dtype=bool)
        rows = np.arange(self.fast_rows + 1, dtype=float)
        rows[0] = 1.0
        self.temp_rise_per_m = mech["temp_rise"][None, :] / rows[:, None]
        self.decay_pow = np.power(self.cycle_decay[None, :], np.arange(self.fast_rows + 1, dtype=float)[:, None])
        # Per-axis constants of the small-block path, as Python floats.
        self.small_limits = [
            (float(self.alpha[i]), float(self.b[i]), float(self.kv[i]), float(self.ffw_net[i]),
             float(self.limits["contour"][i]), float(self.ctrlout_mm_s[i]), float(self.limits["velo"][i]),
             float(self.limits["fine"][i]), float(self.limits["pos_time"][i]),
             float(self.limits["still_delay"][i]), float(self.limits["still"][i]), float(self.limits["clamp"][i]),
             float(self.torque_per_dv[i]), float(self.torque_friction[i]), float(self.torque_gravity[i]),
             float(self.inv_rated_torque[i]), float(mech["temp_rise"][i]), float(self.cycle_decay[i]))
            for i in range(n)
        ]
        self.small_e = np.minimum(self.limits["fine"], np.minimum(self.limits["still"], self.limits["clamp"]))
        # Deferred blocks (nck.motion.servo_defer): queued setpoints and their error bound.
        self.bound_tables = make_bound_tables(self)
        self.pending: list[np.ndarray] = []
        self.pending_bound: list[float] | None = None


def make_bound_tables(model: ServoModel) -> list[tuple[float, float, float, float, float, float, float, float]]:
    """Per-axis constants of :func:`nck.motion.servo_defer.quiet_bound` as Python floats."""
    limits = model.limits
    tables = []
    for i in range(len(model.axes)):
        alpha, b = float(model.alpha[i]), abs(float(model.b[i]))
        e_per_v = b / (1.0 - alpha) if alpha < 1.0 else float("inf")
        tables.append((
            e_per_v, float(model.kv[i]), abs(float(model.ffw_net[i])),
            float(model.ctrlout_mm_s[i]) * SAFETY, float(limits["velo"][i]) * SAFETY,
            (1.0 - alpha) * model.inv_t, b * model.inv_t, float(model.small_e[i]) * SAFETY,
        ))
    return tables
