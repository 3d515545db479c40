"""A terminal plot of up to four trace curves on a braille canvas, with a cursor.

Each curve is scaled to its own value range (the signals have different units);
the legend gives every curve's range, and the cursor line reads out the values
of every curve at the sample under the cursor. Uses the braille canvas of
:mod:`hmi.widgets.toolpath`.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from rich.text import Text
from textual.widget import Widget

from nck import fixed

from hmi.i18n import _
from hmi.widgets.toolpath import BrailleCanvas

CURVE_STYLES = ("bold green", "bold yellow", "bold cyan", "bold magenta")
CURSOR_STYLE = "reverse"


def format_value(value: float) -> str:
    """A value for the legend and the read-out: fewer decimals for large magnitudes."""
    magnitude = abs(value)
    if magnitude >= 1000:
        return fixed(value, 1)
    if magnitude >= 1:
        return fixed(value, 3)
    return fixed(value, 4)


def value_range(values: Sequence[float]) -> tuple[float, float]:
    """(low, high) of ``values`` with a little room; a flat curve gets ±1 around its value."""
    array = np.asarray(values, dtype=float)
    finite = array[np.isfinite(array)]
    if finite.size == 0:
        return -1.0, 1.0
    low, high = float(finite.min()), float(finite.max())
    if high - low < 1e-9:
        pad = max(abs(low) * 0.05, 1e-3)
        return low - pad, high + pad
    pad = (high - low) * 0.05
    return low - pad, high + pad


def _draw_curve(canvas: BrailleCanvas, columns: np.ndarray, values: Sequence[float], kind: str) -> None:
    """One curve: per dot column the span of its samples, joined to the next column."""
    low, high = value_range(values)
    y = (1.0 - (np.asarray(values, dtype=float) - low) / (high - low)) * (canvas.dot_height - 1)
    y = np.nan_to_num(y, nan=float(canvas.dot_height - 1))
    starts = np.r_[0, np.flatnonzero(np.diff(columns)) + 1]
    ends = np.r_[starts[1:] - 1, columns.size - 1]
    y_min = np.minimum.reduceat(y, starts)
    y_max = np.maximum.reduceat(y, starts)
    previous: tuple[float, float] | None = None
    for column, first, last, lo, hi in zip(columns[starts], y[starts], y[ends], y_min, y_max):
        x = float(column)
        if previous is not None:
            canvas.line(previous[0], previous[1], x, float(first), kind)
        if hi - lo >= 1.0:
            canvas.line(x, float(lo), x, float(hi), kind)
        else:
            canvas.set_dot(int(x), int(round(float(first))), kind)
        previous = (x, float(last))


def draw_rows(times: Sequence[float], curves: Sequence[Sequence[float]], width: int,
              height: int) -> list[list[tuple[str, str]]]:
    """The curves on a ``width × height`` braille canvas, as rows of (character, curve kind)."""
    canvas = BrailleCanvas(width, height)
    if len(times):
        t = np.asarray(times, dtype=float)
        span = float(t[-1] - t[0]) or 1.0
        columns = np.rint((t - t[0]) / span * (canvas.dot_width - 1)).astype(int)
        for index, values in enumerate(curves):
            _draw_curve(canvas, columns, values, f"curve{index}")
    return canvas.rows()


def rows_to_text(rows: list[list[tuple[str, str]]], cursor_column: int | None = None) -> Text:
    """Rich text of canvas rows, one style run per curve, the cursor column highlighted."""
    text = Text(no_wrap=True, end="")
    for row_index, row in enumerate(rows):
        if row_index:
            text.append("\n")
        run, run_style = "", None
        for column, (char, kind) in enumerate(row):
            style = CURVE_STYLES[int(kind[5:])] if kind.startswith("curve") else None
            if column == cursor_column:
                style = CURSOR_STYLE if char != " " else "dim"
                char = char if char != " " else "│"
            if style != run_style and run:
                text.append(run, run_style)
                run = ""
            run_style = style
            run += char
        if run:
            text.append(run, run_style)
    return text


def cursor_column_of(times: Sequence[float], cursor: int, width: int) -> int:
    """The character column of sample ``cursor`` on a plot ``width`` characters wide."""
    span = (times[-1] - times[0]) or 1.0
    return int(round((times[cursor] - times[0]) / span * (width - 1)))


def render_curves(times: Sequence[float], curves: Sequence[Sequence[float]], width: int, height: int,
                  cursor: int | None = None) -> Text:
    """The curves drawn on a ``width × height`` character canvas (time from left to right)."""
    column = cursor_column_of(times, cursor, width) if cursor is not None and len(times) else None
    return rows_to_text(draw_rows(times, curves, width, height), column)


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
        self._version = 0
        self._drawn: tuple[tuple[int, int, int], list[list[tuple[str, str]]]] | None = None

    def set_data(self, times: Sequence[float], names: Sequence[str], units: Sequence[str],
                 curves: Sequence[Sequence[float]]) -> None:
        """Show new samples (no repaint when they are the ones shown); the cursor stays inside them."""
        data = (list(times), list(names), list(units), [list(c) for c in curves])
        if data == (self.times, self.names, self.units, self.curves):
            return
        self.times, self.names, self.units, self.curves = data
        self.cursor = min(self.cursor, max(len(self.times) - 1, 0))
        self._version += 1
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
            text.append(" " + _("No samples yet: choose signals, then start the trace."), style="dim")
            return text
        for index, (name, unit, curve) in enumerate(zip(self.names, self.units, self.curves)):
            array = np.asarray(curve, dtype=float)
            finite = array[np.isfinite(array)]
            low, high = (float(finite.min()), float(finite.max())) if finite.size else (0.0, 0.0)
            text.append(" ■ ", style=CURVE_STYLES[index])
            text.append(f"{name} [{unit}] {format_value(low)} … {format_value(high)}   ")
        text.append("\n")
        key = (self._version, width, height)
        if self._drawn is None or self._drawn[0] != key:  # moving the cursor does not redraw the curves
            self._drawn = (key, draw_rows(self.times, self.curves, width, height))
        text.append_text(rows_to_text(self._drawn[1], cursor_column_of(self.times, self.cursor, width)))
        t0, t1 = self.times[0], self.times[-1]
        left, right = f"{t0:.3f} s", f"{t1:.3f} s"
        text.append("\n" + left + " " * max(1, width - len(left) - len(right)) + right + "\n", style="dim")
        text.append(" " + self.readout(), style="bold")
        return text
