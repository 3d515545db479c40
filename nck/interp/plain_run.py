"""A run of plain motion blocks interpreted as one batch (the fast path of ``nck check``).

CAM programs are long runs of plain blocks (:mod:`nck.lang.plain`): ``G1 X… Y…
Z…`` with an occasional F. While the modal state is *simple* — G0/G1, G90 or
G91, G94 feed, no radius compensation, no chamfer or rounding pending, no
modal call or section repeat, frames that do not couple the geometry axes —
such a block does nothing but move the programmed point. :func:`plan` reads a
run of them into arrays and computes what the general path would compute
block by block, with the same floating-point operations in the same order:

* the programmed WCS end point (mm): absolute values, or running sums in G91;
* the machine end point: ``_r((wcs · m_ii + t_i) + tool_i)`` for programmed
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
from typing import TYPE_CHECKING, Any

import numpy as np

from nck import canon
from nck.errors import NcAlarmError
from nck.interp.api import BlockResult
from nck.geometry.contour_aids import LineElement
from nck.geometry.path_builder import _couples_axes, _end_tangent
from nck.geometry.trc_canon import STAGE_ATTRIBUTE
from nck.geometry.units import UnitSystem
from nck.interp.program_text import TextLines
from nck.lang.plain import G_CODES, PLAIN_LINE, PLAIN_WORDS, axis_value, feed_value

if TYPE_CHECKING:
    from nck.interp.interpreter import Interpreter

BATCH_LINES = 32_768
"""At most this many blocks per batch (bounds the memory of the arrays)."""

GEOMETRY = ("X", "Y", "Z")
BLOCK_COST_S = 0.001  # the interpreter's cost of one block (nck.interp.interpreter.BLOCK_COST_S)
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
        state = interp._state
        frame = state.frames[-1]
        modal = interp.modal
        last = count - 1
        frame.pc = self.first + count
        state.blocks += count
        interp._skip_run = None
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
        geo.tangent = _end_tangent(LineElement(tuple(float(v) for v in before),  # type: ignore[arg-type]
                                               (wcs["X"], wcs["Y"], wcs["Z"])))
        mcs = self.mcs_mm[moves - 1]
        modal.position_mcs = {axis: float(mcs[i]) for i, axis in enumerate(self.axes)}
        modal.position_wcs = path.wcs_view(geo, modal)

    def motions_before(self, count: int) -> int:
        """Number of motion blocks among the first ``count`` blocks."""
        return int(np.searchsorted(self.motion_line, count - 1, side="right")) if count > 0 else 0


def plan(interp: Interpreter, max_blocks: int) -> PlainBatch | None:
    """The batch of plain blocks from the current position, or None (the general path goes on)."""
    state = interp._state
    if state.finished or not state.frames or max_blocks <= 0:
        return None
    frame = state.frames[-1]
    program = frame.program
    lines = program.lines
    if not isinstance(lines, TextLines) or frame.modal_call is not None or frame.repeats:
        return None
    first = frame.pc
    stop = min(program.plain_run_end(first), first + max_blocks, first + BATCH_LINES)
    if stop <= first:
        return None
    setup = _simple_setup(interp)
    if setup is None:
        return None
    chunk = lines.chunk(first, stop)
    words = _uniform_words(chunk, stop - first) or _words(chunk, stop - first)
    if words is None:
        return None
    return _plan_words(interp, setup, first, words)


def _axis_affine(transform: Any) -> tuple[tuple[float, float, float], tuple[float, float, float]] | None:
    """(scale, offset) per geometry axis of a frame that maps every axis on its own, else None.

    Only exactly diagonal matrices, and per axis a scale of ±1 or no offset:
    then ``matrix @ point`` is ``point_i * m_ii + t_i`` bit for bit, whatever
    the order of the sum. Cached on the (immutable) transform.
    """
    cached = transform.__dict__.get("_plain_affine", False)
    if cached is not False:
        return cached
    matrix = transform.matrix
    linear = matrix[:3, :3]
    found: Any = None
    if not (_couples_axes(transform) or np.count_nonzero(linear - np.diag(np.diag(linear)))
            or np.count_nonzero(matrix[3] - (0.0, 0.0, 0.0, 1.0))):
        scale = (float(matrix[0, 0]), float(matrix[1, 1]), float(matrix[2, 2]))
        offset = (float(matrix[0, 3]), float(matrix[1, 3]), float(matrix[2, 3]))
        if all(abs(scale[i]) == 1.0 or offset[i] == 0.0 for i in range(3)):
            found = (scale, offset)
    transform.__dict__["_plain_affine"] = found
    return found


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


@dataclass
class _Setup:
    absolute: bool
    kind: int
    feed: float
    position_mm: float
    feed_mm: float
    diameter: tuple[bool, bool, bool]
    scale: tuple[float, float, float]
    offset: tuple[float, float, float]
    tool: tuple[float, float, float]
    wcs: tuple[float, float, float]
    mcs: dict[str, float]  # the modal MCS position (read only)
    axes: tuple[str, ...]
    diameter_on: bool


@dataclass(frozen=True)
class _Machine:
    """What the fast path needs of the machine (fixed for an interpreter)."""

    usable: bool  # X, Y, Z are the linear geometry axes and path axes
    axes: tuple[str, ...]  # path axes
    linear: tuple[bool, ...]  # per path axis: a linear axis (mm) or not (degrees)
    diameter: tuple[bool, ...]  # per path axis: programmed in diameter under DIAMON


def _machine(interp: Interpreter) -> _Machine:
    cached = interp.__dict__.get("_plain_machine")
    if cached is None:
        path = interp.builder.path
        axes = tuple(path.path_axes)
        usable = path.geo_axes == GEOMETRY and all(a in axes for a in GEOMETRY) \
            and all(path.kinds.get(a, "linear") == "linear" for a in GEOMETRY)
        cached = _Machine(usable, axes, tuple(path.kinds.get(a, "linear") == "linear" for a in axes),
                          tuple(a in path.diameter_axes for a in axes))
        interp.__dict__["_plain_machine"] = cached
    return cached


def _simple_setup(interp: Interpreter) -> _Setup | None:
    """The constants of the batch when the modal state is simple, else None."""
    if interp.dialect != "siemens":
        return None
    machine = _machine(interp)
    if not machine.usable:
        return None
    modal = interp.modal
    geo = modal.geometry
    gcodes = modal.gcodes
    if geo is None or not geo.loaded or geo.pending is not None or geo.rndm_mm:
        return None
    kind, distance = gcodes.get(1), gcodes.get(14)
    if kind not in ("G0", "G1") or distance not in ("G90", "G91") or gcodes.get(7, "G40") != "G40":
        return None
    if gcodes.get(15, "G94") != "G94" or geo.feed_type != "G94" or geo.frames.settable_code != gcodes.get(8, "G500"):
        return None
    stage = getattr(geo, STAGE_ATTRIBUTE, None)
    if stage is None or stage.compensator.active:
        return None
    affine = _axis_affine(geo.frames.transform())
    if affine is None:
        return None
    path = interp.builder.path
    try:
        tool = path.tool_vector(modal)
    except NcAlarmError:
        return None
    units = _units(interp, gcodes.get(13, "G71"))
    diameter_on = gcodes.get(29) == "DIAMON"
    return _Setup(
        absolute=distance == "G90",
        kind=1 if kind == "G1" else 0,
        feed=float(modal.feed),
        position_mm=units[0],
        feed_mm=units[1],
        diameter=tuple(diameter_on and a in path.diameter_axes for a in GEOMETRY),  # type: ignore[arg-type]
        scale=affine[0],
        offset=affine[1],
        tool=(float(tool.get("X", 0.0)), float(tool.get("Y", 0.0)), float(tool.get("Z", 0.0))),
        wcs=(float(geo.wcs_mm.get("X", 0.0)), float(geo.wcs_mm.get("Y", 0.0)), float(geo.wcs_mm.get("Z", 0.0))),
        mcs=modal.position_mcs,
        axes=machine.axes,
        diameter_on=diameter_on,
    )


def _units(interp: Interpreter, code: str) -> tuple[float, float]:
    """(position_mm, feed_mm) of G group 13 member ``code`` (cached per interpreter)."""
    table = interp.__dict__.setdefault("_plain_units", {})
    found = table.get(code)
    if found is None:
        units = UnitSystem(code, basic_metric=interp.builder.path.basic_metric)
        found = table[code] = (units.position_mm, units.feed_mm)
    return found


def _plan_words(interp: Interpreter, setup: _Setup, first: int, words: _Words) -> PlainBatch | None:
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
    rounded_start = np.array([_r(v) for v in start_mcs])
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
        machine = _round_array((column * setup.scale[i] + setup.offset[i]) + setup.tool[i])
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


def _r(value: float) -> float:
    """The path builder's rounding (9 decimals, no negative zero)."""
    return round(float(value), 9) + 0.0


