"""The recorder's float sum gives numpy's sum bit for bit.

The path recorder sums each arc's chord lengths with :func:`pairwise_sum` instead of
``np.sum`` (a few floats, where numpy's per-call cost outweighed the additions); the reference
here is numpy itself on random lists of every length up to past two of numpy's 128-value
blocks, and longer ones: equal as floats, not approximately.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.simulation.pairwise import pairwise_sum

LENGTHS = st.floats(min_value=0.0, max_value=1e6, allow_nan=False, allow_infinity=False)
SIGNED = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)


def _same(a: float, b: float) -> bool:
    return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)


@settings(max_examples=400, deadline=None)
@given(st.lists(LENGTHS, max_size=300))
def test_pairwise_sum_of_chord_lengths_equals_numpys_sum(values: list[float]) -> None:
    assert _same(pairwise_sum(values), float(np.sum(values)))


@settings(max_examples=200, deadline=None)
@given(st.lists(SIGNED, max_size=300))
def test_pairwise_sum_of_signed_values_equals_numpys_sum(values: list[float]) -> None:
    assert _same(pairwise_sum(values), float(np.sum(values)))


def test_long_lists_and_zeros_sum_as_numpy_sums_them() -> None:
    rng = np.random.default_rng(24)
    for count in (0, 1, 7, 8, 9, 127, 128, 129, 255, 256, 257, 1000, 8191, 8192, 8193, 20001):
        values = (rng.random(count) ** 3 * 1e3).tolist()
        assert _same(pairwise_sum(values), float(np.sum(values)))
    for zeros in ([-0.0], [-0.0] * 3, [-0.0] * 9, [-0.0] * 200, [0.0, -0.0]):
        assert _same(pairwise_sum(zeros), float(np.sum(zeros)))
