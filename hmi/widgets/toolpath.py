"""Toolpath simulation drawn in the terminal with braille dots.

Two layers, each testable on its own (the pieces, straight 3-D chords in the workpiece
coordinate system, come from the simulation's recorded path):

* :class:`BrailleCanvas` rasterises 2-D lines into a grid of braille cells
  (2 × 4 dots per character) and remembers, per cell, the most important kind
  of line drawn there (current block > feed move > rapid move);
* :class:`ToolpathView` is the widget: a projection (top view XY, side views
  XZ / YZ), zoom and pan by keys, fit-to-part, rapid moves dotted and dimmed,
  the current block's moves marked.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from rich.style import Style
from rich.text import Text
from textual.binding import Binding
from textual.reactive import reactive
from textual.widget import Widget

from hmi import i18n

Point3 = tuple[float, float, float]

VIEWS: dict[str, tuple[int, int, str]] = {
    "XY": (0, 1, i18n.N_("Top view XY  (→X ↑Y)")),
    "XZ": (0, 2, i18n.N_("Side view XZ  (→X ↑Z)")),
    "YZ": (1, 2, i18n.N_("Side view YZ  (→Y ↑Z)")),
}
"""Projection of each view: index of the horizontal and the vertical coordinate, and its title."""
TURNING_VIEW = "XZ"
"""A lathe's view: its path and blank as the half section (Z, 0, radius), Z across, the radius up."""
TURNING_TITLE = i18n.N_("Half section Z-X")

KIND_PRIORITY = {"rapid": 1, "feed": 2, "origin": 3, "current": 4}
KIND_STYLES = {
    "rapid": Style(color="#6c7a89", dim=True),
    "feed": Style(color="#7fd1ff"),
    "origin": Style(color="#ff9e3d"),
    "current": Style(color="#ffd700", bold=True),
}


@dataclass(frozen=True, slots=True)
class PathPiece:
    """One straight piece of the toolpath in the WCS.

    Attributes:
        start: (X, Y, Z) start point.
        end: (X, Y, Z) end point.
        rapid: True for G0 moves.
        line: 1-based source line of the block that produced it.
    """

    start: Point3
    end: Point3
    rapid: bool
    line: int


# ---------------------------------------------------------------------------------------------
# Braille canvas
# ---------------------------------------------------------------------------------------------

_DOT_BITS = ((0x01, 0x08), (0x02, 0x10), (0x04, 0x20), (0x40, 0x80))  # [row][column] in a cell
_DOT_BIT_TABLE = np.array(_DOT_BITS, dtype=np.int64)
_KIND_OF_PRIORITY = {priority: kind for kind, priority in KIND_PRIORITY.items()}
DOTS_PER_BATCH = 1 << 20
""":func:`draw_path` works out at most about this many dots at once (memory for a path zoomed in
far: each of its pieces then spans many dots)."""


