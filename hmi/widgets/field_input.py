"""The text field of the panel's forms (cycle forms, JOG windows): fixed size, ↑/↓ between fields."""

from __future__ import annotations

from textual.binding import Binding

from hmi.widgets.fixed_size_input import FixedSizeInput

FIELD_KEYS = [
    Binding("down", "app.focus_next", "Next field", show=False),
    Binding("up", "app.focus_previous", "Previous field", show=False),
]
"""↑/↓ go from field to field (an Input would ignore them or scroll with them)."""


class FieldInput(FixedSizeInput):
    """A text field of a form; the form's CSS gives it its width and a height of 1."""

    BINDINGS = FIELD_KEYS