def _round_array(values: np.ndarray) -> np.ndarray:
    """:func:`_r` of every element: values numpy rounds to themselves are kept (see module notes)."""
    out = values + 0.0
    same = (np.round(values, 9) == values) & (np.abs(values) < ROUND_SAFE_MM)
    for i in np.flatnonzero(~same).tolist():
        out[i] = _r(values[i])
    return out


# ----------------------------------------------------------------------------- one block
def step_plain(interp: Interpreter) -> BlockResult | None:
    """Interpret the next block if it is plain and the state simple (else None: the general path).

    Gives exactly the general path's :class:`BlockResult` (the same canonical
    motion) and state, without parser, snapshot or motion builder.
    """
    state = interp._state
    frame = state.frames[-1]
    program = frame.program
    lines = program.lines
    if not isinstance(lines, TextLines) or frame.modal_call is not None or frame.repeats:
        return None
    index = frame.pc
    if program.plain_run_end(index) <= index:
        return None
    raw = lines.raw(index)
    found = PLAIN_LINE.fullmatch(raw)
    if found is None:
        return None
    number, motion_a, distance_a, distance_b, motion_b, x, y, z, f = found.groups()
    setup = _simple_setup(interp)
    if setup is None:
        return None
    distance = distance_a or distance_b
    if distance is not None and (distance == "G91") == setup.absolute:
        return None  # a change of G90/G91: the general path
    feed = setup.feed
    if f is not None:
        feed = feed_value(f)
        if feed <= 0.0:
            return None  # alarm 14800
    motion = motion_a or motion_b
    kind = setup.kind if motion is None else (1 if G_CODES[motion] == "G1" else 0)
    texts = (x, y, z)
    moving = x is not None or y is not None or z is not None
    if moving and kind == 1 and feed <= 0.0:
        return None  # alarm 10860
    modal = interp.modal
    source = canon.Source(program.name, index + 1, int(number) if number is not None else None)
    if motion is not None or distance is not None or f is not None or moving:
        frame.def_open = False
    if motion is not None:
        modal.gcodes[1] = "G1" if kind else "G0"
    if distance is not None:
        modal.gcodes[14] = distance
    modal.feed = feed
    commands: tuple[canon.CanonCommand, ...] = ()
    if moving:
        commands = (_move(interp, setup, source, kind, texts),)
    frame.pc = index + 1
    interp._skip_run = None
    return BlockResult(
        source=source, text=raw, commands=commands, action_block=bool(commands), finished=False,
        cost_s=BLOCK_COST_S,
        extras={"level": len(state.frames), "preprocessing_stop": False,
                "single_block_off": frame.single_block_off, "display_off": frame.display_off},
    )


