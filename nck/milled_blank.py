"""The blank on a mill's table as it is cut: what is left of it for contact detection.

The material model is the simulation's Z-map (:class:`nck.simulation.zmap.ZMap`, here in
machine coordinates over the clamped solid's outline): a cutter moving at feed with the
spindle turning lowers the cells it sweeps, so a later move — a rapid traverse back into a
drilled hole, through a milled slot — meets only the material still there. What is left is
the clamped solid (exact, :mod:`nck.contact`) intersected with one column per cell: the
cell's square (clipped to the solid's outline) from the solid's bottom up to the cell's
height (the solid's top while the cell is uncut). Every column is a box, so the gap function
of :mod:`nck.contact` to it is convex along a step and its first contact is found exactly
(golden section and bisection, all columns near the step at once): the detection stays
cycle-exact, no surface is jumped over. Where nothing near a step has been cut the kernel
judges the step against the solid alone (the measuring functions keep their exactness).

Trainer choices (the manuals do not describe a simulated workpiece):

* a cut removes the cells whose centre the tool's side passes within the tool radius plus
  half a cell diagonal (:attr:`MilledBlank.sweep_radius_mm`), and :data:`CUT_CLEARANCE_MM`
  (one increment of the position display) below the tool's end face. A tool moving again
  where it has cut (or a thinner one) therefore never meets a column edge of the grid; the
  price is that the model removes up to half a cell diagonal more beside a cut than the
  tool did. A move that changes height and moves in the plane is cut in pieces of a quarter
  cell height (:meth:`nck.simulation.zmap.ZMap.sweep`), and lowered by that quarter more.
* the grid's cell is chosen from the blank: the smallest multiple of :data:`CELL_STEP_MM`
  (at least :data:`MIN_CELL_MM`) that keeps the grid at most :data:`MAX_CELLS` cells (the
  shipped 100 × 80 mm block: 0.175 mm; memory at most a few megabytes).
* the tool's end face is flat for contact (``nck.contact``), so the cut is swept with a flat
  end mill of that radius: a drill's point is not modelled here.
* a turned box or a cylinder: a column is the cell's square clipped to the outline's
  axis-parallel bounding rectangle; the tool must touch the solid and a column (a tool
  beside a cut near a slanted edge may count as touching a hair early).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from nck.contact import BALL, ToolBody, clearance, first_contact
from nck.simulation.blank import Blank
from nck.simulation.cutter import Cutter
from nck.simulation.zmap import ZMap
from nck.workpiece import Box, Cylinder, Point, Solid

CUT_CLEARANCE_MM = 0.001
MAX_CELLS = 262_144
MIN_CELL_MM = 0.05
CELL_STEP_MM = 0.005
PENDING_LIMIT = 256
"""Cuts kept before they are swept into the Z-map (all are swept before any question)."""
TOUCH_MM = 1e-9
"""A gap this small at a computed point of contact is rounding: touching."""
NEAR_MM = 1.0
"""How far around a point the columns are looked at for :meth:`MilledBlank.clearance`."""
BROAD_SLACK_MM = 1e-6
"""Margin of the broad phase (:meth:`MilledBlank._near`) for rounding: a column this much
beyond what the tool can reach is still looked at exactly."""
_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0
_SEARCH_STEPS = 64  # golden-section steps: 0.618**64 ≈ 4e-14 of the step
_ROOT_STEPS = 52  # bisection steps of the root: 2**-52 of the step
_COLLINEAR = 1e-12


def cell_size_mm(width_mm: float, depth_mm: float) -> float:
    """The grid's cell edge for a blank of ``width_mm`` × ``depth_mm`` (module docstring)."""
    needed = math.sqrt(max(width_mm, 0.0) * max(depth_mm, 0.0) / MAX_CELLS)
    return max(MIN_CELL_MM, math.ceil(needed / CELL_STEP_MM - 1e-9) * CELL_STEP_MM)


def _outline(solid: Solid) -> tuple[tuple[float, float], tuple[float, float], tuple[float, float]]:
    """X, Y (axis-parallel bounding rectangle) and Z (bottom, top) of ``solid`` in the MCS."""
    if isinstance(solid, Cylinder):
        (x, y, bottom), radius = solid.base_mcs, solid.diameter_mm / 2.0
        return (x - radius, x + radius), (y - radius, y + radius), (bottom, bottom + solid.length_mm)
    (lx, ly, lz), (hx, hy, hz) = solid.low_mcs, solid.high_mcs
    if solid.rotation_z_deg:
        (cx, cy), angle = solid.centre_xy_mcs, math.radians(solid.rotation_z_deg)
        half_x = (abs((hx - lx) * math.cos(angle)) + abs((hy - ly) * math.sin(angle))) / 2.0
        half_y = (abs((hx - lx) * math.sin(angle)) + abs((hy - ly) * math.cos(angle))) / 2.0
        return (cx - half_x, cx + half_x), (cy - half_y, cy + half_y), (lz, hz)
    return (lx, hx), (ly, hy), (lz, hz)


