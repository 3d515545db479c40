"""The refusals of ``data/refusals.toml`` by key, and the exception that carries one.

An exception of the kernel's data layers (access, data writes, set-up values) that a
panel shows is a :class:`Refused`: it is raised with the refusal's key and the values of
its placeholders (``raise PasswordError("password_too_long", max=8)``), ``str()`` is the
English text (what the command line, the logs and the tests read), and
:func:`nck.refusals.rejected_by` turns it into a keyed :class:`nck.commands.Rejected` that
a panel says in its own language. Pure: reads the data table only (and imports nothing
else of the kernel, so that every layer may raise it).
"""

from __future__ import annotations

import functools

from nck.resources import load_toml


@functools.cache
def refusal_texts() -> dict[str, str]:
    """Every refusal's English text by key (``data/refusals.toml``)."""
    return {str(key): str(entry["text"]) for key, entry in load_toml("refusals.toml")["refusal"].items()}


def refusal_fields(fields: dict[str, object]) -> tuple[tuple[str, str], ...]:
    """The values of a refusal's placeholders as text, in the order given."""
    return tuple((name, str(value)) for name, value in fields.items())


class Refused(Exception):
    """A refusal of ``data/refusals.toml``: ``key`` and its placeholders' values (``fields``);
    ``str()`` is the English text (``KeyError``: no such key)."""

    def __init__(self, key: str, **fields: object) -> None:
        self.key = key
        self.fields = refusal_fields(fields)
        super().__init__(refusal_texts()[key].format(**dict(self.fields)))


__all__ = ["Refused", "refusal_fields", "refusal_texts"]
