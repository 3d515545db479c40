"""The block window: the current program block with a few before and after."""

from __future__ import annotations

from typing import Sequence

from rich.text import Text
from textual.widgets import Static

from nck.status import AlarmEntry, BlockView, ChannelStatus

from hmi.program_lines import ProgramLines

BEFORE = 3
"""Blocks shown before the current one."""


def block_lines(blocks: tuple[BlockView, ...], current: BlockView | None, height: int) -> Text:
    """Render ``height`` lines of ``blocks`` around ``current`` (highlighted)."""
    if not blocks:
        return _window_text((), None)
    index = 0
    if current is not None:
        for i, block in enumerate(blocks):
            if block.line == current.line and _same_file(block.file, current.file):
                index = i
                break
    start = max(0, min(index - BEFORE, len(blocks) - height))
    shown = blocks[start:start + height]
    return _window_text(shown, index - start if current is not None else None)


def _window_text(shown: Sequence[BlockView], highlight: int | None) -> Text:
    """The block window's text: ``shown`` with the block at ``highlight`` marked."""
    text = Text()
    if not shown:
        text.append(" (no program)\n", style="dim")
        return text
    for i, block in enumerate(shown):
        if i == highlight:
            text.append(f"▶{block.text}".ljust(120)[:120] + "\n", style="bold black on #f39200")
        else:
            text.append(f" {block.text}\n")
    return text


def _same_file(a: str, b: str) -> bool:
    return a.replace("\\", "/").rsplit("/", 1)[-1].upper() == b.replace("\\", "/").rsplit("/", 1)[-1].upper()


def program_views(name: str, lines: Sequence[str]) -> tuple[BlockView, ...]:
    """The lines of a program text as block views (blank lines left out)."""
    return tuple(BlockView(name, number, text.rstrip())
                 for number, text in enumerate(lines, start=1) if text.strip())


def program_window(program: ProgramLines, current: BlockView | None, height: int) -> Text:
    """Render ``height`` blocks of ``program`` around ``current`` (as :func:`block_lines` would).

    Only the lines on display are looked at, so a program of hundreds of
    thousands of lines costs no more per refresh than a short one.
    """
    shown, position = program.blocks_around(current.line if current is not None else None,
                                            BEFORE, height)
    views = [BlockView(program.name, index + 1, program[index].rstrip()) for index in shown]
    return _window_text(views, position if current is not None else None)


def marked_block(channel: ChannelStatus, alarms: Sequence[AlarmEntry] = ()) -> BlockView | None:
    """The block the ▶ marks: the one in execution or, stopped by an alarm, the block that raised it.

    An alarm found while a block is prepared names that block, not the one still
    in execution (issue 18: the ▶ stood on the block before the faulty one).
    """
    current = channel.current_block
    if channel.stop_reason != "alarm":
        return current
    for alarm in sorted(alarms, key=lambda a: a.seq, reverse=True):
        if alarm.line is not None and alarm.file:
            return BlockView(alarm.file, alarm.line, "")
    return current


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

    def show(self, channel: ChannelStatus, program: ProgramLines | None = None,
             alarms: Sequence[AlarmEntry] = ()) -> None:
        """Redraw when the program or the marked block (:func:`marked_block`) changed."""
        current = marked_block(channel, alarms)
        if program is not None and (current is None or _same_file(current.file, program.name)):
            key: object = (id(program), current, self.height_lines)
            if key != self._key:
                self._key = key
                self.update(program_window(program, current, self.height_lines), layout=False)
            return
        key = (channel.blocks, current, self.height_lines)
        if key == self._key:
            return
        self._key = key
        self.update(block_lines(channel.blocks, current, self.height_lines), layout=False)
