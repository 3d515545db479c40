"""The basic block display: the blocks as the NCK executes them (002 L23515-23800).

A second block display beside the program's own shows every block that acts on the machine,
also the blocks a cycle generates (a cycle is ``DISPLOF``: the program's display keeps its
call), with the end positions the block approaches as absolute values in the WCS. A
:class:`BasicBlockLog` belongs to one program run: the run hands it each block it takes for
execution (:meth:`BasicBlockLog.taken`) and each path segment it passes on to the motion
(:meth:`BasicBlockLog.moved`), in the order the main run will execute them; the status asks it
for the display blocks around the block in execution (:meth:`BasicBlockLog.around`).

How a display block is written (002 L23656-23800, "Structure for a DIN block"):

- the block number of the original block, left out when the block runs under ``DISPLOF``;
- the G code of group 1 when it differs from that of the last motion block;
- the axes the block programs, with their absolute end positions in the WCS ("Programmed axis
  positions are represented as absolute positions", L23726-23728; the manual's example shows
  ``N20 G91 X1`` as ``N20 X11.123``, L23733), also when the axis does not move; an axis the
  block does not program is left out. The block's text names its axes; an axis the text cannot
  name (``AX[_AX]=`` of a cycle, an ISO block) is shown when the block moves it. The transverse
  axis as a diameter under DIAMON, as the program writes it; circles add their centre as
  absolute values (``I=AC(…)``); positions with at most three decimals (MD9004's default
  resolution);
- F when a block other than G0 moves at a feed that differs from the last one shown;
- the other addresses of the block as values: T, D, S and M3/M4/M5, SPOS, M and H functions,
  the dwell ``G4 F…``/``G4 S…``, M0/M1 and the program end.

Our choices where the manual says more than we model: the other modal G codes are not shown
(the manual collects changed ones into the next block), nor labels; a block that only
computes (a cycle's arithmetic, jumps) has no display block. The block search interprets
without taking blocks, so it writes none (002 L23610: the display is off during block search);
the first block after it shows its G code and F again.

The words of a block's positions are made when the block is shown (most never are): the run
only keeps each segment (:meth:`BasicBlockLog.moved`), on the path of every block.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, field
from functools import lru_cache

from nck.canon import (
    AuxFunction, CanonCommand, Dwell, EdgeSelect, Motion, ProgramEnd, SpindleCommand, StopPoint,
    Source, ToolSelect,
)
from nck.block_search import programmed_axes
from nck.interp.api import BlockResult
from nck.number_text import trimmed
from nck.status import BlockView

BLOCKS_KEPT = 4096
"""Display blocks remembered: more than the look-ahead buffer (MD28060, at most 1000 segments)
lets the interpreter read ahead of the block in execution."""
POSITION_PLACES = 3
"""Decimals of a position (MD9004 DISPLAY_RESOLUTION, default 3)."""
CENTRE_WORDS = {"G17": {"X": "I", "Y": "J"}, "G18": {"Z": "K", "X": "I"}, "G19": {"Y": "J", "Z": "K"}}
"""The interpolation parameters of a circle's centre, by the plane of the circle."""
STOP_WORDS = frozenset({"M0", "M00", "M1", "M01"})


@dataclass(slots=True)
class _DisplayBlock:
    """One display block while it is written: its source, its text and its words (a segment of
    the block stands for its position and centre words until the block is shown)."""

    source: Source
    seq: int
    label: str
    text: str
    motion_words: list[str | Motion] = field(default_factory=list)
    other_words: list[str] = field(default_factory=list)
    shown: BlockView | None = None  # the view, made again when a word was added

    def view(self) -> BlockView:
        if self.shown is None:
            words = [self.label] if self.label else []
            for word in self.motion_words:
                if isinstance(word, str):
                    words.append(word)
                else:
                    words += _segment_words(word, _programmed(self.text, frozenset(word.end_wcs)))
            words += self.other_words
            self.shown = BlockView(self.source.file, self.source.line, " ".join(words))
        return self.shown


@lru_cache(maxsize=1024)
def _programmed(text: str, axes: frozenset[str]) -> frozenset[str]:
    """The axes among ``axes`` the block ``text`` names (none when it is not a Siemens block)."""
    return programmed_axes(text, axes) or frozenset()


def _segment_words(motion: Motion, programmed: frozenset[str]) -> list[str]:
    """The position words of a segment (the axes ``programmed``, and those it moves) and the
    words of a circle's centre."""
    words = []
    start_mcs, end_mcs = motion.start_mcs, motion.end_mcs
    for axis, value in motion.end_wcs.items():
        moved = _shown(float(start_mcs.get(axis, value))) != _shown(float(end_mcs.get(axis, value)))
        if axis in programmed or moved:
            words.append(f"{axis}{_shown(float(value))}")
    centre_words = CENTRE_WORDS.get(motion.plane, {})
    for axis, value in (motion.center_wcs or {}).items():
        if axis in centre_words:
            words.append(f"{centre_words[axis]}=AC({_shown(float(value))})")
    return words


