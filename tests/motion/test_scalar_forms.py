"""The Python-float forms of hot motion arithmetic give the numpy forms' results bit for bit.

Short CAM blocks last two or three IPO cycles, where numpy's per-call cost
outweighs the arithmetic; the motion therefore computes some values with
Python floats. Each test here compares such a form with the numpy form it
replaced (written out below as the reference) on random inputs: equal as
floats, not approximately.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.motion import servo_defer
from nck.motion.interpolator import SCALAR_SAMPLES
from nck.motion.path import Segment, line
from nck.motion.profile import build_profile, build_profile_stepwise

FINITE = st.floats(min_value=-1000.0, max_value=1000.0, allow_nan=False, allow_infinity=False)


def _numpy_speed_range(rows: np.ndarray, previous: np.ndarray, inv_t: float) -> tuple[list[float], list[float]]:
    """The reference: the numpy form of the deferred servo queue's speed range."""
    v = np.empty_like(rows)
    np.subtract(rows[0], previous, out=v[0])
    np.subtract(rows[1:], rows[:-1], out=v[1:])
    v *= inv_t
    speed = np.abs(v)
    return speed.max(axis=0).tolist(), speed.min(axis=0).tolist()


@settings(max_examples=300)
@given(st.integers(1, 40).flatmap(lambda m: st.lists(st.lists(FINITE, min_size=3, max_size=3),
                                                      min_size=m + 1, max_size=m + 1)))
def test_speed_range_equals_the_numpy_form(points: list[list[float]]) -> None:
    """Up to SMALL_ROWS rows in Python floats, more in numpy; both scale after the max and min."""
    previous, rows = np.array(points[0]), np.array(points[1:])
    inv_t = 1.0 / 0.004
    assert servo_defer.speed_range(rows, previous, inv_t) == _numpy_speed_range(rows, previous, inv_t)


def _reference_distance_at(profile, t: float) -> float:
    """The reference: the per-phase formula read from the numpy columns (the former form)."""
    t = min(max(t, 0.0), profile.duration_s)
    i = len(profile.t0) - 1
    while i > 0 and float(profile.t0[i]) > t:
        i -= 1
    dt = t - float(profile.t0[i])
    a, j = float(profile.a0[i]), float(profile.j[i])
    s = float(profile.s0[i]) + float(profile.v0[i]) * dt
    if a != 0.0 or j != 0.0:
        s = s + a * dt * dt / 2.0 + j * dt**3 / 6.0
    return min(s, profile.length)


@settings(max_examples=200)
@given(st.floats(0.01, 200.0), st.floats(0.0, 80.0), st.floats(0.0, 80.0), st.floats(1.0, 100.0),
       st.floats(100.0, 5000.0), st.one_of(st.none(), st.floats(1e3, 1e5)), st.floats(0.0, 1.0))
def test_profile_columns_and_scalar_distance_match_the_phases(length: float, v0: float, v1: float, vmax: float,
                                                              accel: float, jerk: float | None,
                                                              fraction: float) -> None:
    profile = build_profile(length, v0, v1, vmax, accel, jerk)
    columns = np.array(profile.phases, dtype=float)
    for index, name in enumerate(("t0", "s0", "v0", "a0", "j")):
        assert getattr(profile, name).tolist() == columns[:, index].tolist()
    assert list(profile.starts) == columns[:, 0].tolist()
    for t in (0.0, fraction * profile.duration_s, profile.duration_s, profile.duration_s + 1.0):
        assert profile.distances_after(t, 0.0, 1) == [_reference_distance_at(profile, t)]


@settings(max_examples=200)
@given(st.lists(FINITE, min_size=3, max_size=3), st.lists(FINITE, min_size=3, max_size=3))
def test_a_line_has_one_tangent_at_both_ends(start: list[float], end: list[float]) -> None:
    segment = line(np.array(start), np.array(end), np.ones(3, dtype=bool))
    if segment.length <= 1e-9:
        return
    first = segment.delta / segment.length
    expected = first / math.sqrt(float(first @ first))  # the reference: numpy's dot (BLAS) as matmul
    assert segment.tangent(False).tolist() == expected.tolist()
    assert segment.tangent(True).tolist() == expected.tolist()


