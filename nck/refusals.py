"""The kernel's refusals by key: ``refuse("emergency_stop_active")`` is the :class:`Rejected`
an operator command gets, with its English text from ``data/refusals.toml``.

The key is the refusal's identity (a panel shows its text in its own language from
``data/lang/<code>/refusals.toml``); the English sentence stays the ``reason`` that the
headless command line, the logs and the tests read. Placeholders are named
(``{program}``) and filled from the keyword arguments. Pure: reads the data table only.
"""

from __future__ import annotations

import functools

from nck.commands import Rejected
from nck.resources import load_toml


@functools.cache
def refusal_texts() -> dict[str, str]:
    """Every refusal's English text by key (``data/refusals.toml``)."""
    return {str(key): str(entry["text"]) for key, entry in load_toml("refusals.toml")["refusal"].items()}


def refuse(key: str, *, alarm: int | None = None, **fields: object) -> Rejected:
    """The refusal ``key`` with its placeholders filled from ``fields`` (``KeyError``: no such key)."""
    values = tuple((name, str(value)) for name, value in fields.items())
    return Rejected(refusal_texts()[key].format(**dict(values)), alarm=alarm, key=key, fields=values)
