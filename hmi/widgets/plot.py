"""A terminal plot of up to four trace curves on a braille canvas, with a cursor.

Each curve is scaled to its own value range (the signals have different units);
the legend gives every curve's range, and the cursor line reads out the values
of every curve at the sample under the cursor. Uses the braille canvas of
:mod:`hmi.widgets.toolpath`.
"""

from __future__ import annotations

import math
from typing import Sequence

from rich.text import Text
from textual.widget import Widget

from hmi.widgets.toolpath import BrailleCanvas

CURVE_STYLES = ("bold green", "bold yellow", "bold cyan", "bold magenta")
CURSOR_STYLE = "reverse"


def format_value(value: float) -> str:
    """A value for the legend and the read-out: fewer decimals for large magnitudes."""
    magnitude = abs(value)
    if magnitude >= 1000:
        return f"{value:.1f}"
    if magnitude >= 1:
        return f"{value:.3f}"
    return f"{value:.4f}"


def value_range(values: Sequence[float]) -> tuple[float, float]:
    """(low, high) of ``values`` with a little room; a flat curve gets ±1 around its value."""
    finite = [v for v in values if math.isfinite(v)]
    if not finite:
        return -1.0, 1.0
    low, high = min(finite), max(finite)
    if high - low < 1e-9:
        pad = max(abs(low) * 0.05, 1e-3)
        return low - pad, high + pad
    pad = (high - low) * 0.05
    return low - pad, high + pad


def render_curves(times: Sequence[float], curves: Sequence[Sequence[float]], width: int, height: int,
                  cursor: int | None = None) -> Text:
    """The curves drawn on a ``width × height`` character canvas (time from left to right)."""
    canvas = BrailleCanvas(width, height)
    count = len(times)
    if count:
        t0, t1 = times[0], times[-1]
        span = (t1 - t0) or 1.0
        for index, values in enumerate(curves):
            low, high = value_range(values)
            kind = f"curve{index}"
            last: tuple[float, float] | None = None
            step = max(1, count // (canvas.dot_width * 2))
            for k in list(range(0, count, step)) + [count - 1]:
                x = (times[k] - t0) / span * (canvas.dot_width - 1)
                y = (1.0 - (values[k] - low) / (high - low)) * (canvas.dot_height - 1)
                if last is not None:
                    canvas.line(last[0], last[1], x, y, kind)
                else:
                    canvas.set_dot(round(x), round(y), kind)
                last = (x, y)
    cursor_column = None
    if cursor is not None and count:
        span = (times[-1] - times[0]) or 1.0
        cursor_column = int(round((times[cursor] - times[0]) / span * (width - 1)))
    text = Text(no_wrap=True, end="")
    for row_index, row in enumerate(canvas.rows()):
        if row_index:
            text.append("\n")
        for column, (char, kind) in enumerate(row):
            style = CURVE_STYLES[int(kind[5:])] if kind.startswith("curve") else None
            if column == cursor_column:
                text.append(char if char != " " else "│", style=CURSOR_STYLE if char != " " else "dim")
            else:
                text.append(char, style)
    return text


class TracePlot(Widget):
    """Up to four curves against time, a legend and a cursor read-out."""

    DEFAULT_CSS = """
    TracePlot { height: 1fr; }
    """

    def __init__(self, **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self.times: list[float] = []
        self.names: list[str] = []
        self.units: list[str] = []
        self.curves: list[list[float]] = []
        self.cursor = 0

    def set_data(self, times: Sequence[float], names: Sequence[str], units: Sequence[str],
                 curves: Sequence[Sequence[float]]) -> None:
        """Show new samples; the cursor stays inside them."""
        self.times = list(times)
        self.names = list(names)
        self.units = list(units)
        self.curves = [list(c) for c in curves]
        self.cursor = min(self.cursor, max(len(self.times) - 1, 0))
        self.refresh()

    def move_cursor(self, samples: int) -> None:
        """Move the cursor by ``samples`` (negative: to the left), clamped to the data."""
        if self.times:
            self.cursor = max(0, min(len(self.times) - 1, self.cursor + samples))
            self.refresh()

    def readout(self) -> str:
        """``t = …  name = value unit …`` at the cursor (empty without data)."""
        if not self.times:
            return ""
        parts = [f"t = {self.times[self.cursor]:.3f} s"]
        for name, unit, curve in zip(self.names, self.units, self.curves):
            parts.append(f"{name} = {format_value(curve[self.cursor])} {unit}")
        return "   ".join(parts)

    def render(self) -> Text:
        """Legend, canvas, time axis and cursor read-out."""
        width = max(self.size.width, 10)
        height = max(self.size.height - 4, 2)
        text = Text(no_wrap=True, end="")
        if not self.times:
            text.append(" No samples yet: choose signals, then start the trace.", style="dim")
            return text
        for index, (name, unit, curve) in enumerate(zip(self.names, self.units, self.curves)):
            finite = [v for v in curve if math.isfinite(v)] or [0.0]
            low, high = min(finite), max(finite)
            text.append(" ■ ", style=CURVE_STYLES[index])
            text.append(f"{name} [{unit}] {format_value(low)} … {format_value(high)}   ")
        text.append("\n")
        text.append_text(render_curves(self.times, self.curves, width, height, self.cursor))
        t0, t1 = self.times[0], self.times[-1]
        left, right = f"{t0:.3f} s", f"{t1:.3f} s"
        text.append("\n" + left + " " * max(1, width - len(left) - len(right)) + right + "\n", style="dim")
        text.append(" " + self.readout(), style="bold")
        return text