@settings(max_examples=300)
@given(st.floats(0.01, 200.0), st.floats(0.0, 80.0), st.floats(0.0, 80.0), st.floats(1.0, 100.0),
       st.floats(100.0, 5000.0), st.one_of(st.none(), st.floats(1e3, 1e5)), st.floats(-0.1, 1.0),
       st.integers(1, SCALAR_SAMPLES), st.floats(-0.004, 0.0))
def test_scalar_samples_of_a_brisk_profile_equal_the_numpy_samples(length: float, v0: float, v1: float,
                                                                    vmax: float, accel: float,
                                                                    jerk: float | None, fraction: float,
                                                                    samples: int, carry: float) -> None:
    """The interpolator samples a short BRISK block with distances_after; the numpy form
    (distances) over the same times must give the same floats, across phases and past the end."""
    profile = build_profile(length, v0, v1, vmax, accel, jerk)
    assert profile.scalar_exact == (jerk is None or all(row[4] == 0.0 for row in profile.phases))
    if not profile.scalar_exact:
        return
    period = 0.004
    tau0 = carry + fraction * profile.duration_s
    times = tau0 + period * np.arange(1, samples + 1)
    expected = profile.distances(times).tolist()
    assert profile.distances_after(tau0, period, samples) == expected


EDGE_SPEEDS = st.sampled_from([0.0, -0.0, 1e-13, 1e-12, 2e-12, 1e-9, -1.0, 1e6, 1e110, math.inf])


@settings(max_examples=500)
@given(st.one_of(st.floats(0.0, 200.0), EDGE_SPEEDS), st.one_of(st.floats(-1.0, 80.0), EDGE_SPEEDS),
       st.one_of(st.floats(-1.0, 80.0), EDGE_SPEEDS), st.one_of(st.floats(0.0, 100.0), EDGE_SPEEDS),
       st.one_of(st.floats(1e-3, 5000.0), st.sampled_from([1e-3, 1e6, math.inf])), st.floats(-50.0, 50.0))
def test_a_brisk_profile_equals_the_builders(length: float, v0: float, v1: float, vmax: float, accel: float,
                                            a_start: float) -> None:
    """build_profile writes the BRISK builder's steps out for the usual case: the same phases,
    duration, length and end velocity as the stepwise builder (which the rare cases keep), also
    when a velocity is at the edge (zero, TINY, above the limit, infinite) or an exception."""
    try:
        expected = build_profile_stepwise(length, v0, v1, vmax, accel, None, a_start)
    except (ArithmeticError, ValueError) as error:
        expected_error = type(error)
        try:
            build_profile(length, v0, v1, vmax, accel, None, a_start)
        except (ArithmeticError, ValueError) as raised:
            assert type(raised) is expected_error
        else:
            raise AssertionError("the written-out form did not raise")
        return
    got = build_profile(length, v0, v1, vmax, accel, None, a_start)
    assert repr((got.phases, got.duration_s, got.length, got.v_end, got.scalar_exact)) == repr(
        (expected.phases, expected.duration_s, expected.length, expected.v_end, expected.scalar_exact))


ANGLE = st.floats(min_value=-4.0 * math.pi, max_value=4.0 * math.pi, allow_nan=False)


def _arc_segment(centre: list[float], r0: float, r1: float, th0: float, sweep: float, dz: float) -> Segment:
    """An arc, helix or spiral in the XY plane around ``centre`` (radius r0 → r1, rising dz)."""
    c1, c2, z = centre
    th1 = th0 + sweep
    start = np.array([c1 + r0 * math.cos(th0), c2 + r0 * math.sin(th0), z])
    end = np.array([c1 + r1 * math.cos(th1), c2 + r1 * math.sin(th1), z + dz])
    length = math.hypot(abs(sweep) * (r0 + r1) / 2.0, dz)
    return Segment(start=start, end=end, length=length, arc=(0, 1, c1, c2, r0, r1, th0, sweep))


@settings(max_examples=400)
@given(st.lists(FINITE, min_size=3, max_size=3), st.floats(0.01, 500.0), st.floats(0.01, 500.0), ANGLE,
       st.floats(-3.0 * math.pi, 3.0 * math.pi).filter(lambda sweep: abs(sweep) > 1e-6),
       st.lists(st.floats(-0.5, 1.5), min_size=1, max_size=SCALAR_SAMPLES), st.floats(-20.0, 20.0))
