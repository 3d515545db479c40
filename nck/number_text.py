"""Numbers as the operator reads them: fixed decimals and never a negative zero.

A value that rounds to zero at the shown precision (``-0.0004`` with 3 decimals,
``-0.2`` rpm with none) is shown without its sign, as the panel does: the screen
and the ``nck`` output print ``0.000``, never ``-0.000``.
"""

from __future__ import annotations


def fixed(value: float, places: int = 3, width: int = 0) -> str:
    """``value`` with ``places`` decimals, right aligned in ``width``; no ``-0``."""
    shown = round(float(value), places) + 0.0  # + 0.0 turns -0.0 into 0.0
    return f"{shown:{width}.{places}f}"


def trimmed(value: float, places: int = 6) -> str:
    """``value`` with at most ``places`` decimals, trailing zeros dropped; no ``-0``."""
    text = fixed(value, places).rstrip("0").rstrip(".")
    return text or "0"
