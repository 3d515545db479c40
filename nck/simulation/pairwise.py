"""The sum of a list of floats in numpy's order, without an array.

``float(np.sum(values))`` of a few floats costs a list-to-array conversion and a ufunc call,
several microseconds, where the additions take a fraction of one; the path recorder sums the
chord lengths of every arc (mostly two or three). :func:`pairwise_sum` adds in the order of
numpy's ``add.reduce`` over a contiguous float64 array (numpy's pairwise summation: fewer than
8 values from left to right; up to 128 in eight interleaved partial sums, combined pairwise,
then the remainder; more split in two halves at a multiple of 8), so its result equals
numpy's bit for bit (tests/simulation/test_pairwise.py compares them on random lists).
"""

from __future__ import annotations

from typing import Sequence

_BLOCK = 128
"""Up to this many values are summed in one block of eight partial sums (numpy's PW_BLOCKSIZE)."""


def pairwise_sum(values: Sequence[float]) -> float:
    """``float(np.sum(values))`` of a sequence of floats, added in numpy's order (after numpy's
    identity 0.0: an empty list or one of negative zeros sums to 0.0)."""
    return 0.0 + _sum_of(values, 0, len(values))


def _sum_of(values: Sequence[float], first: int, count: int) -> float:
    if count < 8:
        total = -0.0
        for i in range(first, first + count):
            total += values[i]
        return total
    if count <= _BLOCK:
        r0, r1, r2, r3, r4, r5, r6, r7 = values[first:first + 8]
        end = first + count - count % 8
        for i in range(first + 8, end, 8):
            r0 += values[i]
            r1 += values[i + 1]
            r2 += values[i + 2]
            r3 += values[i + 3]
            r4 += values[i + 4]
            r5 += values[i + 5]
            r6 += values[i + 6]
            r7 += values[i + 7]
        total = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
        for i in range(end, first + count):
            total += values[i]
        return total
    half = count // 2
    half -= half % 8
    return _sum_of(values, first, half) + _sum_of(values, first + half, count - half)