def _signed(*outside: np.ndarray) -> np.ndarray:
    """Signed distance from per-axis signed excesses (as ``nck.contact``), element-wise."""
    beyond = np.sqrt(sum(np.maximum(q, 0.0) ** 2 for q in outside))
    return beyond + np.minimum(np.maximum.reduce(outside), 0.0)


@dataclass
class _Columns:
    """The columns near one step: their squares, bottom and top (arrays, one entry a column)."""

    x0: np.ndarray
    x1: np.ndarray
    y0: np.ndarray
    y1: np.ndarray
    top: np.ndarray
    bottom: float

    def gap(self, body: ToolBody, tip: tuple[np.ndarray, np.ndarray, np.ndarray]) -> np.ndarray:
        """The gap function of ``nck.contact`` from the tool at ``tip`` to each column."""
        x, y, z = tip
        qx = np.maximum(self.x0 - x, x - self.x1)
        qy = np.maximum(self.y0 - y, y - self.y1)
        if body.shape == BALL:
            return _signed(qx, qy, np.maximum(self.bottom - z, z - self.top)) - body.radius_mm
        gap_z = np.maximum(self.bottom - (z + body.length_mm), z - self.top)
        return np.maximum(_signed(qx, qy) - body.radius_mm, gap_z)

    def select(self, keep: np.ndarray) -> "_Columns":
        return _Columns(self.x0[keep], self.x1[keep], self.y0[keep], self.y1[keep], self.top[keep], self.bottom)