class BrailleCanvas:
    """A grid of ``width × height`` characters, each 2 dots wide and 4 dots high."""

    def __init__(self, width: int, height: int) -> None:
        self.width = max(1, width)
        self.height = max(1, height)
        self._bits = [[0] * self.width for _ in range(self.height)]
        self._kinds = [[""] * self.width for _ in range(self.height)]

    def copy(self) -> BrailleCanvas:
        """An independent copy (to draw a marker over a kept drawing)."""
        twin = BrailleCanvas(self.width, self.height)
        twin._bits = [row[:] for row in self._bits]
        twin._kinds = [row[:] for row in self._kinds]
        return twin

    @property
    def dot_width(self) -> int:
        """Width in dots."""
        return self.width * 2

    @property
    def dot_height(self) -> int:
        """Height in dots."""
        return self.height * 4

    @property
    def far_limit(self) -> float:
        """A line with an end farther than this (in dots, either axis) is clipped to the canvas
        before it is drawn (a line zoomed far beyond the window)."""
        return 4 * (self.dot_width + self.dot_height) * 50.0

    def set_dot(self, x: int, y: int, kind: str) -> None:
        """Set the dot at (x, y) (origin top left); dots outside are ignored."""
        if 0 <= x < self.dot_width and 0 <= y < self.dot_height:
            row, column = y // 4, x // 2
            self._bits[row][column] |= _DOT_BITS[y % 4][x % 2]
            if KIND_PRIORITY.get(kind, 0) >= KIND_PRIORITY.get(self._kinds[row][column], 0):
                self._kinds[row][column] = kind

    def set_dots(self, xs: np.ndarray, ys: np.ndarray, priorities: np.ndarray) -> None:
        """:meth:`set_dot` for many dots at once (integer dot coordinates and the priority of each
        dot's kind in :data:`KIND_PRIORITY`); the same canvas as setting them one by one in any
        order, since each kind has a priority of its own."""
        inside = (xs >= 0) & (xs < self.dot_width) & (ys >= 0) & (ys < self.dot_height)
        xs, ys, priorities = xs[inside], ys[inside], priorities[inside]
        if not len(xs):
            return
        cells = (ys // 4) * self.width + xs // 2
        bits = _DOT_BIT_TABLE[ys % 4, xs % 2]
        touched, where = np.unique(cells, return_inverse=True)
        cell_bits = np.zeros(len(touched), dtype=np.int64)
        np.bitwise_or.at(cell_bits, where, bits)
        cell_priority = np.zeros(len(touched), dtype=np.int64)
        np.maximum.at(cell_priority, where, priorities)
        for cell, bit, priority in zip(touched.tolist(), cell_bits.tolist(), cell_priority.tolist()):
            row, column = divmod(cell, self.width)
            self._bits[row][column] |= bit
            if priority >= KIND_PRIORITY.get(self._kinds[row][column], 0):
                self._kinds[row][column] = _KIND_OF_PRIORITY[priority]

    def line(self, x0: float, y0: float, x1: float, y1: float, kind: str, dashed: bool = False) -> None:
        """Draw a line between dot coordinates; ``dashed`` leaves gaps (2 on, 2 off)."""
        if not all(math.isfinite(v) for v in (x0, y0, x1, y1)):
            return
        limit = self.far_limit
        if max(abs(x0), abs(x1)) > limit or max(abs(y0), abs(y1)) > limit:
            clipped = _clip(x0, y0, x1, y1, -2, -2, self.dot_width + 2, self.dot_height + 2)
            if clipped is None:
                return
            x0, y0, x1, y1 = clipped
        steps = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for step in range(steps + 1):
            if dashed and (step // 2) % 2 == 1:
                continue
            fraction = step / steps
            self.set_dot(round(x0 + (x1 - x0) * fraction), round(y0 + (y1 - y0) * fraction), kind)

    def rows(self) -> list[list[tuple[str, str]]]:
        """Each row as a list of (character, kind); empty cells are spaces with kind ''."""
        return [
            [(chr(0x2800 + bits) if bits else " ", kind) for bits, kind in zip(bit_row, kind_row)]
            for bit_row, kind_row in zip(self._bits, self._kinds)
        ]

    def to_text(self) -> Text:
        """The canvas as Rich text with one style per kind."""
        text = Text(no_wrap=True, end="")
        for index, row in enumerate(self.rows()):
            if index:
                text.append("\n")
            for char, kind in row:
                text.append(char, KIND_STYLES.get(kind))
        return text


def _clip(
    x0: float, y0: float, x1: float, y1: float, xmin: float, ymin: float, xmax: float, ymax: float
) -> tuple[float, float, float, float] | None:
    """Liang–Barsky clipping of a line to a rectangle."""
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x0 - xmin), (dx, xmax - x0), (-dy, y0 - ymin), (dy, ymax - y0)):
        if p == 0:
            if q < 0:
                return None
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return None
    return x0 + t0 * dx, y0 + t0 * dy, x0 + t1 * dx, y0 + t1 * dy


# ---------------------------------------------------------------------------------------------
# Projection
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Viewport:
    """What part of the plane is shown: centre (h, v) in mm and mm per dot."""

    center_h: float
    center_v: float
    mm_per_dot: float


@dataclass(frozen=True)
class PieceArrays:
    """The pieces of a path as arrays (what :func:`draw_path` works on): starts and ends
    (n × 3, WCS), rapid flags and source lines."""

    starts: np.ndarray
    ends: np.ndarray
    rapid: np.ndarray
    lines: np.ndarray

    @classmethod
    def of(cls, pieces: Sequence[PathPiece]) -> PieceArrays:
        """The arrays of ``pieces`` (made once per path: for 100,000s of pieces it takes a while)."""
        return cls(np.array([piece.start for piece in pieces], dtype=np.float64).reshape(-1, 3),
                   np.array([piece.end for piece in pieces], dtype=np.float64).reshape(-1, 3),
                   np.array([piece.rapid for piece in pieces], dtype=bool),
                   np.array([piece.line for piece in pieces], dtype=np.int64))


