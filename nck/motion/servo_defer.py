"""Deferred position control: several blocks of setpoints through one numpy pass.

Inside one motion step (:meth:`nck.motion.system.PlannedMotion.advance_cycles`)
the kernel is called back at every block end, so the servo used to run once
per block — about 45 small numpy operations for a block of some 40 cycles.
When a cheap bound proves that no monitor can respond anywhere in a block,
its setpoints are only queued; :func:`settle` runs the queued blocks through
:func:`nck.motion.servo_paths.process_fast` at once, before anything reads
the servo state (every :class:`~nck.motion.servo.ServoBank` accessor settles
first) and at the end of the step.

The bound: without faults and without contour deviation the following error
obeys ``e[k] = alpha e[k-1] + b v[k]`` (see :mod:`nck.motion.servo`), so with
``V`` the largest setpoint speed of the block, ``|e| <= E = max(|e0|,
b V / (1 - alpha))`` in every cycle; the speed setpoint ``kv e + ffw v`` is at
most ``kv E + |ffw| V``; the actual velocity ``v - (e[k] - e[k-1]) / T`` at
most ``V + ((1 - alpha) E + b V) / T``; and an axis that stops in the block
must have ``E`` inside its standstill windows. The bounds carry over from
block to block (``E`` of one block is ``|e0|`` of the next). A block that
fails them is processed at once, after the queue, exactly as before.
"""

from __future__ import annotations

from operator import sub

import numpy as np

from nck.motion.servo_model import MOVING_MM_S, ServoModel
from nck.motion.servo_paths import process_fast

SMALL_ROWS = 16  # up to this many rows the speed range is taken in Python floats (cheaper than numpy)


def quiet_bound(bank: ServoModel, rows: np.ndarray) -> list[float] | None:
    """The following-error bound after ``rows`` when no monitor can respond in them, else None.

    Starts from the queued blocks' bound, or from the settled state (which
    must then have no contour deviation).
    """
    pending = bank.pending
    if pending:
        previous = pending[-1][-1]
        start = bank.pending_bound
        assert start is not None, "queued blocks always carry their bound"
    else:
        if not np.array_equal(bank.e, bank.e_model):
            return None  # a contour deviation: the full model decides
        previous = bank.x_set
        start = np.abs(bank.e).tolist()
    tops, lows = speed_range(rows, previous, bank.inv_t)
    out = []
    for (e_per_v, kv, ffw, ctrlout, velo, decay_rate, b_rate, small_e), top, low, e0 in zip(
            bank.bound_tables, tops, lows, start):
        bound = e_per_v * top
        if not bound > e0:  # max(e0, bound) as the builtin decides
            bound = e0
        if kv * bound + ffw * top > ctrlout or top + decay_rate * bound + b_rate * top > velo:
            return None
        if low <= MOVING_MM_S and bound > small_e:
            return None  # a stopped axis that may be outside its windows
        out.append(bound)
    return out


def speed_range(rows: np.ndarray, previous: np.ndarray, inv_t: float) -> tuple[list[float], list[float]]:
    """Largest and smallest setpoint speed |difference × 1/T| of every axis over ``rows``
    (``previous``: the setpoint before them); up to SMALL_ROWS rows in Python floats."""
    m = rows.shape[0]
    if m == 1:
        return speed_range_of_rows(rows.tolist(), previous.tolist(), inv_t)
    if m <= SMALL_ROWS:
        # Every step at once, row after row (each value minus the one an axis count before it),
        # then axis by axis the largest and smallest step of each column (max and min of
        # finite floats: the same values as the row-by-row comparisons and numpy's reductions).
        width = rows.shape[1]
        values = previous.tolist()
        values += rows.ravel().tolist()
        steps = list(map(abs, map(sub, values[width:], values)))
        tops: list[float] = []
        lows: list[float] = []
        for axis in range(width):
            column = steps[axis::width]
            tops.append(max(column) * inv_t)
            lows.append(min(column) * inv_t)
        return tops, lows
    step = np.empty_like(rows)
    np.subtract(rows[0], previous, out=step[0])
    np.subtract(rows[1:], rows[:-1], out=step[1:])
    np.abs(step, out=step)
    # Scaled after the max and min, as in speed_range_of_rows: the same floats.
    return [top * inv_t for top in step.max(axis=0).tolist()], [low * inv_t for low in step.min(axis=0).tolist()]


def speed_range_of_rows(rows: list[list[float]], previous: list[float], inv_t: float) -> tuple[list[float], list[float]]:
    """Largest and smallest setpoint speed of every axis over a few rows, in Python floats.

    The same values as the numpy form |difference × 1/T|: the step is scaled after taking the
    largest and smallest, which gives the same floats because rounding is monotonic (a ≤ b
    gives fl(a·c) ≤ fl(b·c) for c > 0) and symmetric (|fl(d·c)| = fl(|d|·c))."""
    tops: list[float] = []
    lows: list[float] = []
    before = previous
    for row in rows:
        steps = [abs(x - x0) for x, x0 in zip(row, before)]
        if tops:
            tops = [top if top >= step else step for top, step in zip(tops, steps)]
            lows = [low if low <= step else step for low, step in zip(lows, steps)]
        else:
            tops, lows = steps, steps
        before = row
    return [top * inv_t for top in tops], [low * inv_t for low in lows]


def settle(bank: ServoModel) -> None:
    """Process the queued setpoints (in chunks the fast path can take)."""
    pending = bank.pending
    if not pending:
        return
    rows = pending[0] if len(pending) == 1 else np.concatenate(pending)
    bank.pending = []
    bank.pending_bound = None
    step = bank.fast_rows
    for start in range(0, rows.shape[0], step):
        if process_fast(bank, rows[start:start + step]) is None:
            # The bound proved every monitor silent: this is a programming error.
            raise RuntimeError("deferred servo block failed its proven bounds")
