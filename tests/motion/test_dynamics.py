"""Planner and interpolator: limits, corners, exact stop, hold/resume, overrides, Kv."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck.motion.params import motion_params
from tests.motion.helpers import derivatives, dwell, machine, motion, move, run_to_idle

MILL = motion_params(machine())
VMAX = np.array([a.max_velo_mm_s for a in MILL.axes])
AMAX = np.array([a.max_accel_mm_s2 for a in MILL.axes])
JMAX = np.array([a.max_jerk_mm_s3 for a in MILL.axes])
OVL = np.array([a.accel_ovl_factor for a in MILL.axes])


def test_ipo_cycle_comes_from_machine_data() -> None:
    m = motion()
    assert m.ipo_cycle_s == pytest.approx(0.004)
    m2 = motion(MD10070=2)
    assert m2.ipo_cycle_s == pytest.approx(0.002)


def test_long_g1_reaches_end_at_programmed_feed() -> None:
    m = motion()
    t = run_to_idle(m, feed=[move("G1", 1000.0, X=100.0)])
    _rows, v, _a, _j = derivatives(m)
    assert np.abs(v[:, 0]).max() * 60.0 == pytest.approx(1000.0, rel=1e-6)
    assert m.positions_mcs()["X"] == pytest.approx(100.0, abs=0.04)
    assert 6.0 <= t <= 6.5


def test_brisk_acceleration_equals_md32300() -> None:
    """Digest 828d-1 rank 8 (BRISK at MD32300, 002 L1866, L7624)."""
    m = motion()
    run_to_idle(m, feed=[move("G1", 6000.0, X=100.0)])
    _rows, _v, a, _j = derivatives(m)
    assert np.abs(a[:, 0]).max() == pytest.approx(AMAX[0], rel=1e-6)


def test_soft_limits_jerk_and_takes_longer_than_brisk() -> None:
    """Digest 828d-1 rank 8 (SOFT limited by MD32431, 002 L7641)."""
    brisk = motion()
    t_brisk = run_to_idle(brisk, step_s=0.004, feed=[move("G1", 12000.0, X=100.0)])
    soft = motion()
    t_soft = run_to_idle(soft, step_s=0.004, feed=[move("G1", 12000.0, soft=True, X=100.0)])
    _rows, _v, a, j = derivatives(soft)
    assert np.abs(j[:, 0]).max() <= JMAX[0] * 1.000001
    assert np.abs(a[:, 0]).max() <= AMAX[0] * 1.000001
    assert t_soft > t_brisk


def test_path_velocity_limited_by_slowest_axis() -> None:
    m = motion()
    run_to_idle(m, feed=[move("G0", X=300.0, Z=300.0)])
    _rows, v, _a, _j = derivatives(m)
    assert np.abs(v[:, 2]).max() == pytest.approx(VMAX[2], rel=1e-6)
    assert np.abs(v[:, 0]).max() <= VMAX[0]


def test_short_block_limit() -> None:
    m = motion()
    run_to_idle(m, feed=[move("G1", 20000.0, X=0.1 * (k + 1)) for k in range(50)])
    _rows, v, _a, _j = derivatives(m)
    limit = 0.9 * 0.1 / m.ipo_cycle_s
    assert np.abs(v[:, 0]).max() <= limit * 1.0001


def test_g64_corner_is_passed_with_reduced_nonzero_velocity() -> None:
    """Digest 828d-1 rank 7 (G64: corner velocity above 0).

    Digest programming-840c rank 15.
    """
    m = motion()
    m.push(move("G1", 6000.0, X=50.0))
    m.push(move("G1", 6000.0, X=50.0, Y=50.0))
    speeds = []
    while not m.is_idle():
        m.advance(m.ipo_cycle_s)
        speeds.append(float(np.hypot(*m.servo.v_set[:2])))
    speeds_arr = np.array(speeds)
    # No standstill between the start and the end of the two blocks.
    moving = np.flatnonzero(speeds_arr > 0)
    inner = speeds_arr[moving[0]:moving[-1]]
    assert inner.min() > 0.0
    assert inner.min() < 0.1 * 100.0  # well below F6000 = 100 mm/s at the corner


def test_g60_stops_at_the_corner_and_waits_for_the_fine_window() -> None:
    """Digest 828d-1 rank 7: G60 stops at the corner inside STOP_LIMIT_FINE (002 L1919, L4703-4761).

    Digest programming-840c rank 15.
    """
    m = motion(MD32620={"X": 0, "Y": 0}, MD32200={"X": 1.0, "Y": 1.0})
    m.push(move("G1", 6000.0, exact_stop=True, X=50.0))
    m.push(move("G1", 6000.0, X=50.0, Y=50.0))
    last_fe = None
    while m.servo.x_set[1] == 0.0:
        last_fe = m.servo.e.copy()
        m.advance(m.ipo_cycle_s)
        assert m.time_s < 10.0
    assert last_fe is not None
    assert abs(last_fe[0]) <= 0.01  # MD36010 exact stop fine
    assert m.servo.x_set[0] == pytest.approx(50.0)


def test_g602_changes_block_earlier_than_g601() -> None:
    """Digest 828d-1 rank 7 (G601/G602/G603 block change order, 002 L4703-4761)."""
    def block_change(window: str) -> float:
        m = motion(MD32620={"X": 0, "Y": 0}, MD32200={"X": 1.0, "Y": 1.0})
        m.push(move("G1", 6000.0, exact_stop=True, window=window, X=50.0))
        m.push(move("G1", 6000.0, X=50.0, Y=50.0))
        while m.servo.x_set[1] == 0.0:
            m.advance(m.ipo_cycle_s)
        return m.time_s

    assert block_change("G602") < block_change("G601")
    assert block_change("G603") < block_change("G602")


def test_nc_stop_brakes_on_ramp_and_nc_start_reaches_end_point() -> None:
    m = motion()
    m.push(move("G1", 3000.0, X=100.0))
    m.advance(1.0)
    m.hold()
    velocities = []
    for _ in range(100):
        m.advance(m.ipo_cycle_s)
        velocities.append(float(m.servo.v_set[0]))
    assert velocities[0] > 0.0  # braking, not an instant stop
    assert velocities[-1] == 0.0
    assert np.all(np.diff(velocities) <= 1e-9)
    stopped_at = m.positions_mcs()["X"]
    m.advance(2.0)
    assert m.positions_mcs()["X"] == pytest.approx(stopped_at, abs=1e-3)
    assert not m.is_idle()
    m.resume()
    run_to_idle(m)
    assert m.positions_mcs()["X"] == pytest.approx(100.0, abs=0.04)


def test_repos_returns_to_the_hold_point_after_jog() -> None:
    m = motion()
    m.push(move("G1", 3000.0, X=100.0))
    m.advance(1.0)
    m.hold()
    m.advance(0.5)
    held_y = m.positions_mcs()["Y"]
    m.jog_increment("Y", 5.0, 2000.0)
    m.advance(1.0)
    assert m.positions_mcs()["Y"] == pytest.approx(held_y + 5.0, abs=0.01)
    m.reposition(None)
    m.resume()
    run_to_idle(m)
    pos = m.positions_mcs()
    assert pos["X"] == pytest.approx(100.0, abs=0.04)
    assert pos["Y"] == pytest.approx(held_y, abs=0.04)


def test_feed_override_50_percent_doubles_time_of_long_g1() -> None:
    """Digest 828d-3 rank 9 (50 % doubles the block time)."""
    def duration(percent: float) -> float:
        m = motion()
        m.set_overrides(percent, 100.0)
        return run_to_idle(m, feed=[move("G1", 1000.0, X=300.0)])

    assert duration(50.0) / duration(100.0) == pytest.approx(2.0, rel=0.02)


def test_override_changes_on_the_fly_and_zero_stops_the_path() -> None:
    m = motion()
    m.push(move("G1", 3000.0, X=200.0))
    m.advance(0.5)
    m.set_overrides(50.0, 100.0)
    m.advance(1.0)
    assert m.axis_states()["X"].velocity_setpoint_mm_min == pytest.approx(1500.0)
    m.set_overrides(0.0, 100.0)
    m.advance(1.0)
    assert m.axis_states()["X"].velocity_setpoint_mm_min == 0.0
    assert not m.is_idle()
    m.set_overrides(120.0, 100.0)
    m.advance(1.0)
    assert m.axis_states()["X"].velocity_setpoint_mm_min == pytest.approx(3600.0)
    run_to_idle(m)
    assert m.positions_mcs()["X"] == pytest.approx(200.0, abs=0.04)


def test_rapid_override_scales_g0_only() -> None:
    m = motion()
    m.set_overrides(100.0, 25.0)
    run_to_idle(m, feed=[move("G0", X=300.0)])
    _rows, v, _a, _j = derivatives(m)
    assert np.abs(v[:, 0]).max() == pytest.approx(VMAX[0] * 0.25, rel=1e-6)


def test_dry_run_feed_replaces_a_slower_programmed_feed() -> None:
    m = motion()
    m.set_dry_run(5000.0, 0)
    run_to_idle(m, feed=[move("G1", 100.0, X=100.0)])
    _rows, v, _a, _j = derivatives(m)
    assert np.abs(v[:, 0]).max() * 60.0 == pytest.approx(5000.0, rel=1e-6)


def test_dwell_waits_its_time() -> None:
    m = motion()
    t_plain = run_to_idle(m, feed=[move("G1", 3000.0, X=10.0), move("G1", 3000.0, X=20.0)])
    m2 = motion()
    t_dwell = run_to_idle(m2, feed=[move("G1", 3000.0, X=10.0), dwell(1.5), move("G1", 3000.0, X=20.0)])
    assert t_dwell - t_plain == pytest.approx(1.5 + 0.1, abs=0.25)


def test_arc_reaches_end_with_radius_kept() -> None:
    m = motion()
    run_to_idle(m, feed=[
        move("G1", 2000.0, X=10.0),
        move("G3", 2000.0, X=-10.0, Y=0.0, center={"X": 0.0, "Y": 0.0}),
    ])
    rows, _v, _a, _j = derivatives(m)
    on_arc = rows[rows[:, 1] > 1e-6]
    assert np.allclose(np.hypot(on_arc[:, 0], on_arc[:, 1]), 10.0, atol=1e-6)
    assert on_arc[:, 1].max() == pytest.approx(10.0, abs=1e-3)  # G3 from +X goes through +Y
    assert m.positions_mcs()["X"] == pytest.approx(-10.0, abs=0.04)


def test_kv_gives_following_error_v_over_kv() -> None:
    """Digest 828d-1 rank 1: FE = v/Kv, F1000 at Kv 1 gives 1 mm (002 L837-842, L1855-1860)."""
    m = motion(MD32620={"X": 0}, MD32200={"X": 1.0})
    m.push(move("G1", 1000.0, X=100.0))
    m.advance(3.0)
    state = m.axis_states()["X"]
    assert state.following_error_mm == pytest.approx(1.0, rel=0.02)
    assert state.kv_calculated == pytest.approx(1.0, rel=0.02)


def test_feedforward_reduces_following_error() -> None:
    """Digest 828d-1 rank 1 (feedforward variant: FE near 0)."""
    m = motion()
    m.push(move("G1", 1000.0, X=100.0))
    m.advance(3.0)
    assert 0.0 < m.axis_states()["X"].following_error_mm < 0.1


def test_drive_values_follow_motion() -> None:
    """Digest 828d-1 rank 20 (simulated axes still show a following error, 002 L1663)."""
    m = motion()
    before = m.axis_states()["X"].motor_temperature_c
    m.push(move("G1", 20000.0, X=400.0))
    m.advance(0.05)
    accelerating = m.axis_states()["X"]
    assert accelerating.torque_nm > 0.0 and accelerating.current_pct > 0.0
    m.advance(0.5)
    cruising = m.axis_states()["X"]
    assert cruising.motor_speed_setpoint_rpm == pytest.approx(2000.0, rel=0.02)
    assert 0.0 < cruising.speed_setpoint_pct < 100.0
    run_to_idle(m)
    assert m.axis_states()["X"].motor_temperature_c > before


# ---------------------------------------------------------------- property test
def _programs() -> st.SearchStrategy:
    point = st.tuples(
        st.floats(-200, 200, allow_nan=False), st.floats(-200, 200, allow_nan=False),
        st.floats(-100, 100, allow_nan=False),
    )
    block = st.tuples(
        st.sampled_from(["G0", "G1", "G1", "G2", "G3"]), point,
        st.floats(500, 20000), st.booleans(), st.floats(2.0, 40.0),
    )
    return st.tuples(st.booleans(), st.lists(block, min_size=1, max_size=6), st.floats(50, 120))


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_programs())
def test_velocity_acceleration_jerk_never_exceed_machine_data(program) -> None:
    soft, blocks, override = program
    m = motion()
    m.set_overrides(override, override)
    items = []
    pos = np.zeros(3)
    for kind, (x, y, z), feed, exact, radius in blocks:
        end = {"X": x, "Y": y, "Z": z}
        if kind in ("G2", "G3"):
            # Centre at ``radius`` to the side of the start, end on that circle.
            cx, cy = pos[0] + radius, pos[1]
            angle = math.atan2(y, x)
            end = {"X": cx + radius * math.cos(angle), "Y": cy + radius * math.sin(angle), "Z": z}
            items.append(move(kind, feed, soft=soft, exact_stop=exact, center={"X": cx, "Y": cy}, **end))
        else:
            items.append(move(kind, feed, soft=soft, exact_stop=exact, **end))
        pos = np.array([end["X"], end["Y"], end["Z"]])
    run_to_idle(m, step_s=0.25, feed=items)
    rows, v, a, j = derivatives(m)
    if rows.shape[0] < 4:
        return
    assert np.all(np.abs(v) <= VMAX * (1 + 1e-6) + 1e-6)
    # At continuous-path corners MD32310 allows the overload factor.
    assert np.all(np.abs(a) <= AMAX * OVL * (1 + 1e-6) + 1e-3)
    if soft:
        assert np.all(np.abs(j) <= JMAX * OVL * (1 + 1e-6) + 1e-1)
    assert np.allclose(rows[-1], pos, atol=1e-9)


def test_result_does_not_depend_on_the_step_size() -> None:
    program = [move("G1", 4000.0, X=30.0), move("G1", 4000.0, X=30.0, Y=20.0),
               move("G2", 3000.0, X=50.0, Y=40.0, center={"X": 50.0, "Y": 20.0}), move("G0", Z=50.0)]

    def run(step: float) -> np.ndarray:
        m = motion()
        for item in program:
            m.push(item)
        for _ in range(int(round(4.0 / step))):
            m.advance(step)
        return m.trace()[1]

    per_cycle = run(0.004)
    blocks = run(0.5)
    assert per_cycle.shape == blocks.shape
    assert np.allclose(per_cycle, blocks, atol=1e-9)


def test_fast_one_cycle_servo_path_matches_the_block_path() -> None:
    def states(step: float) -> dict:
        m = motion(MD32620={"X": 0}, MD32200={"X": 1.0})
        m.push(move("G1", 3000.0, X=20.0))
        for _ in range(int(round(2.0 / step))):
            m.advance(step)
        return m.axis_states()["X"]

    a, b = states(0.004), states(0.4)
    assert a.following_error_mm == pytest.approx(b.following_error_mm, abs=1e-12)
    assert a.motor_temperature_c == pytest.approx(b.motor_temperature_c, abs=1e-6)
    assert a.torque_nm == pytest.approx(b.torque_nm, abs=1e-9)


def test_reset_brakes_and_a_new_program_starts_from_the_stop_point() -> None:
    m = motion()
    m.push(move("G1", 6000.0, X=100.0))
    m.push(move("G1", 6000.0, X=100.0, Y=100.0))
    m.advance(0.5)
    m.abort()
    assert not m.is_idle()  # braking on the ramp
    m.push(move("G1", 2000.0, Z=-10.0))
    run_to_idle(m)
    _rows, v, _a, _j = derivatives(m)
    assert np.abs(v).max() <= 100.0 + 1e-9  # no jump anywhere
    pos = m.positions_mcs()
    assert pos["Y"] == pytest.approx(0.0)
    assert 20.0 < pos["X"] < 100.0
    assert pos["Z"] == pytest.approx(-10.0)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    soft=st.booleans(), t_stop=st.integers(10, 370), hold=st.booleans(),
    first=st.floats(20, 120), t_change=st.integers(10, 250), second=st.floats(0, 120),
)
def test_stop_and_override_changes_keep_limits_and_reach_the_end(soft, t_stop, hold, first, t_change, second) -> None:
    m = motion()
    m.push(move("G1", 12000.0, soft=soft, X=100.0))
    m.push(move("G1", 12000.0, soft=soft, X=100.0, Y=80.0))
    m.advance(t_stop * m.ipo_cycle_s)
    if hold:
        m.hold()
        m.advance(1.0)
    m.set_overrides(first, 100.0)
    m.resume()
    m.advance(t_change * m.ipo_cycle_s)
    m.set_overrides(second, 100.0)
    m.advance(0.5)
    m.set_overrides(100.0, 100.0)
    run_to_idle(m)
    rows, _v, a, j = derivatives(m)
    assert np.allclose(rows[-1], [100.0, 80.0, 0.0], atol=1e-9)
    assert np.all(np.abs(a) <= AMAX * OVL * (1 + 1e-6) + 1e-3)
    if soft:
        assert np.all(np.abs(j) <= JMAX * OVL * (1 + 1e-6) + 1e-1)


def test_small_block_servo_path_equals_cycle_by_cycle() -> None:
    """The Python-float path for short blocks gives the per-cycle model's state."""
    import copy

    from nck.motion.servo import SMALL_ROWS
    from nck.motion.servo_paths import process_small

    rng = np.random.default_rng(5)
    base = motion().servo
    for _ in range(20):
        m = int(rng.integers(2, SMALL_ROWS + 1))
        start = rng.uniform(-0.05, 0.05, size=3)
        rows = start + np.cumsum(rng.uniform(-0.2, 0.2, size=(m, 3)), axis=0)
        small = copy.deepcopy(base)
        single = copy.deepcopy(base)
        out = process_small(small, rows)
        assert out is not None
        for row in rows:
            single._process_one(row)
        for name in ("x_set", "v_set", "e", "e_model", "v_act", "v_cmd", "stop_cycles", "fine_since_stop"):
            np.testing.assert_allclose(getattr(small, name), getattr(single, name), rtol=0, atol=1e-12)
        np.testing.assert_allclose(small.temperature, single.temperature, rtol=1e-12)
        base = small


def test_a_spindle_advanced_by_no_time_changes_nothing() -> None:
    """A step that ends at a block event advances the spindles by 0 s; no time passing changes
    neither its speed nor its angle, torque or temperature. (It did: at speed, a zero advance
    took the ramp branch and set the full ramp acceleration, so between steps the service
    screens read the accelerating torque, 16.9 Nm on the mill at S8000, not the 2 % friction.)"""
    from nck.machine import load_machine
    from nck.motion.params import motion_params
    from nck.motion.spindle import Spindle

    spindle = Spindle(motion_params(load_machine()).spindles[0])
    spindle.command("M3", 8000.0)
    for _cycle in range(1000):  # 4 s: the mill's spindle ramps at 3000 rpm/s, up in 2.7 s
        spindle.advance(0.004)
    state = spindle.state
    assert state.actual_rpm == 8000.0
    at_speed = (state.actual_rpm, state.angle_deg, state.torque_nm, state.temperature_c)
    assert state.torque_nm == pytest.approx(0.02 * spindle.params.rated_torque_nm)  # friction only
    spindle.advance(0.0)
    assert (state.actual_rpm, state.angle_deg, state.torque_nm, state.temperature_c) == at_speed
