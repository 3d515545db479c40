"""The material view's path overlay for every number of chords drawn, worked out once per view.

Drawing the overlay chord by chord (rapid moves first, feed moves over them) costs about as
much as the rest of a picture together, and a scrub step or the cursor moving to another
block draws the same chords at the same place again, only up to another chord. So, per view,
viewport and size, each pixel keeps the first chord that draws it in feed and the first that
draws it in rapid: with ``count`` chords drawn a pixel is in feed when its first feed chord is
below ``count``, else in rapid when its first rapid chord is — the same pixels as drawing the
chords one after the other.

Chords are sampled at half a pixel along their length (:func:`segment_pixels`), as every
straight line of the view is.
"""

from __future__ import annotations

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


def segment_pixels(port: Viewport, width_px: int, height_px: int, a: np.ndarray,
                   b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The pixels of the straight lines a[i] → b[i] (rows h, v in mm), sampled at half a pixel:
    columns, rows and the line each sample belongs to, in the lines' order (samples outside the
    image included)."""
    ah, av = np.ascontiguousarray(a[:, 0]), np.ascontiguousarray(a[:, 1])  # 1-D gathers below are cheaper
    dh, dv = b[:, 0] - ah, b[:, 1] - av
    length = np.hypot(dh, dv) / port.mm_per_pixel
    steps = np.minimum(np.ceil(length * 2.0).astype(np.int64) + 1, 4 * (width_px + height_px))
    owner = np.repeat(np.arange(len(a)), steps)
    first = np.concatenate(([0], np.cumsum(steps)[:-1]))
    f = (np.arange(len(owner)) - np.repeat(first, steps)) / np.repeat(np.maximum(steps - 1, 1), steps)
    h = ah[owner] + dh[owner] * f
    v = av[owner] + dv[owner] * f
    px, py = to_pixels(port, width_px, height_px, h, v)
    return px, py, owner


def first_chords(port: Viewport, width_px: int, height_px: int, a: np.ndarray, b: np.ndarray,
                 chords: np.ndarray, never: int) -> np.ndarray:
    """Per pixel (height_px × width_px) the smallest of ``chords`` whose line a → b draws it
    (``never`` where none does)."""
    layer = np.full(height_px * width_px, never, dtype=np.int64)
    if len(a):
        px, py, owner = segment_pixels(port, width_px, height_px, a, b)
        inside = (px >= 0) & (px < width_px) & (py >= 0) & (py < height_px)
        # A pixel's first chord is the smallest chord index among its samples.
        np.minimum.at(layer, py[inside] * width_px + px[inside], chords[owner[inside]])
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


class PathLayerCache:
    """The layers of the last view asked for (a widget keeps one: its path, view and viewport
    change far less often than what it draws up to)."""

    def __init__(self) -> None:
        self._key: tuple[object, ...] | None = None
        self._layers: PathLayers | None = None

    def layers(self, starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, axes: tuple[int, int],
               port: Viewport, width_px: int, height_px: int) -> PathLayers:
        """The layers of the path ``starts`` → ``ends`` (``rapid`` per chord) seen along ``axes``."""
        key = (starts, ends, rapid, axes, port, width_px, height_px)
        if self._key is not None and self._layers is not None and len(key) == len(self._key) and all(
                mine is theirs if isinstance(mine, np.ndarray) else mine == theirs
                for mine, theirs in zip(key, self._key)):
            return self._layers
        self._layers = path_layers(starts, ends, rapid, axes, port, width_px, height_px)
        self._key = key
        return self._layers


def path_layers(starts: np.ndarray, ends: np.ndarray, rapid: np.ndarray, axes: tuple[int, int],
                port: Viewport, width_px: int, height_px: int) -> PathLayers:
    """:class:`PathLayers` of the path ``starts`` → ``ends`` seen along ``axes`` (h, v)."""
    h, v = axes
    a = starts[:, [h, v]]
    b = ends[:, [h, v]]
    index = np.arange(len(starts))
    never = len(starts)
    return PathLayers(
        first_feed=first_chords(port, width_px, height_px, a[~rapid], b[~rapid], index[~rapid], never),
        first_rapid=first_chords(port, width_px, height_px, a[rapid], b[rapid], index[rapid], never))
