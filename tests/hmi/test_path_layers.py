"""The material view's path overlay painted from its per-pixel layers is the overlay drawn chord by
chord — rapid moves first, feed moves over them — for every number of chords drawn."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from hmi.widgets.path_layers import PathLayerCache, Viewport, path_layers, segment_pixels

FEED = np.array([1, 2, 3], dtype=np.uint8)
RAPID = np.array([4, 5, 6], dtype=np.uint8)


def drawn_one_by_one(starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, count: int, port: Viewport,
                     width_px: int, height_px: int) -> np.ndarray:
    image = np.zeros((height_px, width_px, 3), dtype=np.uint8)
    for colour, chosen in ((RAPID, rapid), (FEED, ~rapid)):
        for chord in np.flatnonzero(chosen[:count]).tolist():
            px, py, _ = segment_pixels(port, width_px, height_px, starts[chord:chord + 1, :2], ends[chord:chord + 1, :2])
            inside = (px >= 0) & (px < width_px) & (py >= 0) & (py < height_px)
            image[py[inside], px[inside]] = colour
    return image


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), chords=st.integers(0, 40), width_px=st.integers(1, 30),
       height_px=st.integers(1, 30), mm_per_pixel=st.floats(0.05, 5.0))
def test_layers_paint_what_drawing_the_chords_in_turn_draws(seed: int, chords: int, width_px: int, height_px: int,
                                                            mm_per_pixel: float) -> None:
    rng = np.random.default_rng(seed)
    starts = rng.uniform(-20.0, 20.0, (chords, 3))
    ends = starts + rng.normal(0.0, 3.0, (chords, 3))
    rapid = rng.random(chords) < 0.3
    port = Viewport(float(rng.uniform(-5, 5)), float(rng.uniform(-5, 5)), mm_per_pixel)
    layers = path_layers(starts, ends, rapid, (0, 1), port, width_px, height_px)
    cache = PathLayerCache()
    for count in range(chords + 1):
        image = np.zeros((height_px, width_px, 3), dtype=np.uint8)
        layers.paint(image, count, FEED, RAPID)
        assert np.array_equal(image, drawn_one_by_one(starts, ends, rapid, count, port, width_px, height_px)), count
        # the cache answers the same layers for the same path and view
        assert cache.layers(starts, ends, rapid, (0, 1), port, width_px, height_px).first_feed.tobytes() == \
            layers.first_feed.tobytes()


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), chords=st.integers(1, 300), width_px=st.integers(1, 40),
       height_px=st.integers(1, 40), zoom=st.floats(0.02, 50.0), pan=st.floats(-1.0, 1.0))
def test_a_long_polyline_in_any_viewport_paints_what_drawing_it_chord_by_chord_draws(
        seed: int, chords: int, width_px: int, height_px: int, zoom: float, pan: float) -> None:
    # A CAM program's path: many short chords one after the other (most shorter than a pixel
    # seen whole, several pixels long zoomed in), partly outside the picture when panned.
    rng = np.random.default_rng(seed)
    points = np.cumsum(rng.normal(0.0, 0.4, (chords + 1, 3)), axis=0)
    starts, ends = points[:-1], points[1:]
    rapid = rng.random(chords) < 0.05
    span = float(np.ptp(points[:, :2], axis=0).max()) + 1e-3
    port = Viewport(float(points[:, 0].mean() + pan * span), float(points[:, 1].mean() - pan * span / 2),
                    span / max(width_px, height_px) / zoom)
    layers = path_layers(starts, ends, rapid, (0, 1), port, width_px, height_px)
    for count in sorted({0, 1, chords // 3, chords // 2, chords}):
        image = np.zeros((height_px, width_px, 3), dtype=np.uint8)
        layers.paint(image, count, FEED, RAPID)
        assert np.array_equal(image, drawn_one_by_one(starts, ends, rapid, count, port, width_px, height_px)), count


def test_the_cache_gives_back_a_viewport_seen_before_and_works_out_a_new_path() -> None:
    rng = np.random.default_rng(7)
    starts = rng.uniform(-20.0, 20.0, (50, 3))
    ends = starts + rng.normal(0.0, 3.0, (50, 3))
    rapid = rng.random(50) < 0.3
    cache = PathLayerCache()
    ports = [Viewport(0.0, 0.0, 0.5 / 1.5 ** zoom) for zoom in range(4)]
    first = [cache.layers(starts, ends, rapid, (0, 1), port, 20, 16) for port in ports]
    again = [cache.layers(starts, ends, rapid, (0, 1), port, 20, 16) for port in reversed(ports)]
    assert all(kept is seen for kept, seen in zip(reversed(again), first))  # kept, not worked out again
    moved = ends + 1.0
    other = cache.layers(starts, moved, rapid, (0, 1), ports[0], 20, 16)
    assert np.array_equal(other.first_feed, path_layers(starts, moved, rapid, (0, 1), ports[0], 20, 16).first_feed)


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), chords=st.integers(1, 300), width_px=st.integers(1, 40),
       height_px=st.integers(1, 40), zoom_steps=st.integers(-3, 4),
       pans=st.lists(st.tuples(st.integers(-1, 1), st.integers(-1, 1)), min_size=1, max_size=8))
def test_a_panned_view_has_the_layers_worked_out_from_scratch_at_its_viewport(
        seed: int, chords: int, width_px: int, height_px: int, zoom_steps: int, pans: list[tuple[int, int]]) -> None:
    # A polyline (each chord starts where the one before it ends; some stand still, some repeat
    # a point) panned by a quarter of the view as the material view pans: the cache samples the
    # whole path once at the scale and marks the samples' pixels in each viewport panned to.
    rng = np.random.default_rng(seed)
    moves = rng.normal(0.0, 0.4, (chords + 1, 3)) * (rng.random((chords + 1, 1)) < 0.9)
    points = np.cumsum(moves, axis=0)
    starts, ends = points[:-1], points[1:]
    rapid = rng.random(chords) < 0.1
    span = float(np.ptp(points[:, :2], axis=0).max()) + 1e-3
    scale = span / max(width_px - 2, 1) / 1.5 ** zoom_steps
    centre_h, centre_v = float(points[:, 0].mean()), float(points[:, 1].mean())
    cache = PathLayerCache()
    pan_h = pan_v = 0
    for step_h, step_v in [(0, 0), *pans, (0, 0)]:
        pan_h, pan_v = pan_h + step_h, pan_v + step_v
        port = Viewport(centre_h + pan_h * width_px / 4.0 * scale, centre_v + pan_v * height_px / 4.0 * scale, scale)
        panned = cache.layers(starts, ends, rapid, (0, 1), port, width_px, height_px)
        scratch = path_layers(starts, ends, rapid, (0, 1), port, width_px, height_px)
        assert np.array_equal(panned.first_feed, scratch.first_feed), (pan_h, pan_v)
        assert np.array_equal(panned.first_rapid, scratch.first_rapid), (pan_h, pan_v)
