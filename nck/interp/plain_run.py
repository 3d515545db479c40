"""A run of plain motion blocks interpreted as one batch (the fast path of ``nck check``).

CAM programs are long runs of plain blocks (:mod:`nck.lang.plain`): ``G1 X… Y…
Z…`` with an occasional F. While the modal state is *simple* — G0/G1, G90 or
G91, G94 feed, no radius compensation, no chamfer or rounding pending, no
modal call or section repeat, frames that do not couple the geometry axes —
such a block does nothing but move the programmed point. :func:`plan` reads a
run of them into arrays and computes what the general path would compute
block by block, with the same floating-point operations in the same order:

* the programmed WCS end point (mm): absolute values, or running sums in G91;
* the machine end point: ``round((wcs · m_ii + t_i) + tool_i, 9)`` for programmed
  axes (a diagonal frame matrix, as :class:`~nck.geometry.transform.Transform`
  computes it), the start position (rounded) for the others;
* per motion block the MCS deltas and the path feed in mm/min (rapid: None),
  from which the caller estimates the traverse time.

The batch stops *before* any block the general path must see: a block that
changes the distance mode, an F of zero (alarm 14800), a G1 without feed
(alarm 10860), or the end of the run. Those blocks are then interpreted by
:meth:`Interpreter.step`, which raises the alarm at the exact line. Nothing is
changed until :meth:`PlainBatch.commit` takes over the state after the first
*k* blocks (the caller may stop earlier, at a time or block budget).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from nck.geometry.path_builder import ROUND_DIGITS, machine_mm, round_position
from nck.geometry.tangents import line_tangent
from nck.interp.host import InterpreterHost
from nck.interp.plain_setup import GEOMETRY, Setup, plain_frame, simple_setup
from nck.lang.plain import G_CODES, PLAIN_WORDS

BATCH_LINES = 32_768
"""At most this many blocks per batch (bounds the memory of the arrays)."""

MIN_BATCH_LINES = 16
"""Shorter runs of plain blocks go block by block (:mod:`nck.interp.simple_step`): the same
result, without the fixed cost of the arrays (CAM code mixes a few lines between arcs)."""

ROUND_SAFE_MM = 4.0e6  # below this, a value that numpy rounds to itself is Python-rounded to itself
_NAN = math.nan


@dataclass
class PlainBatch:
    """The planned outcome of a run of plain blocks (nothing applied yet).

    Attributes:
        blocks: number of blocks planned.
        motion_line: per motion block, its index (0-based) within the batch.
        deltas_mm: per motion block and path axis (``axes`` order), end minus start MCS.
        feed_mm_min: per motion block, path feed in mm/min; NaN for rapid traverse (G0).
        axes: the machine's path axes (order of ``deltas_mm`` columns).
    """

    interp: Any
    first: int
    blocks: int
    motion_line: np.ndarray
    deltas_mm: np.ndarray
    feed_mm_min: np.ndarray
    axes: tuple[str, ...]
    kind: np.ndarray  # per line: 0 = G0, 1 = G1 (after the line)
    feed: np.ndarray  # per line: modal F after the line
    first_executable: int  # first line (in the batch) with a statement
    wcs_mm: np.ndarray  # per motion block: WCS end point X, Y, Z (mm)
    mcs_mm: np.ndarray  # per motion block: MCS end point of every path axis
    start_wcs: tuple[float, float, float]

    def commit(self, count: int) -> None:
        """Apply the first ``count`` blocks to the interpreter (0 ≤ count ≤ blocks)."""
        if count <= 0:
            return
        interp = self.interp
        state = interp.run_state
        frame = state.frames[-1]
        modal = interp.modal
        last = count - 1
        frame.pc = self.first + count
        state.blocks += count
        interp.skip_run = None
        if self.first_executable < count:
            frame.def_open = False
        modal.gcodes[1] = "G1" if self.kind[last] else "G0"
        modal.feed = float(self.feed[last])
        moves = int(np.searchsorted(self.motion_line, last, side="right"))
        if not moves:
            return
        path = interp.builder.path
        geo = modal.geometry
        end = self.wcs_mm[moves - 1]
        before = self.wcs_mm[moves - 2] if moves > 1 else self.start_wcs
        wcs = dict(geo.wcs_mm)
        for i, axis in enumerate(GEOMETRY):
            wcs[axis] = float(end[i])
        geo.wcs_mm = wcs
        geo.tangent = line_tangent((float(before[0]), float(before[1]), float(before[2])),
                                   (wcs["X"], wcs["Y"], wcs["Z"]))
        mcs = self.mcs_mm[moves - 1]
        modal.position_mcs = {axis: float(mcs[i]) for i, axis in enumerate(self.axes)}
        modal.position_wcs = path.wcs_view(geo, modal)

    def motions_before(self, count: int) -> int:
        """Number of motion blocks among the first ``count`` blocks."""
        return int(np.searchsorted(self.motion_line, count - 1, side="right")) if count > 0 else 0


def plan(interp: InterpreterHost, max_blocks: int) -> PlainBatch | None:
    """The batch of plain blocks from the current position, or None (the general path goes on)."""
    found = plain_frame(interp) if max_blocks > 0 else None
    if found is None:
        return None
    frame, lines = found
    first = frame.pc
    stop = min(frame.program.plain_run_end(first), first + max_blocks, first + BATCH_LINES)
    if stop - first < max(MIN_BATCH_LINES, 1):
        return None  # a short run between arcs: block by block is cheaper than the arrays
    setup = simple_setup(interp)
    if setup is None:
        return None
    chunk = lines.chunk(first, stop)
    words = _uniform_words(chunk, stop - first) or _words(chunk, stop - first)
    if words is None:
        return None
    return _plan_words(interp, setup, first, words)


@dataclass
class _Words:
    """The words of a run of plain lines, one entry per line."""

    motion: np.ndarray  # int8: 0 = G0, 1 = G1, -1 = none written
    distance: np.ndarray  # int16: 90, 91, 0 = none written
    axes: tuple[np.ndarray, np.ndarray, np.ndarray]  # X, Y, Z values (NaN: not written)
    feed: np.ndarray  # F values (NaN: not written)
    first_executable: int  # first line with a statement (count: none)


_NUMERIC = str.maketrans("", "", "0123456789.+- \t")
_LETTERS = str.maketrans("NGXYZF\n", "       ")


def _uniform_words(chunk: str, count: int) -> _Words | None:
    """The words when every line has the same words in the same order (``G1 X… Y… Z…``).

    Then the numbers are read by numpy in one go; None otherwise (or for an
    integer ``-0``, which the parser reads as +0).
    """
    newline = chunk.find("\n")
    shape = (chunk if newline < 0 else chunk[:newline]).translate(_NUMERIC)
    if shape.strip("NGXYZF"):  # a comment: the findall path
        return None
    if chunk.translate(_NUMERIC) != "\n".join([shape] * count):
        return None
    values = np.fromstring(chunk.translate(_LETTERS), sep=" ")  # text mode (not deprecated)
    if values.size != count * len(shape):
        return None
    table = values.reshape(count, len(shape))
    motion = np.full(count, -1, dtype=np.int8)
    distance = np.zeros(count, dtype=np.int16)
    axes = [np.full(count, _NAN), np.full(count, _NAN), np.full(count, _NAN)]
    feed = np.full(count, _NAN)
    for column, letter in enumerate(shape):
        data = table[:, column]
        if letter == "G":
            is_motion = data < 2.0
            motion = np.where(is_motion, data, motion).astype(np.int8)
            distance = np.where(is_motion, distance, data).astype(np.int16)
        elif letter in "XYZ":
            if np.any((data == 0.0) & np.signbit(data)):
                return None
            axes["XYZ".index(letter)] = data
        elif letter == "F":
            feed = data
    executable = 0 if shape.replace("N", "") else count
    return _Words(motion, distance, (axes[0], axes[1], axes[2]), feed, executable)


def _words(chunk: str, count: int) -> _Words | None:
    """The words of any run of plain lines (one pattern match per line)."""
    rows = PLAIN_WORDS.findall(chunk)
    if len(rows) != count:  # cannot happen: the run was scanned as plain
        return None
    columns = list(zip(*rows))
    prefixes = {prefix: _prefix_codes(prefix) for prefix in set(columns[0])}
    motion = np.array([prefixes[p][0] for p in columns[0]], dtype=np.int8)
    distance = np.array([prefixes[p][1] for p in columns[0]], dtype=np.int16)
    first_executable = next((i for i, row in enumerate(rows) if any(row)), count)
    return _Words(motion, distance, (_axis_floats(columns[1]), _axis_floats(columns[2]),
                                     _axis_floats(columns[3])), _floats(columns[4]), first_executable)


def _plan_words(interp: InterpreterHost, setup: Setup, first: int, words: _Words) -> PlainBatch | None:
    count = words.motion.size
    # Cut before the first block the general path must take.
    cut = count
    changes = np.flatnonzero(words.distance == (91 if setup.absolute else 90))
    if changes.size:
        cut = int(changes[0])
    feeds_written = words.feed[:cut]
    written = ~np.isnan(feeds_written)
    bad_feed = np.flatnonzero(written & (feeds_written <= 0.0))
    if bad_feed.size:
        cut = int(bad_feed[0])
    if cut == 0:
        return None
    kind_code = words.motion[:cut]
    kind = _forward_fill(kind_code >= 0, kind_code, setup.kind)
    feed = _forward_fill(written[:cut], feeds_written[:cut], setup.feed)
    values = [words.axes[i][:cut] for i in range(3)]
    programmed = [~np.isnan(v) for v in values]
    moving = programmed[0] | programmed[1] | programmed[2]
    no_feed = np.flatnonzero(moving & (kind == 1) & (feed <= 0.0))
    if no_feed.size:
        cut = int(no_feed[0])
        if cut == 0:
            return None
        kind, feed, moving = kind[:cut], feed[:cut], moving[:cut]
        values = [v[:cut] for v in values]
        programmed = [p[:cut] for p in programmed]
    motion_line = np.flatnonzero(moving)
    moves = motion_line.size
    axes = setup.axes
    start_mcs = np.array([float(setup.mcs.get(a, 0.0)) for a in axes])
    if moves == 0:
        empty = np.zeros((0, len(axes)))
        return PlainBatch(interp, first, cut, motion_line, empty, np.zeros(0), axes, kind, feed,
                          words.first_executable, np.zeros((0, 3)), empty, setup.wcs)
    wcs = np.empty((moves, 3))
    mcs = np.empty((moves, len(axes)))
    rounded_start = np.array([round_position(v) for v in start_mcs])
    for i, axis in enumerate(axes):
        mcs[:, i] = rounded_start[i]
    for i in range(3):
        mask = programmed[i][motion_line]
        value_mm = values[i][motion_line] * setup.position_mm
        if setup.diameter[i]:
            value_mm = value_mm / 2.0
        if setup.absolute:
            column = _forward_fill(mask, value_mm, setup.wcs[i])
        else:
            steps = np.where(mask, value_mm, 0.0)
            running = np.cumsum(np.concatenate(([setup.wcs[i]], steps)))[1:]
            column = _forward_fill(mask, running, setup.wcs[i])
        wcs[:, i] = column
        machine = _round_array(machine_mm(column, setup.scale[i], setup.offset[i], setup.tool[i]))
        where = axes.index(GEOMETRY[i])
        mcs[:, where] = _forward_fill(mask, machine, rounded_start[where])
    starts = np.vstack((start_mcs[None, :], mcs[:-1]))
    deltas = mcs - starts
    feed_mm_min = np.where(kind[motion_line] == 1, feed[motion_line] * setup.feed_mm, _NAN)
    return PlainBatch(interp, first, cut, motion_line, deltas, feed_mm_min, axes, kind, feed,
                      words.first_executable, wcs, mcs, setup.wcs)


def _prefix_codes(prefix: str) -> tuple[int, int]:
    """The G words before the axis words of a plain line: (motion 0/1 or -1, 90/91 or 0)."""
    motion, distance = -1, 0
    for word in prefix.replace("G", " G").split():
        code = G_CODES[word]
        if code in ("G0", "G1"):
            motion = 1 if code == "G1" else 0
        else:
            distance = int(code[1:])
    return motion, distance


def _floats(texts: tuple[str, ...]) -> np.ndarray:
    """Unsigned plain numbers (NaN where absent), as the parser converts them."""
    return np.array([float(t) if t else _NAN for t in texts], dtype=np.float64)


def _axis_floats(texts: tuple[str, ...]) -> np.ndarray:
    """Signed axis values: ``-1 * value`` of an integer mantissa has no negative zero."""
    values = _floats(texts)
    negative_zero = np.flatnonzero((values == 0.0) & np.signbit(values))
    for i in negative_zero.tolist():
        if "." not in texts[i]:
            values[i] = 0.0
    return values


def _forward_fill(mask: np.ndarray, values: np.ndarray, initial: float) -> np.ndarray:
    """Per position the value of the last position with ``mask`` set (``initial`` before any)."""
    index = np.where(mask, np.arange(mask.size), -1)
    np.maximum.accumulate(index, out=index)
    filled = np.where(index >= 0, values[np.maximum(index, 0)], initial)
    return filled.astype(np.float64) if filled.dtype != np.float64 else filled


def _round_array(values: np.ndarray) -> np.ndarray:
    """:func:`round_position` of every element: values numpy rounds to themselves are kept (see module notes)."""
    out = values + 0.0
    same = (np.round(values, ROUND_DIGITS) == values) & (np.abs(values) < ROUND_SAFE_MM)
    for i in np.flatnonzero(~same).tolist():
        out[i] = round_position(values[i])
    return out
