"""Deferred position control (nck.motion.servo_defer) gives the servo state of block-by-block control.

The same programs run twice — once with the servo processing every block at
once (deferral switched off), once with the deferral — and the axis states
the service screens show are compared after every kernel step, together with
the alarms and the cycle they came in.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nck import commands as c
from nck.interp.sources import MemorySource
from nck.kernel import Nck
from nck.motion import servo_defer
from nck.motion.servo import ServoBank
from tests.kernel.test_batch_equivalence import MIXED

FIELDS = ("position_setpoint_mm", "position_actual_mm", "following_error_mm", "velocity_actual_mm_min",
          "speed_setpoint_pct", "torque_nm", "motor_temperature_c")  # temperature last


def _states(program: str, enabled: bool, monkeypatch: pytest.MonkeyPatch, machine=None) -> tuple[list, list, int]:
    queued = [0]
    original = ServoBank.process

    def process(self: ServoBank, setpoints: np.ndarray, defer: bool = False) -> tuple:
        before = len(self.pending)
        out = original(self, setpoints, enabled and defer)
        queued[0] += len(self.pending) > before
        return out

    with monkeypatch.context() as patch:
        patch.setattr(ServoBank, "process", process)
        nck = Nck(machine=machine, programs=MemorySource({"P.MPF": program}), referenced=True)
        assert nck.submit(c.SelectMode("AUTO")) == c.Accepted()
        assert nck.submit(c.SelectProgram("P.MPF")) == c.Accepted()
        assert nck.submit(c.CycleStart()) == c.Accepted()
        states = []
        for _ in range(4000):
            if nck.situation.channel != "active":
                break
            nck.step(nck.batch_cycles)
            axes = nck.motion.axis_states()
            states.append((nck.cycles_done, {name: [getattr(s, f) for f in FIELDS] for name, s in axes.items()}))
        alarms = [(e.number, round(e.came_s / nck.ipo_cycle_s)) for e in nck.alarm_history()]
        assert not nck.internal_errors
    return states, alarms, queued[0]


def _assert_same(program: str, monkeypatch: pytest.MonkeyPatch, machine=None) -> int:
    plain, plain_alarms, _ = _states(program, False, monkeypatch, machine)
    deferred, deferred_alarms, queued = _states(program, True, monkeypatch, machine)
    assert deferred_alarms == plain_alarms
    assert [cycles for cycles, _ in deferred] == [cycles for cycles, _ in plain]
    for (_, a), (_, b) in zip(deferred, plain):
        for name in a:
            np.testing.assert_allclose(a[name][:-1], b[name][:-1], rtol=1e-9, atol=1e-9, err_msg=name)
            # The thermal model averages the load over each processed stretch: longer
            # stretches round differently, far below what the display shows (0.1 °C).
            assert a[name][-1] == pytest.approx(b[name][-1], abs=1e-4)
    return queued


def test_a_contour_is_queued_and_ends_in_the_same_servo_state(monkeypatch: pytest.MonkeyPatch) -> None:
    queued = _assert_same(MIXED, monkeypatch)
    assert not _states(MIXED, True, monkeypatch)[1]  # no alarm
    assert queued > 20  # most contour blocks went through the queue


def test_a_speed_setpoint_trip_after_queued_blocks_comes_in_the_same_cycle(monkeypatch: pytest.MonkeyPatch) -> None:
    """MD36210 too low for the second block's feed: that block fails the bound, 25060 is exact."""
    from tests.motion.helpers import machine

    low = machine(MD36210={"X": 10.0})
    program = "N10 G1 X5 F500\nN20 G1 X80 F6000\nN30 M30\n"
    _, alarms, queued = _states(program, True, monkeypatch, low)
    assert [number for number, _ in alarms] == [25060]
    assert queued >= 1  # the slow first block was queued
    _assert_same(program, monkeypatch, low)


def test_the_bound_refuses_a_block_beyond_the_velocity_limit() -> None:
    nck = Nck(programs=MemorySource({}), referenced=True)
    servo = nck.motion.servo
    velo = float(servo.limits["velo"][0])
    fast = np.zeros((10, len(servo.axes)))
    fast[:, 0] = np.arange(1, 11) * velo * 1.5 * servo.T
    assert servo_defer.quiet_bound(servo, fast) is None
    slow = fast * 0.01
    bound = servo_defer.quiet_bound(servo, slow)
    assert bound is not None and bound[0] > 0.0


# monkeypatch is only used through monkeypatch.context(), undone after every example.
@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(st.lists(st.tuples(st.sampled_from(["G0", "G1", "G2", "G3"]), st.integers(-60, 60), st.integers(-60, 60),
                          st.sampled_from(["", "G60", "G64", "SOFT", "BRISK", "G9"]),
                          st.sampled_from([200, 3000, 9000])), min_size=2, max_size=12))
def test_random_programs_give_the_same_servo_state(monkeypatch: pytest.MonkeyPatch, moves: list) -> None:
    lines = ["G90 G17 G64 G0 X0 Y0 Z0"]
    x = y = 0
    for kind, nx, ny, extra, feed in moves:
        if (nx, ny) == (x, y):
            continue
        arc = f" CR={max(abs(nx - x), abs(ny - y)):d}" if kind in ("G2", "G3") else ""
        lines.append(f"{extra} {kind} X{nx} Y{ny}{arc} F{feed}".strip())
        x, y = nx, ny
    lines.append("M30")
    _assert_same("\n".join(lines) + "\n", monkeypatch)

