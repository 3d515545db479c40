"""Update a fixed-size text widget only when what it shows changes."""

from __future__ import annotations

from textual.widgets import Static


def show_text(widget: Static, content: object) -> None:
    """Update a fixed-size Static only when ``content`` differs from what it shows.

    No layout pass is made: area windows, the header fields and the dialog line have fixed
    sizes, so a refresh repaints just the widget (this keeps a refresh well under the 15 ms
    CPU budget).
    """
    if getattr(widget, "_shown_content", None) == content:
        return
    widget._shown_content = content  # type: ignore[attr-defined]
    widget.update(content, layout=False)  # type: ignore[arg-type]
