"""Toolpath geometry and the braille canvas."""

from __future__ import annotations

import math

from nck.canon import Motion, Source
from hmi.widgets.toolpath import BrailleCanvas, draw_path, fit_viewport, path_from_motions


def motion(kind: str, line: int, x: float, y: float, z: float = 0.0, start=None, center=None) -> Motion:
    end = {"X": x, "Y": y, "Z": z}
    return Motion(kind=kind, source=Source("T.MPF", line), plane="G17", end_wcs=end, end_mcs=end,
                  start_mcs=start or {}, center_wcs=center)


def test_path_pieces_follow_the_motions() -> None:
    """Each motion becomes a piece from the previous end point; G0 pieces are rapid."""
    pieces = path_from_motions([
        motion("G0", 1, 10, 0, start={"X": 0.0, "Y": 0.0, "Z": 0.0}),
        motion("G1", 2, 10, 10),
    ])
    assert [(p.start, p.end, p.rapid, p.line) for p in pieces] == [
        ((0.0, 0.0, 0.0), (10.0, 0.0, 0.0), True, 1),
        ((10.0, 0.0, 0.0), (10.0, 10.0, 0.0), False, 2),
    ]


def test_arc_is_split_into_chords_on_its_circle() -> None:
    """A G3 half circle becomes chords whose points all lie on the circle."""
    pieces = path_from_motions([
        motion("G1", 1, 10, 0, start={"X": 10.0, "Y": 0.0, "Z": 0.0}),
        motion("G3", 2, -10, 0, center={"X": 0.0, "Y": 0.0}),
    ])
    arc = [p for p in pieces if p.line == 2]
    assert len(arc) >= 4
    for piece in arc:
        assert math.isclose(math.hypot(piece.end[0], piece.end[1]), 10.0, abs_tol=1e-9)
        assert piece.end[1] >= -1e-9  # counter-clockwise from +X to -X passes through +Y
    assert arc[-1].end == (-10.0, 0.0, 0.0)


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
    pieces = path_from_motions([
        motion("G0", 1, 50, -20, 5, start={"X": 0.0, "Y": 0.0, "Z": 100.0}),
        motion("G1", 2, -30, 40, -8),
    ])
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

    pieces = path_from_motions([
        motion("G0", 1, 10, 0, start={"X": 0.0, "Y": 0.0, "Z": 0.0}),
        motion("G1", 2, 10, 10),
        motion("G1", 3, 0, 10),
    ])
    view = ToolpathView(pieces)
    kinds = lambda c: {k for row in c.rows() for _, k in row}
    plain, _ = view.render_canvas(40, 12)
    assert "current" not in kinds(plain)
    view.current_line = 2
    marked, _ = view.render_canvas(40, 12)
    assert "current" in kinds(marked)
    view.current_line = None
    assert "current" not in kinds(view.render_canvas(40, 12)[0])
