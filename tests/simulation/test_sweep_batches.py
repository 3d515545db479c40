"""The Z-map's batched sweep cuts exactly what the moves cut one at a time (issue 24).

``ZMap.sweep`` evaluates many moves in one numpy pass, each over a window padded to the
batch's largest and shifted to stay inside the map, and lowers the cells by a minimum over
the batch. Lowering is a minimum, so the result must not depend on how the moves are
grouped or ordered: the height map after one call with every move is compared bit for bit
with the map after one call per move (a batch of one: the move's own window) and after the
moves in reverse order. The shape of each cut is tested against hand-computed volumes and
depths in ``test_removal.py``.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from nck.simulation.blank import Blank
from nck.simulation.cutter import Cutter
from nck.simulation.zmap import ZMap

CUTTERS = st.sampled_from([
    Cutter.flat(2.0), Cutter.ball(1.5), Cutter(2.5, 0.8), Cutter.drill(1.0), Cutter.drill(3.0, 90.0),
    Cutter.flat(0.0),
])
# Points around and beyond a 30 × 20 × 10 mm blank, so that windows reach over the edges.
COORD_X = st.floats(-6.0, 36.0, allow_nan=False)
COORD_Y = st.floats(-6.0, 26.0, allow_nan=False)
COORD_Z = st.floats(-12.0, 2.0, allow_nan=False)
POINT = st.tuples(COORD_X, COORD_Y, COORD_Z)


@st.composite
def paths(draw: st.DrawFn) -> np.ndarray:
    """A path of 1-40 points: straight moves, plunges (same X Y), ramps and long crossings."""
    points = [draw(POINT)]
    for _ in range(draw(st.integers(1, 40))):
        x, y, z = points[-1]
        kind = draw(st.sampled_from(["step", "plunge", "far", "level"]))
        if kind == "plunge":
            points.append((x, y, draw(COORD_Z)))
        elif kind == "far":
            points.append(draw(POINT))
        else:
            dx = draw(st.floats(-3.0, 3.0, allow_nan=False))
            dy = draw(st.floats(-3.0, 3.0, allow_nan=False))
            dz = 0.0 if kind == "level" else draw(st.floats(-1.0, 1.0, allow_nan=False))
            points.append((x + dx, y + dy, z + dz))
    return np.array(points, dtype=np.float64)


def fresh_map(resolution_mm: float) -> ZMap:
    return ZMap(Blank("box", (0.0, 30.0), (0.0, 20.0), (-10.0, 0.0)), resolution_mm)


@settings(max_examples=80, deadline=None)
@given(path=paths(), cutter=CUTTERS, resolution_mm=st.sampled_from([0.25, 0.4, 0.7]))
def test_batched_sweep_equals_one_move_at_a_time(path: np.ndarray, cutter: Cutter, resolution_mm: float) -> None:
    starts, ends = path[:-1], path[1:]
    batched = fresh_map(resolution_mm)
    batched.sweep(starts, ends, cutter)
    one_by_one = fresh_map(resolution_mm)
    for start, end in zip(starts, ends):
        one_by_one.sweep(start[None, :], end[None, :], cutter)
    reverse = fresh_map(resolution_mm)
    reverse.sweep(starts[::-1], ends[::-1], cutter)
    assert np.array_equal(batched.heights, one_by_one.heights)
    assert np.array_equal(batched.heights, reverse.heights)


@settings(max_examples=40, deadline=None)
@given(path=paths(), cutter=CUTTERS)
def test_depth_of_a_move_alone_is_its_deepest_cut(path: np.ndarray, cutter: Cutter) -> None:
    # One move on the uncut blank: the depth it reports is the most it lowered a cell.
    zmap = fresh_map(0.4)
    depth = zmap.sweep(path[:1], path[1:2], cutter)
    lowered = float((zmap.initial - zmap.heights).max())
    assert depth.shape == (1,)
    assert float(depth[0]) == lowered
