"""The table of a path's chord extents answers what going through the chord ends answers, and
the material view fits the same picture with it as without."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from hmi.widgets.chord_extents import BLOCK_CHORDS, ChordExtents, chord_extents
from hmi.widgets.stock_view import VIEW_TITLES, StockPicture


def chord_ends(seed: int, chords: int) -> np.ndarray:
    return np.cumsum(np.random.default_rng(seed).normal(0.0, 1.0, (chords, 3)), axis=0)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), chords=st.integers(0, 3 * BLOCK_CHORDS + 5))
@example(seed=1, chords=3 * BLOCK_CHORDS + 5)
@example(seed=2, chords=2 * BLOCK_CHORDS)
def test_the_extents_of_the_first_chords_are_those_of_their_ends(seed: int, chords: int) -> None:
    ends = chord_ends(seed, chords)
    table = ChordExtents.of(ends)
    counts = {0, 1, BLOCK_CHORDS - 1, BLOCK_CHORDS, BLOCK_CHORDS + 1, 2 * BLOCK_CHORDS + 3, chords,
              *np.random.default_rng(seed).integers(0, chords + 1, 8).tolist()}
    for count in sorted(min(count, chords) for count in counts):
        drawn = table.of_first(count)
        if count == 0:
            assert drawn is None
        else:
            assert drawn is not None
            assert np.array_equal(drawn[0], ends[:count].min(axis=0))
            assert np.array_equal(drawn[1], ends[:count].max(axis=0))


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), chords=st.integers(0, 2500), shown=st.integers(0, 2500))
def test_a_picture_with_the_table_has_the_extents_of_one_without(seed: int, chords: int, shown: int) -> None:
    ends = chord_ends(seed, chords)
    plain = StockPicture(heights=np.zeros((2, 2), dtype=np.float32), z_mm=(-10.0, 5.0), blank_x_mm=(-15.0, 15.0),
                         blank_y_mm=(-10.0, 10.0), starts=ends, ends=ends, shown_chords=min(shown, chords))
    with_table = replace(plain, extents_table=chord_extents(ends))
    for view in VIEW_TITLES:
        assert with_table.extents(view) == plain.extents(view)
    assert chord_extents(ends) is with_table.extents_table  # the same path: the table made last