def fit_viewport(pieces: Sequence[PathPiece] | PieceArrays, view: str, canvas: BrailleCanvas) -> Viewport:
    """The viewport that shows every piece of the path with a small margin."""
    h_index, v_index, _ = VIEWS[view]
    arrays = pieces if isinstance(pieces, PieceArrays) else PieceArrays.of(pieces)
    if len(arrays.rapid):
        ends = np.concatenate((arrays.starts, arrays.ends))
        low_h, high_h = float(ends[:, h_index].min()), float(ends[:, h_index].max())
        low_v, high_v = float(ends[:, v_index].min()), float(ends[:, v_index].max())
    else:
        low_h = high_h = low_v = high_v = 0.0
    span_h = high_h - low_h
    span_v = high_v - low_v
    # a terminal cell is about twice as high as wide: 2 dots across ≈ 4 dots down, so dots are square
    mm_per_dot = max(span_h / max(canvas.dot_width - 4, 1), span_v / max(canvas.dot_height - 4, 1), 1e-3)
    return Viewport((high_h + low_h) / 2, (high_v + low_v) / 2, mm_per_dot * 1.05)


def draw_path(
    pieces: Sequence[PathPiece] | PieceArrays, view: str, viewport: Viewport, canvas: BrailleCanvas,
    current_line: int | None = None, origin: bool = True,
) -> None:
    """Project ``pieces`` into ``canvas`` (rapid dashed, current block marked, origin cross).

    The same dots as :meth:`BrailleCanvas.line` for each piece in turn (every step of each piece
    worked out with the same arithmetic, as arrays): a long program's hundreds of thousands of
    pieces take a fraction of a second, not seconds (less with their :class:`PieceArrays` kept)."""
    h_index, v_index, _ = VIEWS[view]
    half_w, half_h = canvas.dot_width / 2, canvas.dot_height / 2
    if origin:
        ox = (0.0 - viewport.center_h) / viewport.mm_per_dot + half_w
        oy = half_h - (0.0 - viewport.center_v) / viewport.mm_per_dot
        canvas.line(ox - 3, oy, ox + 3, oy, "origin")
        canvas.line(ox, oy - 3, ox, oy + 3, "origin")
    arrays = pieces if isinstance(pieces, PieceArrays) else PieceArrays.of(pieces)
    if not len(arrays.rapid):
        return
    starts, ends, rapid = arrays.starts, arrays.ends, arrays.rapid
    current = arrays.lines == current_line if current_line is not None else np.zeros(len(rapid), dtype=bool)
    x0 = (starts[:, h_index] - viewport.center_h) / viewport.mm_per_dot + half_w
    y0 = half_h - (starts[:, v_index] - viewport.center_v) / viewport.mm_per_dot
    x1 = (ends[:, h_index] - viewport.center_h) / viewport.mm_per_dot + half_w
    y1 = half_h - (ends[:, v_index] - viewport.center_v) / viewport.mm_per_dot
    priority = np.where(current, KIND_PRIORITY["current"],
                        np.where(rapid, KIND_PRIORITY["rapid"], KIND_PRIORITY["feed"]))
    with np.errstate(invalid="ignore"):
        finite = np.isfinite(x0) & np.isfinite(y0) & np.isfinite(x1) & np.isfinite(y1)
        limit = canvas.far_limit
        far = finite & ((np.maximum(np.abs(x0), np.abs(x1)) > limit) | (np.maximum(np.abs(y0), np.abs(y1)) > limit))
        # a piece whose dots all round to outside the canvas sets none of them
        outside = ((np.maximum(x0, x1) < -1.0) | (np.minimum(x0, x1) > canvas.dot_width + 1.0)
                   | (np.maximum(y0, y1) < -1.0) | (np.minimum(y0, y1) > canvas.dot_height + 1.0))
    for index in np.flatnonzero(far).tolist():  # clipped first, as BrailleCanvas.line does
        kind = _KIND_OF_PRIORITY[int(priority[index])]
        canvas.line(float(x0[index]), float(y0[index]), float(x1[index]), float(y1[index]), kind,
                    dashed=bool(rapid[index]))
    near = np.flatnonzero(finite & ~far & ~outside)
    steps = np.maximum(np.abs(x1[near] - x0[near]), np.abs(y1[near] - y0[near])).astype(np.int64) + 1
    dots = steps + 1  # step 0 … steps
    batch_ends = np.searchsorted(np.cumsum(dots), np.arange(DOTS_PER_BATCH, int(dots.sum()) + DOTS_PER_BATCH,
                                                             DOTS_PER_BATCH), side="right")
    first = 0
    for last in [*batch_ends.tolist(), len(near)]:
        if last > first:
            _draw_pieces(canvas, near[first:last], steps[first:last], x0, y0, x1, y1, rapid, priority)
        first = max(first, last)


