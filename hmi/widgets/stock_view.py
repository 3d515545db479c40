"""The blank being cut, drawn in the terminal with half-block cells in true colour.

Every character cell shows two pixels, one above the other (``▀`` with the upper pixel as
foreground and the lower as background), so the pixels are about square. Three layers:

* :class:`StockPicture` — what is shown, as plain numpy data: the Z-map heights over the
  blank, the executed path as chords, the tool; set by the screen from a simulation result;
* :func:`render_pixels` — one view of it as an RGB pixel image: the top view shaded by depth
  ("the deeper, the darker"; no material: background), the front section (XZ, through the
  tool's Y) or the side section (YZ, through the tool's X); the blank's extents outlined;
  the path overlay (feed, rapid dimmed, the highlighted block bright); the tool at its place;
  a lathe's picture (``turning``) is the half section of the bar: Z across, the radius up,
  the profile's heights being radii and the tool its nose circle;
* :class:`StockView` — the widget: zoom, pan, fit, the view, the overlay switch; its cells are
  made by :class:`~hmi.widgets.half_blocks.HalfBlockPicture`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from rich.text import Text
from textual.binding import Binding
from textual.reactive import reactive
from textual.widget import Widget

from hmi.i18n import N_, _, reason_text
from hmi.widgets.chord_extents import ChordExtents, chord_extents
from hmi.widgets.half_blocks import HalfBlockPicture
from hmi.widgets.path_layers import PathLayerCache, Viewport, path_layers, segment_pixels, to_pixels
from hmi.widgets.toolpath import TURNING_TITLE, TURNING_VIEW, VIEW_BINDINGS, ZOOM_STEP

BACKGROUND = np.array([16, 20, 28], dtype=np.uint8)
MATERIAL_TOP = np.array([214, 218, 226], dtype=np.float64)
MATERIAL_DEEP = np.array([52, 58, 70], dtype=np.float64)
SECTION = np.array([168, 174, 186], dtype=np.uint8)
OUTLINE = np.array([120, 200, 120], dtype=np.uint8)
FEED = np.array([70, 190, 255], dtype=np.uint8)
RAPID = np.array([110, 118, 130], dtype=np.uint8)
HIGHLIGHT = np.array([255, 215, 0], dtype=np.uint8)
TOOL = np.array([255, 140, 40], dtype=np.uint8)
BLOCK_CUT = np.array([230, 170, 60], dtype=np.float64)
"""The cut of the editor's cursor block: tints the cut cells of the top view, fills the removed
material of a section."""
BLOCK_CUT_TINT = 0.6
TOOL_HEIGHT_MM = 30.0
"""How much of the tool the sections draw above its tip."""

VIEW_TITLES = {"XY": N_("Top view XY"), "XZ": N_("Front section XZ"), "YZ": N_("Side section YZ")}
VIEW_AXES = {"XY": (0, 1), "XZ": (0, 2), "YZ": (1, 2)}


@dataclass
class StockPicture:
    """What the view shows (mm, workpiece coordinates)."""

    heights: np.ndarray = field(default_factory=lambda: np.zeros((0, 0), dtype=np.float32))
    x0_mm: float = 0.0
    y0_mm: float = 0.0
    resolution_mm: float = 1.0
    z_mm: tuple[float, float] = (0.0, 0.0)  # bottom, top
    blank_x_mm: tuple[float, float] = (0.0, 0.0)
    blank_y_mm: tuple[float, float] = (0.0, 0.0)
    starts: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    ends: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    rapid: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=bool))
    lines: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int32))
    shown_chords: int = 0  # chords drawn (the path up to the shown block)
    tool_mm: tuple[float, float, float] | None = None
    tool_radius_mm: float = 0.0
    turning: bool = False  # a lathe's half section: heights are radii over Z, the tool a nose circle
    outline_xy: np.ndarray | None = None  # the blank seen from above (corners X, Y); None: its extents
    cut_top: np.ndarray | None = None  # the cursor block's cut: heights before it, NaN: not cut
    cut_bottom: np.ndarray | None = None  # … and after it
    extents_table: ChordExtents | None = None  # the extents of the first n of ``ends`` (None: go through them)

    @property
    def empty(self) -> bool:
        """True before any simulation result arrived."""
        return self.heights.size == 0

    def extents(self, view: str) -> tuple[float, float, float, float]:
        """(h_min, h_max, v_min, v_max) of the blank and the path in ``view``."""
        h, v = VIEW_AXES[view]
        box = [(self.blank_x_mm[0], self.blank_y_mm[0], self.z_mm[0]),
               (self.blank_x_mm[1], self.blank_y_mm[1], self.z_mm[1])]
        if self.extents_table is not None and self.extents_table.ends is self.ends:
            drawn = self.extents_table.of_first(self.shown_chords)
            points = np.vstack([np.array(box), *drawn]) if drawn is not None else np.array(box)
        else:
            points = np.vstack([np.array(box), self.ends[: self.shown_chords]]) if len(self.ends) else np.array(box)
        return (float(points[:, h].min()), float(points[:, h].max()),
                float(points[:, v].min()), float(points[:, v].max()))


def picture_of(simulation: Any, zmap: Any, chords: int) -> StockPicture:
    """What the material view shows of ``simulation`` with the blank as ``zmap`` holds it (a
    copy of its heights) and the path drawn up to chord ``chords`` (the tool stands at that
    chord's end). A lathe's picture is the half section: Z across, the radius up
    (``simulation.turning``)."""
    path = simulation.path
    tool, tool_radius = simulation.tool_at(chords)
    starts, ends = simulation.drawn_path()
    blank = simulation.blank
    if simulation.turning:
        extent_x, extent_y, extent_z = blank.z_mm, (0.0, 0.0), (0.0, blank.diameter_mm / 2.0)
    else:
        extent_x, extent_y, extent_z = blank.x_mm, blank.y_mm, blank.z_mm
    return StockPicture(
        heights=zmap.heights.copy(), x0_mm=zmap.x0_mm, y0_mm=zmap.y0_mm,
        resolution_mm=zmap.resolution_mm, z_mm=extent_z, blank_x_mm=extent_x, blank_y_mm=extent_y,
        starts=starts, ends=ends, rapid=path.rapid, lines=path.lines, shown_chords=chords, tool_mm=tool,
        tool_radius_mm=tool_radius, turning=simulation.turning,
        outline_xy=None if simulation.turning else blank.outline_xy(), extents_table=chord_extents(ends))


def material_events(simulation: Any) -> str:
    """The sweep's events in one phrase: the first one (and how many more), else none."""
    events = simulation.events
    if not events:
        return _("no collisions")
    more = _(" (+{count} more)").format(count=len(events) - 1) if len(events) > 1 else ""
    return reason_text(events[0].text) + more


def fit_viewport(picture: StockPicture, view: str, width_px: int, height_px: int) -> Viewport:
    """The viewport that shows the blank and the path with a small margin."""
    h0, h1, v0, v1 = picture.extents(view)
    span = max((h1 - h0) / max(width_px - 2, 1), (v1 - v0) / max(height_px - 2, 1), 1e-3)
    return Viewport((h0 + h1) / 2.0, (v0 + v1) / 2.0, span * 1.05)


def _shade(depth_fraction: np.ndarray) -> np.ndarray:
    """Colour of material by its depth below the top (0: top, 1: bottom): the deeper, the darker."""
    f = np.clip(depth_fraction, 0.0, 1.0)[..., None]
    return (MATERIAL_TOP * (1.0 - f) + MATERIAL_DEEP * f).astype(np.uint8)


def render_pixels(picture: StockPicture, view: str, port: Viewport, width_px: int, height_px: int,
                  overlay: bool = True, highlight_line: int | None = None,
                  path_cache: PathLayerCache | None = None) -> np.ndarray:
    """The RGB image (height_px, width_px, 3) of ``view``; ``path_cache`` keeps the path
    overlay's layers from one call to the next (the same pixels as without it)."""
    image = np.empty((height_px, width_px, 3), dtype=np.uint8)
    image[:] = BACKGROUND
    if picture.empty:
        return image
    scale = port.mm_per_pixel
    hs = port.centre_h + (np.arange(width_px) - width_px / 2.0 + 0.5) * scale
    vs = port.centre_v - (np.arange(height_px) - height_px / 2.0 + 0.5) * scale
    heights = picture.heights
    ny, nx = heights.shape
    res = picture.resolution_mm
    bottom, top = picture.z_mm
    if view == "XY":
        ix = np.floor((hs - picture.x0_mm) / res).astype(np.int64)
        iy = np.floor((vs - picture.y0_mm) / res).astype(np.int64)
        inside = ((iy >= 0) & (iy < ny))[:, None] & ((ix >= 0) & (ix < nx))[None, :]
        values = heights[np.clip(iy, 0, ny - 1)[:, None], np.clip(ix, 0, nx - 1)[None, :]]
        material = inside & (values > bottom + 1e-6)
        colours = _shade((top - values) / max(top - bottom, 1e-9))
        if picture.cut_top is not None:
            cut = ~np.isnan(picture.cut_top[np.clip(iy, 0, ny - 1)[:, None], np.clip(ix, 0, nx - 1)[None, :]])
            tinted = colours * (1.0 - BLOCK_CUT_TINT) + BLOCK_CUT * BLOCK_CUT_TINT
            colours = np.where(cut[..., None], tinted.astype(np.uint8), colours)
        image[material] = colours[material]
    else:
        along = hs
        across = picture.tool_mm[1 if view == "XZ" else 0] if picture.tool_mm else None
        if across is None:
            across = sum(picture.blank_y_mm if view == "XZ" else picture.blank_x_mm) / 2.0
        if view == "XZ":
            ix = np.floor((along - picture.x0_mm) / res).astype(np.int64)
            row = int(math.floor((across - picture.y0_mm) / res))
            valid = (ix >= 0) & (ix < nx) & (0 <= row < ny)
            cells = (min(max(row, 0), ny - 1), np.clip(ix, 0, nx - 1))
        else:
            iy = np.floor((along - picture.y0_mm) / res).astype(np.int64)
            col = int(math.floor((across - picture.x0_mm) / res))
            valid = (iy >= 0) & (iy < ny) & (0 <= col < nx)
            cells = (np.clip(iy, 0, ny - 1), min(max(col, 0), nx - 1))
        column = heights[cells]
        material = valid[None, :] & (vs[:, None] <= column[None, :]) & (vs[:, None] >= bottom)
        image[material] = SECTION
        if picture.cut_top is not None and picture.cut_bottom is not None:
            top_of, bottom_of = picture.cut_top[cells], picture.cut_bottom[cells]
            with np.errstate(invalid="ignore"):  # NaN: not cut
                removed = valid[None, :] & (vs[:, None] <= top_of[None, :]) & (vs[:, None] > bottom_of[None, :])
            image[removed] = BLOCK_CUT.astype(np.uint8)
    _outline(image, picture, view, port)
    if overlay:
        _draw_path(image, picture, view, port, highlight_line, path_cache)
    _draw_tool(image, picture, view, port)
    return image


def _plot(image: np.ndarray, px: np.ndarray, py: np.ndarray, colour: np.ndarray) -> None:
    height_px, width_px = image.shape[:2]
    keep = (px >= 0) & (px < width_px) & (py >= 0) & (py < height_px)
    image[py[keep], px[keep]] = colour


def _segments(image: np.ndarray, port: Viewport, a: np.ndarray, b: np.ndarray, colour: np.ndarray) -> None:
    """Draw straight lines a[i] → b[i] (rows h, v in mm) by sampling at half a pixel."""
    if len(a) == 0:
        return
    height_px, width_px = image.shape[:2]
    px, py, _owner = segment_pixels(port, width_px, height_px, a, b)
    _plot(image, px, py, colour)


def _outline(image: np.ndarray, picture: StockPicture, view: str, port: Viewport) -> None:
    h, v = VIEW_AXES[view]
    lows = (picture.blank_x_mm[0], picture.blank_y_mm[0], picture.z_mm[0])
    highs = (picture.blank_x_mm[1], picture.blank_y_mm[1], picture.z_mm[1])
    h0, h1, v0, v1 = lows[h], highs[h], lows[v], highs[v]
    corners = np.array([[h0, v0], [h1, v0], [h1, v1], [h0, v1]])
    if view == "XY" and picture.outline_xy is not None:
        corners = picture.outline_xy  # a turned box, a cylinder
    _segments(image, port, corners, np.roll(corners, -1, axis=0), OUTLINE)


def _draw_path(image: np.ndarray, picture: StockPicture, view: str, port: Viewport, highlight_line: int | None,
               path_cache: PathLayerCache | None) -> None:
    count = picture.shown_chords
    if count == 0:
        return
    h, v = VIEW_AXES[view]
    height_px, width_px = image.shape[:2]
    if path_cache is not None:
        layers = path_cache.layers(picture.starts, picture.ends, picture.rapid, (h, v), port, width_px, height_px)
    else:
        layers = path_layers(picture.starts, picture.ends, picture.rapid, (h, v), port, width_px, height_px)
    layers.paint(image, count, FEED, RAPID)
    if highlight_line is not None:
        mine = np.flatnonzero(picture.lines[: len(picture.starts)] == highlight_line)
        _segments(image, port, picture.starts[mine][:, [h, v]], picture.ends[mine][:, [h, v]], HIGHLIGHT)


def _draw_tool(image: np.ndarray, picture: StockPicture, view: str, port: Viewport) -> None:
    if picture.tool_mm is None:
        return
    height_px, width_px = image.shape[:2]
    x, y, z = picture.tool_mm
    radius = max(picture.tool_radius_mm, port.mm_per_pixel)
    if view == "XY" or picture.turning:  # a lathe's tool is its nose circle in the half section
        v = z if picture.turning else y
        angles = np.linspace(0.0, 2.0 * math.pi, 180)
        px, py = to_pixels(port, width_px, height_px, x + radius * np.cos(angles), v + radius * np.sin(angles))
        _plot(image, px, py, TOOL)
        return
    centre = x if view == "XZ" else y
    corners = np.array([[centre - radius, z], [centre + radius, z], [centre + radius, z + TOOL_HEIGHT_MM],
                        [centre - radius, z + TOOL_HEIGHT_MM]])
    _segments(image, port, corners, np.roll(corners, -1, axis=0), TOOL)


class StockView(Widget, can_focus=True):
    """The blank being cut: top view or sections, with zoom, pan, fit and the path overlay."""

    BINDINGS = [*VIEW_BINDINGS, Binding("o", "overlay", "Path", show=False)]
    ALLOW_SELECT = False  # a picture: no text to select (its cells carry no offsets for it)

    view: reactive[str] = reactive("XY")
    overlay: reactive[bool] = reactive(True)
    highlight_line: reactive[int | None] = reactive(None)
    status_text: reactive[str] = reactive("")

    def __init__(self, **kwargs: object) -> None:
        super().__init__(**kwargs)  # type: ignore[arg-type]
        self.picture = StockPicture()
        self.auto_links = False  # a picture has no links: Textual need not look through its thousands of segments
        self._path_layers = PathLayerCache()
        self._zoom_steps = 0
        self._pan_px = (0, 0)

    @property
    def zoom(self) -> float:
        """Magnification relative to fit (1 = fit)."""
        return ZOOM_STEP ** self._zoom_steps

    def set_picture(self, picture: StockPicture, status_text: str = "") -> None:
        """Show a new picture (the view, zoom and pan stay)."""
        self.picture = picture
        self.status_text = status_text
        self.refresh()

    def action_zoom(self, direction: int) -> None:
        """Zoom in (+1) or out (-1) about the centre."""
        self._zoom_steps = max(-6, min(12, self._zoom_steps + direction))
        self.refresh()

    def action_pan(self, dh: int, dv: int) -> None:
        """Move the view by a quarter of its size."""
        self._pan_px = (self._pan_px[0] + dh, self._pan_px[1] + dv)
        self.refresh()

    def action_fit(self) -> None:
        """Show the whole blank and path."""
        self._zoom_steps = 0
        self._pan_px = (0, 0)
        self.refresh()

    def action_view(self, view: str) -> None:
        """Top view or a section (a lathe's picture stays the half section)."""
        if view in VIEW_TITLES:
            self.view = view

    @property
    def shown_view(self) -> str:
        """The view drawn: the chosen one, or a lathe's half section."""
        return TURNING_VIEW if self.picture.turning else self.view

    def action_overlay(self) -> None:
        """Path overlay on/off."""
        self.overlay = not self.overlay

    def viewport(self, width_px: int, height_px: int) -> Viewport:
        """The fitted viewport with this widget's zoom and pan."""
        port = fit_viewport(self.picture, self.shown_view, width_px, height_px)
        scale = port.mm_per_pixel / self.zoom
        return Viewport(port.centre_h + self._pan_px[0] * width_px / 4.0 * scale,
                        port.centre_v + self._pan_px[1] * height_px / 4.0 * scale, scale)

    def render(self) -> Text | HalfBlockPicture:
        """Caption line, then the picture."""
        width = max(self.size.width, 1)
        rows = max(self.size.height - 1, 1)
        title = TURNING_TITLE if self.picture.turning else VIEW_TITLES[self.view]
        path = _("path on") if self.overlay else _("path off")
        caption = Text(f"{_(title)}  {_('zoom')} {self.zoom:.2f}  {path}  {self.status_text}"[:width], style="bold")
        if self.picture.empty:
            return caption
        width_px, height_px = width, rows * 2
        image = render_pixels(self.picture, self.shown_view, self.viewport(width_px, height_px), width_px, height_px,
                              self.overlay, self.highlight_line, self._path_layers)
        return HalfBlockPicture(caption, image)

    def watch_view(self) -> None:
        self.refresh()

    def watch_overlay(self) -> None:
        self.refresh()

    def watch_highlight_line(self) -> None:
        self.refresh()

    def watch_status_text(self) -> None:
        self.refresh()