class BasicBlockLog:
    """The display blocks of one program run, oldest first (see the module docstring)."""

    def __init__(self, capacity: int = BLOCKS_KEPT) -> None:
        self._blocks: deque[_DisplayBlock] = deque(maxlen=capacity)
        self._by_source: dict[int, _DisplayBlock] = {}
        self._seq = 0
        self._motion_code: str | None = None
        self._feed: float | None = None

    def taken(self, block: BlockResult) -> None:
        """A block taken for execution: a display block when it acts on the machine."""
        source = block.source
        words: list[str] = []
        moves = False
        for command in block.commands:
            if isinstance(command, Motion):
                moves = moves or command.source is source
            else:
                words += _words_of(command)
        if not words and not moves:
            return
        label = "" if block.extras.get("display_off") or source.n is None else f"N{source.n}"
        entry = _DisplayBlock(source, self._seq, label, block.text, [], words)
        self._seq += 1
        if len(self._blocks) == self._blocks.maxlen:
            dropped = self._blocks.popleft()
            if self._by_source.get(id(dropped.source)) is dropped:
                del self._by_source[id(dropped.source)]
        self._blocks.append(entry)
        self._by_source[id(block.source)] = entry

    def moved(self, motion: Motion) -> None:
        """A path segment passed on to the motion: its words join its block's display block.

        A segment that its block releases late (radius compensation, RND) still belongs to
        the block that programmed it."""
        entry = self._entry(motion.source)
        if entry is None:
            return
        entry.shown = None
        words = entry.motion_words
        if motion.kind != self._motion_code:
            words.append(motion.kind)
            self._motion_code = motion.kind
        words.append(motion)  # its position and centre words when the block is shown
        if motion.kind != "G0" and motion.feed is not None and motion.feed != self._feed:
            words.append(f"F{trimmed(motion.feed)}")
            self._feed = motion.feed

    def forget_shown_modals(self) -> None:
        """After a block search: the next display block shows its G code and F again."""
        self._motion_code = None
        self._feed = None

    def around(self, source: Source | None, before: int, after: int) -> tuple[tuple[BlockView, ...], int]:
        """The display blocks from ``before`` blocks before the one of ``source`` (the block in
        execution) to ``after`` blocks after it, and the index of that block in them.

        ``source`` None: nothing executes, the motion stands and every block taken has been
        executed: the newest block is the one marked. A ``source`` without a display block
        (forgotten): the newest blocks, none marked (-1)."""
        if not self._blocks:
            return (), -1
        if source is None:
            entry: _DisplayBlock | None = self._blocks[-1]
        else:
            entry = self._entry(source)
        if entry is None:
            start = max(0, len(self._blocks) - before - 1)
            return tuple(self._blocks[i].view() for i in range(start, len(self._blocks))), -1
        index = entry.seq - self._blocks[0].seq
        start = max(0, index - before)
        stop = min(len(self._blocks), index + after + 1)
        shown = tuple(self._blocks[i].view() for i in range(start, stop))
        return shown, index - start

    def _entry(self, source: Source) -> _DisplayBlock | None:
        entry = self._by_source.get(id(source))
        return entry if entry is not None and entry.source is source else None


def _shown(value: float) -> str:
    return trimmed(value, POSITION_PLACES)


def _spindle_address(address: str, spindle: int) -> str:
    """``S``/``M`` of the master spindle, ``S2=``/``M2=`` of another (002 L23774-23781)."""
    return address if spindle == 1 else f"{address}{spindle}="


def _words_of(command: CanonCommand) -> list[str]:
    """The address words a command other than a path segment adds to its display block."""
    if isinstance(command, SpindleCommand):
        words = []
        if command.speed_rpm is not None:
            words.append(f"{_spindle_address('S', command.spindle)}{trimmed(command.speed_rpm)}")
        if command.state in ("M3", "M4", "M5", "M19"):
            words.append(f"{_spindle_address('M', command.spindle)}{command.state[1:]}")
        elif command.state == "SPOS" and command.position_deg is not None:
            name = "SPOS" if command.spindle == 1 else f"SPOS[{command.spindle}]"
            words.append(f"{name}={trimmed(command.position_deg)}")
        return words
    if isinstance(command, ToolSelect):
        return [f"T{command.tool}"]
    if isinstance(command, EdgeSelect):
        return [f"D{command.edge}"]
    if isinstance(command, AuxFunction):
        extension = "" if command.extension is None else f"{command.extension}="
        return [f"{command.address.upper()}{extension}{trimmed(command.value)}"]
    if isinstance(command, Dwell):
        if command.wait_spindle:
            return []
        if command.revolutions is not None:
            return [f"G4 S{trimmed(command.revolutions)}"]
        return [f"G4 F{trimmed(command.seconds or 0.0)}"]
    if isinstance(command, StopPoint) and command.kind.upper() in STOP_WORDS:
        return [command.kind.upper()]
    if isinstance(command, ProgramEnd) and command.kind.upper().startswith("M"):
        return [command.kind.upper()]
    return []