def _draw_pieces(canvas: BrailleCanvas, which: np.ndarray, steps: np.ndarray, x0: np.ndarray, y0: np.ndarray,
                 x1: np.ndarray, y1: np.ndarray, rapid: np.ndarray, priority: np.ndarray) -> None:
    """The dots of pieces ``which`` (``steps`` each, as :meth:`BrailleCanvas.line` counts them)."""
    counts = steps + 1
    piece = np.repeat(which, counts)
    step = np.arange(int(counts.sum()), dtype=np.int64) - np.repeat(np.cumsum(counts) - counts, counts)
    keep = ~(rapid[piece] & ((step // 2) % 2 == 1))  # dashed: 2 on, 2 off
    piece, step = piece[keep], step[keep]
    fraction = step / np.repeat(steps, counts)[keep]
    xs = np.rint(x0[piece] + (x1[piece] - x0[piece]) * fraction).astype(np.int64)
    ys = np.rint(y0[piece] + (y1[piece] - y0[piece]) * fraction).astype(np.int64)
    canvas.set_dots(xs, ys, priority[piece])


# ---------------------------------------------------------------------------------------------
# Widget
# ---------------------------------------------------------------------------------------------

VIEW_BINDINGS = [
    Binding("plus,equals_sign", "zoom(1)", "Zoom +", show=False),
    Binding("minus", "zoom(-1)", "Zoom -", show=False),
    Binding("left", "pan(-1, 0)", "Pan left", show=False),
    Binding("right", "pan(1, 0)", "Pan right", show=False),
    Binding("up", "pan(0, 1)", "Pan up", show=False),
    Binding("down", "pan(0, -1)", "Pan down", show=False),
    Binding("f", "fit", "Fit", show=False),
    Binding("1", "view('XY')", "XY", show=False),
    Binding("2", "view('XZ')", "XZ", show=False),
    Binding("3", "view('YZ')", "YZ", show=False),
]
"""Keys of a focused simulation view (the toolpath and the material view alike): zoom, pan,
fit and the three projections; the screen's softkeys call the same actions."""

ZOOM_STEP = 1.5
PAN_FRACTION = 0.1


class ToolpathView(Widget, can_focus=True):
    """The simulation window: a projection of the toolpath with zoom and pan by keys.

    Keys (while focused): ``+``/``-`` zoom, arrows pan, ``f`` fit, ``1``/``2``/``3``
    views XY / XZ / YZ. The screen's softkeys call the same actions.
    """

    DEFAULT_CSS = """
    ToolpathView { height: 1fr; width: 1fr; }
    """

    BINDINGS = VIEW_BINDINGS

    view: reactive[str] = reactive("XY")
    """The projection shown: ``XY``, ``XZ`` or ``YZ``."""
    current_line: reactive[int | None] = reactive(None)
    """1-based source line of the block being executed (marked), or None."""

    def __init__(self, pieces: Sequence[PathPiece] = (), **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self._path = PieceArrays.of(pieces)
        self._line_order: tuple[np.ndarray, np.ndarray] | None = None  # piece indices by line, their lines
        self._turning = False  # a lathe's path, drawn as its half section whatever the view chosen
        self._base: tuple[tuple, BrailleCanvas, Viewport] | None = None
        self._fitted: tuple[tuple, Viewport] | None = None
        self._zoom = 1.0
        self._pan_h = 0.0
        self._pan_v = 0.0
        self.status_text = ""

    @property
    def path(self) -> PieceArrays:
        """The toolpath shown, as arrays."""
        return self._path

    @property
    def pieces(self) -> list[PathPiece]:
        """The toolpath shown, piece by piece (made on each call: a long path's pieces take a
        while; the view itself draws from :attr:`path`)."""
        path = self._path
        return [PathPiece(tuple(start), tuple(end), rapid, line)  # type: ignore[arg-type]
                for start, end, rapid, line in zip(path.starts.tolist(), path.ends.tolist(),
                                                   path.rapid.tolist(), path.lines.tolist())]

    @property
    def shown_view(self) -> str:
        """The view drawn: the chosen one, or a lathe's half section."""
        return TURNING_VIEW if self._turning else self.view

    def set_pieces(self, pieces: Sequence[PathPiece], status_text: str = "") -> None:
        """Show a new toolpath (fitted to the window)."""
        self.set_path(PieceArrays.of(pieces), status_text)

    def set_path(self, path: PieceArrays, status_text: str = "", *, turning: bool = False) -> None:
        """Show a new toolpath given as arrays (fitted to the window): a long simulation's
        hundreds of thousands of pieces are drawn from its arrays, never made into objects.
        ``turning``: a lathe's path given as its half section (Z, 0, radius), shown as the
        material view shows the bar, Z across and the radius up."""
        self._path = path
        self._turning = turning
        self._line_order = None
        self._base = None
        self._fitted = None
        self.status_text = status_text
        self.action_fit()

    def _pieces_of_line(self, line: int) -> PieceArrays | None:
        """The pieces of source line ``line`` (None: it has none): a binary search in the
        pieces sorted by line (sorted once per path, at the first block marked)."""
        path = self._path
        if self._line_order is None:
            order = np.argsort(path.lines, kind="stable")
            self._line_order = (order, path.lines[order])
        order, sorted_lines = self._line_order
        first, last = np.searchsorted(sorted_lines, [line, line + 1])
        if first == last:
            return None
        which = order[first:last]
        return PieceArrays(path.starts[which], path.ends[which], path.rapid[which], path.lines[which])

    @property
    def zoom(self) -> float:
        """Zoom factor relative to the fitted view."""
        return self._zoom

    def action_zoom(self, direction: int) -> None:
        """Zoom in (+1) or out (−1) by one step."""
        self._zoom = max(0.05, min(1000.0, self._zoom * (ZOOM_STEP if direction > 0 else 1 / ZOOM_STEP)))
        self.refresh()

    def action_pan(self, dh: int, dv: int) -> None:
        """Move the view a tenth of its size right (dh=+1)/left or up (dv=+1)/down."""
        self._pan_h += dh * PAN_FRACTION / self._zoom
        self._pan_v += dv * PAN_FRACTION / self._zoom
        self.refresh()

    def action_fit(self) -> None:
        """Show the whole toolpath again."""
        self._zoom = 1.0
        self._pan_h = self._pan_v = 0.0
        self.refresh()

    def action_view(self, view: str) -> None:
        """Switch the projection."""
        if view in VIEWS:
            self.view = view
            self.action_fit()

    def render_canvas(self, width: int, height: int) -> tuple[BrailleCanvas, Viewport]:
        """Draw the toolpath into a canvas of ``width × height`` cells.

        The path without the current block is drawn once per size, view, zoom and
        pan and kept; a new current block only redraws its own pieces on a copy.
        """
        path = self._path
        view = self.shown_view
        key = (width, height, view, self._zoom, self._pan_h, self._pan_v)  # set_path drops both caches
        if self._base is None or self._base[0] != key:
            canvas = BrailleCanvas(width, height)
            fit_key = (width, height, view)
            if self._fitted is None or self._fitted[0] != fit_key:  # zoom and pan keep the fit
                self._fitted = (fit_key, fit_viewport(path, view, canvas))
            fitted = self._fitted[1]
            span_h = fitted.mm_per_dot * canvas.dot_width
            span_v = fitted.mm_per_dot * canvas.dot_height
            viewport = Viewport(
                fitted.center_h + self._pan_h * span_h,
                fitted.center_v + self._pan_v * span_v,
                fitted.mm_per_dot / self._zoom,
            )
            draw_path(path, view, viewport, canvas)
            self._base = (key, canvas, viewport)
        _, base, viewport = self._base
        line = self.current_line
        current = self._pieces_of_line(line) if line is not None else None
        if current is None:
            return base, viewport
        canvas = base.copy()
        draw_path(current, view, viewport, canvas, line, origin=False)
        return canvas, viewport

    def render(self) -> Text:
        """Title line plus the canvas."""
        width, height = self.size.width, max(self.size.height - 1, 1)
        canvas, viewport = self.render_canvas(width, height)
        title = TURNING_TITLE if self._turning else VIEWS[self.view][2]
        scale_mm = viewport.mm_per_dot * 2 * 10  # ten characters
        head = Text(no_wrap=True, end="")
        head.append(f" {i18n._(title)} ", Style(bold=True, reverse=True))
        head.append("  " + i18n._("zoom {zoom}x   10 chars = {scale} mm").format(zoom=f"{self._zoom:g}", scale=f"{scale_mm:.3f}")
                    + "   ")
        head.append("── " + i18n._("feed") + "  ", KIND_STYLES["feed"])
        head.append("┄┄ " + i18n._("rapid") + "  ", KIND_STYLES["rapid"])
        head.append("── " + i18n._("current block") + "  ", KIND_STYLES["current"])
        if self.status_text:
            head.append(self.status_text)
        head.truncate(width)  # one line, whatever the terminal width
        head.append("\n")
        head.append_text(canvas.to_text())
        return head

    def watch_current_line(self) -> None:
        """Repaint when the executing block changes."""
        self.refresh()