def _move(interp: Interpreter, setup: _Setup, source: canon.Source, kind: int,
          texts: tuple[str | None, str | None, str | None]) -> canon.Motion:
    """The motion of one plain block; updates the modal state like the path builder."""
    modal = interp.modal
    geo = modal.geometry
    start = geo.wcs_mm
    end = dict(start)
    for axis in GEOMETRY:
        end.setdefault(axis, 0.0)
    machine_geo: dict[str, float] = {}
    for i, axis in enumerate(GEOMETRY):
        text = texts[i]
        if text is None:
            continue
        value_mm = axis_value(text) * setup.position_mm
        if setup.diameter[i]:
            value_mm = value_mm / 2.0
        end[axis] = value_mm if setup.absolute else end.get(axis, 0.0) + value_mm
        machine_geo[axis] = _r((end[axis] * setup.scale[i] + setup.offset[i]) + setup.tool[i])
    start_mcs = dict(modal.position_mcs)
    end_mcs = {axis: machine_geo[axis] if axis in machine_geo else _r(start_mcs.get(axis, 0.0))
               for axis in setup.axes}
    geo.wcs_mm = end
    geo.tangent = _end_tangent(LineElement(
        (float(start.get("X", 0.0)), float(start.get("Y", 0.0)), float(start.get("Z", 0.0))),
        (float(end["X"]), float(end["Y"]), float(end["Z"]))))
    modal.position_wcs = _wcs_view(interp, setup, end)
    modal.position_mcs = dict(end_mcs)
    gcodes = modal.gcodes
    rapid = kind == 0
    return canon.Motion(
        kind="G1" if kind else "G0", source=source, plane=gcodes.get(6, "G17"),
        end_wcs=dict(modal.position_wcs), end_mcs=end_mcs, start_mcs=start_mcs,
        feed=None if rapid else modal.feed,
        feed_mm_min=None if rapid else modal.feed * setup.feed_mm,
        exact_stop=gcodes.get(10, "G60") == "G60", exact_stop_window=gcodes.get(12, "G601"),
        gcodes=dict(gcodes),
    )


def _wcs_view(interp: Interpreter, setup: _Setup, wcs_mm: dict[str, float]) -> dict[str, float]:
    """The path builder's ``wcs_view``: program units per path axis, rounded."""
    machine = _machine(interp)
    out: dict[str, float] = {}
    for axis, linear, diameter in zip(machine.axes, machine.linear, machine.diameter):
        value = wcs_mm.get(axis, 0.0)
        if not linear:
            out[axis] = _r(value)
            continue
        value = float(value) / setup.position_mm
        out[axis] = _r(value * 2.0 if diameter and setup.diameter_on else value)
    return out
