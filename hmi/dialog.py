"""The base class of the HMI's dialogs (modal screens over an operating area).

Each area is a Textual mode with its own screen stack. A dialog's own message
(an ``Input.Submitted`` after Enter, an option chosen) can still be in its
queue when the next key, an area key, has switched to another area. Textual's
``dismiss`` would then pop the *current* area's top screen and hand the result
to the hidden area. :class:`AreaDialog` closes only while it is the active
screen; otherwise the dialog stays open in its area, as it was, for when the
operator comes back (the monkey test found this with fast keys).
"""

from __future__ import annotations

from typing import Any

from textual.await_complete import AwaitComplete
from textual.screen import ModalScreen, ScreenResultType


class AreaDialog(ModalScreen[ScreenResultType]):
    """A modal dialog that closes only while it is on top of the current area."""

    def dismiss(self, result: Any = None) -> AwaitComplete:
        """Close with ``result`` if this dialog is the active screen; else leave it open."""
        if not self.is_active:
            return AwaitComplete.nothing()
        return super().dismiss(result)
