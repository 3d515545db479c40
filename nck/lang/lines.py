"""Program lines: one :class:`Line` per source line, and :class:`TextLines`, a program's
lines kept as text, parsed on demand with a bounded cache.

A long program (a CAM file of a million lines) must not become a million
syntax trees. :class:`TextLines` keeps the program text and a line-start
checkpoint every :data:`CHECKPOINT_LINES` lines; ``lines[i]`` finds line *i*
from the checkpoint before it and parses it when it is asked for. Parsed lines
are kept in a small cache (:data:`CACHE_LINES`), so a loop over a few hundred
lines is parsed once, and the interpreter's per-line caches (``touches_modal``
…) live as long as the line stays in the cache. Parsing is deterministic, so a
line parsed again is the same line.

Lines that failed to parse at load time keep their alarm (``errors``); they are
not parsed again.
"""

from __future__ import annotations

from array import array
from dataclasses import dataclass
from itertools import islice
from typing import Any, Iterator, Protocol

from nck.errors import NcAlarmError
from nck.lang import ast
from nck.lang.parser import parse_block
from nck.lang.plain import simple_block

CHECKPOINT_LINES = 64
"""A line-start offset is kept for every this many lines."""

CACHE_LINES = 1024
"""Parsed lines kept per program."""


@dataclass
class Line:
    """One source line: its parsed block or the alarm its parsing raised."""

    number: int  # 1-based line
    text: str
    block: ast.Block | None
    error: NcAlarmError | None = None
    touches_modal: bool | tuple[str, ...] | None = None  # cache for the interpreter's block snapshot
    main_run_read: bool | None = None  # cache: the block reads $A…/$V… (preprocessing stop)


class LineSequence(Protocol):
    """A program's lines, read-only: a list (translated ISO text) or :class:`TextLines`."""

    def __len__(self) -> int: ...

    def __getitem__(self, index: int) -> Line: ...

    def __iter__(self) -> Iterator[Line]: ...


def remember_bounded(cache: dict, key: Any, value: Any, limit: int) -> None:
    """Put ``key: value`` into an insertion-ordered cache of at most ``limit`` entries.

    The oldest entries go first, a quarter of ``limit`` at a time: removing one at a time,
    each ``next(iter(cache))`` walks over the slots the earlier removals left empty at the
    front (~4 us a line in a 4,096-line cache, where a CAM program's lines are all new). The
    HMI checks programs in a worker thread, so an eviction racing with another thread is
    tolerated.
    """
    if len(cache) >= limit:
        try:
            for old in list(islice(cache, len(cache) - limit + max(1, limit // 4))):
                cache.pop(old, None)
        except RuntimeError:
            pass
    cache[key] = value


class TextLines:
    """The lines of a program text as a read-only sequence of :class:`Line`.

    ``text`` has its line ends normalised to ``\\n``. ``count`` is the number of
    lines (a last empty line after the final line end does not count).
    """

    def __init__(self, text: str, count: int, checkpoints: array, errors: dict[int, NcAlarmError]) -> None:
        self.text = text
        self.count = count
        self.checkpoints = checkpoints
        self.errors = errors
        self._cache: dict[int, Line] = {}
        self._cursor = (0, 0)  # (line index, offset of its start): sequential access is O(1)

    def __len__(self) -> int:
        return self.count

    def __iter__(self) -> Iterator[Line]:
        for index in range(self.count):
            yield self[index]

    def __getitem__(self, index: int) -> Line:
        if index < 0:
            index += self.count
        if not 0 <= index < self.count:
            raise IndexError(index)
        found = self._cache.get(index)
        if found is not None:
            return found
        raw = self.raw(index)
        error = self.errors.get(index)
        if error is not None:
            line = Line(index + 1, raw, None, error)
        else:
            try:  # a simple motion line needs no lexer (the parser's tree, property-tested)
                line = Line(index + 1, raw, simple_block(raw, index + 1) or parse_block(raw, index + 1))
            except NcAlarmError as alarm:  # cannot happen for a line that parsed at load time
                line = Line(index + 1, raw, None, alarm)
        self.remember(index, line)
        return line

    def remember(self, index: int, line: Line) -> None:
        """Keep a parsed line in the cache (the oldest one goes when it is full)."""
        remember_bounded(self._cache, index, line, CACHE_LINES)

    # ------------------------------------------------------------------ text access
    def start(self, index: int) -> int:
        """Offset in ``text`` where line ``index`` starts (``index == count``: the end)."""
        last, offset = self._cursor
        if not last <= index < last + CHECKPOINT_LINES:
            last = (index // CHECKPOINT_LINES) * CHECKPOINT_LINES
            offset = self.checkpoints[index // CHECKPOINT_LINES] if last < self.count else len(self.text)
        find = self.text.find
        while last < index:
            found = find("\n", offset)
            offset = len(self.text) + 1 if found < 0 else found + 1
            last += 1
        self._cursor = (index, offset)
        return offset

    def raw(self, index: int) -> str:
        """The source text of line ``index`` (without its line end)."""
        begin = self.start(index)
        end = self.text.find("\n", begin)
        return self.text[begin:] if end < 0 else self.text[begin:end]

    def chunk(self, first: int, stop: int) -> str:
        """The text of lines ``first`` … ``stop - 1`` (line ends included except the last one's)."""
        begin = self.start(first)
        end = self.start(stop) - 1 if stop < self.count else len(self.text)
        return self.text[begin:end]