def test_points_of_an_arc_equal_the_numpy_positions(centre: list[float], r0: float, r1: float, th0: float,
                                                    sweep: float, fractions: list[float], dz: float) -> None:
    """Segment.points (math.cos, math.sin) gives Segment.positions' rows (numpy's cos, sin)
    bit for bit, for arcs, helices and spirals, with the end pinned and the fractions clipped."""
    segment = _arc_segment(centre, r0, r1, th0, sweep, dz)
    distances = [f * segment.length for f in fractions]
    assert segment.points(distances) == segment.positions(np.array(distances)).reshape(-1).tolist()


@settings(max_examples=300)
@given(st.lists(FINITE, min_size=3, max_size=3), st.lists(FINITE, min_size=3, max_size=3),
       st.lists(st.floats(-0.5, 1.5), min_size=1, max_size=SCALAR_SAMPLES))
def test_points_of_a_line_equal_the_numpy_positions(start: list[float], end: list[float],
                                                    fractions: list[float]) -> None:
    segment = line(np.array(start), np.array(end), np.ones(3, dtype=bool))
    if segment.length <= 1e-9:
        return  # not a segment: the motion drops such a block
    distances = [f * segment.length for f in fractions]
    assert segment.points(distances) == segment.positions(np.array(distances)).reshape(-1).tolist()


def _reference_derivatives(segment: Segment, lam: float) -> tuple[np.ndarray, np.ndarray]:
    """The reference: the numpy form of an arc's first and second derivative (the former form)."""
    first = (segment.end - segment.start) / segment.length
    second = np.zeros_like(first)
    i1, i2, _c1, _c2, r0, r1, th0, sweep = segment.arc
    th, r, dr, length = th0 + lam * sweep, r0 + lam * (r1 - r0), r1 - r0, segment.length
    first[i1] = (dr * math.cos(th) - r * sweep * math.sin(th)) / length
    first[i2] = (dr * math.sin(th) + r * sweep * math.cos(th)) / length
    second[i1] = (-2 * dr * sweep * math.sin(th) - r * sweep * sweep * math.cos(th)) / length**2
    second[i2] = (2 * dr * sweep * math.cos(th) - r * sweep * sweep * math.sin(th)) / length**2
    return first, second


@settings(max_examples=300)
@given(st.lists(FINITE, min_size=3, max_size=3), st.floats(0.01, 500.0), st.floats(0.01, 500.0), ANGLE,
       st.floats(-3.0 * math.pi, 3.0 * math.pi).filter(lambda sweep: abs(sweep) > 1e-6), st.floats(-20.0, 20.0))
def test_tangent_and_curvature_of_an_arc_equal_the_numpy_form(centre: list[float], r0: float, r1: float,
                                                              th0: float, sweep: float, dz: float) -> None:
    segment = _arc_segment(centre, r0, r1, th0, sweep, dz)
    for at_end in (False, True):
        first, second = _reference_derivatives(segment, 1.0 if at_end else 0.0)
        assert segment.curvature(at_end).tolist() == second.tolist()
        assert segment.tangent(at_end).tolist() == (first / math.sqrt(float(first @ first))).tolist()


@settings(max_examples=300)
@given(st.floats(0.01, 200.0), st.floats(0.0, 80.0), st.floats(0.0, 80.0), st.floats(1.0, 100.0),
       st.floats(100.0, 5000.0), st.one_of(st.none(), st.floats(1e3, 1e5)),
       st.lists(st.floats(-0.1, 1.1), min_size=1, max_size=8))
def test_state_at_equals_the_numpy_sample(length: float, v0: float, v1: float, vmax: float, accel: float,
                                          jerk: float | None, fractions: list[float]) -> None:
    """The kernel's velocity bound asks ``state_at`` every IPO cycle while it steps single
    cycles; in a phase without jerk it works in Python floats, and gives ``sample``'s values
    (before, during and after the profile, and at each phase start)."""
    profile = build_profile(length, v0, v1, vmax, accel, jerk)
    for t in [f * profile.duration_s for f in fractions] + list(profile.starts):
        s, v, a = profile.sample(np.array([t]))
        assert repr(profile.state_at(t)) == repr((float(s[0]), float(v[0]), float(a[0])))
