"""A sentence of the kernel that a panel says in its own language.

A :class:`Phrase` is the English sentence (a ``str``: what reports, recordings, the command
line and the tests read) with its ``template`` and the values of its named placeholders
(``fields``). The template is a text of the panel's gettext catalogue (``tests.i18n.sources``
collects the ``Phrase("…")`` and ``Reason("…")`` templates of the kernel modules that write
them); a field may itself be a phrase. Pure: no imports of the kernel.
"""

from __future__ import annotations

from typing import Any


class Phrase(str):
    """The English sentence ``template.format(**fields)``, keeping ``template`` and ``fields``."""

    template: str
    fields: dict[str, Any]

    def __new__(cls, template: str, **fields: Any) -> "Phrase":
        phrase = super().__new__(cls, template.format(**fields))
        phrase.template = template
        phrase.fields = fields
        return phrase


__all__ = ["Phrase"]
