"""Dot product and length of 3-vectors in plain floats, bit for bit numpy's.

The path geometry was first written with numpy (``np.dot``, ``np.linalg.norm``) and every
recorded result depends on its rounding. For three elements numpy's ``dot`` takes one of two
forms, depending on the BLAS kernel the machine's processor gets: a chain of fused
multiply-adds, ``fma(a2, b2, fma(a1, b1, a0 * b0))`` (one rounding per step, not two: a plain
Python sum differs in the last bit in about a quarter of the cases), or the plain sum
``((0 + a0 * b0) + a1 * b1) + a2 * b2``. A probe at import finds which (on probe vectors where
the two differ). Python 3.11 has no ``math.fma``; :func:`fused_multiply_add` computes it
exactly: the product's rounding error comes from Dekker's split (``a * b == p + e`` exactly)
and ``math.fsum`` rounds ``p + e + c`` once, correctly.

A numpy call costs microseconds of dispatch for three elements; these functions cost about a
third of that. Values the split cannot take exactly (very large, very small, not finite) go
to numpy, and so does everything when numpy's ``dot`` is neither form, so the results are
numpy's on every machine.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

_SPLIT = 134_217_729.0  # 2**27 + 1: Dekker's splitter for 53-bit doubles
_LARGEST = 1e150  # beyond this the split overflows
_SMALLEST_PRODUCT = 1e-250  # below this the product's error term may be subnormal (inexact)


def fused_multiply_add(a: float, b: float, c: float) -> float | None:
    """``a * b + c`` rounded once (IEEE fma), or None where the exact split cannot be used."""
    p = a * b
    if not (abs(a) < _LARGEST and abs(b) < _LARGEST and (abs(p) > _SMALLEST_PRODUCT or a == 0.0 or b == 0.0)):
        return None
    t = _SPLIT * a
    a_high = t - (t - a)
    a_low = a - a_high
    t = _SPLIT * b
    b_high = t - (t - b)
    b_low = b - b_high
    error = ((a_high * b_high - p) + a_high * b_low + a_low * b_high) + a_low * b_low
    if error == 0.0:
        return p + c  # the product is exact: one rounding, signed zeros as the fma gives them
    return math.fsum((p, error, c))  # p + error + c is not zero (p + error is not a double)


def _chain_dot(a: Sequence[float], b: Sequence[float]) -> float | None:
    first = a[0] * b[0] + 0.0  # numpy's accumulator starts at +0.0
    inner = fused_multiply_add(a[1], b[1], first)
    if inner is None:
        return None
    return fused_multiply_add(a[2], b[2], inner)


def _plain_dot(a: Sequence[float], b: Sequence[float]) -> float:
    return ((0.0 + a[0] * b[0]) + a[1] * b[1]) + a[2] * b[2]  # numpy's accumulator starts at +0.0


PROBES = (((-0.619, -5.069, 0.875), (1.479, -9.738, -5.665)),
          ((2.349, -7.466, -9.965), (7.428, -5.811, -5.69)),
          ((-5.904, 8.82, 3.813), (9.331, 7.875, -4.024)))
"""Vector pairs on which the fused chain and the plain sum (in either order) differ."""


def _numpy_dot_form() -> str | None:
    """``"chain"`` or ``"plain"``: the form numpy's 3-element ``dot`` gives on :data:`PROBES`;
    None when it is neither."""
    numpy_dots = [float(np.dot(np.asarray(a), np.asarray(b))) for a, b in PROBES]
    if all(_chain_dot(a, b) == d for (a, b), d in zip(PROBES, numpy_dots)):
        return "chain"
    if all(_plain_dot(a, b) == d for (a, b), d in zip(PROBES, numpy_dots)):
        return "plain"
    return None


_FORM = _numpy_dot_form()


def dot3(a: Sequence[float], b: Sequence[float]) -> float:
    """``float(np.dot(a, b))`` of two 3-vectors, the same bits."""
    if _FORM == "chain":
        found = _chain_dot(a, b)
        if found is not None:
            return found
    elif _FORM == "plain":
        return _plain_dot(a, b)
    return float(np.dot(np.asarray(a, dtype=float), np.asarray(b, dtype=float)))


def norm3(v: Sequence[float]) -> float:
    """``float(np.linalg.norm(v))`` of a 3-vector (the square root of ``dot(v, v)``), the same bits."""
    return math.sqrt(dot3(v, v))
