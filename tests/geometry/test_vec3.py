"""The plain-float 3-vector arithmetic of the arc geometry gives numpy's bits.

Recorded results (goldens, the plain fast path's equivalence) were computed with numpy's
``dot``/``norm``, which on this machine round like a fused multiply-add chain; the float
versions must give the same bits, signed zeros included. The numpy forms below are the
arc formulas as they were written before (the reference).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from nck.geometry import vec3
from nck.geometry.circles import Arc

coordinates = st.one_of(
    st.floats(min_value=-1e4, max_value=1e4, allow_nan=False),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 1e-300, -1e200, 0.1, 2.5e-9]),
    st.integers(-10**6, 10**6).map(lambda n: n / 1000.0),
)
vectors = st.tuples(coordinates, coordinates, coordinates)
unit_axes = st.sampled_from([(0.0, 0.0, 1.0), (0.0, 0.0, -1.0), (1.0, 0.0, 0.0), (-1.0, 0.0, 0.0),
                             (0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (0.6, 0.0, 0.8), (0.0, -0.8, 0.6)])


def _bits(value: float) -> str:
    return repr(float(value))


@given(vectors, vectors)
def test_dot_and_norm_are_numpys(a: tuple[float, float, float], b: tuple[float, float, float]) -> None:
    with np.errstate(all="ignore"):
        assert _bits(vec3.dot3(a, b)) == _bits(np.dot(np.asarray(a), np.asarray(b)))
        assert _bits(vec3.norm3(a)) == _bits(np.linalg.norm(np.asarray(a)))


def test_the_probes_tell_the_fused_chain_from_a_plain_sum() -> None:
    """On every probe pair the fused chain differs from the plain sum in either order, so the
    probe at import cannot mistake one form of numpy's ``dot`` for the other (numpy takes one
    or the other depending on the processor)."""
    for a, b in vec3.PROBES:
        inner = vec3.fused_multiply_add(a[1], b[1], a[0] * b[0] + 0.0)
        assert inner is not None
        chain = vec3.fused_multiply_add(a[2], b[2], inner)
        assert chain != ((0.0 + a[0] * b[0]) + a[1] * b[1]) + a[2] * b[2]
        assert chain != a[2] * b[2] + (a[1] * b[1] + a[0] * b[0])
        assert vec3.dot3(a, b) == float(np.dot(np.asarray(a), np.asarray(b)))


def _np_cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.array((a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]))


def _np_rotate(v: np.ndarray, k: np.ndarray, angle: float) -> np.ndarray:
    return v * math.cos(angle) + _np_cross(k, v) * math.sin(angle) + k * np.dot(k, v) * (1 - math.cos(angle))


def _reference(arc: Arc, fraction: float) -> tuple[float, tuple[float, ...], tuple[float, ...]]:
    """Lead, point and tangent of ``arc`` by the numpy formulas the arc geometry had."""
    axis = np.asarray(arc.axis)
    lead = float(np.dot(np.subtract(arc.end, arc.start), arc.axis))
    radial = np.subtract(arc.start, arc.center)
    radial = radial - np.dot(radial, arc.axis) * axis
    turned = _np_rotate(radial, axis, arc.sweep_rad * fraction)
    point = np.asarray(arc.center) + turned + axis * lead * fraction
    direction = _np_cross(axis, turned) * arc.sweep_rad + axis * lead
    norm = float(np.linalg.norm(direction))
    tangent = (0.0, 0.0, 0.0) if norm < 1e-9 else tuple(float(v) for v in direction / norm)
    return lead, tuple(float(v) for v in point), tangent


@given(vectors, vectors, vectors, unit_axes, st.floats(0.01, 40.0), st.sampled_from([0.0, 0.25, 0.5, 1.0]))
def test_arc_lead_point_and_tangent_are_the_numpy_forms(start: tuple[float, float, float],
                                                        end: tuple[float, float, float],
                                                        center: tuple[float, float, float],
                                                        axis: tuple[float, float, float],
                                                        sweep: float, fraction: float) -> None:
    arc = Arc(start=start, end=end, center=center, axis=axis, radius=math.dist(start, center), sweep_rad=sweep)
    with np.errstate(all="ignore"):
        lead, point, tangent = _reference(arc, fraction)
        point_at, tangent_at = arc.point_at(fraction), arc.tangent_at(fraction)
    assert _bits(arc.lead) == _bits(lead)
    assert [_bits(v) for v in point_at] == [_bits(v) for v in point]
    assert [_bits(v) for v in tangent_at] == [_bits(v) for v in tangent]
