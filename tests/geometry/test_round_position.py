"""``round_position`` is Python's ``round(value, 9) + 0.0`` bit for bit, also where it takes its
two-step form (``round(value · 10^9) / 10^9``): every position the path builder keeps goes
through it, so a difference in the last bit would change machine positions."""

from __future__ import annotations

import math
import struct

from hypothesis import given, settings
from hypothesis import strategies as st

from nck.geometry.path_builder import ROUND_FAST_LIMIT, round_position


def _bits(value: float) -> bytes:
    return struct.pack("<d", value)


def _reference(value: float) -> float:
    return round(value, 9) + 0.0


def _same(value: float) -> None:
    got, expected = round_position(value), _reference(value)
    if math.isnan(expected):
        assert math.isnan(got)
    else:
        assert _bits(got) == _bits(expected), (value, got, expected)


@settings(max_examples=3000, deadline=None)
@given(st.floats(allow_nan=True, allow_infinity=True))
def test_any_double(value: float) -> None:
    _same(value)


@settings(max_examples=3000, deadline=None)
@given(st.integers(-10**13, 10**13), st.integers(0, 12))
def test_decimal_positions(digits: int, places: int) -> None:
    """Positions as programs and frames make them: decimals of up to 12 places, also sums and
    products of them (the machine formula), around the limit of the two-step form."""
    value = digits / 10**places
    _same(value)
    _same(value * 25.4)
    _same(value + 0.1)
    _same(value / 3.0)


def test_ties_and_edges() -> None:
    """Exact halves of the last digit (ties to even through the decimal string), negative zero,
    and values at the limit of the two-step form."""
    for k in range(-2000, 2000):
        _same((k + 0.5) * 1e-9)
        _same(k * 1e-9)
        _same(k * 1e-9 + 5e-10)
    for value in (0.0, -0.0, 5e-10, -5e-10, 1.0000000005, 2.5e-9, -2.5e-9, 1e-300, -1e-300,
                  ROUND_FAST_LIMIT / 1e9, -ROUND_FAST_LIMIT / 1e9, math.nextafter(ROUND_FAST_LIMIT / 1e9, 0.0),
                  8796.0930222715, 1e6 + 0.0000000005, 123456.7890123455):
        _same(value)
        _same(math.nextafter(value, math.inf))
        _same(math.nextafter(value, -math.inf))


@settings(max_examples=3000, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=True))
def test_rounding_twice_changes_nothing(value: float) -> None:
    """Idempotent, so a position already rounded (``from_mm``'s result) is not rounded again:
    the double nearest to ``k · 10^-9`` is within half an ulp of it, and below 2^23 half an ulp
    is below 0.5 · 10^-9 (so ``k`` is found again); above, the double itself is the nearest to
    whatever multiple of 10^-9 lies within 0.5 · 10^-9 of it."""
    once = round_position(value)
    assert _bits(round_position(once)) == _bits(once), value


@settings(max_examples=2000, deadline=None)
@given(st.integers(-10**13, 10**13), st.integers(0, 12))
def test_rounding_decimal_positions_twice_changes_nothing(digits: int, places: int) -> None:
    once = round_position(digits / 10**places)
    assert _bits(round_position(once)) == _bits(once)
