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
            if block.line == current.line and block.file == current.file:
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


class BlockWindow(Static):
    """The blocks of the selected (or MDA) program; the current block highlighted."""

    def __init__(self, height_lines: int = 9, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self.height_lines = height_lines
        self._key: object = None

    def show(self, channel: ChannelStatus) -> None:
        """Redraw when the program or the current block changed."""
        key = (channel.blocks, channel.current_block, self.height_lines)
        if key == self._key:
            return
        self._key = key
        self.update(block_lines(channel.blocks, channel.current_block, self.height_lines))
