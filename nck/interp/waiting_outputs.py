"""Outputs of blocks whose place in the path is still held back.

A chamfer or rounding (CHF/CHR/RND/RNDM, G641) and the radius compensation
look-ahead (G41/G42) hold a block's motion back until a later block is known.
The outputs of the blocks in between must still come out where the program
puts them (002 L4797-4809; 001 L7752-7760, the 840C rule the 840D keeps):

* a block without path motion (``M8``, ``G4 F1``) in between is output after
  the motion of the block before it, at that block's end point (the rounding
  or the compensated corner of the block before belongs to it);
* the outputs of a block whose own motion is held go out with that motion
  when it is released (before the motion, or after it at block end, by
  MD22080), behind the intermediate blocks the control inserted for it.

The waiting blocks live in ``GeometryState.waiting`` (tuples, replaced and
never changed in place, so the interpreter's snapshot before each block
rolls them back on an alarm).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from nck import canon

Place = Callable[[list[canon.CanonCommand], list[canon.CanonCommand], canon.Source], list[canon.CanonCommand]]


@dataclass(frozen=True)
class WaitingBlock:
    """One block's outputs waiting in the path.

    Attributes:
        source: the block.
        outputs: its outputs; for a block without path motion already placed (exact stop first).
        moves: True if the block's own motion is held back (its outputs are placed around it).
    """

    source: canon.Source
    outputs: tuple[canon.CanonCommand, ...]
    moves: bool


def release(released: list[canon.CanonCommand], waiting: tuple[WaitingBlock, ...],
            place: Place) -> tuple[list[canon.CanonCommand], tuple[WaitingBlock, ...]]:
    """Put the waiting outputs among motions released now; (commands in output order, still waiting).

    Every run of released motions of one block takes that block's outputs; blocks without
    path motion waiting before it go out first. Blocks without motion at the head of what
    is left go out behind the released motions (nothing before them is held any more).
    """
    out: list[canon.CanonCommand] = []
    queue = list(waiting)
    for source, run in _runs(released):
        index = next((i for i, block in enumerate(queue) if block.moves and block.source == source), None)
        if index is None or source is None:
            out.extend(run)
            continue
        for block in queue[:index]:
            out.extend(_alone(block, place))
        block = queue[index]
        del queue[:index + 1]
        out.extend(place(list(block.outputs), run, source))
    while queue and not queue[0].moves:
        out.extend(queue.pop(0).outputs)
    return out, tuple(queue)


def release_all(waiting: tuple[WaitingBlock, ...], place: Place) -> list[canon.CanonCommand]:
    """Every waiting output (nothing is held back any more: stop point, program end)."""
    out: list[canon.CanonCommand] = []
    for block in waiting:
        out.extend(_alone(block, place))
    return out


def _alone(block: WaitingBlock, place: Place) -> list[canon.CanonCommand]:
    """A waiting block's outputs without motion (a block without path motion, or one whose
    held motion came to nothing)."""
    return place(list(block.outputs), [], block.source) if block.moves else list(block.outputs)


def _runs(commands: list[canon.CanonCommand]) -> list[tuple[canon.Source | None, list[canon.CanonCommand]]]:
    """Consecutive motions of one block as (its source, commands); other commands alone (source None)."""
    runs: list[tuple[canon.Source | None, list[canon.CanonCommand]]] = []
    for command in commands:
        source = command.source if isinstance(command, canon.Motion) else None
        if runs and source is not None and runs[-1][0] == source:
            runs[-1][1].append(command)
        else:
            runs.append((source, [command]))
    return runs
