"""The block window: the current program block with a few before and after."""

from __future__ import annotations

from typing import Sequence

from rich.text import Text
from textual.widgets import Static

from nck.status import AlarmEntry, BlockView, ChannelStatus

from hmi.i18n import N_, _
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


def _window_text(shown: Sequence[BlockView], highlight: int | None, empty: str = N_("(no program)")) -> Text:
    """The block window's text: ``shown`` with the block at ``highlight`` marked."""
    text = Text()
    if not shown:
        text.append(f" {_(empty)}\n", style="dim")
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
        self.most_lines = height_lines
        self._key: object = None
        self._shown: tuple | None = None

    def on_resize(self) -> None:
        """At most as many lines as the window has room for (the basic block display may share
        its room), so that the marked block stays in sight."""
        lines = min(self.most_lines, self.size.height) if self.size.height > 0 else self.most_lines
        if lines != self.height_lines:
            self.height_lines = lines
            if self._shown is not None:
                self.show(*self._shown)

    def show(self, channel: ChannelStatus, program: ProgramLines | None = None,
             alarms: Sequence[AlarmEntry] = ()) -> None:
        """Redraw when the program or the marked block (:func:`marked_block`) changed."""
        self._shown = (channel, program, alarms)
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


def basic_block_lines(blocks: Sequence[BlockView], index: int, height: int) -> Text:
    """``height`` lines of the basic block display, the block at ``index`` (in execution) marked
    with at least a few before it (more when no more follow); -1 marks none."""
    start = max(0, min(index - BEFORE, len(blocks) - height)) if index >= 0 else max(0, len(blocks) - height)
    shown = blocks[start:start + height]
    return _window_text(shown, index - start if index >= 0 else None, _("(no block executed yet)"))


class BasicBlockWindow(Static):
    """The basic block display (softkey Basic blocks): the blocks as the NCK executes them,
    those a cycle generates included, with absolute end positions in the WCS
    (:mod:`nck.basic_blocks`; 002 L23515-23530)."""

    def __init__(self, **kwargs: object) -> None:
        super().__init__("", markup=False, **kwargs)  # type: ignore[arg-type]
        self.height_lines = 1
        self._key: object = None
        self._shown: ChannelStatus | None = None

    def on_resize(self) -> None:
        """As many lines as the window has room for."""
        self.height_lines = max(1, self.size.height)
        if self._shown is not None:
            self.show(self._shown)

    def show(self, channel: ChannelStatus) -> None:
        """Redraw when the display blocks or the one in execution changed."""
        self._shown = channel
        key = (channel.basic_blocks, channel.basic_block_index, self.height_lines)
        if key == self._key:
            return
        self._key = key
        self.update(basic_block_lines(channel.basic_blocks, channel.basic_block_index, self.height_lines),
                    layout=False)