@dataclass
class MilledBlank:
    """The solid ``blank`` clamped on a mill and the Z-map ``zmap`` (MCS) of what was cut from it."""

    blank: Solid
    zmap: ZMap
    pending: list[tuple[Point, Point, float]] = field(default_factory=list)
    cut_area: tuple[float, float, float, float] | None = None
    """X low, X high, Y low, Y high around everything cut so far (``None``: nothing)."""

    @classmethod
    def of(cls, blank: Solid) -> "MilledBlank":
        """The uncut blank, its grid chosen from its size (module docstring)."""
        xs, ys, zs = _outline(blank)
        cell = cell_size_mm(xs[1] - xs[0], ys[1] - ys[0])
        # A whole number of cells, each with its centre inside: every cell starts at the top.
        nx, ny = (max(1, math.ceil((high - low) / cell - 1e-9)) for low, high in (xs, ys))
        grid = Blank("box", (xs[0], xs[0] + nx * cell), (ys[0], ys[0] + ny * cell), zs)
        return cls(blank, ZMap(grid, cell))

    @property
    def sweep_radius_mm(self) -> float:
        """How much wider than the tool a cut removes: half a cell diagonal."""
        return self.zmap.resolution_mm * math.sqrt(0.5)

    # ------------------------------------------------------------------ cutting
    def cut(self, body: ToolBody, start: Point, end: Point) -> None:
        """The cutter swept from ``start`` to ``end`` (tip, MCS) at feed: what it passed is gone."""
        if body.shape == BALL or clearance(body, self.blank, start) > math.dist(start, end):
            return  # a probe does not cut; nor does a tool that cannot reach the blank in this step
        reach = body.radius_mm + self.sweep_radius_mm
        area = (min(start[0], end[0]) - reach, max(start[0], end[0]) + reach,
                min(start[1], end[1]) - reach, max(start[1], end[1]) + reach)
        if self.cut_area is not None:
            old = self.cut_area
            area = (min(old[0], area[0]), max(old[1], area[1]), min(old[2], area[2]), max(old[3], area[3]))
        self.cut_area = area
        if self.pending:
            last_start, last_end, radius = self.pending[-1]
            if radius == body.radius_mm and last_end == start and _continues(last_start, last_end, end):
                self.pending[-1] = (last_start, end, radius)
                return
        self.pending.append((start, end, body.radius_mm))
        if len(self.pending) >= PENDING_LIMIT:
            self._sweep()

    def _sweep(self) -> None:
        by_radius: dict[float, list[tuple[Point, Point]]] = {}
        for start, end, radius in self.pending:
            by_radius.setdefault(radius, []).append((start, end))
        self.pending.clear()
        quarter = self.zmap.resolution_mm / 4.0
        for radius, moves in by_radius.items():
            starts = np.array([m[0] for m in moves], dtype=np.float64)
            ends = np.array([m[1] for m in moves], dtype=np.float64)
            ramp = (np.abs(ends[:, 2] - starts[:, 2]) > 0.0) & (
                np.hypot(ends[:, 0] - starts[:, 0], ends[:, 1] - starts[:, 1]) > 1e-9)
            lower = CUT_CLEARANCE_MM + np.where(ramp, quarter, 0.0)
            starts[:, 2] -= lower
            ends[:, 2] -= lower
            self.zmap.sweep(starts, ends, Cutter.flat(radius + self.sweep_radius_mm), quarter)

    # ------------------------------------------------------------------ questions
    def _columns(self, low_x: float, high_x: float, low_y: float, high_y: float,
                 reach: tuple[Point, Point, float, float] | None = None) -> _Columns | None:
        """The columns of the cells reaching into the rectangle, ``None`` when none is cut.

        ``reach`` (start, end, radius, lowest Z) is the broad phase: only columns whose square
        lies within ``radius`` of the step in the plane and whose top is not below the lowest Z
        are kept (the others cannot be touched: :meth:`_near`)."""
        if self.pending:
            self._sweep()
        zmap = self.zmap
        res = zmap.resolution_mm
        ix0 = max(int(math.floor((low_x - zmap.x0_mm) / res)), 0)
        ix1 = min(int(math.floor((high_x - zmap.x0_mm) / res)) + 1, zmap.nx)
        iy0 = max(int(math.floor((low_y - zmap.y0_mm) / res)), 0)
        iy1 = min(int(math.floor((high_y - zmap.y0_mm) / res)) + 1, zmap.ny)
        if ix0 >= ix1 or iy0 >= iy1:
            return None
        heights = zmap.heights[iy0:iy1, ix0:ix1]
        cut = heights < zmap.initial[iy0:iy1, ix0:ix1]
        if not cut.any():
            return None
        xs, ys, (bottom, top) = _outline(self.blank)
        column_top = np.where(cut, heights.astype(np.float64), top)
        keep = column_top > bottom
        ix, iy = np.arange(ix0, ix1), np.arange(iy0, iy1)
        if reach is not None:
            keep &= _reachable(reach, column_top, zmap.x0_mm + (ix + 0.5) * res, zmap.y0_mm + (iy + 0.5) * res,
                               res * math.sqrt(0.5))
        shape = keep.shape
        x0 = np.broadcast_to(np.maximum(zmap.x0_mm + ix * res, xs[0]), shape)[keep]
        x1 = np.broadcast_to(np.minimum(zmap.x0_mm + (ix + 1) * res, xs[1]), shape)[keep]
        y0 = np.broadcast_to(np.maximum(zmap.y0_mm + iy * res, ys[0])[:, None], shape)[keep]
        y1 = np.broadcast_to(np.minimum(zmap.y0_mm + (iy + 1) * res, ys[1])[:, None], shape)[keep]
        return _Columns(x0, x1, y0, y1, column_top[keep], bottom)

    def _near(self, body: ToolBody, start: Point, end: Point, margin_mm: float = 0.0) -> _Columns | None:
        """The columns the tool moving from ``start`` to ``end`` can come within ``margin_mm``
        of (``None``: nothing cut near it). Broad phase: a cutter touches a column only with
        its tip at or below the column's top and its axis within its radius of the column's
        square, a probe's ball only within its radius of the column; columns farther than
        the radius plus the margin from the step in the plane, or with their top more than the
        margin (a ball: plus its radius) below the step's lowest tip, are left out: their gap
        is larger than the margin, so neither a contact nor :meth:`clearance` changes."""
        reach = body.radius_mm + margin_mm
        lowest = min(start[2], end[2]) - (reach if body.shape == BALL else margin_mm)
        return self._columns(min(start[0], end[0]) - reach, max(start[0], end[0]) + reach,
                             min(start[1], end[1]) - reach, max(start[1], end[1]) + reach,
                             (start, end, reach, lowest))

    def touches_cut(self, body: ToolBody, start: Point, end: Point) -> bool:
        """True when the tool moving from ``start`` to ``end`` may pass near something cut (the
        kernel then judges the step against what is left, else against the solid alone)."""
        area = self.cut_area
        reach = body.radius_mm + NEAR_MM
        return area is not None and (
            min(start[0], end[0]) - reach <= area[1] and max(start[0], end[0]) + reach >= area[0]
            and min(start[1], end[1]) - reach <= area[3] and max(start[1], end[1]) + reach >= area[2])

    def clearance(self, body: ToolBody, tip: Point) -> float:
        """A gap to what is left: ≤ 0 when the tool touches it, else at most the distance the
        tool must still travel to touch it (a lower bound of it, as ``nck.contact``)."""
        gap = clearance(body, self.blank, tip)
        if gap > 0.0 or not self.touches_cut(body, tip, tip):
            return gap
        columns = self._near(body, tip, tip, NEAR_MM)
        if columns is None:
            return gap
        if len(columns.top) == 0:
            return NEAR_MM
        near = float(np.min(columns.gap(body, _along(tip, tip, np.zeros(1)))))
        return max(gap, min(near, NEAR_MM))

    def first_contact(self, body: ToolBody, start: Point, end: Point, depth_mm: float = 0.0) -> float | None:
        """The first parameter ``t`` along ``start`` → ``end`` where the tool is ``depth_mm``
        deep in what is left of the blank (0: touching), ``None`` if nowhere."""
        entry = first_contact(body, self.blank, start, end, depth_mm)
        if entry is None or not self.touches_cut(body, start, end):
            return entry
        columns = self._near(body, start, end)
        if columns is None:
            return entry  # nothing cut within the tool's reach: the solid itself
        if len(columns.top) == 0:
            return None
        if body.shape == BALL:
            hits = _first_entries(body, columns, start, end, depth_mm)
        else:
            hits = _cutter_entries(body, columns, start, end, depth_mm)
        entered = ~np.isnan(hits)
        if not entered.any():
            return None
        # A column entered before the solid counts from the solid's entry if it still overlaps
        # there (the gap at a computed entry is zero to rounding: TOUCH_MM).
        candidates = np.maximum(hits[entered], entry)
        gaps = columns.select(entered).gap(body, _along(start, end, candidates)) + depth_mm
        deep = (hits[entered] >= entry) | (gaps <= TOUCH_MM)
        return float(candidates[deep].min()) if deep.any() else None

