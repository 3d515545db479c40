"""The screen as the terminal shows it, row by row (from the SVG export).

``widget.render()`` returns a widget's text even when the layout gave the widget
no room; these rows hold only what the compositor actually drew.
"""

from __future__ import annotations

import html
import re

from textual.app import App

_TEXT = re.compile(r'<text [^>]*clip-path="url\(#[\w-]*line-(\d+)\)"[^>]*>([^<]*)</text>')


def screen_rows(app: App) -> dict[int, str]:
    """The drawn text of each screen row (row number -> text pieces joined by a space)."""
    rows: dict[int, list[str]] = {}
    for row, text in _TEXT.findall(app.export_screenshot()):
        rows.setdefault(int(row), []).append(html.unescape(text).replace("\xa0", " "))
    return {row: " ".join(pieces) for row, pieces in rows.items()}
