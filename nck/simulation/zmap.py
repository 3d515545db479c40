"""The Z-map: a height field over the blank, lowered by sweeping the tool along straight moves.

Each cell holds the height of the material at its centre (``bottom`` where there is none).
A straight move of the tool tip from ``P0`` to ``P1`` lowers every cell under it to the lowest
tool surface passing over the cell centre ``q``. For a move that keeps its height this is
exact: the tool's lower envelope ``h(r)`` grows with ``r``, so the lowest surface over ``q`` is
``z + h(d)`` with ``d`` the distance from ``q`` to the move in the plane — the slot's walls are
where the tool's side passes. A move that changes height is cut into pieces of at most
``dz_step_mm`` (default: a quarter cell) and each piece is evaluated at the point of the move
nearest to ``q``: the surface is then right to that step. A plunge (no motion in the plane)
is exact.

Many moves are swept at once: a batch of consecutive moves is one numpy array of moves ×
rows × columns, each move over a window of the batch's largest size (its own cells and some
more, where the tool does not reach). Lowering is a minimum, so neither the order of the
moves nor how they are grouped changes the result (property-tested bit for bit against one
move at a time). The tool's surface is computed in single precision, relative to the move's
start (the heights are single precision anyway).
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

from nck.simulation.blank import Blank
from nck.simulation.cutter import Cutter

CELL_BUDGET = 65_536
"""Cells evaluated per numpy pass: the temporary arrays (4 bytes a cell) stay small and are
reused from pass to pass instead of fresh pages each time (measured on the material bench's
path: 16,384 and 32,768 cells took 1.5-1.7× the CPU, 131,072 about 1.1×)."""


class ZMap:
    """Material heights over a grid of square cells covering the blank's outline."""

    def __init__(self, blank: Blank, resolution_mm: float) -> None:
        self.blank = blank
        self.resolution_mm = float(resolution_mm)
        self.x0_mm, self.y0_mm = blank.x_mm[0], blank.y_mm[0]
        self.nx = max(1, int(math.ceil((blank.x_mm[1] - blank.x_mm[0]) / resolution_mm - 1e-9)))
        self.ny = max(1, int(math.ceil((blank.y_mm[1] - blank.y_mm[0]) / resolution_mm - 1e-9)))
        self.bottom_mm, self.top_mm = blank.z_mm
        xs = self.x0_mm + (np.arange(self.nx) + 0.5) * resolution_mm
        ys = self.y0_mm + (np.arange(self.ny) + 0.5) * resolution_mm
        inside = blank.material_mask(xs[None, :], ys[:, None])
        self.initial = np.where(inside, self.top_mm, self.bottom_mm).astype(np.float32)
        self.heights = self.initial.copy()
        """Material height per cell, rows Y (index 0 at the lowest Y), columns X."""

    def fresh(self) -> ZMap:
        """The uncut blank at the same resolution."""
        return ZMap(self.blank, self.resolution_mm)

    # ------------------------------------------------------------------ questions
    def removed_volume_mm3(self) -> float:
        """Volume cut away so far."""
        cut = self.initial.astype(np.float64) - self.heights.astype(np.float64)
        return float(cut.sum()) * self.resolution_mm ** 2

    def height_at(self, x_mm: float, y_mm: float) -> float:
        """Material height at the cell containing (x, y)."""
        ix = int((x_mm - self.x0_mm) / self.resolution_mm)
        iy = int((y_mm - self.y0_mm) / self.resolution_mm)
        return float(self.heights[iy, ix])

    def cell_centres(self) -> tuple[np.ndarray, np.ndarray]:
        """X of the columns and Y of the rows."""
        res = self.resolution_mm
        return (self.x0_mm + (np.arange(self.nx) + 0.5) * res, self.y0_mm + (np.arange(self.ny) + 0.5) * res)

    # ------------------------------------------------------------------ sweeping
    def sweep(self, starts: np.ndarray, ends: np.ndarray, cutter: Cutter, dz_step_mm: float | None = None,
              done: Callable[[int], None] | None = None) -> np.ndarray:
        """Sweep ``cutter`` along the straight moves ``starts[i] → ends[i]`` (tip, rows X Y Z).

        Returns, per move, the deepest cut it made into material that was there before
        its batch (mm, 0: none) — how the caller finds rapid moves into material.
        ``done(k)`` is called after a batch that ends with a whole move: the heights are
        then those after the first ``k`` moves.
        """
        starts = np.asarray(starts, dtype=np.float64).reshape(-1, 3)
        ends = np.asarray(ends, dtype=np.float64).reshape(-1, 3)
        count = len(starts)
        if count == 0:
            return np.zeros(0)
        step = dz_step_mm if dz_step_mm is not None else self.resolution_mm / 4.0
        starts, ends, owner = _split_height_changes(starts, ends, step)
        depth = np.zeros(count)
        reach = cutter.reach_mm
        res = self.resolution_mm
        low = np.minimum(starts, ends)
        high = np.maximum(starts, ends)
        ix0 = np.clip(np.floor((low[:, 0] - reach - self.x0_mm) / res - 0.5).astype(np.int64) + 1, 0, self.nx)
        ix1 = np.clip(np.floor((high[:, 0] + reach - self.x0_mm) / res - 0.5).astype(np.int64) + 1, 0, self.nx)
        iy0 = np.clip(np.floor((low[:, 1] - reach - self.y0_mm) / res - 0.5).astype(np.int64) + 1, 0, self.ny)
        iy1 = np.clip(np.floor((high[:, 1] + reach - self.y0_mm) / res - 0.5).astype(np.int64) + 1, 0, self.ny)
        width = ix1 - ix0
        height = iy1 - iy0
        # Skip moves whose tool stays above the material everywhere it passes.
        index = np.flatnonzero((width > 0) & (height > 0) & (low[:, 2] < self.top_mm))
        for chosen in _batches(width[index].tolist(), height[index].tolist()):
            moves = index[chosen]
            self._sweep_batch(starts[moves], ends[moves], owner[moves], ix0[moves], iy0[moves],
                              int(width[moves].max()), int(height[moves].max()), cutter, depth)
            if done is not None:
                last = int(moves[-1])
                if last + 1 == len(owner) or owner[last + 1] != owner[last]:
                    done(int(owner[last]) + 1)  # pieces skipped after it cut nothing
        return depth

    def _sweep_batch(self, starts: np.ndarray, ends: np.ndarray, owner: np.ndarray, ix0: np.ndarray,
                     iy0: np.ndarray, width: int, height: int, cutter: Cutter, depth: np.ndarray) -> None:
        """Sweep the moves of one batch: every move over a window of ``height`` rows and
        ``width`` columns (its own cells and more, all within the map), as one array of
        ``moves × rows × columns``. The tool's surface is computed in single precision
        relative to the move's start (the heights are single precision)."""
        res = self.resolution_mm
        ix0 = np.minimum(ix0, self.nx - width)
        iy0 = np.minimum(iy0, self.ny - height)
        delta = ends - starts
        dx, dy, dz = delta[:, 0], delta[:, 1], delta[:, 2]
        length2 = dx * dx + dy * dy
        plunge = length2 <= 1e-18
        # A plunge (no motion in the plane) cuts with its lower end: start there, no height change.
        sz = np.where(plunge, np.minimum(starts[:, 2], ends[:, 2]), starts[:, 2])
        dz = np.where(plunge, 0.0, dz)
        inv = np.where(plunge, 0.0, 1.0 / np.where(plunge, 1.0, length2))
        # Cell centres relative to the move's start: columns (moves × 1 × columns), rows (moves × rows × 1).
        qx = ((self.x0_mm + (ix0[:, None] + np.arange(width) + 0.5) * res) - starts[:, :1])
        qy = ((self.y0_mm + (iy0[:, None] + np.arange(height) + 0.5) * res) - starts[:, 1:2])
        qx = qx.astype(np.float32)[:, None, :]
        qy = qy.astype(np.float32)[:, :, None]
        dx, dy, dz, ux, uy = (v.astype(np.float32)[:, None, None] for v in (dx, dy, dz, dx * inv, dy * inv))
        # The point of the move nearest to the cell centre in the plane (t: 0 … 1 along the move).
        t = qx * ux + qy * uy
        np.clip(t, 0.0, 1.0, out=t)
        px = qx - t * dx
        py = qy - t * dy
        px *= px
        py *= py
        px += py
        surface = cutter.height_above_tip(px)
        if np.any(dz):
            t *= dz
            surface += t
        surface += sz.astype(np.float32)[:, None, None]
        lowered = np.maximum(surface, np.float32(self.bottom_mm), out=surface)
        windows = sliding_window_view(self.heights, (height, width))
        cut = windows[iy0, ix0] - lowered
        deepest = cut.reshape(len(starts), -1).max(axis=1)
        np.maximum.at(depth, owner, np.maximum(deepest, 0.0))
        for move in np.flatnonzero(deepest > 0.0).tolist():
            row, column = int(iy0[move]), int(ix0[move])
            window = self.heights[row:row + height, column:column + width]
            np.minimum(window, lowered[move], out=window)


