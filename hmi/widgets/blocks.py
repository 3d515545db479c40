"""The block window: the current program block with a few before and after."""

from __future__ import annotations

from rich.text import Text
from textual.widgets import Static

from nck.status import BlockView, ChannelStatus

BEFORE = 3
"""Blocks shown before the current one."""


def block_lines(blocks: tuple[BlockView, ...], current: BlockView | None, height: int) -> Text:
    """Render ``height`` lines of ``blocks`` around ``current`` (highlighted)."""
    text = Text()
    if not blocks:
        text.append(" (no program)\n", style="dim")
        return text
    index = 0
    if current is not None:
        for i, block in enumerate(blocks):
            if block.line == current.line and _same_file(block.file, current.file):
                index = i
                break
    start = max(0, min(index - BEFORE, len(blocks) - height))
    for i in range(start, min(len(blocks), start + height)):
        block = blocks[i]
        if current is not None and i == index:
            text.append(f"▶{block.text}".ljust(120)[:120] + "\n", style="bold black on #f39200")
        else:
            text.append(f" {block.text}\n")
    return text


def _same_file(a: str, b: str) -> bool:
    return a.replace("\\", "/").rsplit("/", 1)[-1].upper() == b.replace("\\", "/").rsplit("/", 1)[-1].upper()


def program_views(name: str, lines: tuple[str, ...]) -> tuple[BlockView, ...]:
    """The lines of a program text as block views (blank lines left out)."""
    return tuple(BlockView(name, number, text.rstrip())
                 for number, text in enumerate(lines, start=1) if text.strip())


class BlockWindow(Static):
    """The blocks of the selected (or MDA) program; the current block highlighted.

    With the program text at hand the window shows the program around the
    current block (blocks before and after); otherwise the blocks the kernel
    reports (those already interpreted).
    """

    def __init__(self, height_lines: int = 9, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self.height_lines = height_lines
        self._key: object = None

    def show(self, channel: ChannelStatus, program: tuple[str, tuple[str, ...]] | None = None) -> None:
        """Redraw when the program or the current block changed."""
        current = channel.current_block
        blocks = channel.blocks
        if program is not None and (current is None or _same_file(current.file, program[0])):
            blocks = program_views(*program)
        key = (blocks, current, self.height_lines)
        if key == self._key:
            return
        self._key = key
        self.update(block_lines(blocks, current, self.height_lines), layout=False)
