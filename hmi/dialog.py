"""The base class of the HMI's dialogs (modal screens over an operating area).

Each area is a Textual mode with its own screen stack. A dialog's own message
(an ``Input.Submitted`` after Enter, an option chosen) can still be in its
queue when the next key, an area key, has switched to another area. Textual's
``dismiss`` would then pop the *current* area's top screen and hand the result
to the hidden area. :class:`AreaDialog` closes only while it is the active
screen; otherwise the dialog stays open in its area, as it was, for when the
operator comes back (the monkey test found this with fast keys).

The result goes to the code that opened the dialog at once, while the dialog
closes (Textual would queue it for the opener, behind keys the operator typed
after the dialog: a field opened by the result would miss them).
:meth:`hmi.app.HmiApp.push_screen` hands the callback to the dialog.
"""

from __future__ import annotations

from typing import Any, Callable

from textual.await_complete import AwaitComplete
from textual.binding import Binding
from textual.screen import ModalScreen, ScreenResultType

from hmi.focus import FocusRepaintsItsWidgets
from hmi.key_settle import BindingsInPlace


class AreaDialog(FocusRepaintsItsWidgets, BindingsInPlace, ModalScreen[ScreenResultType]):
    """A modal dialog that closes only while it is on top of the current area; Escape cancels it."""

    BINDINGS = [Binding("escape", "cancel_dialog", "Cancel", show=False)]

    result_handler: Callable[[Any], object] | None = None
    """Called with the result when the dialog closes (set by the app's ``push_screen``)."""

    def action_cancel_dialog(self) -> None:
        """Escape: close without a result."""
        self.dismiss(None)

    def dismiss(self, result: Any = None) -> AwaitComplete:
        """Close with ``result`` if this dialog is the active screen; else leave it open."""
        if not self.is_active:
            return AwaitComplete.nothing()
        closing = super().dismiss(result)
        handler, self.result_handler = self.result_handler, None
        if handler is not None:
            handler(result)
        return closing
