"""JOG, incremental JOG, reference point approach, spindle, the lathe machine."""

from __future__ import annotations

import pytest

from nck.canon import Source, SpindleCommand
from nck.machine import load_machine
from nck.motion.system import PlannedMotion
from tests.motion.helpers import motion, move, run_to_idle


def until_jog_done(m, limit_s: float = 60.0) -> None:
    while m.jog_active():
        m.advance(0.1)
        assert m.time_s < limit_s


def test_continuous_jog_at_jog_velocity_with_override() -> None:
    m = motion()
    m.jog_continuous("Y", 1, 2000.0)
    m.advance(1.0)
    assert m.axis_states()["Y"].velocity_setpoint_mm_min == pytest.approx(2000.0)
    m.set_overrides(50.0, 100.0)
    m.advance(0.5)
    assert m.axis_states()["Y"].velocity_setpoint_mm_min == pytest.approx(1000.0)
    m.jog_continuous("Y", 0, 0.0)
    m.advance(0.004)
    assert m.jog_active()  # braking on the ramp
    until_jog_done(m)
    assert m.axis_states()["Y"].velocity_setpoint_mm_min == 0.0


def test_incremental_jog_travels_exactly_the_increment() -> None:
    m = motion()
    m.jog_increment("Z", -0.01, 1000.0)
    until_jog_done(m)
    assert m.axis_states()["Z"].position_setpoint_mm == pytest.approx(-0.01, abs=1e-12)
    m.jog_increment("Z", 10.0, 10000.0)
    until_jog_done(m)
    assert m.axis_states()["Z"].position_setpoint_mm == pytest.approx(9.99, abs=1e-9)


def test_incremental_jog_stops_at_the_limit() -> None:
    m = motion()
    run_to_idle(m, feed=[move("G0", Y=395.0)])
    m.jog_increment("Y", 10.0, 2000.0)
    until_jog_done(m)
    assert m.axis_states()["Y"].position_setpoint_mm == pytest.approx(400.0, abs=1e-9)


def test_jog_while_path_is_held() -> None:
    m = motion()
    m.push(move("G1", 2000.0, X=100.0))
    m.advance(1.0)
    m.hold()
    m.advance(0.5)
    m.jog_increment("Z", 5.0, 2000.0)
    until_jog_done(m)
    assert m.axis_states()["Z"].position_setpoint_mm == pytest.approx(5.0)


def test_reference_point_approach_of_all_axes_in_phases() -> None:
    """Digest 828d-1 rank 20 (reference approach ends referenced at the reference value)."""
    m = motion(referenced=False)
    # Power-on position on the other side of the cam than the reference point.
    m.jog_increment("X", -50.0, 5000.0)
    until_jog_done(m)
    assert not m.is_referenced("X")
    m.start_reference("X")
    phases = []
    while m.jog_active():
        m.advance(0.02)
        run = m.jog.runs.get(0)
        if run is not None and (not phases or phases[-1] != run.purpose):
            phases.append(run.purpose)
    assert phases == ["ref1", "ref2", "ref3"]
    for axis in ("Y", "Z"):
        m.start_reference(axis)
    until_jog_done(m)
    for axis in ("X", "Y", "Z"):
        assert m.is_referenced(axis)
        assert m.axis_states()[axis].position_setpoint_mm == pytest.approx(0.0, abs=1e-9)  # MD34100


def test_creep_speed_in_phase_two_ignores_override() -> None:
    m = motion(referenced=False)
    m.set_overrides(10.0, 100.0)
    m.start_reference("X")
    while m.jog.runs.get(0) is None or m.jog.runs[0].purpose != "ref2":
        m.advance(0.02)
    m.advance(0.5)
    assert abs(m.axis_states()["X"].velocity_setpoint_mm_min) == pytest.approx(300.0)  # MD34040


def test_reset_during_reference_leaves_axis_unreferenced() -> None:
    m = motion(referenced=True)
    m.jog_increment("X", -40.0, 5000.0)
    until_jog_done(m)
    m.start_reference("X")
    assert not m.is_referenced("X")
    m.advance(0.2)
    m.abort()
    until_jog_done(m)
    assert not m.is_referenced("X")


def test_reference_cam_not_found_raises_20000() -> None:
    m = motion(referenced=False, MD34030={"X": 10.0})
    m.jog_increment("X", -50.0, 5000.0)
    until_jog_done(m)
    m.start_reference("X")
    until_jog_done(m)
    assert [a.number for a in m.drain_alarms()] == [20000]
    assert not m.is_referenced("X")


def test_spindle_ramps_to_speed_and_jogs() -> None:
    """Digest 828d-3 rank 16 (spindle ramps to speed)."""
    m = motion()
    m.spindle_command(SpindleCommand(Source("T", 1), 1, state="M3", speed_rpm=3000.0))
    m.advance(0.5)
    ramping = m.spindles["SP"].state.actual_rpm
    assert 0.0 < ramping < 3000.0
    m.advance(2.0)
    assert m.spindles["SP"].state.actual_rpm == pytest.approx(3000.0)
    m.set_spindle_override(120.0)
    m.advance(2.0)
    assert m.spindles["SP"].state.actual_rpm == pytest.approx(3600.0)
    m.spindle_command(SpindleCommand(Source("T", 2), 1, state="M3", speed_rpm=9000.0))
    m.advance(5.0)
    assert m.spindles["SP"].state.actual_rpm == pytest.approx(8000.0)  # MD35130 gear limit
    m.abort()
    m.advance(5.0)
    assert m.spindles["SP"].state.actual_rpm == 0.0
    m.jog_continuous("SP", -1, 0.0)
    m.advance(1.0)
    assert m.spindles["SP"].state.actual_rpm == pytest.approx(-200.0 * 1.2)  # MD32020 × override
    m.jog_continuous("SP", 0, 0.0)
    m.advance(1.0)
    assert m.spindles["SP"].state.actual_rpm == 0.0


def test_lathe_machine_moves_in_radius() -> None:
    lathe = load_machine("lathe2")
    assert lathe.axis("X").diameter
    m = PlannedMotion(lathe, referenced=True)
    assert set(m.positions_mcs()) == {"X", "Z", "SP"}
    m.push(move("G1", 500.0, X=20.0, Z=-30.0))
    run_to_idle(m)
    assert m.positions_mcs()["X"] == pytest.approx(20.0, abs=0.04)
    assert m.positions_mcs()["Z"] == pytest.approx(-30.0, abs=0.04)