def _reachable(reach: tuple[Point, Point, float, float], column_top: np.ndarray, centre_x: np.ndarray,
               centre_y: np.ndarray, half_diagonal_mm: float) -> np.ndarray:
    """Per column (rows Y, columns X): can the step ``reach`` = (start, end, radius, lowest Z)
    touch it? Its centre within radius + half a cell diagonal of the step in the plane, and
    its top not below the lowest Z (with :data:`BROAD_SLACK_MM` to spare for rounding)."""
    start, end, radius, lowest = reach
    dx, dy = end[0] - start[0], end[1] - start[1]
    qx = (centre_x - start[0])[None, :]
    qy = (centre_y - start[1])[:, None]
    length2 = dx * dx + dy * dy
    if length2 > 0.0:
        t = np.clip((qx * dx + qy * dy) / length2, 0.0, 1.0)
        qx, qy = qx - t * dx, qy - t * dy
    near = radius + half_diagonal_mm + BROAD_SLACK_MM
    return (qx * qx + qy * qy <= near * near) & (column_top >= lowest - BROAD_SLACK_MM)


def _continues(start: Point, middle: Point, end: Point) -> bool:
    """True when ``middle`` → ``end`` goes on in the direction of ``start`` → ``middle``."""
    a = [m - s for s, m in zip(start, middle)]
    b = [e - m for m, e in zip(middle, end)]
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    dot = sum(p * q for p, q in zip(a, b))
    size = math.hypot(*a) * math.hypot(*b)
    return dot > 0.0 and math.hypot(*cross) <= _COLLINEAR * size


