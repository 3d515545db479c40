"""The NC editor's document without per-line row tables behaves like Textual's own."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from textual.document._document import Document
from textual.document._wrapped_document import WrappedDocument

from hmi.widgets.nc_editor import _CountedWrappedDocument, _IdentityRows, _NcDocument, widest_line_cells

PIECES = st.sampled_from(["G1 X1", "\n", "\tY2", "", "N10\n\n", "ä", "; c\n\t"])
TEXTS = st.lists(PIECES, max_size=8).map("".join)


def tables(wrapped: WrappedDocument) -> tuple[object, ...]:
    return (list(wrapped._offset_to_line_info), list(wrapped._line_index_to_offsets),
            list(wrapped._tab_width_cache), list(wrapped._wrap_offsets), wrapped.height)


@settings(max_examples=200, deadline=None)
@given(TEXTS, st.lists(st.tuples(st.integers(0, 12), st.integers(0, 6), st.integers(0, 12),
                                 st.integers(0, 6), TEXTS), max_size=6))
def test_edits_keep_the_same_row_tables(text: str, edits: list[tuple[int, int, int, int, str]]) -> None:
    ours_doc, theirs_doc = _NcDocument(text), Document(text)
    ours, theirs = _CountedWrappedDocument(ours_doc, tab_width=4), WrappedDocument(theirs_doc, tab_width=4)
    assert isinstance(ours._offset_to_line_info, _IdentityRows)
    assert tables(ours) == tables(theirs)
    for row_a, col_a, row_b, col_b, insert in edits:
        start = (min(row_a, theirs_doc.line_count - 1), min(col_a, len(theirs_doc[min(row_a, theirs_doc.line_count - 1)])))
        end = (min(row_b, theirs_doc.line_count - 1), min(col_b, len(theirs_doc[min(row_b, theirs_doc.line_count - 1)])))
        start, end = sorted((start, end))
        result = theirs_doc.replace_range(start, end, insert)
        assert ours_doc.replace_range(start, end, insert) == result
        theirs.wrap_range(start, end, result.end_location)
        ours.wrap_range(start, end, result.end_location)
        assert ours_doc.text == theirs_doc.text
        assert tables(ours) == tables(theirs)


def test_widest_line_counts_cells() -> None:
    assert widest_line_cells(["G1", "G1 X100", ""], 4) == 7
    assert widest_line_cells(["\tX", "ab"], 4) == 5
    assert widest_line_cells(["全角"], 4) == 4
