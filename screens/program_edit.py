"""Editing softkeys of the program editor: mark, copy, cut, paste, delete, undo, redo,
renumber, cursor to start/end, search and replace.

A mixin of :class:`screens.program.ProgramScreen` (which provides ``editor``,
``say``, ``push_softkeys``, ``_show_view`` and the ``_mark_anchor`` /
``search_open`` state); kept apart so each module has one job.
"""

from __future__ import annotations

import re
from typing import Any

from textual.widgets import Input
from textual.widgets.text_area import Selection

from hmi.focus import focus_now
from hmi.i18n import N_, _
from hmi.softkeys import Softkey, SoftkeyMenu
from hmi.widgets.nc_editor import find_text, renumber_blocks


MARKING = N_("Marking: move the cursor, then Copy / Cut / Delete")
"""The dialog line while a block is being marked (Edit → Mark); it goes when the marking ends."""


class EditActions:
    """Edit and search softkeys of the program editor (mixin)."""

    editor: Any
    search_open: bool
    area_hint: str
    _mark_anchor: tuple[int, int] | None

    def edit_menu(self) -> SoftkeyMenu:
        writable = lambda s: s.program is not None and not s.editor.read_only  # noqa: E731
        return SoftkeyMenu.of(
            [
                Softkey("program.mark", "Mark", "mark", active=lambda s: s._mark_anchor is not None),
                Softkey("program.copy", "Copy", "copy"),
                Softkey("program.cut", "Cut", "cut", enabled=writable),
                Softkey("program.paste", "Paste", "paste", enabled=writable),
                Softkey("program.delete", "Delete", "delete_selection", enabled=writable),
                Softkey("program.undo_e", "Undo", "undo", enabled=writable),
                Softkey("program.redo_e", "Redo", "redo", enabled=writable),
                Softkey("program.edit_back", "Back", "pop_menu"),
            ]
        )

    def search_menu(self) -> SoftkeyMenu:
        writable = lambda s: s.program is not None and not s.editor.read_only  # noqa: E731
        return SoftkeyMenu.of(
            [
                Softkey("program.find_next", "Find\nnext", "find_next"),
                Softkey("program.replace", "Replace", "replace_one", enabled=writable),
                Softkey("program.replace_all", "Replace\nall", "replace_all", enabled=writable),
                None, None, None, None,
                Softkey("program.search_back", "Back", "close_search"),
            ]
        )

    # -- edit softkeys --------------------------------------------------------------------------
    def action_cursor_start(self) -> None:
        """Cursor to the start of the program."""
        self.editor.move_cursor((0, 0), center=True)
        focus_now(self.editor)

    def action_cursor_end(self) -> None:
        """Cursor to the end of the program."""
        self.editor.move_cursor(self.editor.document.end, center=True)
        focus_now(self.editor)

    def action_mark(self) -> None:
        """Mark: start (or end) marking a block from the cursor."""
        if self._mark_anchor is None:
            self._mark_anchor = self.editor.cursor_location
            self.say(_(MARKING))
        else:
            self.unmark()
        focus_now(self.editor)

    def unmark(self) -> None:
        """End the marking without using the block (Mark again, the Edit level left): nothing
        stays marked."""
        self._stop_marking()
        self.editor.selection = Selection.cursor(self.editor.cursor_location)

    def _stop_marking(self) -> None:
        """No marking any more: the dialog line no longer says how to mark (a message said
        since, such as "2 line(s) copied", stays)."""
        self._mark_anchor = None
        if self.area_hint == _(MARKING):
            self.say("")

    def _selected_text(self) -> str:
        return self.editor.selected_text

    def action_copy(self) -> None:
        """Copy the marked text to the clipboard."""
        text = self._selected_text()
        if text:
            self.app.copy_to_clipboard(text)
            self.say(_("{count} line(s) copied").format(count=len(text.splitlines()) or 1))
        self._end_mark()

    def action_cut(self) -> None:
        """Cut the marked text into the clipboard."""
        text = self._selected_text()
        if text and not self.editor.read_only:
            self.app.copy_to_clipboard(text)
            self.editor.delete(*self.editor.selection)
        self._end_mark()

    def action_paste(self) -> None:
        """Paste the clipboard at the cursor (replacing a marked block)."""
        if self.editor.read_only or not self.app.clipboard:
            return
        start, end = self.editor.selection
        self.editor.replace(self.app.clipboard, start, end)
        self._end_mark()

    def action_delete_selection(self) -> None:
        """Delete the marked text."""
        if not self.editor.read_only and self._selected_text():
            self.editor.delete(*self.editor.selection)
        self._end_mark()

    def _end_mark(self) -> None:
        self._stop_marking()
        focus_now(self.editor)
        self.refresh_softkeys()

    def action_undo(self) -> None:
        """Undo the last edit."""
        if not self.editor.read_only:
            self.editor.undo()

    def action_redo(self) -> None:
        """Redo the last undone edit."""
        if not self.editor.read_only:
            self.editor.redo()

    def action_renumber(self) -> None:
        """Renumber softkey: block numbers N10, N20 … (one undo step)."""
        if self.editor.read_only:
            return
        text = self.editor.text
        new = renumber_blocks(text, start=10, step=10)
        if new != text:
            cursor = self.editor.cursor_location
            self.editor.replace(new, (0, 0), self.editor.document.end)
            row = min(cursor[0], self.editor.document.line_count - 1)
            self.editor.move_cursor((row, 0))
            self.say(_("Blocks renumbered (step 10)"))

    # -- search --------------------------------------------------------------------------------
    def action_search(self) -> None:
        """Search softkey: open the search bar."""
        self.search_open = True
        self._show_view()
        self.push_softkeys(self.search_menu())
        focus_now(self.query_one("#prog-find", Input))

    def action_close_search(self) -> None:
        """Close the search bar."""
        self.search_open = False
        self._show_view()
        self.pop_softkeys()
        focus_now(self.editor)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter in the search field finds the next occurrence."""
        if event.input.id == "prog-find":
            self.action_find_next()
        elif event.input.id == "prog-replace":
            self.action_replace_one()

    def action_find_next(self) -> bool:
        """Find the search text after the cursor (wrapping round)."""
        query = self.query_one("#prog-find", Input).value
        if not query:
            return False
        lines = self.editor.document.lines
        start = self.editor.selection.end if self.editor.selected_text.upper() == query.upper() else None
        row, column = self.editor.cursor_location
        after = (start[0], start[1] - 1) if start else (row, column - 1)
        found = find_text(lines, query, after)
        if found is None:
            self.say(_("'{text}' not found").format(text=query))
            return False
        row, column = found
        self.editor.selection = Selection((row, column), (row, column + len(query)))
        self.editor.scroll_cursor_visible(center=True)
        self.say("")
        return True

    def action_replace_one(self) -> None:
        """Replace the found text, then find the next one."""
        query = self.query_one("#prog-find", Input).value
        replacement = self.query_one("#prog-replace", Input).value
        if self.editor.read_only or not query:
            return
        if self.editor.selected_text.upper() != query.upper():
            if not self.action_find_next():
                return
        start, end = sorted(self.editor.selection)
        self.editor.replace(replacement, start, end)
        self.action_find_next()

    def action_replace_all(self) -> None:
        """Replace every occurrence (one undo step)."""
        query = self.query_one("#prog-find", Input).value
        replacement = self.query_one("#prog-replace", Input).value
        if self.editor.read_only or not query:
            return
        text = self.editor.text
        new, count = re.subn(re.escape(query), lambda _m: replacement, text, flags=re.IGNORECASE)
        if count:
            self.editor.replace(new, (0, 0), self.editor.document.end)
        self.say(_("{count} replaced").format(count=count))