def _along(start: Point, end: Point, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return (start[0] + (end[0] - start[0]) * t, start[1] + (end[1] - start[1]) * t,
            start[2] + (end[2] - start[2]) * t)


def _first_entries(body: ToolBody, columns: _Columns, start: Point, end: Point, depth_mm: float) -> np.ndarray:
    """Per column the first ``t`` in 0 … 1 where the tool is ``depth_mm`` deep in it (NaN: never):
    ``nck.contact.first_contact`` for all columns at once (the gap is convex along the step)."""
    result = np.full(len(columns.top), np.nan)
    at_start = columns.gap(body, _along(start, end, np.zeros(len(columns.top)))) + depth_mm
    result[at_start <= 0.0] = 0.0
    index = np.flatnonzero((at_start > 0.0) & (at_start <= math.dist(start, end)))
    if len(index) == 0:
        return result
    chosen = columns.select(index)

    def gap(t: np.ndarray) -> np.ndarray:
        return chosen.gap(body, _along(start, end, t)) + depth_mm

    high = np.ones(len(index))
    a, b = np.zeros(len(index)), np.ones(len(index))
    c, d = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
    gc, gd = gap(c), gap(d)
    moving = gap(high) > 0.0  # else the root lies in 0 … 1 already
    for _ in range(_SEARCH_STEPS):  # the minimum of the convex gap (golden section)
        moving &= np.minimum(gc, gd) > 0.0
        if not moving.any():
            break
        left = moving & (gc <= gd)
        right = moving & ~left
        b = np.where(left, d, b)
        a = np.where(right, c, a)
        new_point = np.where(left, b - _GOLDEN * (b - a), a + _GOLDEN * (b - a))
        new_gap = gap(new_point)
        d, gd = np.where(left, c, d), np.where(left, gc, gd)
        c, gc = np.where(right, d, c), np.where(right, gd, gc)
        c, gc = np.where(left, new_point, c), np.where(left, new_gap, gc)
        d, gd = np.where(right, new_point, d), np.where(right, new_gap, gd)
    searched = gap(high) > 0.0
    high = np.where(searched, np.where(gc <= 0.0, c, np.where(gd <= 0.0, d, np.nan)), high)
    low = np.zeros(len(index))
    for _ in range(_ROOT_STEPS):  # the root before it (bisection); NaN stays NaN
        middle = (low + high) / 2.0
        inside = gap(np.nan_to_num(middle, nan=0.0)) <= 0.0
        high = np.where(inside, middle, high)
        low = np.where(inside, low, middle)
    result[index] = high
    return result


def _slab(position: float, delta: float, low: np.ndarray | float, high: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The parameter interval where ``position + t·delta`` lies in ``low`` … ``high`` (empty: enter > leave)."""
    if delta == 0.0:
        inside = (low <= position) & (position <= high)
        return np.where(inside, -np.inf, np.inf), np.where(inside, np.inf, -np.inf)
    with np.errstate(over="ignore"):  # a tiny delta gives ±inf: the limit, as delta == 0 above
        t0, t1 = (low - position) / delta, (high - position) / delta
    return np.minimum(t0, t1), np.maximum(t0, t1)


def _cutter_entries(body: ToolBody, columns: _Columns, start: Point, end: Point, depth_mm: float) -> np.ndarray:
    """Per column the first ``t`` in 0 … 1 where a cutter (an upright cylinder on its tip) is
    ``depth_mm`` deep in it (NaN: never), exactly: in the plane the tip must lie in the column's
    square widened by the radius with rounded corners (two widened rectangles and four
    discs, a convex set: one interval), along Z between the column's bottom and top."""
    radius = body.radius_mm - depth_mm
    (sx, sy, sz), (ex, ey, ez) = start, end
    dx, dy, dz = ex - sx, ey - sy, ez - sz
    enter, leave = np.full(len(columns.top), np.inf), np.full(len(columns.top), -np.inf)
    if radius >= 0.0:
        for wide_x, wide_y in ((radius, 0.0), (0.0, radius)):
            ax, bx = _slab(sx, dx, columns.x0 - wide_x, columns.x1 + wide_x)
            ay, by = _slab(sy, dy, columns.y0 - wide_y, columns.y1 + wide_y)
            a, b = np.maximum(ax, ay), np.minimum(bx, by)
            found = a <= b
            enter, leave = np.where(found, np.minimum(enter, a), enter), np.where(found, np.maximum(leave, b), leave)
        planar = dx * dx + dy * dy
        for cx, cy in ((columns.x0, columns.y0), (columns.x0, columns.y1), (columns.x1, columns.y0),
                       (columns.x1, columns.y1)):
            fx, fy = sx - cx, sy - cy
            c = fx * fx + fy * fy - radius * radius
            if planar == 0.0:
                a, b = np.where(c <= 0.0, -np.inf, np.inf), np.where(c <= 0.0, np.inf, -np.inf)
            else:
                half_b = fx * dx + fy * dy
                root = np.sqrt(np.maximum(half_b * half_b - planar * c, 0.0))
                real = half_b * half_b - planar * c >= 0.0
                a = np.where(real, (-half_b - root) / planar, np.inf)
                b = np.where(real, (-half_b + root) / planar, -np.inf)
            found = a <= b
            enter, leave = np.where(found, np.minimum(enter, a), enter), np.where(found, np.maximum(leave, b), leave)
    # Along Z: bottom − length + depth ≤ z ≤ top − depth.
    az, bz = _slab(sz, dz, columns.bottom - body.length_mm + depth_mm, columns.top - depth_mm)
    first = np.maximum.reduce([enter, az, np.zeros(len(columns.top))])
    last = np.minimum.reduce([leave, bz, np.ones(len(columns.top))])
    return np.where(first <= last, first, np.nan)
