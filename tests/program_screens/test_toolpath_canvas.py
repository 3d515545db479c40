"""Toolpath geometry and the braille canvas."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from hmi.widgets import toolpath
from hmi.widgets.toolpath import VIEWS, BrailleCanvas, PathPiece, Viewport, draw_path, fit_viewport


def test_canvas_draws_braille_dots_and_keeps_priority() -> None:
    """A horizontal line lights dots; the current-block kind wins over feed in a shared cell."""
    canvas = BrailleCanvas(4, 2)
    canvas.line(0, 0, 7, 0, "feed")
    canvas.line(0, 0, 0, 0, "current")
    row = canvas.rows()[0]
    assert all(char != " " for char, _ in row)
    assert row[0][1] == "current" and row[1][1] == "feed"
    assert all(char == " " for char, _ in canvas.rows()[1])


def test_rapid_moves_are_dashed() -> None:
    """A dashed line lights fewer dots than a solid one."""
    solid, dashed = BrailleCanvas(20, 1), BrailleCanvas(20, 1)
    solid.line(0, 0, 39, 0, "feed")
    dashed.line(0, 0, 39, 0, "rapid", dashed=True)
    count = lambda c: sum(bin(ord(ch) - 0x2800).count("1") for row in c.rows() for ch, _ in row if ch != " ")
    assert 0 < count(dashed) < count(solid)


def test_fit_viewport_shows_the_whole_path_in_each_view() -> None:
    """After fitting, every end point projects inside the canvas, in XY, XZ and YZ."""
    pieces = [PathPiece((0.0, 0.0, 100.0), (50.0, -20.0, 5.0), True, 1),
              PathPiece((50.0, -20.0, 5.0), (-30.0, 40.0, -8.0), False, 2)]
    for view in ("XY", "XZ", "YZ"):
        canvas = BrailleCanvas(40, 12)
        viewport = fit_viewport(pieces, view, canvas)
        draw_path(pieces, view, viewport, canvas)
        text = "".join(ch for row in canvas.rows() for ch, _ in row)
        assert text.strip(), view
        # the path fills the canvas in at least one direction (fitted, not just somewhere inside)
        cells = [(r, c) for r, row in enumerate(canvas.rows()) for c, (ch, _) in enumerate(row) if ch != " "]
        columns = [c for _, c in cells]
        rows = [r for r, _ in cells]
        assert max(columns) - min(columns) >= 34 or max(rows) - min(rows) >= 10, view
        assert min(columns) >= 0 and max(columns) <= 39 and max(rows) <= 11


def test_huge_coordinates_do_not_hang() -> None:
    """Lines far outside the canvas are clipped instead of rasterised dot by dot."""
    canvas = BrailleCanvas(10, 5)
    canvas.line(-1e12, 5, 1e12, 5, "feed")
    canvas.line(float("nan"), 0, 1, 1, "feed")
    assert any(ch != " " for ch, _ in canvas.rows()[1])


def test_view_marks_the_current_block_over_the_kept_drawing() -> None:
    """The current block is drawn in its own colour; the kept base drawing stays unmarked."""
    from hmi.widgets.toolpath import ToolpathView

    pieces = [PathPiece((0.0, 0.0, 0.0), (10.0, 0.0, 0.0), True, 1),
              PathPiece((10.0, 0.0, 0.0), (10.0, 10.0, 0.0), False, 2),
              PathPiece((10.0, 10.0, 0.0), (0.0, 10.0, 0.0), False, 3)]
    view = ToolpathView(pieces)
    kinds = lambda c: {k for row in c.rows() for _, k in row}
    plain, _ = view.render_canvas(40, 12)
    assert "current" not in kinds(plain)
    view.current_line = 2
    marked, _ = view.render_canvas(40, 12)
    assert "current" in kinds(marked)
    view.current_line = None
    assert "current" not in kinds(view.render_canvas(40, 12)[0])


def _drawn_piece_by_piece(pieces, view, viewport, canvas, current_line=None) -> None:
    """The reference: every piece through BrailleCanvas.line in turn (the drawing before arrays)."""
    h_index, v_index, _ = VIEWS[view]

    def to_dots(point):
        return ((point[h_index] - viewport.center_h) / viewport.mm_per_dot + canvas.dot_width / 2,
                canvas.dot_height / 2 - (point[v_index] - viewport.center_v) / viewport.mm_per_dot)

    ox, oy = to_dots((0.0, 0.0, 0.0))
    canvas.line(ox - 3, oy, ox + 3, oy, "origin")
    canvas.line(ox, oy - 3, ox, oy + 3, "origin")
    for piece in pieces:
        kind = "current" if current_line is not None and piece.line == current_line else (
            "rapid" if piece.rapid else "feed")
        canvas.line(*to_dots(piece.start), *to_dots(piece.end), kind, dashed=piece.rapid)


coordinate = st.one_of(st.floats(-60.0, 60.0), st.sampled_from([0.0, 0.5, -0.5, 1e9, -1e9]))
point = st.tuples(coordinate, coordinate, coordinate)
piece_strategy = st.builds(PathPiece, point, point, st.booleans(), st.integers(1, 4))


@settings(max_examples=300, deadline=None)
@given(pieces=st.lists(piece_strategy, max_size=40), view=st.sampled_from(["XY", "XZ", "YZ"]),
       center=st.tuples(st.floats(-30.0, 30.0), st.floats(-30.0, 30.0)),
       mm_per_dot=st.sampled_from([0.25, 0.5, 1.0, 3.7]), size=st.tuples(st.integers(1, 30), st.integers(1, 9)),
       current_line=st.one_of(st.none(), st.integers(1, 4)), batch=st.sampled_from([1, 7, 1 << 20]))
def test_the_path_is_drawn_as_piece_by_piece(pieces, view, center, mm_per_dot, size, current_line, batch) -> None:
    """draw_path sets the same dots and cell kinds as drawing each piece with BrailleCanvas.line
    (rapid dashed, the current block's kind, pieces far outside clipped, any batch size)."""
    viewport = Viewport(center[0], center[1], mm_per_dot)
    expected, drawn = BrailleCanvas(*size), BrailleCanvas(*size)
    _drawn_piece_by_piece(pieces, view, viewport, expected, current_line)
    saved = toolpath.DOTS_PER_BATCH
    toolpath.DOTS_PER_BATCH = batch
    try:
        draw_path(pieces, view, viewport, drawn, current_line)
    finally:
        toolpath.DOTS_PER_BATCH = saved
    assert drawn.rows() == expected.rows()


def test_pieces_along_the_canvas_edges_are_drawn_as_piece_by_piece() -> None:
    """Pieces just inside and just outside each edge of the canvas: a dot rounds onto the canvas
    from up to half a dot outside, so such pieces are drawn, and farther ones are not."""
    canvas_size = (12, 4)  # 24 × 16 dots; with 1 mm per dot and the centre at 0 the dots span ±12, ±8 mm
    viewport = Viewport(0.0, 0.0, 1.0)
    offsets = (-1.6, -1.4, -0.6, -0.5, -0.4, 0.0, 0.4)
    pieces = []
    for offset in offsets:
        left, right = -12.0 + offset, 12.0 - 1.0 - offset  # dot x = mm + 12
        top, bottom = 8.0 - offset, -8.0 + 1.0 + offset  # dot y = 8 - mm
        pieces += [PathPiece((left, -7.0, 0.0), (left, 7.0, 0.0), False, 1),
                   PathPiece((right, -7.0, 0.0), (right, 7.0, 0.0), True, 2),
                   PathPiece((-11.0, top, 0.0), (11.0, top, 0.0), False, 3),
                   PathPiece((-11.0, bottom, 0.0), (11.0, bottom, 0.0), False, 4)]
    for piece in pieces:
        expected, drawn = BrailleCanvas(*canvas_size), BrailleCanvas(*canvas_size)
        _drawn_piece_by_piece([piece], "XY", viewport, expected)
        draw_path([piece], "XY", viewport, drawn)
        assert drawn.rows() == expected.rows(), piece


def test_fit_viewport_by_hand() -> None:
    """Pieces spanning X 0…10 and Y −4…20 on 40 × 12 cells (80 × 48 dots, two left free on each
    side): the larger of 10/76 and 24/44 mm per dot, 5 % margin, centred on the extents."""
    pieces = [PathPiece((0.0, -4.0, 1.0), (10.0, 3.0, 1.0), False, 1),
              PathPiece((10.0, 3.0, 1.0), (2.0, 20.0, -5.0), True, 2)]
    viewport = fit_viewport(pieces, "XY", BrailleCanvas(40, 12))
    assert viewport.center_h == 5.0 and viewport.center_v == 8.0
    assert math.isclose(viewport.mm_per_dot, 24.0 / 44.0 * 1.05)
    assert fit_viewport([], "XY", BrailleCanvas(40, 12)) == Viewport(0.0, 0.0, 1e-3 * 1.05)


def test_the_view_marks_every_piece_of_the_current_block_and_no_other() -> None:
    """The toolpath view draws the block being executed (``current_line``) in the current
    block's kind over the rest: the same dots as each piece drawn in turn, those of the
    marked line as current (lines 2 and 1 interleaved, line 3 alone, line 9 has no piece)."""
    pieces = [PathPiece((0.0, 0.0, 0.0), (10.0, 0.0, 0.0), False, 2),
              PathPiece((10.0, 0.0, 0.0), (10.0, 8.0, 0.0), True, 1),
              PathPiece((10.0, 8.0, 0.0), (0.0, 8.0, 0.0), False, 2),
              PathPiece((0.0, 8.0, 0.0), (0.0, 0.0, 0.0), False, 3)]
    view = toolpath.ToolpathView(pieces)
    for line in (1, 2, 3, 9, None):
        view.current_line = line
        drawn, viewport = view.render_canvas(30, 10)
        expected = BrailleCanvas(30, 10)
        _drawn_piece_by_piece(pieces, "XY", fit_viewport(pieces, "XY", expected), expected, line)
        assert viewport == fit_viewport(pieces, "XY", expected)
        assert drawn.rows() == expected.rows(), line
