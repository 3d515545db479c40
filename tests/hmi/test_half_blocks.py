"""The material view's half-block cells made straight from the pixels are the cells Textual made
of the rich Text the view drew before (a ``▀`` per cell, a span per run of equal cells, the
caption's style over the whole text): same characters, colours and attributes, cell by cell."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from rich.color import ColorSystem
from rich.style import Style as RichStyle
from rich.text import Span, Text
from textual.color import Color
from textual.content import Content
from textual.strip import Strip
from textual.style import Style
from textual.visual import RenderOptions

from hmi.widgets.half_blocks import HalfBlockPicture


def text_of(caption: Text, image: np.ndarray) -> Text:
    """The view's Text before: the caption, a line break, then a span per run of equal cells."""
    height_px, width_px = image.shape[0] - image.shape[0] % 2, image.shape[1]
    rows = height_px // 2
    text = caption.copy()
    if rows == 0 or width_px == 0:
        return text
    pairs = np.concatenate([image[0:height_px:2], image[1:height_px:2]], axis=2)
    spans: list[Span] = []
    for row in range(rows):
        offset = row * (width_px + 1)
        begin = 0
        for column in range(1, width_px + 1):
            if column == width_px or not np.array_equal(pairs[row, column], pairs[row, begin]):
                r, g, b, r2, g2, b2 = pairs[row, begin].tolist()
                spans.append(Span(offset + begin, offset + column,
                                  RichStyle(color=f"rgb({r},{g},{b})", bgcolor=f"rgb({r2},{g2},{b2})")))
                begin = column
    text.append("\n")
    text.append_text(Text("\n".join(["▀" * width_px] * rows), spans=spans))
    return text


def cells(strips: list[Strip]) -> list[list[tuple[str, str]]]:
    """Per line its cells: the character and the terminal codes of its style."""
    return [[(character, style.render(character, color_system=ColorSystem.TRUECOLOR) if style else character)
             for text, style, _ in strip for character in text] for strip in strips]


def options() -> RenderOptions:
    return RenderOptions(lambda style: style if isinstance(style, Style) else Style.parse(style), {})


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), width_px=st.integers(1, 40), height_px=st.integers(0, 24),
       colours=st.integers(1, 6), caption_style=st.sampled_from(["bold", "", "italic"]),
       base=st.sampled_from([Style(), Style(background=Color(30, 40, 50), foreground=Color(200, 210, 220)),
                             Style(background=Color(1, 2, 3), bold=True)]))
def test_cells_are_those_of_the_text_the_view_drew_before(seed: int, width_px: int, height_px: int, colours: int,
                                                          caption_style: str, base: Style) -> None:
    rng = np.random.default_rng(seed)
    palette = rng.integers(0, 256, (colours, 3), dtype=np.uint8)
    image = palette[rng.integers(0, colours, (height_px, width_px))]  # runs of equal cells when few colours
    caption = Text("Top view XY  zoom 1.00  path on"[:width_px], style=caption_style)
    before = Content.from_rich_text(text_of(caption, image)).render_strips(width_px, None, base, options())
    after = HalfBlockPicture(caption, image).render_strips(width_px, None, base, options())
    assert cells(after) == cells(before)