def _batches(widths: list[int], heights: list[int]) -> list[slice]:
    """Consecutive moves in batches whose common window (the largest width times the largest
    height, times the number of moves) stays within :data:`CELL_BUDGET` cells (a larger move
    alone)."""
    batches: list[slice] = []
    begin = 0
    most_w = most_h = 0
    for i, (w, h) in enumerate(zip(widths, heights)):
        grown_w, grown_h = max(most_w, w), max(most_h, h)
        if i > begin and (i + 1 - begin) * grown_w * grown_h > CELL_BUDGET:
            batches.append(slice(begin, i))
            begin, grown_w, grown_h = i, w, h
        most_w, most_h = grown_w, grown_h
    if begin < len(widths):
        batches.append(slice(begin, len(widths)))
    return batches


def _split_height_changes(starts: np.ndarray, ends: np.ndarray, step_mm: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cut moves that change height and move in the plane into pieces of at most ``step_mm``
    height; return the pieces and, per piece, the index of its move."""
    count = len(starts)
    dz = np.abs(ends[:, 2] - starts[:, 2])
    planar = np.hypot(ends[:, 0] - starts[:, 0], ends[:, 1] - starts[:, 1]) > 1e-9
    pieces = np.where(planar, np.maximum(np.ceil(dz / step_mm - 1e-9), 1), 1).astype(np.int64)
    owner = np.repeat(np.arange(count), pieces)
    if len(owner) == count:
        return starts, ends, owner
    first = np.concatenate(([0], np.cumsum(pieces)[:-1]))
    k = np.arange(len(owner)) - first[owner]
    n = pieces[owner]
    delta = ends - starts
    a = starts[owner] + delta[owner] * (k / n)[:, None]
    b = starts[owner] + delta[owner] * ((k + 1) / n)[:, None]
    return a, b, owner
