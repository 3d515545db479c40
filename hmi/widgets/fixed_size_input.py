"""A text field whose CSS fixes its width and height: a typed character repaints the field alone.

Textual's ``Input`` sets its virtual (scrollable) width to the text's width plus the cursor on
every change of value, and ``Widget`` declares ``virtual_size`` with ``layout=True``: each typed
or deleted character laid out the whole screen again (Textual 8.2.8, ``Input._watch_value``).
A field of fixed size cannot move anything in that layout. What the layout did for the field
itself is done without it: the scroll offset is clamped against the new virtual width when it is
set (``Widget.validate_scroll_x``) and ``Input`` scrolls to the cursor with ``force``, so the
text in the field scrolls as before; a field's horizontal scrollbar is 0 cells high in
``Input``'s CSS, so its visibility, which the layout would have updated, is never drawn.
"""

from __future__ import annotations

from textual.geometry import Size
from textual.reactive import Reactive
from textual.widgets import Input


class FixedSizeInput(Input):
    """An ``Input`` for CSS that sets its ``width`` and ``height`` (not ``auto``): typing only repaints it."""

    virtual_size: Reactive[Size] = Reactive(Size(0, 0), layout=False)
