"""An RGB pixel image as terminal cells, two pixels a cell, handed to Textual as strips.

Every cell is ``▀`` with the upper pixel as its foreground and the lower as its background, a
run of equal cells in a row one segment. :class:`HalfBlockPicture` builds the strips straight
from the pixels (numpy finds the runs, a segment per run is all Python does). Handing Textual a
rich ``Text`` with a span per run instead cost several times as much: Textual converts every
span's style, lays the text out again, and gives every span a style of its own carrying its
offset (for text selection, which a picture does not offer). The cells are the same: the
caption's style under every cell, the cell's colours over it.
"""

from __future__ import annotations

import numpy as np
from rich.segment import Segment
from rich.style import Style as RichStyle
from rich.text import Text
from textual.content import Content
from textual.css.styles import RulesMap
from textual.strip import Strip
from textual.style import Style
from textual.visual import RenderOptions, Visual

UPPER_HALF = "▀"
MAX_CELL_STYLES = 65_536

_cell_styles: dict[tuple[Style, int], RichStyle] = {}
"""The style of every cell met so far: (style under it, both pixels' colours packed). A picture
has a few thousand cells but far fewer colour pairs, and most of them come back in the next
picture."""


def packed_cells(image: np.ndarray) -> np.ndarray:
    """Per cell (rows × width) of the RGB ``image`` its upper and lower pixel packed in one
    integer: upper red, green, blue, lower red, green, blue, a byte each (an odd last pixel
    row is left out)."""
    height_px = image.shape[0] - image.shape[0] % 2
    upper = image[0:height_px:2].astype(np.int64)
    lower = image[1:height_px:2].astype(np.int64)
    return ((upper[..., 0] << 40) | (upper[..., 1] << 32) | (upper[..., 2] << 24)
            | (lower[..., 0] << 16) | (lower[..., 1] << 8) | lower[..., 2])


def _cell_style(under: Style, cell: int) -> RichStyle:
    """The cell's colours (packed as :func:`packed_cells` does) over ``under``."""
    style = _cell_styles.get((under, cell))
    if style is None:
        if len(_cell_styles) >= MAX_CELL_STYLES:
            _cell_styles.clear()
        r, g, b, r2, g2, b2 = ((cell >> shift) & 0xFF for shift in (40, 32, 24, 16, 8, 0))
        colours = Style.from_rich_style(RichStyle(color=f"rgb({r},{g},{b})", bgcolor=f"rgb({r2},{g2},{b2})"))
        style = _cell_styles[(under, cell)] = (under + colours).rich_style
    return style


class HalfBlockPicture(Visual):
    """A caption line, then the image ``image`` (height × width × RGB, uint8) in half-block
    cells; the caption's style lies under the picture's cells too."""

    def __init__(self, caption: Text, image: np.ndarray) -> None:
        self.caption = caption
        self.cells = packed_cells(image)

    def render_strips(self, width: int, height: int | None, style: Style, options: RenderOptions) -> list[Strip]:
        """The caption's strip, then a strip per row of cells (Visual protocol)."""
        strips = Content.from_rich_text(self.caption).render_strips(width, 1, style, options)[:1]
        caption_style = self.caption.style
        under = style + (Style.from_rich_style(caption_style) if isinstance(caption_style, RichStyle)
                         else options.get_style(caption_style))
        strips.extend(self._rows(under))
        if height is not None:
            strips = strips[:height]
        return [strip.crop(0, width) if strip.cell_length > width else strip for strip in strips]

    def _rows(self, under: Style) -> list[Strip]:
        cells = self.cells
        rows, width = cells.shape
        if rows == 0 or width == 0:
            return []
        # Where a run of equal cells starts (every row starts one), in reading order.
        starts = np.ones((rows, width), dtype=bool)
        np.not_equal(cells[:, 1:], cells[:, :-1], out=starts[:, 1:])
        begin = np.flatnonzero(starts)
        lengths = np.diff(begin, append=rows * width).tolist()
        kinds, kind_of_run = np.unique(cells.ravel()[begin], return_inverse=True)
        styles = [_cell_style(under, kind) for kind in kinds.tolist()]
        segments = [Segment(UPPER_HALF * length, styles[kind]) for length, kind in zip(lengths, kind_of_run.tolist())]
        row_ends = np.cumsum(starts.sum(axis=1)).tolist()
        return [Strip(segments[first:last], width) for first, last in zip([0, *row_ends[:-1]], row_ends)]

    def get_optimal_width(self, rules: RulesMap, container_width: int) -> int:
        """The picture's width in cells (Visual protocol)."""
        return max(self.cells.shape[1], self.caption.cell_len)

    def get_height(self, rules: RulesMap, width: int) -> int:
        """The caption line and the rows of cells (Visual protocol)."""
        return 1 + self.cells.shape[0]
