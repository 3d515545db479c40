"""Machine data the motion system reads, converted to internal units (mm, s).

Every value comes from the machine file (``MD<number>`` keys, see
``data/machines/*.toml``) with a realistic default when a file leaves it out.
MD velocities are mm/min, accelerations m/s², jerk m/s³, Kv (m/min)/mm;
internally everything is mm, mm/s, mm/s², mm/s³ and 1/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from nck.machine import MachineConfig
from nck.md_catalog import catalog

#: Every MD number this package reads (listed for the MD catalogue).
MD_READ = (
    10050, 10070, 20602, 28060, 31030, 31050, 31060, 31090, 32000, 32010, 32020,
    32200, 32260, 32300, 32310, 32431, 32433, 32434, 32435, 32610, 32620, 32810, 34000,
    34010, 34020, 34030, 34040, 34060, 34070, 34080, 34090, 34100, 34110, 35100, 35130,
    35140, 35200, 36000, 36010, 36020, 36030, 36040, 36050, 36100, 36110, 36200, 36210,
    36220, 36400, 36610,
)


@dataclass(frozen=True, slots=True)
class AxisParams:
    """Dynamics, control and monitoring data of one path axis (internal units)."""

    name: str
    index: int
    rotary: bool
    max_velo_mm_s: float
    max_accel_mm_s2: float
    max_jerk_mm_s3: float
    accel_ovl_factor: float
    soft_accel_factor: float
    g0_accel_factor: float
    g0_jerk_factor: float
    kv_per_s: float
    ffw_weight: float
    equiv_speedctrl_time_s: float
    stop_limit_coarse_mm: float
    stop_limit_fine_mm: float
    positioning_time_s: float
    standstill_tol_mm: float
    standstill_delay_s: float
    clamp_tol_mm: float
    pos_limit_minus_mm: float
    pos_limit_plus_mm: float
    velo_limit_mm_s: float
    ctrlout_limit_pct: float
    ctrlout_limit_time_s: float
    contour_tol_mm: float
    emergency_stop_time_s: float
    jog_velo_mm_min: float
    jog_velo_rapid_mm_min: float
    # drive train and simulated mechanics
    leadscrew_pitch_mm: float
    gear_ratio: float  # motor revolutions per load revolution
    rated_motor_rpm: float
    mass_kg: float
    friction_n: float
    gravity_n: float
    rated_torque_nm: float
    thermal_time_s: float
    rated_temp_rise_k: float
    # reference point approach
    ref_cam_active: bool
    ref_cam_dir_minus: bool
    ref_velo_search_cam_mm_s: float
    ref_max_cam_dist_mm: float
    ref_velo_search_marker_mm_s: float
    ref_max_marker_dist_mm: float
    ref_velo_pos_mm_s: float
    ref_move_dist_mm: float
    ref_set_pos_mm: float
    ref_cycle_nr: int
    ref_cam_mm: float
    power_on_mm: float
    hw_limit_minus_mm: float = -math.inf  # hardware limit switches, raw encoder coordinate (mechanics)
    hw_limit_plus_mm: float = math.inf
    brake_mode_choice: int = 0  # MD36600: 0 ramp with MD32300, 1 setpoint velocity zero at once

    @property
    def motor_rpm_per_mm_s(self) -> float:
        """Motor speed in rpm for 1 mm/s of axis velocity."""
        if self.rotary:
            return 60.0 / 360.0 * self.gear_ratio
        return 60.0 / max(self.leadscrew_pitch_mm, 1e-9) * self.gear_ratio


@dataclass(frozen=True, slots=True)
class SpindleParams:
    """Speed limits, acceleration and simulated mechanics of one spindle."""

    name: str
    index: int
    max_rpm: float
    gear_max_rpm: float
    gear_min_rpm: float
    accel_rev_s2: float
    posctrl_accel_rev_s2: float  # MD35210: acceleration while positioning (SPOS, M19)
    posctrl_rpm: float  # MD35300: speed of the positioning move
    jog_rpm: float
    velo_limit_rpm: float
    rated_motor_rpm: float
    rated_torque_nm: float
    inertia_kgm2: float
    thermal_time_s: float
    rated_temp_rise_k: float
    speed_tolerance: float = 0.1  # MD35150: the set speed range is ± this share of the set speed
    on_speed_at_ipo_start: int = 1  # MD35500: a machining block waits for the set speed range (0: never)


@dataclass(frozen=True, slots=True)
class MotionParams:
    """Channel-wide data: IPO cycle, buffer size, arc acceleration share; all axes."""

    ipo_cycle_s: float
    buffer_segments: int
    curv_effect: float
    jog_incr_weight_mm: float
    axes: tuple[AxisParams, ...]
    spindles: tuple[SpindleParams, ...]
    dwell_resumes: bool = False  # MD11470 bit 0: NC START resumes an interrupted dwell

    def axis(self, name: str) -> AxisParams:
        """The parameters of path axis ``name``."""
        for axis in self.axes:
            if axis.name == name:
                return axis
        raise KeyError(name)


def _axis_params(machine: MachineConfig, name: str, index: int, rotary: bool) -> AxisParams:
    md = machine.md_float
    sim = machine.sim_float
    vmax = md("MD32000", name, 10000.0) / 60.0
    ffw_mode = int(md("MD32620", name, 0))
    cam_dir_minus = bool(md("MD34010", name, 0))
    direction = -1.0 if cam_dir_minus else 1.0
    return AxisParams(
        name=name,
        index=index,
        rotary=rotary,
        max_velo_mm_s=vmax,
        max_accel_mm_s2=md("MD32300", name, 1.0) * 1000.0,
        max_jerk_mm_s3=md("MD32431", name, 1000.0) * 1000.0,
        accel_ovl_factor=max(md("MD32310", name, 1.2), 1.0),
        soft_accel_factor=md("MD32433", name, 1.0),
        g0_accel_factor=md("MD32434", name, 1.0),
        g0_jerk_factor=md("MD32435", name, 1.0),
        kv_per_s=max(md("MD32200", name, 1.0), 1e-6) * 1000.0 / 60.0,
        ffw_weight=md("MD32610", name, 1.0) if ffw_mode in (3, 4) else 0.0,
        equiv_speedctrl_time_s=md("MD32810", name, 0.0015),
        stop_limit_coarse_mm=md("MD36000", name, 0.04),
        stop_limit_fine_mm=md("MD36010", name, 0.01),
        positioning_time_s=md("MD36020", name, 1.0),
        standstill_tol_mm=md("MD36030", name, 0.2),
        standstill_delay_s=md("MD36040", name, 0.4),
        clamp_tol_mm=md("MD36050", name, 0.5),
        pos_limit_minus_mm=md("MD36100", name, -1e8),
        pos_limit_plus_mm=md("MD36110", name, 1e8),
        velo_limit_mm_s=md("MD36200", name, vmax * 60.0 * 1.15) / 60.0,
        ctrlout_limit_pct=md("MD36210", name, 110.0),
        ctrlout_limit_time_s=md("MD36220", name, 0.0),
        contour_tol_mm=md("MD36400", name, 1.0),
        emergency_stop_time_s=md("MD36610", name, 0.05),
        jog_velo_mm_min=md("MD32020", name, 2000.0),
        jog_velo_rapid_mm_min=md("MD32010", name, 10000.0),
        leadscrew_pitch_mm=md("MD31030", name, 10.0),
        gear_ratio=md("MD31060", name, 1.0) / max(md("MD31050", name, 1.0), 1e-9),
        rated_motor_rpm=md("MD32260", name, 3000.0),
        mass_kg=sim("mass_kg", name, 300.0),
        friction_n=sim("friction_n", name, 300.0),
        gravity_n=sim("gravity_n", name, 0.0),
        rated_torque_nm=sim("rated_torque_nm", name, 10.0),
        thermal_time_s=sim("thermal_time_s", name, 900.0),
        rated_temp_rise_k=sim("rated_temp_rise_k", name, 80.0),
        ref_cam_active=bool(md("MD34000", name, 1)),
        ref_cam_dir_minus=cam_dir_minus,
        ref_velo_search_cam_mm_s=md("MD34020", name, 5000.0) / 60.0,
        ref_max_cam_dist_mm=md("MD34030", name, 10000.0),
        ref_velo_search_marker_mm_s=md("MD34040", name, 300.0) / 60.0,
        ref_max_marker_dist_mm=md("MD34060", name, 20.0),
        ref_velo_pos_mm_s=md("MD34070", name, 10000.0) / 60.0,
        ref_move_dist_mm=md("MD34080", name, -2.0) + md("MD34090", name, 0.0),
        ref_set_pos_mm=md("MD34100", name, 0.0),
        ref_cycle_nr=int(md("MD34110", name, 1)),
        ref_cam_mm=sim("ref_cam_mm", name, 5.0 * direction),
        power_on_mm=sim("power_on_mm", name, 0.0),
        hw_limit_minus_mm=sim("hw_limit_minus_mm", name, -math.inf),
        hw_limit_plus_mm=sim("hw_limit_plus_mm", name, math.inf),
        brake_mode_choice=int(md("MD36600", name, 0)),
    )


def _spindle_params(machine: MachineConfig, name: str, index: int) -> SpindleParams:
    md = machine.md_float
    sim = machine.sim_float
    max_rpm = md("MD35100", name, md("MD32000", name, 10000.0))
    return SpindleParams(
        name=name,
        index=index,
        max_rpm=max_rpm,
        gear_max_rpm=md("MD35130", name, max_rpm),
        gear_min_rpm=md("MD35140", name, 0.0),
        accel_rev_s2=max(md("MD35200", name, 30.0), 1e-3),
        posctrl_accel_rev_s2=max(md("MD35210", name, 30.0), 1e-3),
        posctrl_rpm=max(md("MD35300", name, 500.0), 1e-3),
        jog_rpm=md("MD32020", name, 100.0),
        velo_limit_rpm=md("MD36200", name, max_rpm * 1.1),
        rated_motor_rpm=md("MD32260", name, max_rpm),
        rated_torque_nm=sim("rated_torque_nm", name, 50.0),
        inertia_kgm2=sim("spindle_inertia_kgm2", name, 0.05),
        thermal_time_s=sim("thermal_time_s", name, 1200.0),
        rated_temp_rise_k=sim("rated_temp_rise_k", name, 90.0),
        speed_tolerance=max(md("MD35150", name, _default("MD35150")), 0.0),
        on_speed_at_ipo_start=int(md("MD35500", name, _default("MD35500"))),
    )


def _default(ident: str) -> float:
    """The catalogue's default of a numeric machine datum."""
    definition = catalog().get(ident)
    assert definition is not None, ident
    return float(definition.default)


def motion_params(machine: MachineConfig) -> MotionParams:
    """Read every motion-relevant machine datum of ``machine``."""
    md = machine.md_float
    sysclock = md("MD10050", None, 0.001)
    ratio = md("MD10070", None, 4.0)
    axes = tuple(
        _axis_params(machine, a.name, i, a.kind == "rotary")
        for i, a in enumerate(a for a in machine.axes if a.kind != "spindle")
    )
    spindles = tuple(
        _spindle_params(machine, a.name, i)
        for i, a in enumerate(a for a in machine.axes if a.kind == "spindle")
    )
    return MotionParams(
        ipo_cycle_s=max(sysclock * ratio, 1e-4),
        buffer_segments=max(int(md("MD28060", None, 64)), 2),
        curv_effect=min(max(md("MD20602", None, 0.5), 0.0), 0.95),
        jog_incr_weight_mm=md("MD31090", None, 0.001),
        axes=axes,
        spindles=spindles,
        dwell_resumes=bool(int(md("MD11470", None, 0)) & 1),
    )
