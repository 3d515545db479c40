"""The kernel's refusals by key: ``refuse("emergency_stop_active")`` is the :class:`Rejected`
an operator command gets, with its English text from ``data/refusals.toml``.

The key is the refusal's identity (a panel shows its text in its own language from
``data/lang/<code>/refusals.toml``); the English sentence stays the ``reason`` that the
headless command line, the logs and the tests read. Placeholders are named
(``{program}``) and filled from the keyword arguments. An exception of the data layers
(:class:`nck.refused.Refused`) becomes the same keyed refusal with :func:`rejected_by`.
Pure: reads the data table only.
"""

from __future__ import annotations

from nck.commands import Rejected
from nck.refused import Refused, refusal_texts


def refuse(key: str, *, alarm: int | None = None, **fields: object) -> Rejected:
    """The refusal ``key`` with its placeholders filled from ``fields`` (``KeyError``: no such key)."""
    return rejected_by(Refused(key, **fields), alarm=alarm)


def rejected_by(error: Refused, *, alarm: int | None = None) -> Rejected:
    """The keyed refusal an exception of the data layers carries (its English text as the reason)."""
    return Rejected(str(error), alarm=alarm, key=error.key, fields=error.fields)


__all__ = ["refusal_texts", "refuse", "rejected_by"]
