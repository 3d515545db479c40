"""A part program's text as lines, without one Python string per line.

The block window of the Machine area shows twenty lines of the selected
program around the current block. A CAM program has hundreds of thousands of
lines; a tuple of line strings would cost tens of megabytes and a scan of every
line per refresh. :class:`ProgramLines` keeps the text once and the start
offset of every line in a compact array (8 bytes a line); a line is cut out of
the text when it is shown.

Line ends are normalised as the kernel does (``\\r\\n`` and a lone ``\\r`` are
line ends), so line numbers agree with the kernel's current block.
"""

from __future__ import annotations

import re
from array import array
from typing import Iterator

_LINE_END = re.compile("\n")


class ProgramLines:
    """The lines of one program text (read-only sequence of ``str``, line ends removed).

    Args:
        name: the program's name as the kernel reports it.
        text: the program text.
    """

    def __init__(self, name: str, text: str) -> None:
        if "\r" in text:
            text = text.replace("\r\n", "\n").replace("\r", "\n")
        self.name = name
        self.text = text
        starts = array("q", [0])
        starts.extend(match.end() for match in _LINE_END.finditer(text))
        if starts[-1] == len(text) and len(starts) > 1:
            starts.pop()  # a final line end does not open another line
        if not text:
            starts = array("q")
        self._starts = starts

    def __len__(self) -> int:
        return len(self._starts)

    def __getitem__(self, index: int) -> str:
        count = len(self._starts)
        if index < 0:
            index += count
        if not 0 <= index < count:
            raise IndexError(index)
        start = self._starts[index]
        end = self._starts[index + 1] - 1 if index + 1 < count else len(self.text)
        if end > start and self.text[end - 1 : end] == "\n":
            end -= 1
        return self.text[start:end]

    def __iter__(self) -> Iterator[str]:
        for index in range(len(self._starts)):
            yield self[index]

    def is_blank(self, index: int) -> bool:
        """True when line ``index`` holds only white space."""
        return not self[index].strip()

    def blocks_around(self, line_number: int | None, before: int, height: int) -> tuple[list[int], int]:
        """Line indexes of up to ``height`` non-blank lines around line ``line_number`` (1-based).

        ``before`` non-blank lines come before the current one, more when the
        program ends sooner (the window stays full). When ``line_number`` is no
        non-blank line the window starts at the first block. Returns the indexes
        and the position among them of the current line (of the first block when
        it was not found).
        """
        count = len(self)
        first = 0
        if line_number is not None and 1 <= line_number <= count and not self.is_blank(line_number - 1):
            first = line_number - 1
        after: list[int] = []
        index = first
        while index < count and len(after) < height:
            if not self.is_blank(index):
                after.append(index)
            index += 1
        wanted = before if len(after) >= height - before else height - len(after)
        earlier: list[int] = []
        index = first - 1
        while index >= 0 and len(earlier) < wanted:
            if not self.is_blank(index):
                earlier.append(index)
            index -= 1
        return (earlier[::-1] + after)[:height], len(earlier)
