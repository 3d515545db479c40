"""Focus that moves before the next key is read.

Textual's ``Widget.focus()`` asks the app to move the focus later, behind the
messages already in the app's queue. The keys of a burst (one read of the
terminal: a fast typist, a paste, ``tmux send-keys``) are in that queue
already, so the keys behind the one that moved the focus still went to the old
focus: Alt+D followed at once by ``G4 F1`` typed nothing into the MDA editor
(issue 18). :func:`focus_now` moves the focus at once, in line with the keys.
The HMI moves the focus only with it.
"""

from __future__ import annotations

from textual.reactive import Reactive
from textual.screen import Screen
from textual.widget import NoScreen, Widget


def focus_now(widget: Widget) -> None:
    """Give ``widget`` the focus now; a widget not on a screen yet gets it once it is."""
    try:
        screen = widget.screen
    except NoScreen:
        widget.focus()
        return
    screen.set_focus(widget)


class FocusRepaintsItsWidgets(Screen):
    """A screen whose focus change repaints the widgets it concerns, not the whole screen.

    Textual's ``Screen.focused`` is a reactive that repaints the whole screen when it changes.
    The focus change itself already restyles and repaints the blurred and the focused widget
    (``Widget._on_blur`` / ``_on_focus``, their ``:focus`` styles through ``has_focus``); the
    whole-screen repaint rendered every other widget again on every ↑/↓ between fields (and,
    under a translucent dialog, the panel beneath it too).
    """

    focused: Reactive[Widget | None] = Reactive(None, repaint=False)
    """Textual's ``Screen.focused`` without its repaint of the whole screen."""
