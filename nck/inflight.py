"""The blocks of the motion items a program run pushed and has not seen executed yet.

:class:`nck.program_control.ProgramRun` holds an output (M function, message) back until the
motion pushed before it has been executed; it keeps the block, ``(file, line)``, of every item
it pushes, oldest first, and drops the executed ones as the main run goes on (up to the first
item of the block now executing), so the queue stays about as long as the motion's look-ahead.
One integer per entry in an array, not a tuple and a deque slot."""

from __future__ import annotations

from array import array

from nck.canon import Source

FILE_SLOTS = 1 << 20
"""A block is ``line × FILE_SLOTS + file number`` (the files numbered as first pushed): one
integer per (file, line), different for different blocks while a run has fewer files."""


class InFlight:
    """The pushed items' blocks, oldest first, as a queue of block numbers (see the module)."""

    def __init__(self) -> None:
        self._blocks = array("q")
        self._head = 0  # the oldest entry; those before it are dropped
        self._files: dict[str, int] = {}

    def __len__(self) -> int:
        return len(self._blocks) - self._head

    def append(self, source: Source) -> None:
        """An item of block ``source`` pushed."""
        files = self._files
        number = files.get(source.file)
        if number is None:
            number = files[source.file] = len(files)
            if number >= FILE_SLOTS:
                raise OverflowError("more program files in one run than FILE_SLOTS")
        self._blocks.append(source.line * FILE_SLOTS + number)

    def clear(self) -> None:
        """Every item executed."""
        del self._blocks[:]
        self._head = 0

    def find(self, source: Source) -> int | None:
        """The position (0: the oldest) of the first entry of the block of ``source``, None if none."""
        number = self._files.get(source.file)
        if number is None:
            return None
        try:
            return self._blocks.index(source.line * FILE_SLOTS + number, self._head) - self._head
        except ValueError:
            return None

    def drop(self, count: int) -> None:
        """The ``count`` oldest entries executed (at most all of them)."""
        self._head = min(self._head + count, len(self._blocks))
        if self._head > 4096 and self._head * 2 > len(self._blocks):
            del self._blocks[:self._head]  # amortised: at most as many moves as drops
            self._head = 0
