"""The material view's path overlay for every number of chords drawn, worked out once per view.

Drawing the overlay chord by chord (rapid moves first, feed moves over them) costs about as
much as the rest of a picture together, and a scrub step or the cursor moving to another
block draws the same chords at the same place again, only up to another chord. So, per view,
viewport and size, each pixel keeps the first chord that draws it in feed and the first that
draws it in rapid: with ``count`` chords drawn a pixel is in feed when its first feed chord is
below ``count``, else in rapid when its first rapid chord is — the same pixels as drawing the
chords one after the other.

Chords are sampled at half a pixel along their length (:func:`segment_pixels`), as every
straight line of the view is. Working the layers out only samples the chords whose extents
reach into the picture (a zoomed-in view of a long program sees few of them), and a widget's
:class:`PathLayerCache` keeps the layers of the last few viewports, so zooming back to a level
seen before costs nothing. A pan keeps the scale: the cache samples the whole path once at the
scale of the view shown (:class:`ScaleSamples`, while that is a few samples a chord) and each
viewport panned to only finds its samples' pixels.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Viewport:
    """Pixel ↔ mm: the view's centre and the size of a pixel."""

    centre_h: float
    centre_v: float
    mm_per_pixel: float


def to_pixels(port: Viewport, width_px: int, height_px: int, h: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Pixel column and row of the points (h, v) in mm."""
    px = np.floor((h - port.centre_h) / port.mm_per_pixel + width_px / 2.0).astype(np.int64)
    py = np.floor((port.centre_v - v) / port.mm_per_pixel + height_px / 2.0).astype(np.int64)
    return px, py


def sample_steps(length_mm: np.ndarray, port: Viewport, width_px: int, height_px: int) -> np.ndarray:
    """How many samples a line of ``length_mm`` gets: one every half pixel and both ends, at most
    four per pixel of the picture's width and height together."""
    length = length_mm / port.mm_per_pixel
    return np.minimum(np.ceil(length * 2.0).astype(np.int64) + 1, 4 * (width_px + height_px))


def sample_points(start_h: np.ndarray, start_v: np.ndarray, delta_h: np.ndarray, delta_v: np.ndarray,
                  steps: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The samples (h, v in mm) of the lines start → start + delta, ``steps`` of them along each
    from end to end, and the line each belongs to, in the lines' order."""
    owner = np.repeat(np.arange(len(steps)), steps)
    first = np.cumsum(steps) - steps
    fraction = (np.arange(len(owner)) - np.repeat(first, steps)) / np.repeat(np.maximum(steps - 1, 1), steps)
    return start_h[owner] + delta_h[owner] * fraction, start_v[owner] + delta_v[owner] * fraction, owner


def segment_pixels(port: Viewport, width_px: int, height_px: int, a: np.ndarray,
                   b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The pixels of the straight lines a[i] → b[i] (rows h, v in mm), sampled at half a pixel:
    columns, rows and the line each sample belongs to, in the lines' order (samples outside the
    image included)."""
    ah, av = np.ascontiguousarray(a[:, 0]), np.ascontiguousarray(a[:, 1])  # 1-D gathers below are cheaper
    dh, dv = b[:, 0] - ah, b[:, 1] - av
    h, v, owner = sample_points(ah, av, dh, dv, sample_steps(np.hypot(dh, dv), port, width_px, height_px))
    px, py = to_pixels(port, width_px, height_px, h, v)
    return px, py, owner


@dataclass(frozen=True)
class Chords:
    """Straight lines seen along two axes, kept for rasterising them in any viewport: start
    (h, v), direction (end − start), length and extents in mm, and each line's chord number."""

    start_h: np.ndarray
    start_v: np.ndarray
    delta_h: np.ndarray
    delta_v: np.ndarray
    length_mm: np.ndarray
    low_h: np.ndarray
    high_h: np.ndarray
    low_v: np.ndarray
    high_v: np.ndarray
    numbers: np.ndarray

    @classmethod
    def of(cls, a: np.ndarray, b: np.ndarray, numbers: np.ndarray) -> Chords:
        """The lines a[i] → b[i] (rows h, v in mm) numbered ``numbers``."""
        ah, av = np.ascontiguousarray(a[:, 0]), np.ascontiguousarray(a[:, 1])
        bh, bv = np.ascontiguousarray(b[:, 0]), np.ascontiguousarray(b[:, 1])
        dh, dv = bh - ah, bv - av
        return cls(ah, av, dh, dv, np.hypot(dh, dv), np.minimum(ah, bh), np.maximum(ah, bh),
                   np.minimum(av, bv), np.maximum(av, bv), numbers)

    def __len__(self) -> int:
        return len(self.numbers)


SHORT_LINE_STEPS = 6
"""Lines of up to this many samples are sampled all at once per number of samples (most of a
long program's chords, seen whole, are shorter than a pixel: two samples)."""


def first_chords(port: Viewport, width_px: int, height_px: int, chords: Chords, never: int) -> np.ndarray:
    """Per pixel (height_px × width_px) the smallest number of the ``chords`` that draw it
    (``never`` where none does): the pixels of :func:`segment_pixels`, sampling only the lines
    whose extents reach into the picture."""
    layer = np.full(height_px * width_px, never, dtype=np.int64)
    scale = port.mm_per_pixel
    # The picture in mm with a pixel to spare: a line whose extents stay outside has no sample in it.
    h_low, h_high = port.centre_h - (width_px / 2.0 + 1.0) * scale, port.centre_h + (width_px / 2.0 + 1.0) * scale
    v_low, v_high = port.centre_v - (height_px / 2.0 + 1.0) * scale, port.centre_v + (height_px / 2.0 + 1.0) * scale
    seen = np.flatnonzero((chords.high_h >= h_low) & (chords.low_h <= h_high)
                          & (chords.high_v >= v_low) & (chords.low_v <= v_high))
    steps = sample_steps(chords.length_mm[seen], port, width_px, height_px)
    groups = np.minimum(steps, SHORT_LINE_STEPS + 1)
    for group in np.flatnonzero(np.bincount(groups, minlength=SHORT_LINE_STEPS + 2)).tolist():
        in_group = groups == group
        mine: slice | np.ndarray = slice(None) if len(seen) == len(chords) and in_group.all() else seen[in_group]
        start_h, start_v = chords.start_h[mine], chords.start_v[mine]
        delta_h, delta_v = chords.delta_h[mine], chords.delta_v[mine]
        if group <= SHORT_LINE_STEPS:  # every line here has ``group`` samples: the k-th of them all at once
            numbers = chords.numbers[mine]
            for k in range(group):
                fraction = k / max(group - 1, 1)
                _mark(layer, port, width_px, height_px, start_h + delta_h * fraction, start_v + delta_v * fraction,
                      numbers)
        else:
            h, v, owner = sample_points(start_h, start_v, delta_h, delta_v, steps[in_group])
            _mark(layer, port, width_px, height_px, h, v, chords.numbers[mine][owner])
    return layer.reshape(height_px, width_px)


def _mark(layer: np.ndarray, port: Viewport, width_px: int, height_px: int, h: np.ndarray, v: np.ndarray,
          numbers: np.ndarray) -> None:
    """Lower ``layer``'s pixels at the samples (h, v) (in chord order) to the samples' chord numbers.

    The same operations as :func:`to_pixels`, on arrays of its own (``h`` and ``v`` are left as they are)."""
    h = np.subtract(h, port.centre_h)
    v = np.subtract(port.centre_v, v)
    for values, half in ((h, width_px / 2.0), (v, height_px / 2.0)):
        np.divide(values, port.mm_per_pixel, out=values)
        np.add(values, half, out=values)
        np.floor(values, out=values)
    px, py = h.astype(np.int64), v.astype(np.int64)
    pixel = py * width_px + px
    inside = (px >= 0) & (px < width_px) & (py >= 0) & (py < height_px)
    if not inside.all():
        pixel, numbers = pixel[inside], numbers[inside]
    if len(pixel):
        # Samples come in chord order: of a run of samples in one pixel the first has the smallest number.
        runs = np.empty(len(pixel), dtype=bool)
        runs[0] = True
        np.not_equal(pixel[1:], pixel[:-1], out=runs[1:])
        np.minimum.at(layer, pixel[runs], numbers[runs])


@dataclass(frozen=True)
class ScaleSamples:
    """Every sample of some chords at one scale (mm per pixel and picture size fix how many a
    chord has), in chord order; a sample at exactly the place of the one before it is left out:
    it falls in the same pixel in any viewport, and its chord's number is not the smaller. A pan
    keeps the scale: the layers of the viewport panned to are these samples' pixels, without
    sampling the chords again."""

    h: np.ndarray
    v: np.ndarray
    numbers: np.ndarray

    @classmethod
    def of(cls, chords: Chords, steps: np.ndarray) -> ScaleSamples:
        """The samples of ``chords``, ``steps`` of each (:func:`sample_steps`)."""
        h, v, owner = sample_points(chords.start_h, chords.start_v, chords.delta_h, chords.delta_v, steps)
        moved = np.ones(len(h), dtype=bool)
        moved[1:] = (h[1:] != h[:-1]) | (v[1:] != v[:-1])
        return cls(h[moved], v[moved], chords.numbers[owner[moved]])

    def first_chords(self, port: Viewport, width_px: int, height_px: int, never: int) -> np.ndarray:
        """What :func:`first_chords` gives for these samples' chords in ``port`` (of this scale)."""
        layer = np.full(height_px * width_px, never, dtype=np.int64)
        _mark(layer, port, width_px, height_px, self.h, self.v, self.numbers)
        return layer.reshape(height_px, width_px)


@dataclass(frozen=True)
class PathLayers:
    """The first feed chord and the first rapid chord of every pixel of one view."""

    first_feed: np.ndarray
    first_rapid: np.ndarray

    def paint(self, image: np.ndarray, count: int, feed: np.ndarray, rapid: np.ndarray) -> None:
        """Draw the first ``count`` chords into ``image``: rapid, then feed over it."""
        image[self.first_rapid < count] = rapid
        image[self.first_feed < count] = feed


@dataclass(frozen=True)
class PathChords:
    """A path's feed chords and rapid chords seen along two axes."""

    feed: Chords
    rapid: Chords
    count: int

    @classmethod
    def of(cls, starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, axes: tuple[int, int]) -> PathChords:
        """The path ``starts`` → ``ends`` (``rapid`` per chord) seen along ``axes`` (h, v)."""
        h, v = axes
        a = starts[:, [h, v]]
        b = ends[:, [h, v]]
        numbers = np.arange(len(starts))
        return cls(Chords.of(a[~rapid], b[~rapid], numbers[~rapid]), Chords.of(a[rapid], b[rapid], numbers[rapid]),
                   len(starts))

    def layers(self, port: Viewport, width_px: int, height_px: int) -> PathLayers:
        """:class:`PathLayers` of this path in ``port``."""
        return PathLayers(first_feed=first_chords(port, width_px, height_px, self.feed, self.count),
                          first_rapid=first_chords(port, width_px, height_px, self.rapid, self.count))

    def scale_samples(self, port: Viewport, width_px: int, height_px: int) -> tuple[ScaleSamples, ScaleSamples] | None:
        """The :class:`ScaleSamples` of the feed and the rapid chords at ``port``'s scale, or None
        where they would be more than ``SCALE_SAMPLES_PER_CHORD`` a chord (zoomed in: a
        viewport sees few of the chords, sampling them all would cost more than it saves)."""
        feed_steps = sample_steps(self.feed.length_mm, port, width_px, height_px)
        rapid_steps = sample_steps(self.rapid.length_mm, port, width_px, height_px)
        if int(feed_steps.sum()) + int(rapid_steps.sum()) > SCALE_SAMPLES_PER_CHORD * max(self.count, 1):
            return None
        return ScaleSamples.of(self.feed, feed_steps), ScaleSamples.of(self.rapid, rapid_steps)

    def layers_of(self, samples: tuple[ScaleSamples, ScaleSamples], port: Viewport, width_px: int,
                  height_px: int) -> PathLayers:
        """:class:`PathLayers` of this path in ``port``, from its samples at ``port``'s scale
        (the same layers as :meth:`layers`)."""
        feed, rapid = samples
        return PathLayers(first_feed=feed.first_chords(port, width_px, height_px, self.count),
                          first_rapid=rapid.first_chords(port, width_px, height_px, self.count))


SCALE_SAMPLES_PER_CHORD = 4
"""A path's samples at one scale are kept (for pans) while they are at most this many a chord
on average (a path seen whole is mostly chords shorter than a pixel: two samples each)."""


MAX_CACHED_VIEWPORTS = 12
"""Viewports whose layers a :class:`PathLayerCache` keeps (zoom levels and pans gone back to)."""


class PathLayerCache:
    """The layers of the last viewports asked for, of the last path and view (a widget keeps one:
    its path, view and viewport change far less often than what it draws up to)."""

    def __init__(self) -> None:
        self._path_key: tuple[object, ...] | None = None
        self._chords: PathChords | None = None
        self._layers: OrderedDict[tuple[Viewport, int, int], PathLayers] = OrderedDict()
        self._scale_key: tuple[float, int, int] | None = None  # the scale of the last viewport worked out
        self._scale_sampled = False  # whether the path was sampled whole at that scale …
        self._scale_samples: tuple[ScaleSamples, ScaleSamples] | None = None  # … and its samples (None: too many)

    def layers(self, starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, axes: tuple[int, int],
               port: Viewport, width_px: int, height_px: int) -> PathLayers:
        """The layers of the path ``starts`` → ``ends`` (``rapid`` per chord) seen along ``axes``."""
        path_key = (starts, ends, rapid, axes)
        if self._chords is None or self._path_key is None or not all(
                mine is theirs if isinstance(mine, np.ndarray) else mine == theirs
                for mine, theirs in zip(path_key, self._path_key)):
            self._chords = PathChords.of(starts, ends, rapid, axes)
            self._path_key = path_key
            self._layers.clear()
            self._scale_key = None
        key = (port, width_px, height_px)
        layers = self._layers.get(key)
        scale_key = (port.mm_per_pixel, width_px, height_px)
        new_scale = scale_key != self._scale_key
        if new_scale:
            self._scale_key, self._scale_sampled, self._scale_samples = scale_key, False, None
        if layers is None:
            layers = self._layers[key] = self._new_layers(self._chords, port, width_px, height_px, new_scale)
            if len(self._layers) > MAX_CACHED_VIEWPORTS:
                self._layers.popitem(last=False)
        else:
            self._layers.move_to_end(key)
        return layers

    def _new_layers(self, chords: PathChords, port: Viewport, width_px: int, height_px: int,
                    new_scale: bool) -> PathLayers:
        """The layers of a viewport not in the cache. The first viewport at a scale samples the
        chords it sees; another one at the scale of the one shown before (a pan) samples the
        whole path once, for it and the next ones (a zoom level passed through does not pay)."""
        if new_scale:
            return chords.layers(port, width_px, height_px)
        if not self._scale_sampled:
            self._scale_sampled = True
            self._scale_samples = chords.scale_samples(port, width_px, height_px)
        if self._scale_samples is None:
            return chords.layers(port, width_px, height_px)
        return chords.layers_of(self._scale_samples, port, width_px, height_px)


def path_layers(starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, axes: tuple[int, int],
                port: Viewport, width_px: int, height_px: int) -> PathLayers:
    """:class:`PathLayers` of the path ``starts`` → ``ends`` seen along ``axes`` (h, v)."""
    return PathChords.of(starts, ends, rapid, axes).layers(port, width_px, height_px)
